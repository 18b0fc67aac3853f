// Samples, time averages, spectra, fields (doc/theory/contact.md
// section 5).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/element_kernels.h>
#include <tribodyn/contact/spectrum.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>

namespace tribodyn
{
  namespace contact
  {
    using namespace dealii;
    void
    ContactSolver::record_sample(const double time)
    {
      // State after the step from t_n: u_prev = u_n, u = u_{n+1},
      // p = p_{n+1}, a = a_n; multipliers of step n.
      const unsigned int n_owned = mass.size();
      const double       b2      = prm.time.beta2;
      const bool         large
        = prm.material.kinematics
          == ContactMaterialParameters::Kinematics::large_deformation;
      const double *uv = u.begin();
      const double *up = u_prev.begin();
      const double *pv = p.begin();
      const double *av = a.begin();

      // Elastic energy: small strain 1/2 u_n^T K u_{n+1} (the energy the
      // central-difference scheme conserves exactly); large deformation
      // the stored energy of u_{n+1}.
      double elastic = 0;
      if (!large)
        {
          for (unsigned int i = 0; i < n_owned; ++i)
            scratch.local_element(i) = uv[i];
          scratch.update_ghost_values();
          scratch_result = 0;
          if (single_material)
            apply_element_stiffness<true>(cell_dofs,
                                          cell_material,
                                          element_stiffness,
                                          scratch.begin(),
                                          scratch_result.begin());
          else
            apply_element_stiffness<false>(cell_dofs,
                                           cell_material,
                                           element_stiffness,
                                           scratch.begin(),
                                           scratch_result.begin());
          scratch_result.compress(VectorOperation::add);
          for (unsigned int i = 0; i < n_owned; ++i)
            elastic += 0.5 * up[i] * scratch_result.local_element(i);
        }
      else
        {
          u.update_ghost_values();
          for (std::size_t c = 0; c < cell_material.size(); ++c)
            {
              const unsigned int   *idx = &cell_dofs[8 * c];
              const VoigtStiffness &C   = stiffness[cell_material[c]];
              for (unsigned int q = 0; q < 4; ++q)
                {
                  double H[2][2] = {{0, 0}, {0, 0}};
                  for (unsigned int i = 0; i < 8; ++i)
                    {
                      const Tensor<1, 2> &g = grad_q[q][dof_node[i]];
                      H[dof_component[i]][0] += uv[idx[i]] * g[0];
                      H[dof_component[i]][1] += uv[idx[i]] * g[1];
                    }
                  Tensor<1, 3> e;
                  e[0]
                    = H[0][0] + 0.5 * (H[0][0] * H[0][0] + H[1][0] * H[1][0]);
                  e[1]
                    = H[1][1] + 0.5 * (H[0][1] * H[0][1] + H[1][1] * H[1][1]);
                  e[2]
                    = H[0][1] + H[1][0] + H[0][0] * H[0][1] + H[1][0] * H[1][1];
                  elastic += 0.5 * e * (C * e) * JxW[q];
                }
            }
        }

      double kinetic = 0, mom[2] = {0, 0};
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double vh = (uv[i] - up[i]) / dt;
          kinetic += 0.5 * mass[i] * vh * vh;
          const double v = pv[i] - dt * (1. - b2) * av[i];
          mom[component[i]] += mass[i] * v;
        }
      double lt = 0, ln = 0, counts[3] = {0, 0, 0};
      for (const ContactNode &node : contact_nodes)
        {
          lt += node.lambda_t;
          ln += node.lambda_n;
          counts[node.status] += 1;
        }
      double M[5] = {0, 0, 0, 0, 0};
      if (point_M_index >= 0)
        {
          const ContactNode &node = contact_nodes[point_M_index];
          M[0]                    = up[node.ix];
          M[1]                    = pv[node.ix] - dt * (1. - b2) * av[node.ix];
          M[2]                    = up[node.iy];
          M[3]                    = pv[node.iy] - dt * (1. - b2) * av[node.iy];
          M[4]                    = node.status;
        }
      std::vector<double> local = {elastic,
                                   kinetic,
                                   mom[0],
                                   mom[1],
                                   lt,
                                   ln,
                                   counts[0],
                                   counts[1],
                                   counts[2],
                                   work_external,
                                   work_internal,
                                   work_contact,
                                   dissipation_friction,
                                   M[0],
                                   M[1],
                                   M[2],
                                   M[3],
                                   M[4]};
      std::vector<double> g(local.size());
      MPI_Allreduce(
        local.data(), g.data(), local.size(), MPI_DOUBLE, MPI_SUM, comm);

