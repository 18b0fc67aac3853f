#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>
#include <tribodyn/core/version.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/friction_observer.h>
#include <tribodyn/mca/mca_problem.h>

namespace tribodyn
{
  namespace mca
  {
    void
    McaProblem::declare_parameters(dealii::ParameterHandler &prm)
    {
      Parameters::declare_parameters(prm);
    }


    void
    McaProblem::print_partition_report(dealii::ParameterHandler &handler,
                                       const unsigned int        n_ranks,
                                       std::ostream             &out)
    {
      Parameters p;
      p.parse_parameters(handler);
      const auto f = AutomatonSystem::partition_report(p, n_ranks);
      out << std::setprecision(4) << "Partition of " << f.n_automata
          << " automata over " << n_ranks
          << " ranks (p4est's partition of the cells along its space-filling "
             "curve, emulated):\n"
          << "  owned automata per rank: min " << f.owned_min << ", mean "
          << f.owned_mean << ", max " << f.owned_max << " (imbalance max/mean "
          << f.owned_max / f.owned_mean << ")\n"
          << "  ghosts per rank:         min " << f.ghosts_min << ", mean "
          << f.ghosts_mean << ", max " << f.ghosts_max << "\n"
          << "  ghost/owned ratio (mean): " << f.ghosts_mean / f.owned_mean
          << "\n"
          << "  memory per rank (estimate, largest rank): "
          << f.bytes_per_rank_max / 1048576. << " MiB ("
          << AutomatonSystem::bytes_per_owned_automaton
          << " B per owned automaton, "
          << AutomatonSystem::bytes_per_ghost_automaton << " B per ghost)"
          << std::endl;
    }


    McaProblem::McaProblem(dealii::ParameterHandler &prm,
                           const RunContext         &context)
        : context(context)
    {
      parameters.parse_parameters(prm);
    }


    namespace
    {
      /// Least-squares line y = a x + b.
      std::pair<double, double>
      fit_line(const std::vector<double> &xs, const std::vector<double> &ys)
      {
        const double n  = xs.size();
        double       sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t k = 0; k < xs.size(); ++k)
          {
            sx += xs[k];
            sy += ys[k];
            sxx += xs[k] * xs[k];
            sxy += xs[k] * ys[k];
          }
        const double den = n * sxx - sx * sx;
        if (xs.size() < 2 || den == 0)
          return {std::nan(""), std::nan("")};
        const double a = (n * sxy - sx * sy) / den;
        return {a, (sy - a * sx) / n};
      }


      /**
       * Figures of a uniaxial test: compressive stress from the reactions
       * of the loaded and supporting groups over the cross-section, axial
       * strain from their displacements, lateral strain from the two
       * lateral faces at mid-height.
       */
      class UniaxialAnalysis
      {
      public:
        UniaxialAnalysis(const AutomatonSystem &s,
                         const Parameters      &p,
                         const MPI_Comm         comm)
            : system(s)
            , prm(p)
            , comm(comm)
        {
          axis    = p.analysis.axis;
          lateral = (axis + 1) % 3;
          for (unsigned int g = 0; g < p.boundary.groups.size(); ++g)
            {
              if (p.boundary.groups[g].name == p.analysis.loaded_group)
                loaded = g;
              if (p.boundary.groups[g].name == p.analysis.support_group)
                support = g;
            }
          if (support < 0)
            throw InputError("Parameter 'Analysis/Support group': no "
                             "boundary group is called '"
                             + p.analysis.support_group + "'.");
          const double a    = p.geometry.automaton_size * std::sqrt(2.);
          layer             = a / 2;
          const auto &x     = s.positions();
          const auto &u     = s.displacements();
          double      lo[3] = {1e300, 1e300, 1e300},
                 hi[3]      = {-1e300, -1e300, -1e300};
          for (unsigned int k = 0; k < s.n_owned_automata(); ++k)
            for (unsigned int c = 0; c < 3; ++c)
              {
                lo[c] = std::min(lo[c], x[k][c] - u[k][c]);
                hi[c] = std::max(hi[c], x[k][c] - u[k][c]);
              }
          for (unsigned int c = 0; c < 3; ++c)
            {
              lo[c] = dealii::Utilities::MPI::min(lo[c], comm);
              hi[c] = dealii::Utilities::MPI::max(hi[c], comm);
            }
          lower  = {{lo[0], lo[1], lo[2]}};
          upper  = {{hi[0], hi[1], hi[2]}};
          height = hi[axis] - lo[axis] + layer;
          area = s.n_global_automata() * std::pow(p.geometry.automaton_size, 3)
                 / std::sqrt(2.) / height;
          // distance between the centroids of the two groups
          const auto u0 = centroid();
          length        = std::abs(u0.first - u0.second);
          width         = hi[lateral] - lo[lateral];
        }