      Sample s;
      s.time = time;
      const double width_top
        = cell_hx * static_cast<double>(n_contact_nodes_global - 1);
      s.normal_force             = prm.loading.pressure_at(time) * width_top;
      s.elastic_energy           = g[0];
      s.kinetic_energy           = g[1];
      s.momentum_x               = g[2];
      s.momentum_y               = g[3];
      s.contact_tangential_force = g[4];
      s.contact_normal_force     = g[5];
      s.mu_contact
        = g[5] > 0 ? (prm.loading.plane_velocity >= 0 ? 1. : -1.) * g[4] / g[5]
                   : 0.;
      const double n_nodes   = std::max(1., g[6] + g[7] + g[8]);
      s.separation_fraction  = g[6] / n_nodes;
      s.stick_fraction       = g[7] / n_nodes;
      s.slip_fraction        = g[8] / n_nodes;
      s.external_work        = g[9];
      s.contact_work         = g[11];
      s.friction_dissipation = g[12];
      s.damping_dissipation  = g[10] - (g[0] - 0.);
      s.M_ux                 = g[13];
      s.M_vx                 = g[14];
      s.M_uy                 = g[15];
      s.M_vy                 = g[16];
      s.M_status             = static_cast<unsigned int>(std::lround(g[17]));
      // Kinetic-energy identity of the scheme:
      // KE_{n+1/2} - KE_{-1/2} = W_ext + W_contact - W_internal.
      scale_energy = std::max({scale_energy,
                               s.kinetic_energy + std::abs(s.elastic_energy),
                               std::abs(s.external_work),
                               std::abs(s.contact_work)});
      s.energy_balance_error
        = std::abs(s.kinetic_energy + g[10] - energy_initial - s.external_work
                   - s.contact_work)
          / std::max(scale_energy, 1e-300);
      history.push_back(s);
    }


    void
    ContactSolver::cell_stresses(
      std::vector<std::array<double, 4>> &stress) const
    {
      // Cell-centre stresses (Cauchy for large deformation) of u (ghosted).
      const bool large
        = prm.material.kinematics
          == ContactMaterialParameters::Kinematics::large_deformation;
      const double *uv = u.begin();
      stress.assign(cell_material.size(), {{0, 0, 0, 0}});
      for (std::size_t c = 0; c < cell_material.size(); ++c)
        {
          const unsigned int   *idx     = &cell_dofs[8 * c];
          const VoigtStiffness &C       = stiffness[cell_material[c]];
          const Tensor<1, 3>   &cz      = stiffness_z[cell_material[c]];
          double                H[2][2] = {{0, 0}, {0, 0}};
          for (unsigned int i = 0; i < 8; ++i)
            {
              const Tensor<1, 2> &g = grad_center[dof_node[i]];
              H[dof_component[i]][0] += uv[idx[i]] * g[0];
              H[dof_component[i]][1] += uv[idx[i]] * g[1];
            }
          Tensor<1, 3> e;
          if (!large)
            {
              e[0]                  = H[0][0];
              e[1]                  = H[1][1];
              e[2]                  = H[0][1] + H[1][0];
              const Tensor<1, 3> sv = C * e;
              stress[c]             = {{sv[0], sv[1], sv[2], cz * e}};
            }
          else
            {
              e[0] = H[0][0] + 0.5 * (H[0][0] * H[0][0] + H[1][0] * H[1][0]);
              e[1] = H[1][1] + 0.5 * (H[0][1] * H[0][1] + H[1][1] * H[1][1]);
              e[2] = H[0][1] + H[1][0] + H[0][0] * H[0][1] + H[1][0] * H[1][1];
              const Tensor<1, 3> S = C * e;
              const double       F[2][2]
                = {{1 + H[0][0], H[0][1]}, {H[1][0], 1 + H[1][1]}};
              const double J           = F[0][0] * F[1][1] - F[0][1] * F[1][0];
              const double Sm[2][2]    = {{S[0], S[2]}, {S[2], S[1]}};
              double       sigma[2][2] = {{0, 0}, {0, 0}};
              for (unsigned int i = 0; i < 2; ++i)
                for (unsigned int j = 0; j < 2; ++j)
                  for (unsigned int k = 0; k < 2; ++k)
                    for (unsigned int l = 0; l < 2; ++l)
                      sigma[i][j] += F[i][k] * Sm[k][l] * F[j][l] / J;
              stress[c]
                = {{sigma[0][0], sigma[1][1], sigma[0][1], (cz * e) / J}};
            }
        }
    }


    void
    ContactSolver::write_fields(const std::string &dir,
                                const double       time,
                                const std::string &file_name)
    {
      const unsigned int n_owned = mass.size();
      const double       b2      = prm.time.beta2;
      u.update_ghost_values();
      // Velocity v_n = p_{n+1} - dt (1 - beta2) a_n.
      for (unsigned int i = 0; i < n_owned; ++i)
        scratch.local_element(i)
          = p.local_element(i) - dt * (1. - b2) * a.local_element(i);
      scratch.update_ghost_values();
      // Contact status (x slot) and normal multiplier (y slot), nodal.
      scratch_result = 0;
      for (const ContactNode &node : contact_nodes)
        {
          scratch_result.local_element(node.ix) = node.status;
          scratch_result.local_element(node.iy) = node.lambda_n;
        }
      scratch_result.update_ghost_values();

      std::vector<std::array<double, 4>> stress;
      cell_stresses(stress);
      const unsigned int n_active = triangulation.n_active_cells();
      Vector<float> sxx(n_active), syy(n_active), sxy(n_active), szz(n_active),
        vm(n_active), mat(n_active), rank(n_active);
      const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
      for (std::size_t c = 0; c < cell_material.size(); ++c)
        {
          const auto k = cell_active_index[c];
          sxx[k]       = stress[c][0];
          syy[k]       = stress[c][1];
          sxy[k]       = stress[c][2];
          szz[k]       = stress[c][3];
          vm[k]        = von_mises(stress[c]);
          mat[k]       = cell_material[c];
          rank[k]      = my_rank;
        }

      DataOut<2> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        vector_kind(2,
                    DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(u,
                               std::vector<std::string>(2, "displacement"),
                               DataOut<2>::type_dof_data,
                               vector_kind);
      data_out.add_data_vector(scratch,
                               std::vector<std::string>(2, "velocity"),
                               DataOut<2>::type_dof_data,
                               vector_kind);
      data_out.add_data_vector(
        scratch_result,
        std::vector<std::string>{"contact_status", "contact_normal_force"},
        DataOut<2>::type_dof_data,
        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          2, DataComponentInterpretation::component_is_scalar));
      data_out.add_data_vector(sxx, "stress_xx", DataOut<2>::type_cell_data);
      data_out.add_data_vector(syy, "stress_yy", DataOut<2>::type_cell_data);
      data_out.add_data_vector(sxy, "stress_xy", DataOut<2>::type_cell_data);
      data_out.add_data_vector(szz, "stress_zz", DataOut<2>::type_cell_data);
      data_out.add_data_vector(vm, "von_mises", DataOut<2>::type_cell_data);
      data_out.add_data_vector(mat, "material_id", DataOut<2>::type_cell_data);
      data_out.add_data_vector(rank, "mpi_rank", DataOut<2>::type_cell_data);
      data_out.build_patches();
      DataOutBase::VtkFlags flags;
      flags.time = time;
      data_out.set_flags(flags);
      write_vtu_file(data_out, join_path(dir, file_name), comm);
      scratch_result.zero_out_ghost_values();
      scratch.zero_out_ghost_values();
    }


    void
    ContactSolver::write_fields_of_step(const std::string &dir,
                                        const double       time,
                                        const std::string &file_name)
    {
      TimerOutput::Scope scope(timer, "output fields");
      // Fields at t_n: swap u_n back in for the writer.
      u.swap(u_prev);
      write_fields(dir, time, file_name);
      u.swap(u_prev);
    }