        /// Centroids along the axis of the two groups' initial positions.
        std::pair<double, double>
        centroid() const
        {
          const auto &x       = system.positions();
          const auto &u       = system.displacements();
          double      sums[4] = {0, 0, 0, 0};
          (void)x;
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double y   = x[k][axis] - u[k][axis];
              const auto  &grp = prm.boundary.groups;
              (void)grp;
              if (in_group(k, loaded))
                {
                  sums[0] += y;
                  sums[1] += 1;
                }
              if (in_group(k, support))
                {
                  sums[2] += y;
                  sums[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, comm);
          return {sums[0] / sums[1], sums[2] / sums[3]};
        }

        bool
        in_group(const unsigned int k, const int g) const
        {
          // group membership from the initial position (same rule as the
          // system's: the group box)
          const auto &grp = prm.boundary.groups[g];
          const auto &x   = system.positions();
          const auto &u   = system.displacements();
          for (unsigned int c = 0; c < 3; ++c)
            {
              const double y = x[k][c] - u[k][c];
              if (y < grp.lower[c] || y > grp.upper[c])
                return false;
            }
          return true;
        }

        void
        record()
        {
          const auto   forces = system.group_forces();
          const auto   disp   = system.group_displacements();
          const double sign   = forces[loaded][axis] >= 0 ? 1 : 1;
          (void)sign;
          const double stress
            = (forces[loaded][axis] - forces[support][axis]) / (2 * area);
          const double strain = -(disp[loaded][axis] - disp[support][axis])
                                / length * (lower_group_is_support() ? 1 : -1);
          // lateral faces at mid-height
          const auto  &x    = system.positions();
          const auto  &u    = system.displacements();
          const double mid  = 0.5 * (lower[axis] + upper[axis]);
          double       s[4] = {0, 0, 0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double ya = x[k][axis] - u[k][axis];
              if (std::abs(ya - mid) > height / 4)
                continue;
              const double yl = x[k][lateral] - u[k][lateral];
              if (yl < lower[lateral] + layer / 2)
                {
                  s[0] += u[k][lateral];
                  s[1] += 1;
                }
              else if (yl > upper[lateral] - layer / 2)
                {
                  s[2] += u[k][lateral];
                  s[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, s, 4, MPI_DOUBLE, MPI_SUM, comm);
          const double lateral_strain
            = (s[2] / std::max(s[3], 1.) - s[0] / std::max(s[1], 1.)) / width;
          // interior stress: automata of the central part, one FCC cell
          // away from the lateral faces
          const unsigned int third = 3 - axis - lateral;
          const auto        &st    = system.stresses();
          double             in[2] = {0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double ya = x[k][axis] - u[k][axis];
              const double yl = x[k][lateral] - u[k][lateral];
              const double yt = x[k][third] - u[k][third];
              if (std::abs(ya - mid) > height / 4
                  || yl < lower[lateral] + 2 * layer
                  || yl > upper[lateral] - 2 * layer
                  || yt < lower[third] + 2 * layer
                  || yt > upper[third] - 2 * layer)
                continue;
              in[0] += -st[k][axis];
              in[1] += 1;
            }
          MPI_Allreduce(MPI_IN_PLACE, in, 2, MPI_DOUBLE, MPI_SUM, comm);
          strains.push_back(strain);
          stresses.push_back(in[1] > 0 ? in[0] / in[1] : stress);
          nominal_stresses.push_back(stress);
          lateral_strains.push_back(lateral_strain);
        }

        bool
        lower_group_is_support() const
        {
          const auto c = centroid();
          return c.second < c.first;
        }

        void
        finish(JsonValue &summary, std::ostream &out) const
        {
          // nominal yield of the material of the first body sets the window
          const double sy0
            = prm.materials[prm.geometry.bodies[0].material].yield_stress;
          std::vector<double> ex, sx, lx;
          double              max_strain = 0;
          for (std::size_t k = 0; k < strains.size(); ++k)
            {
              max_strain = std::max(max_strain, strains[k]);
              if (stresses[k] > 0.05 * sy0
                  && stresses[k] < prm.analysis.elastic_fit_fraction * sy0)
                {
                  ex.push_back(strains[k]);
                  sx.push_back(stresses[k]);
                  lx.push_back(lateral_strains[k]);
                }
            }
          std::vector<double> nx, ns;
          for (std::size_t k = 0; k < strains.size(); ++k)
            if (nominal_stresses[k] > 0.05 * sy0
                && nominal_stresses[k]
                     < prm.analysis.elastic_fit_fraction * sy0)
              {
                nx.push_back(strains[k]);
                ns.push_back(nominal_stresses[k]);
              }
          summary["youngs_modulus_nominal"] = fit_line(nx, ns).first;
          const auto   elastic              = fit_line(ex, sx);
          const auto   nu_fit               = fit_line(ex, lx);
          const double E                    = elastic.first;
          const double nu                   = nu_fit.first;
          summary["youngs_modulus"]         = E;
          summary["poisson_ratio"]          = nu;
          summary["elastic_fit_points"] = static_cast<unsigned long>(ex.size());
          out << "Uniaxial test (stress of the interior automata, strain "
                 "between the loading layers): E = "
              << E / 1e9 << " GPa, nu = " << nu;
          // hardening branch: the last 40 % of the strain range, if plastic
          std::vector<double> ep, sp;
          for (std::size_t k = 0; k < strains.size(); ++k)
            if (strains[k] > 0.6 * max_strain)
              {
                ep.push_back(strains[k]);
                sp.push_back(stresses[k]);
              }
          const auto   hardening = fit_line(ep, sp);
          const double Et        = hardening.first;
          if (!sp.empty() && sp.back() > 1.02 * E * ep.back() + elastic.second)
            {
              // not plastic: the branch lies on the elastic line
            }
          if (!ep.empty() && std::isfinite(Et) && Et < 0.8 * E)
            {
              const double eps_y
                = (hardening.second - elastic.second) / (E - Et);
              const double sigma_y         = E * eps_y + elastic.second;
              summary["yield_stress"]      = sigma_y;
              summary["tangent_modulus"]   = Et;
              summary["hardening_modulus"] = E * Et / (E - Et);
              out << ", sigma_y = " << sigma_y / 1e6
                  << " MPa, tangent modulus = " << Et / 1e9
                  << " GPa (plastic modulus H = " << E * Et / (E - Et) / 1e9
                  << " GPa)";
            }
          else
            summary["yield_stress"] = JsonValue();
          out << "\n  nominal E (reaction / nominal cross-section, lower by "
                 "the surface layer) = "
              << fit_line(nx, ns).first / 1e9 << " GPa" << std::endl;
          summary["max_strain"]         = max_strain;
          summary["cross_section_area"] = area;
          summary["gauge_length"]       = length;
        }

        std::vector<double> strains, stresses, nominal_stresses,
          lateral_strains;

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
        MPI_Comm               comm;
        unsigned int           axis = 2, lateral = 0;
        int                    loaded = -1, support = -1;
        double layer = 0, height = 0, area = 0, length = 0, width = 0;
        Vec3   lower, upper;
      };


      /// Arrival of a pulse at two probe planes (peak of the mean axial
      /// velocity of the automata of each plane).
      class PulseAnalysis
      {
      public:
        PulseAnalysis(const AutomatonSystem &s,
                      const Parameters      &p,
                      const MPI_Comm         comm)
            : system(s)
            , prm(p)
            , comm(comm)
        {
        }

        void
        record(const double t)
        {
          const auto        &x = system.positions();
          const auto        &u = system.displacements();
          const auto        &v = system.velocities();
          const unsigned int a = prm.analysis.axis;
          const double half = prm.geometry.automaton_size * std::sqrt(2.) / 8;
          double       s[4] = {0, 0, 0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double y = x[k][a] - u[k][a];
              if (std::abs(y - prm.analysis.probe_1) < half)
                {
                  s[0] += v[k][a];
                  s[1] += 1;
                }
              if (std::abs(y - prm.analysis.probe_2) < half)
                {
                  s[2] += v[k][a];
                  s[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, s, 4, MPI_DOUBLE, MPI_SUM, comm);
          if (s[1] == 0 || s[3] == 0)
            throw InputError("Parameters 'Analysis/Probe 1' and 'Probe 2' "
                             "must lie on layers of automata (none found "
                             "within a/8 of them).");
          times.push_back(t);
          v1.push_back(s[0] / s[1]);
          v2.push_back(s[2] / s[3]);
        }

        static double
        peak_time(const std::vector<double> &t, const std::vector<double> &v)
        {
          std::size_t best = 0;
          for (std::size_t k = 0; k < v.size(); ++k)
            if (std::abs(v[k]) > std::abs(v[best]))
              best = k;
          if (best == 0 || best + 1 >= v.size())
            return t[best];
          // parabola through three points
          const double y0 = v[best - 1], y1 = v[best], y2 = v[best + 1];
          const double h   = t[best + 1] - t[best];
          const double den = y0 - 2 * y1 + y2;
          return den == 0 ? t[best] : t[best] + 0.5 * h * (y0 - y2) / den;
        }

        void
        finish(JsonValue &summary, std::ostream &out) const
        {
          const double t1 = peak_time(times, v1), t2 = peak_time(times, v2);
          const double c
            = std::abs(prm.analysis.probe_2 - prm.analysis.probe_1) / (t2 - t1);
          summary["arrival_time_1"] = t1;
          summary["arrival_time_2"] = t2;
          summary["wave_speed"]     = c;
          const double cp
            = prm.materials[prm.geometry.bodies[0].material].p_wave_speed();
          summary["p_wave_speed_reference"] = cp;
          out << "Pulse: arrival at the probes " << t1 << " s and " << t2
              << " s, wave speed " << c
              << " m/s (c_p = sqrt((K + 4G/3)/rho) = " << cp << " m/s)"
              << std::endl;
        }

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
        MPI_Comm               comm;
        std::vector<double>    times, v1, v2;
      };
    } // namespace


    void
    McaProblem::run()
    {
      const auto     start = std::chrono::steady_clock::now();
      const MPI_Comm comm  = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(comm);
      dealii::ConditionalOStream pcout(std::cout, root);
      dealii::TimerOutput        timer(comm,
                                pcout,
                                dealii::TimerOutput::summary,
                                dealii::TimerOutput::wall_times);
      const std::string         &out_dir = context.output_directory;
      const Parameters          &p       = parameters;

      AutomatonSystem system(p, comm);
      {
        dealii::TimerOutput::Scope scope(timer, "setup (packing, pair list)");
        system.setup();
      }
      const double dt = system.time_step();
      const auto   n_steps
        = static_cast<unsigned long>(std::ceil(p.time.end_time / dt - 1e-9));
      pcout << "MCA: " << system.n_global_automata() << " automata, "
            << system.n_global_pairs() << " pairs, " << n_ranks
            << " MPI rank(s); dt = " << dt
            << " s (critical d/c_p = " << system.critical_time_step() << " s), "
            << n_steps << " steps" << std::endl;

      // Series
      std::vector<std::string> columns = {"time",
                                          "kinetic_energy",
                                          "elastic_energy",
                                          "plastic_work",
                                          "friction_work",
                                          "n_bonded_pairs",
                                          "n_unbonded_contacts"};
      for (const auto &g : p.boundary.groups)
        for (const char *c : {"fx", "fy", "fz", "ux", "uy", "uz"})
          columns.push_back(g.name + "_" + c);
      const bool friction
        = p.analysis.type == AnalysisParameters::Type::friction;
      int loaded = -1;
      for (unsigned int g = 0; g < p.boundary.groups.size(); ++g)
        if (p.boundary.groups[g].name == p.analysis.loaded_group)
          loaded = g;
      if (friction)
        columns.push_back("mu");
      CsvWriter series(join_path(out_dir, "series.csv"), columns, root);
      PvdWriter pvd(join_path(out_dir, "particles.pvd"), root);
      PvdWriter pvd_slab(join_path(out_dir, "cross_section.pvd"), root);

      std::unique_ptr<UniaxialAnalysis> uniaxial;
      std::unique_ptr<PulseAnalysis>    pulse;
      if (p.analysis.type == AnalysisParameters::Type::uniaxial)
        uniaxial = std::make_unique<UniaxialAnalysis>(system, p, comm);
      if (p.analysis.type == AnalysisParameters::Type::pulse)
        pulse = std::make_unique<PulseAnalysis>(system, p, comm);
      FrictionObserver friction_observer(p, loaded);

      const unsigned long series_every
        = p.output.series_interval > 0
            ? std::max(1ul,
                       static_cast<unsigned long>(
                         std::round(p.output.series_interval / dt)))
            : 100ul;
      const unsigned long output_every
        = p.output.output_interval > 0
            ? std::max(1ul,
                       static_cast<unsigned long>(
                         std::round(p.output.output_interval / dt)))
            : n_steps;
      unsigned int output_number = 0;
      const bool   need_stress   = p.output.write_stress;

      auto write_outputs = [&]() {
        dealii::TimerOutput::Scope scope(timer, "output");
        if (p.output.write_particles)
          pvd.add(system.time(),
                  system.write_particles(
                    out_dir, "particles", output_number, need_stress));
        if (p.output.cross_section)
          {
            const double th = p.output.cross_section_thickness > 0
                                ? p.output.cross_section_thickness
                                : 7 * p.geometry.automaton_size / std::sqrt(2.);
            pvd_slab.add(
              system.time(),
              system.write_particles(out_dir,
                                     "cross_section",
                                     output_number,
                                     need_stress,
                                     true,
                                     p.output.cross_section_axis,
                                     p.output.cross_section_position - th / 2,
                                     p.output.cross_section_position + th / 2));
          }
        ++output_number;
      };

      std::string key_figure;
      auto        record_series = [&]() {
        dealii::TimerOutput::Scope scope(timer, "series");
        const SystemEnergies       e      = system.energies();
        const auto                 forces = system.group_forces();
        const auto                 disp   = system.group_displacements();
        std::vector<double>        row    = {system.time(),
                                             e.kinetic,
                                             e.elastic,
                                             e.plastic_work,
                                             e.friction_work,
                                             double(e.n_bonded),
                                             double(e.n_unbonded_contacts)};
        for (unsigned int g = 0; g < forces.size(); ++g)
          {
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(forces[g][c]);
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(disp[g][c]);
          }
        if (friction && loaded >= 0)
          {
            const double mu
              = friction_observer.record(system.time(), forces, e);
            row.push_back(mu);
            key_figure = "mu = " + format_number(mu);
          }
        series.add_row(row);
        series.flush();
        if (uniaxial)
          uniaxial->record();
      };

      ProgressReporter progress(
        std::cout, root, p.time.end_time, context.progress_interval, "mca");
      write_outputs();
      record_series();
      const auto loop_start = std::chrono::steady_clock::now();
      {
        dealii::TimerOutput::Scope scope(timer, "time steps");
        for (unsigned long s = 1; s <= n_steps; ++s)
          {
            system.step();
            if (pulse)
              pulse->record(system.time());
            if (s % series_every == 0 || s == n_steps)
              {
                timer.leave_subsection("time steps");
                record_series();
                if (s % output_every == 0 || s == n_steps)
                  write_outputs();
                timer.enter_subsection("time steps");
              }
            progress.update(s, system.time(), key_figure);
          }
      }
      const double loop_seconds
        = std::chrono::duration<double>(std::chrono::steady_clock::now()
                                        - loop_start)
            .count();
      progress.update(n_steps, system.time(), key_figure, true);
      series.flush(true);

      const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count();
      JsonValue summary                = JsonValue::object();
      summary["problem"]               = "mca";
      summary["tribodyn_version"]      = version_string;
      summary["n_mpi_ranks"]           = n_ranks;
      summary["n_automata"]            = system.n_global_automata();
      summary["n_pairs"]               = system.n_global_pairs();
      summary["n_steps"]               = n_steps;
      summary["dt"]                    = dt;
      summary["critical_dt"]           = system.critical_time_step();
      summary["end_time"]              = system.time();
      summary["n_pair_list_rebuilds"]  = system.n_rebuilds();
      const unsigned long long dropped = system.n_dropped_bonds();
      summary["n_dropped_bonds"]       = dropped;
      if (dropped > 0)
        pcout << "Warning: " << dropped
              << " bonded pair(s) were stretched beyond the pair-list range "
                 "(automaton size times 1 + Interaction/Skin) and their bonds "
                 "were lost. With Bond breaking = false this is a large "
                 "deformation the list cannot follow: raise Interaction/Skin."
              << std::endl;
      summary["n_ghost_automata_max"]
        = dealii::Utilities::MPI::max(system.n_ghost_automata(), comm);
      summary["n_owned_automata_min"]
        = dealii::Utilities::MPI::min(system.n_owned_automata(), comm);
      summary["n_owned_automata_max"]
        = dealii::Utilities::MPI::max(system.n_owned_automata(), comm);
      summary["memory_bytes_max"] = dealii::Utilities::MPI::max(
        static_cast<double>(system.memory_consumption()), comm);
      summary["wall_time_s"] = wall;
      summary["time_loop_s"] = loop_seconds;
      summary["automaton_steps_per_second"]
        = loop_seconds > 0
            ? double(system.n_global_automata()) * n_steps / loop_seconds
            : 0.;
      summary["automaton_steps_per_second_per_rank"]
        = loop_seconds > 0 ? double(system.n_global_automata()) * n_steps
                               / loop_seconds / n_ranks
                           : 0.;
      {
        const SystemEnergies e         = system.energies();
        summary["kinetic_energy"]      = e.kinetic;
        summary["elastic_energy"]      = e.elastic;
        summary["plastic_work"]        = e.plastic_work;
        summary["friction_work"]       = e.friction_work;
        summary["n_bonded_pairs"]      = e.n_bonded;
        summary["n_unbonded_contacts"] = e.n_unbonded_contacts;
        const auto forces              = system.group_forces();
        JsonValue  groups              = JsonValue::object();
        for (unsigned int g = 0; g < forces.size(); ++g)
          groups[p.boundary.groups[g].name]
            = json_array({forces[g][0], forces[g][1], forces[g][2]});
        summary["group_forces"] = groups;
      }
      std::ostringstream figures;
      figures << std::setprecision(6);
      if (uniaxial)
        uniaxial->finish(summary, figures);
      if (pulse)
        pulse->finish(summary, figures);
      if (friction)
        friction_observer.finish(out_dir, root, summary, figures);
      pcout << figures.str();
      pcout << "Throughput: "
            << double(system.n_global_automata()) * n_steps
                 / std::max(loop_seconds, 1e-300) / n_ranks
            << " automaton-steps/s per rank" << std::endl;
      if (root)
        write_file_atomically(join_path(out_dir, "summary.json"),
                              summary.dump() + "\n");
    }


    static const bool registered = register_problem(
      {"mca",
       "3D movable cellular automata: bonded automata with many-body pair "
       "law, rotations, von Mises plasticity, bond breaking and formation "
       "(seed 000)",
       &McaProblem::declare_parameters,
       [](dealii::ParameterHandler &prm,
          const RunContext         &context) -> std::unique_ptr<Problem> {
         return std::make_unique<McaProblem>(prm, context);
       },
       &McaProblem::print_partition_report});
  } // namespace mca
} // namespace tribodyn