    namespace
    {
      /// Whether a sample at @p time lies in the averaging window
      /// (Output/Averaging start and end time; a negative end: the run's).
      bool
      in_averaging_window(const ContactOutputParameters &output,
                          const double                   time)
      {
        return time >= output.average_start
               && (output.average_end < 0 || time <= output.average_end);
      }
    } // namespace


    ContactSolver::SpectrumSeries
    ContactSolver::spectrum_series() const
    {
      SpectrumSeries series;
      series.spacing               = prm.output.sample_interval * dt;
      const unsigned long interval = prm.output.sample_interval;
      for (const Sample &x : history)
        if (in_averaging_window(prm.output, x.time)
            && std::llround(x.time / dt) % interval == 0)
          {
            series.mu.push_back(x.mu_global);
            series.normal.push_back(x.contact_normal_force);
          }
      return series;
    }


    RunSummary
    ContactSolver::summarize() const
    {
      RunSummary s;
      // The averages take every sample of the window, the spectra those of
      // spectrum_series().
      double n = 0, mu_sum = 0, mu_c = 0, fr[3] = {0, 0, 0},
             m_status[3] = {0, 0, 0};
      for (const Sample &x : history)
        {
          s.energy_balance_error
            = std::max(s.energy_balance_error, x.energy_balance_error);
          if (!in_averaging_window(prm.output, x.time))
            continue;
          n += 1;
          mu_sum += x.mu_global;
          mu_c += x.mu_contact;
          fr[0] += x.stick_fraction;
          fr[1] += x.slip_fraction;
          fr[2] += x.separation_fraction;
          m_status[x.M_status] += 1;
        }
      s.n_samples_averaged = static_cast<std::size_t>(n);
      if (n == 0)
        {
          // An empty window (a leg of a longer run): undefined averages.
          const double undefined = std::numeric_limits<double>::quiet_NaN();
          s.mu_global_mean = s.mu_contact_mean = undefined;
          s.stick_fraction = s.slip_fraction = s.separation_fraction
            = undefined;
          s.M_stick_fraction = s.M_slip_fraction = s.M_separation_fraction
            = undefined;
        }
      else
        {
          s.mu_global_mean        = mu_sum / n;
          s.mu_contact_mean       = mu_c / n;
          s.stick_fraction        = fr[0] / n;
          s.slip_fraction         = fr[1] / n;
          s.separation_fraction   = fr[2] / n;
          s.M_separation_fraction = m_status[separated] / n;
          s.M_stick_fraction      = m_status[stick] / n;
          s.M_slip_fraction       = m_status[slip] / n;
        }
      s.regime              = classify_regime(s.M_stick_fraction,
                                 s.M_slip_fraction,
                                 s.M_separation_fraction,
                                 prm.output.regime_threshold);
      s.regime_contact_face = classify_regime(s.stick_fraction,
                                              s.slip_fraction,
                                              s.separation_fraction,
                                              prm.output.regime_threshold);

      // The peaks of the spectra of mu and of the contact normal force (sum
      // of lambda_N), above the lowest frequencies (trends over the
      // window). The spectra themselves are the "spectrum" output's
      // (postprocessors/spectrum.cc).
      const SpectrumSeries series = spectrum_series();
      const double         f_min  = series.lowest_peak_frequency();
      const auto           peak   = [&](const std::vector<double> &values) {
        std::vector<std::pair<double, double>> above;
        above.emplace_back(0., 0.);
        for (const auto &f : amplitude_spectrum(values, series.spacing))
          if (f.first >= f_min)
            above.push_back(f);
        return dominant_frequency(above);
      };
      s.dominant_frequency_hz              = peak(series.mu);
      s.normal_force_dominant_frequency_hz = peak(series.normal);

      s.wall_time_s          = run_wall_time;
      s.time_loop_s          = loop_wall_time;
      s.dof_steps_per_second = loop_wall_time > 0
                                 ? static_cast<double>(n_dofs())
                                     * (step_count - steps_at_start)
                                     / loop_wall_time
                                 : 0.;
      return s;
    }


    double
    ContactSolver::max_von_mises()
    {
      u.update_ghost_values();
      std::vector<std::array<double, 4>> stress;
      cell_stresses(stress);
      double m = 0;
      for (const auto &s : stress)
        m = std::max(m, von_mises(s));
      return Utilities::MPI::max(m, comm);
    }

  } // namespace contact
} // namespace tribodyn
