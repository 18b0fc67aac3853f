#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/spectrum.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>

namespace tribodyn
{
  namespace contact
  {
    using namespace dealii;

    namespace
    {
      /// Largest eigenvalue of a symmetric n x n matrix (cyclic Jacobi).
      double
      largest_symmetric_eigenvalue(std::vector<double> A, const unsigned int n)
      {
        for (unsigned int sweep = 0; sweep < 100; ++sweep)
          {
            double off = 0, diag = 0;
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                (i == j ? diag : off) += A[i * n + j] * A[i * n + j];
            if (off <= 1e-30 * diag)
              break;
            for (unsigned int p = 0; p < n; ++p)
              for (unsigned int q = p + 1; q < n; ++q)
                {
                  const double apq = A[p * n + q];
                  if (std::abs(apq) < 1e-300)
                    continue;
                  const double theta
                    = (A[q * n + q] - A[p * n + p]) / (2. * apq);
                  const double t
                    = (theta >= 0 ? 1. : -1.)
                      / (std::abs(theta) + std::sqrt(theta * theta + 1.));
                  const double c = 1. / std::sqrt(t * t + 1.), s = t * c;
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double akp = A[k * n + p], akq = A[k * n + q];
                      A[k * n + p] = c * akp - s * akq;
                      A[k * n + q] = s * akp + c * akq;
                    }
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double apk = A[p * n + k], aqk = A[q * n + k];
                      A[p * n + k] = c * apk - s * aqk;
                      A[q * n + k] = s * apk + c * aqk;
                    }
                }
          }
        double largest = -std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < n; ++i)
          largest = std::max(largest, A[i * n + i]);
        return largest;
      }


      /// Check that a Voigt stiffness is symmetric positive definite.
      void
      check_stiffness(const VoigtStiffness &C, const std::string &what)
      {
        double scale = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            scale = std::max(scale, std::abs(C[i][j]));
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < i; ++j)
            if (std::abs(C[i][j] - C[j][i]) > 1e-6 * scale)
              throw InputError("The stiffness of " + what
                               + " is not symmetric (C" + std::to_string(i + 1)
                               + std::to_string(j + 1) + " = "
                               + format_number(C[i][j]) + ", C"
                               + std::to_string(j + 1) + std::to_string(i + 1)
                               + " = " + format_number(C[j][i]) + ").");
        const double m1 = C[0][0];
        const double m2 = C[0][0] * C[1][1] - C[0][1] * C[1][0];
        const double m3 = determinant(C);
        if (!(m1 > 0 && m2 > 0 && m3 > 0))
          throw InputError("The stiffness of " + what
                           + " is not positive definite (leading minors "
                           + format_number(m1) + ", " + format_number(m2) + ", "
                           + format_number(m3)
                           + "); check the moduli and their units (Pa).");
      }


      double
      von_mises(const std::array<double, 4> &s)
      {
        const double a = s[0] - s[1], b = s[1] - s[3], c = s[3] - s[0];
        return std::sqrt(0.5 * (a * a + b * b + c * c) + 3. * s[2] * s[2]);
      }
    } // namespace


    ContactSolver::ContactSolver(const MPI_Comm           comm,
                                 const ContactParameters &parameters,
                                 TimerOutput             &timer)
        : comm(comm)
        , prm(parameters)
        , timer(timer)
        , triangulation(comm)
        , fe(FE_Q<2>(1), 2)
        , dof_handler(triangulation)
    {
    }


    types::global_dof_index
    ContactSolver::n_dofs() const
    {
      return dof_handler.n_dofs();
    }


    double
    ContactSolver::heterogeneity_area_fraction() const
    {
      double n1 = 0;
      for (const unsigned char m : cell_material)
        n1 += (m == 1);
      return Utilities::MPI::sum(n1, comm)
             / triangulation.n_global_active_cells();
    }


    void
    ContactSolver::setup()
    {
      TimerOutput::Scope scope(timer, "setup");
      setup_materials();
      make_mesh();
      dof_handler.distribute_dofs(fe);
      setup_element_data();
      setup_vectors_and_nodes();
      compute_critical_time_step();
    }


    void
    ContactSolver::setup_materials()
    {
      const auto &m = prm.material;
      using Type    = ContactMaterialParameters::Type;
      stiffness.clear();
      stiffness_z.clear();
      density.clear();
      auto add_isotropic = [&](const IsotropicElasticMaterial &iso) {
        stiffness.push_back(iso.plane_strain_voigt_stiffness());
        Tensor<1, 3> cz;
        cz[0] = cz[1] = iso.lambda();
        stiffness_z.push_back(cz);
        density.push_back(iso.density);
      };
      std::ostringstream text;
      text << std::setprecision(4);
      switch (m.type)
        {
          case Type::isotropic:
            add_isotropic(m.isotropic);
            text << "isotropic (E = " << m.isotropic.youngs_modulus / 1e9
                 << " GPa, nu = " << m.isotropic.poisson_ratio
                 << ", rho = " << m.isotropic.density << ")";
            break;
          case Type::anisotropic:
            check_stiffness(m.anisotropic_stiffness,
                            "'Material/Anisotropic/Stiffness'");
            stiffness.push_back(m.anisotropic_stiffness);
            stiffness_z.push_back(m.anisotropic_c_z);
            density.push_back(m.density);
            text << "anisotropic (given stiffness)";
            break;
          case Type::engineering_constants:
            {
              Tensor<1, 3> cz;
              stiffness.push_back(transversely_isotropic_plane_strain(
                m.E_L, m.E_T, m.nu_LT, m.nu_TT, m.G_LT, cz));
              check_stiffness(stiffness.back(),
                              "'Material/Engineering constants'");
              stiffness_z.push_back(cz);
              density.push_back(m.density);
              text << "transversely isotropic (E_L = " << m.E_L / 1e9
                   << " GPa, E_T = " << m.E_T / 1e9
                   << " GPa, G_LT = " << m.G_LT / 1e9 << " GPa)";
              break;
            }
          case Type::homogenization_summary:
            {
              Tensor<1, 3> cz;
              stiffness.push_back(read_homogenization_stiffness(m.summary_file,
                                                                m.summary_key,
                                                                cz));
              check_stiffness(stiffness.back(),
                              "'" + m.summary_key + "' in '" + m.summary_file
                                + "'");
              stiffness_z.push_back(cz);
              density.push_back(m.density);
              text << "homogenized (" << m.summary_key << " of "
                   << m.summary_file << ")";
              break;
            }
          case Type::morphology:
            add_isotropic(m.matrix);
            add_isotropic(m.heterogeneity);
            text << "meso";
            break;
        }
      material_text = text.str();
    }


    void
    ContactSolver::make_mesh()
    {
      if (prm.material.type == ContactMaterialParameters::Type::morphology)
        {
          const Morphology morphology = Morphology::create(prm.morphology);
          create_morphology_mesh(morphology,
                                 prm.geometry.subdivisions_per_pixel,
                                 triangulation);
          material_text += ": " + morphology.description();
        }
      else
        {
          const unsigned int nx
            = std::max(1.,
                       std::round(prm.geometry.width / prm.geometry.mesh_size));
          const unsigned int ny = std::max(
            1., std::round(prm.geometry.height / prm.geometry.mesh_size));
          GridGenerator::subdivided_hyper_rectangle(
            triangulation,
            {nx, ny},
            Point<2>(0, 0),
            Point<2>(prm.geometry.width, prm.geometry.height),
            /*colorize = */ true);
          for (const auto &cell : triangulation.cell_iterators_on_level(0))
            cell->set_material_id(0);
        }
    }


    void
    ContactSolver::setup_element_data()
    {
      // All cells are identical axis-parallel rectangles: take the shape
      // gradients of the first one (every rank computes the same numbers
      // from its first cell, or from the first coarse cell if it owns none).
      typename DoFHandler<2>::active_cell_iterator first = dof_handler.end();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            first = cell;
            break;
          }
      if (first == dof_handler.end())
        first = dof_handler.begin_active();
      cell_hx = first->vertex(1)[0] - first->vertex(0)[0];
      cell_hy = first->vertex(2)[1] - first->vertex(0)[1];

      const QGauss<2> quadrature(2);
      FEValues<2>     fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
      fe_values.reinit(first);
      const QGauss<2> center(1);
      FEValues<2>     fe_center(fe, center, update_gradients);
      fe_center.reinit(first);
      for (unsigned int i = 0; i < 8; ++i)
        {
          const auto ci    = fe.system_to_component_index(i);
          dof_component[i] = ci.first;
          dof_node[i]      = ci.second;
          for (unsigned int q = 0; q < 4; ++q)
            grad_q[q][ci.second]
              = fe_values.shape_grad_component(i, q, ci.first);
          grad_center[ci.second]
            = fe_center.shape_grad_component(i, 0, ci.first);
        }
      for (unsigned int q = 0; q < 4; ++q)
        {
          JxW[q] = fe_values.JxW(q);
          for (unsigned int i = 0; i < 8; ++i)
            {
              grad_x[q][i]   = grad_q[q][dof_node[i]][0];
              grad_y[q][i]   = grad_q[q][dof_node[i]][1];
              grad_x_w[q][i] = grad_x[q][i] * JxW[q];
              grad_y_w[q][i] = grad_y[q][i] * JxW[q];
            }
        }

      // Element stiffness K_e = sum_q B^T C B JxW per material.
      element_stiffness.assign(stiffness.size(), {});
      for (unsigned int mat = 0; mat < stiffness.size(); ++mat)
        {
          const VoigtStiffness &C = stiffness[mat];
          for (unsigned int i = 0; i < 8; ++i)
            for (unsigned int j = 0; j < 8; ++j)
              {
                double k = 0;
                for (unsigned int q = 0; q < 4; ++q)
                  {
                    Tensor<1, 3>        Bi, Bj;
                    const Tensor<1, 2> &gi = grad_q[q][dof_node[i]];
                    const Tensor<1, 2> &gj = grad_q[q][dof_node[j]];
                    const unsigned int  c  = dof_component[i],
                                       d   = dof_component[j];
                    Bi[c]                  = gi[c];
                    Bi[2]                  = gi[1 - c];
                    Bj[d]                  = gj[d];
                    Bj[2]                  = gj[1 - d];
                    k += Bi * (C * Bj) * JxW[q];
                  }
                element_stiffness[mat][8 * i + j] = k;
              }
        }
    }


    void
    ContactSolver::setup_vectors_and_nodes()
    {
      locally_owned = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
      u.reinit(locally_owned, locally_relevant, comm);
      for (VectorType *v :
           {&u_prev, &u_next, &p, &w, &r, &a, &scratch, &scratch_result})
        v->reinit(u);
      const auto        &partitioner = *u.get_partitioner();
      const unsigned int n_owned     = partitioner.locally_owned_size();

      // Cell data, lumped mass (rho A / 4 per node for rectangles, exact
      // row-sum lumping) and the load of a unit pressure on the top face.
      std::vector<unsigned char> comp_local(partitioner.locally_owned_size()
                                              + partitioner.n_ghost_indices(),
                                            0);
      cell_dofs.clear();
      cell_material.clear();
      cell_active_index.clear();
      std::vector<types::global_dof_index> dofs(8);
      std::set<unsigned int>               material_set;
      const double                         area = cell_hx * cell_hy;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            Assert(std::abs(cell->vertex(1)[0] - cell->vertex(0)[0] - cell_hx)
                     < 1e-9 * cell_hx,
                   ExcInternalError());
            cell->get_dof_indices(dofs);
            const unsigned int mat
              = prm.material.type == ContactMaterialParameters::Type::morphology
                  ? cell->material_id()
                  : 0;
            AssertThrow(mat < stiffness.size(), ExcInternalError());
            material_set.insert(mat);
            cell_material.push_back(mat);
            cell_active_index.push_back(cell->active_cell_index());
            for (unsigned int i = 0; i < 8; ++i)
              {
                const unsigned int l = partitioner.global_to_local(dofs[i]);
                cell_dofs.push_back(l);
                comp_local[l] = dof_component[i];
                r.local_element(l) += density[mat] * area / 4.;
              }
            for (const unsigned int f : GeometryInfo<2>::face_indices())
              if (cell->face(f)->at_boundary()
                  && cell->face(f)->boundary_id() == 3)
                for (unsigned int v = 0; v < 2; ++v)
                  {
                    const unsigned int l = partitioner.global_to_local(
                      cell->face(f)->vertex_dof_index(v, 1));
                    scratch_result.local_element(l) -= cell_hx / 2.;
                  }
          }
      single_material
        = Utilities::MPI::max(static_cast<unsigned int>(material_set.size()),
                              comm)
          <= 1;
      r.compress(VectorOperation::add);
      scratch_result.compress(VectorOperation::add);
      mass.resize(n_owned);
      mass_inverse.resize(n_owned);
      unit_load.resize(n_owned);
      component.assign(comp_local.begin(), comp_local.begin() + n_owned);
      double local_mass = 0;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          mass[i]         = r.local_element(i);
          mass_inverse[i] = 1. / mass[i];
          unit_load[i]    = scratch_result.local_element(i);
          if (component[i] == 0)
            local_mass += mass[i];
        }
      mass_total     = Utilities::MPI::sum(local_mass, comm);
      r              = 0;
      scratch_result = 0;

      // Top and bottom nodes (owned).
      std::set<unsigned int>              top_x, top_y;
      std::map<unsigned int, ContactNode> bottom; // keyed by local y dof
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : GeometryInfo<2>::face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto face = cell->face(f);
                for (unsigned int v = 0; v < 2; ++v)
                  {
                    const types::global_dof_index gx
                      = face->vertex_dof_index(v, 0),
                      gy = face->vertex_dof_index(v, 1);
                    if (!locally_owned.is_element(gx))
                      continue;
                    const unsigned int lx = partitioner.global_to_local(gx),
                                       ly = partitioner.global_to_local(gy);
                    if (face->boundary_id() == 3)
                      {
                        top_x.insert(lx);
                        top_y.insert(ly);
                      }
                    else if (face->boundary_id() == 2)
                      {
                        ContactNode node;
                        node.ix    = lx;
                        node.iy    = ly;
                        node.m     = mass[ly];
                        node.x     = face->vertex(v)[0];
                        bottom[ly] = node;
                      }
                  }
              }
      top_x_dofs.assign(top_x.begin(), top_x.end());
      top_y_dofs.assign(top_y.begin(), top_y.end());
      contact_nodes.clear();
      for (const auto &b : bottom)
        contact_nodes.push_back(b.second);
      n_contact_nodes_global
        = Utilities::MPI::sum(static_cast<unsigned int>(contact_nodes.size()),
                              comm);
      if (prm.loading.top_held_in_x)
        for (const unsigned int i : top_x_dofs)
          mass_inverse[i] = 0;

      // Point M: the contact node closest to the middle of the bottom face
      // (the smaller x on a tie).
      const double width
        = prm.material.type == ContactMaterialParameters::Type::morphology
            ? prm.morphology.width
            : cell_hx * std::round(prm.geometry.width / cell_hx);
      double best       = std::numeric_limits<double>::max();
      int    best_index = -1;
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        {
          const double d = std::abs(contact_nodes[k].x - 0.5 * width);
          if (d < best - 1e-12 * width
              || (std::abs(d - best) <= 1e-12 * width && best_index >= 0
                  && contact_nodes[k].x < contact_nodes[best_index].x))
            {
              best       = d;
              best_index = k;
            }
        }
      const double global_best = Utilities::MPI::min(best, comm);
      const double my_x
        = (best_index >= 0 && std::abs(best - global_best) <= 1e-12 * width)
            ? contact_nodes[best_index].x
            : std::numeric_limits<double>::max();
      point_M_x     = Utilities::MPI::min(my_x, comm);
      point_M_index = (best_index >= 0 && my_x == point_M_x) ? best_index : -1;
    }


    void
    ContactSolver::compute_critical_time_step()
    {
      // omega_max <= max over elements of the element's largest frequency
      // with its lumped mass (Irons' element eigenvalue bound).
      omega_maximum = 0;
      double c_max  = 0;
      for (unsigned int mat = 0; mat < stiffness.size(); ++mat)
        {
          const double        m_node = density[mat] * cell_hx * cell_hy / 4.;
          std::vector<double> A(64);
          for (unsigned int k = 0; k < 64; ++k)
            A[k] = element_stiffness[mat][k] / m_node;
          omega_maximum
            = std::max(omega_maximum,
                       std::sqrt(largest_symmetric_eigenvalue(A, 8)));
          c_max = std::max(c_max,
                           std::sqrt(std::max(stiffness[mat][0][0],
                                              stiffness[mat][1][1])
                                     / density[mat]));
        }
      dt_cfl          = std::min(cell_hx, cell_hy) / c_max;
      const double b2 = prm.time.beta2;
      const double xi = prm.time.damping * omega_maximum / 2.;
      dt_critical = (std::sqrt(2. * b2 + xi * xi) - xi) / (b2 * omega_maximum);

      dt = prm.time.time_step;
      if (dt > dt_critical)
        {
          if (prm.time.automatic_time_step)
            dt = prm.time.safety_factor * dt_critical;
          else
            throw InputError(
              "'Time integration/Time step' = " + format_number(dt)
              + " s is above the critical time step "
              + format_number(dt_critical)
              + " s of this mesh and material (omega_max = "
              + format_number(omega_maximum)
              + " rad/s, beta2 = " + format_number(b2)
              + ", damping beta = " + format_number(prm.time.damping)
              + " s; CFL l_min/c_max = " + format_number(dt_cfl)
              + " s): the explicit scheme would be unstable. Use a time step "
                "of at most "
              + format_number(dt_critical)
              + " s, or set 'Automatic time step = true'.");
        }
      h                   = dt * dt * (0.5 + b2);
      friction_step.mu    = prm.contact.law == FrictionLaw::frictionless
                              ? 0.
                              : prm.contact.friction_coefficient;
      friction_step.decay = std::exp(-dt / prm.contact.regularization_time);
    }


    template <bool single>
    inline void
    apply_element_stiffness(const std::vector<unsigned int>  &cell_dofs,
                            const std::vector<unsigned char> &cell_material,
                            const std::vector<std::array<double, 64>> &Ke,
                            const double *__restrict src,
                            double *__restrict dst)
    {
      const std::size_t n_cells = cell_material.size();
      const double     *K0      = Ke[0].data();
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          const unsigned int *idx = &cell_dofs[8 * c];
          const double       *K   = single ? K0 : Ke[cell_material[c]].data();
          double              we[8];
          for (unsigned int j = 0; j < 8; ++j)
            we[j] = src[idx[j]];
          for (unsigned int i = 0; i < 8; ++i)
            {
              double s = 0;
              for (unsigned int j = 0; j < 8; ++j)
                s += K[8 * i + j] * we[j];
              dst[idx[i]] += s;
            }
        }
    }


    void
    ContactSolver::internal_forces_small_strain()
    {
      if (single_material)
        apply_element_stiffness<true>(
          cell_dofs, cell_material, element_stiffness, w.begin(), r.begin());
      else
        apply_element_stiffness<false>(
          cell_dofs, cell_material, element_stiffness, w.begin(), r.begin());
    }


    void
    ContactSolver::internal_forces_large_deformation()
    {
      const double     *uv      = u.begin();
      const double     *pv      = p.begin();
      double           *rv      = r.begin();
      const double      beta    = prm.time.damping;
      const std::size_t n_cells = cell_material.size();
      // Component of each local dof as a 0/1 mask (no branches below).
      double is_y[8];
      for (unsigned int i = 0; i < 8; ++i)
        is_y[i] = dof_component[i];
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          const unsigned int *idx = &cell_dofs[8 * c];
          const unsigned int  mat = cell_material[c];
          const double C00 = stiffness[mat][0][0], C01 = stiffness[mat][0][1],
                       C02 = stiffness[mat][0][2], C11 = stiffness[mat][1][1],
                       C12 = stiffness[mat][1][2], C22 = stiffness[mat][2][2];
          const double *K = element_stiffness[mat].data();
          double        ue[8], pe[8], fe_[8] = {};
          for (unsigned int j = 0; j < 8; ++j)
            {
              ue[j] = uv[idx[j]];
              pe[j] = pv[idx[j]];
            }
          for (unsigned int q = 0; q < 4; ++q)
            {
              // Displacement gradient H[c][d] = sum_i u_i delta(c_i, c)
              // dN/dx_d.
              double Hx0 = 0, Hx1 = 0, Hy0 = 0, Hy1 = 0;
              for (unsigned int i = 0; i < 8; ++i)
                {
                  const double ux = ue[i] * (1. - is_y[i]),
                               uy = ue[i] * is_y[i];
                  Hx0 += ux * grad_x[q][i];
                  Hx1 += ux * grad_y[q][i];
                  Hy0 += uy * grad_x[q][i];
                  Hy1 += uy * grad_y[q][i];
                }
              const double F00 = 1 + Hx0, F01 = Hx1, F10 = Hy0, F11 = 1 + Hy1;
              // Green-Lagrange strain (Voigt, 2 E_xy) and S = C E.
              const double E00 = 0.5 * (F00 * F00 + F10 * F10 - 1.);
              const double E11 = 0.5 * (F01 * F01 + F11 * F11 - 1.);
              const double G01 = F00 * F01 + F10 * F11;
              const double S0  = C00 * E00 + C01 * E11 + C02 * G01;
              const double S1  = C01 * E00 + C11 * E11 + C12 * G01;
              const double S2  = C02 * E00 + C12 * E11 + C22 * G01;
              // First Piola-Kirchhoff P = F S.
              const double P00 = F00 * S0 + F01 * S2, P01 = F00 * S2 + F01 * S1;
              const double P10 = F10 * S0 + F11 * S2, P11 = F10 * S2 + F11 * S1;
              for (unsigned int i = 0; i < 8; ++i)
                {
                  const double fx = P00 * grad_x_w[q][i] + P01 * grad_y_w[q][i];
                  const double fy = P10 * grad_x_w[q][i] + P11 * grad_y_w[q][i];
                  fe_[i] += fx + is_y[i] * (fy - fx);
                }
            }
          for (unsigned int i = 0; i < 8; ++i)
            {
              double s = 0;
              for (unsigned int j = 0; j < 8; ++j)
                s += K[8 * i + j] * pe[j];
              rv[idx[i]] += fe_[i] + beta * s;
            }
        }
    }


    template <FrictionLaw law>
    void
    ContactSolver::contact_node_wise(const double /*time_next*/)
    {
      const double  gap0  = prm.loading.initial_gap;
      const double  slide = prm.loading.plane_velocity * dt;
      const double *uv    = u.begin();
      const double *up    = u_prev.begin();
      double       *un    = u_next.begin();
      double       *av    = a.begin();
      double        wc = 0, df = 0;
      for (ContactNode &node : contact_nodes)
        {
          // Gap at t_{n+1} of the predicted configuration (plane at y = -gap0).
          const double g = un[node.iy] + gap0;
          if (g >= 0)
            {
              node.lambda_n = node.lambda_t = node.tau = 0;
              node.status                              = separated;
              continue;
            }
          const double lambda_n = -node.m * g / h;
          const double trial = node.m * (uv[node.ix] + slide - un[node.ix]) / h;
          ContactStatus status;
          const double  lambda_t = tangential_multiplier<law>(
            trial, lambda_n, node.tau, friction_step, status);
          node.lambda_n = lambda_n;
          node.lambda_t = lambda_t;
          node.tau      = lambda_t;
          node.status   = status;
          un[node.iy] += h * lambda_n / node.m;
          un[node.ix] += h * lambda_t / node.m;
          av[node.iy] += lambda_n / node.m;
          av[node.ix] += lambda_t / node.m;
          wc += 0.5
                * (lambda_n * (un[node.iy] - up[node.iy])
                   + lambda_t * (un[node.ix] - up[node.ix]));
          df += lambda_t * (slide - (un[node.ix] - uv[node.ix]));
        }
      work_contact += wc;
      dissipation_friction += df;
    }


    template <FrictionLaw law>
    void
    ContactSolver::contact_gauss_seidel(const double /*time_next*/)
    {
      // General projected Gauss-Seidel over constraint rows. A row is a list
      // of (dof, coefficient); the normal row of contact k reads
      // g_k = G_N u + gap0 >= 0, the tangential row the slip increment
      // G_T (u_{n+1} - u_n) - V dt. Each update changes u_{n+1} by
      // h M^-1 G^T d(lambda), so rows sharing dofs see each other's
      // corrections (that is what makes the path valid for coupled
      // constraints). Against the rigid plane the rows are decoupled and the
      // first sweep gives the closed form; the second confirms convergence.
      const double  gap0  = prm.loading.initial_gap;
      const double  slide = prm.loading.plane_velocity * dt;
      const double *uv    = u.begin();
      const double *up    = u_prev.begin();
      double       *un    = u_next.begin();
      double       *av    = a.begin();
      for (ContactNode &node : contact_nodes)
        node.lambda_n = node.lambda_t = 0;
      // Rows of node k: normal (dof iy, coefficient 1), tangential (ix, 1).
      auto apply = [&](const unsigned int dof,
                       const double       coefficient,
                       const double       d_lambda,
                       const double       m) {
        un[dof] += h * coefficient * d_lambda / m;
        av[dof] += coefficient * d_lambda / m;
      };
      unsigned int iteration = 0;
      for (; iteration < prm.contact.pgs_max_iterations; ++iteration)
        {
          double change = 0, largest = 0;
          for (ContactNode &node : contact_nodes)
            {
              const double W = h / node.m; // G M^-1 G^T h, diagonal entry
              // Normal row.
              const double g        = un[node.iy] + gap0;
              const double lambda_n = std::max(0., node.lambda_n - g / W);
              apply(node.iy, 1., lambda_n - node.lambda_n, node.m);
              change = std::max(change, std::abs(lambda_n - node.lambda_n));
              node.lambda_n = lambda_n;
              // Tangential row.
              double        lambda_t = 0;
              ContactStatus status   = separated;
              if (lambda_n > 0)
                {
                  const double s     = (un[node.ix] - uv[node.ix]) - slide;
                  const double trial = node.lambda_t - s / W;
                  lambda_t           = tangential_multiplier<law>(
                    trial, lambda_n, node.tau, friction_step, status);
                }
              apply(node.ix, 1., lambda_t - node.lambda_t, node.m);
              change = std::max(change, std::abs(lambda_t - node.lambda_t));
              node.lambda_t = lambda_t;
              node.status   = status;
              largest       = std::max(largest, std::abs(lambda_n));
            }
          if (change <= prm.contact.pgs_tolerance * largest || largest == 0)
            {
              ++iteration;
              break;
            }
        }
      pgs_iterations_max = std::max(pgs_iterations_max, iteration);
      double wc = 0, df = 0;
      for (ContactNode &node : contact_nodes)
        {
          node.tau = node.lambda_t;
          if (node.lambda_n <= 0)
            node.status = separated;
          wc += 0.5
                * (node.lambda_n * (un[node.iy] - up[node.iy])
                   + node.lambda_t * (un[node.ix] - up[node.ix]));
          df += node.lambda_t * (slide - (un[node.ix] - uv[node.ix]));
        }
      work_contact += wc;
      dissipation_friction += df;
    }


    void
    ContactSolver::solve_contact(const double time_next)
    {
      const bool gs
        = prm.contact.algorithm == ContactAlgorithm::projected_gauss_seidel;
      switch (prm.contact.law)
        {
          case FrictionLaw::frictionless:
            gs ? contact_gauss_seidel<FrictionLaw::frictionless>(time_next)
               : contact_node_wise<FrictionLaw::frictionless>(time_next);
            break;
          case FrictionLaw::coulomb:
            gs ? contact_gauss_seidel<FrictionLaw::coulomb>(time_next)
               : contact_node_wise<FrictionLaw::coulomb>(time_next);
            break;
          case FrictionLaw::regularized:
            gs ? contact_gauss_seidel<FrictionLaw::regularized>(time_next)
               : contact_node_wise<FrictionLaw::regularized>(time_next);
            break;
        }
    }


    void
    ContactSolver::run(const std::string &output_directory,
                       const double       progress_interval)
    {
      const bool         root    = Utilities::MPI::this_mpi_process(comm) == 0;
      const auto         start   = std::chrono::steady_clock::now();
      const unsigned int n_owned = mass.size();
      const double       beta    = prm.time.damping;
      const double       b2      = prm.time.beta2;
      const bool         large
        = prm.material.kinematics
          == ContactMaterialParameters::Kinematics::large_deformation;

      // Initial state: u_0 = 0, p_0 = v_0 (held dofs at rest), a = 0, and
      // u_{-1} = u_0 - dt p_0 so that p_n = (u_n - u_{n-1})/dt (energy
      // accounting).
      {
        double *pv = p.begin();
        double  e0 = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            pv[i]                   = mass_inverse[i] == 0
                                        ? 0.
                                        : prm.loading.initial_velocity[component[i]];
            u.local_element(i)      = 0;
            u_prev.local_element(i) = -dt * pv[i];
            a.local_element(i)      = 0;
            w.local_element(i)      = beta * pv[i];
            e0 += 0.5 * mass[i] * pv[i] * pv[i];
          }
        energy_initial = Utilities::MPI::sum(e0, comm);
      }
      r             = 0;
      step_count    = 0;
      work_external = work_internal = work_contact = dissipation_friction = 0;
      scale_energy = energy_initial;
      history.clear();
      for (ContactNode &node : contact_nodes)
        node = ContactNode{node.ix, node.iy, node.m, node.x};

      const bool                 write = !output_directory.empty();
      std::unique_ptr<CsvWriter> friction_csv, point_csv, status_csv;
      std::unique_ptr<PvdWriter> pvd;
      if (write)
        {
          friction_csv = std::make_unique<CsvWriter>(
            join_path(output_directory, "friction.csv"),
            std::vector<std::string>{"time",
                                     "normal_force",
                                     "tangential_force",
                                     "mu_global",
                                     "contact_normal_force",
                                     "contact_tangential_force",
                                     "mu_contact",
                                     "kinetic_energy",
                                     "elastic_energy",
                                     "external_work",
                                     "contact_work",
                                     "damping_dissipation",
                                     "friction_dissipation",
                                     "energy_balance_error",
                                     "momentum_x",
                                     "momentum_y"},
            root);
          point_csv = std::make_unique<CsvWriter>(
            join_path(output_directory, "point_M.csv"),
            std::vector<std::string>{"time",
                                     "tangential_displacement",
                                     "tangential_velocity",
                                     "normal_displacement",
                                     "normal_velocity",
                                     "status"},
            root);
          status_csv = std::make_unique<CsvWriter>(
            join_path(output_directory, "contact_status.csv"),
            std::vector<std::string>{
              "time", "stick_fraction", "slip_fraction", "separation_fraction"},
            root);
          pvd = std::make_unique<PvdWriter>(join_path(output_directory,
                                                      "fields.pvd"),
                                            root);
        }

      const double        end_time = prm.time.end_time;
      const unsigned long n_steps
        = static_cast<unsigned long>(std::ceil(end_time / dt - 1e-9));
      ProgressReporter   progress(std::cout,
                                root && progress_interval >= 0,
                                n_steps * dt,
                                std::max(0., progress_interval),
                                "contact");
      const unsigned int sample_every = prm.output.sample_interval;
      const double       field_every  = prm.output.field_interval;
      unsigned int       field_count  = 0;
      double             next_field   = 0;
      double             top_force    = 0;
      double             loop_seconds = 0;
      const auto         loop_start   = std::chrono::steady_clock::now();

      for (unsigned long n = 0; n < n_steps; ++n)
        {
          const double t = n * dt;
          const double s = prm.loading.pressure_at(t);
          // Internal forces of u_n and the damping force beta K p_n.
          add_internal_forces(large);

          // Predictor: a* = M^-1 (f_n - r), u* = u_n + dt p_n + h a*.
          {
            const double *uv = u.begin();
            const double *pv = p.begin();
            const double *rv = r.begin();
            double       *un = u_next.begin();
            double       *av = a.begin();
            const double *fv = unit_load.data();
            const double *mi = mass_inverse.data();
            for (unsigned int i = 0; i < n_owned; ++i)
              {
                const double ai = (s * fv[i] - rv[i]) * mi[i];
                un[i]           = uv[i] + dt * pv[i] + h * ai;
                av[i]           = ai;
              }
          }
          const bool sample = (n % sample_every == 0) || n + 1 == n_steps;
          if (sample)
            {
              // Reaction of the held top face: R = r - f (a = 0 there).
              double f = 0;
              if (prm.loading.top_held_in_x)
                for (const unsigned int i : top_x_dofs)
                  f += r.local_element(i) - s * unit_load[i];
              top_force = Utilities::MPI::sum(f, comm);
            }

          // Contact and friction: multipliers at t_{n+1}.
          solve_contact(t + dt);

          // Velocities, energy accounting, next predictor velocity.
          {
            const double *uv = u.begin();
            const double *up = u_prev.begin();
            const double *un = u_next.begin();
            const double *av = a.begin();
            double       *pv = p.begin();
            double       *wv = w.begin();
            double       *rv = r.begin();
            const double *fv = unit_load.data();
            double        we = 0, wi = 0;
            for (unsigned int i = 0; i < n_owned; ++i)
              {
                const double d = 0.5 * (un[i] - up[i]);
                we += s * fv[i] * d;
                wi += rv[i] * d;
                const double pn = pv[i] + dt * av[i];
                pv[i]           = pn;
                wv[i]           = un[i] + beta * pn;
                rv[i]           = 0;
              }
            (void)uv;
            work_external += we;
            work_internal += wi;
          }
          u_prev.swap(u); // u_prev = u_n
          u.swap(u_next); // u = u_{n+1}
          ++step_count;

          if (sample)
            {
              const auto t0 = std::chrono::steady_clock::now();
              record_sample(t);
              Sample &smp          = history.back();
              smp.tangential_force = top_force;
              smp.mu_global = prm.loading.top_held_in_x && smp.normal_force > 0
                                ? -(prm.loading.plane_velocity >= 0 ? 1. : -1.)
                                    * top_force / smp.normal_force
                                : smp.mu_contact;
              if (write)
                {
                  friction_csv->add_row({smp.time,
                                         smp.normal_force,
                                         smp.tangential_force,
                                         smp.mu_global,
                                         smp.contact_normal_force,
                                         smp.contact_tangential_force,
                                         smp.mu_contact,
                                         smp.kinetic_energy,
                                         smp.elastic_energy,
                                         smp.external_work,
                                         smp.contact_work,
                                         smp.damping_dissipation,
                                         smp.friction_dissipation,
                                         smp.energy_balance_error,
                                         smp.momentum_x,
                                         smp.momentum_y});
                  point_csv->add_row({smp.time,
                                      smp.M_ux,
                                      smp.M_vx,
                                      smp.M_uy,
                                      smp.M_vy,
                                      double(smp.M_status)});
                  status_csv->add_row({smp.time,
                                       smp.stick_fraction,
                                       smp.slip_fraction,
                                       smp.separation_fraction});
                  friction_csv->flush();
                  point_csv->flush();
                  status_csv->flush();
                }
              std::ostringstream key;
              key << "mu_global = " << std::fixed << std::setprecision(4)
                  << smp.mu_global
                  << "  stick/slip/sep = " << std::setprecision(2)
                  << smp.stick_fraction << "/" << smp.slip_fraction << "/"
                  << smp.separation_fraction;
              progress.update(step_count, t + dt, key.str());
              if (!std::isfinite(smp.kinetic_energy)
                  || !std::isfinite(smp.mu_global))
                throw RunError("The solution became non-finite at t = "
                               + format_number(t) + " s (step "
                               + std::to_string(n) + "): the run is unstable.");
              loop_seconds -= std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - t0)
                                .count();
            }
          if (write && field_every > 0 && t + 0.5 * dt >= next_field)
            {
              const auto         t0 = std::chrono::steady_clock::now();
              TimerOutput::Scope scope(timer, "output fields");
              // Fields at t_n: swap u_n back in for the writer.
              u.swap(u_prev);
              write_fields(output_directory, t, field_count);
              u.swap(u_prev);
              const std::string name
                = "fields_" + Utilities::int_to_string(field_count, 5) + ".vtu";
              pvd->add(t, name);
              ++field_count;
              next_field += field_every;
              loop_seconds -= std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - t0)
                                .count();
            }
        }
      loop_seconds += std::chrono::duration<double>(
                        std::chrono::steady_clock::now() - loop_start)
                        .count();
      loop_wall_time = loop_seconds;
      progress.update(step_count, n_steps * dt, "", true);
      if (write)
        {
          friction_csv->flush(true);
          point_csv->flush(true);
          status_csv->flush(true);
        }
      run_wall_time = std::chrono::duration<double>(
                        std::chrono::steady_clock::now() - start)
                        .count();
      (void)b2;
    }


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
                                const unsigned int index)
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
      data_out.write_vtu_in_parallel(
        join_path(dir, "fields_" + Utilities::int_to_string(index, 5) + ".vtu"),
        comm);
      scratch_result.zero_out_ghost_values();
      scratch.zero_out_ghost_values();
    }


    RunSummary
    ContactSolver::summarize(const std::string &output_directory)
    {
      RunSummary          s;
      const double        t0 = prm.output.average_start;
      const double        t1 = prm.output.average_end < 0
                                 ? std::numeric_limits<double>::max()
                                 : prm.output.average_end;
      std::vector<double> mu;
      double              mu_c = 0, fr[3] = {0, 0, 0}, m_status[3] = {0, 0, 0};
      for (const Sample &x : history)
        {
          s.energy_balance_error
            = std::max(s.energy_balance_error, x.energy_balance_error);
          if (x.time < t0 || x.time > t1)
            continue;
          mu.push_back(x.mu_global);
          mu_c += x.mu_contact;
          fr[0] += x.stick_fraction;
          fr[1] += x.slip_fraction;
          fr[2] += x.separation_fraction;
          m_status[x.M_status] += 1;
        }
      const double n       = static_cast<double>(mu.size());
      s.n_samples_averaged = mu.size();
      if (n > 0)
        {
          double sum = 0;
          for (const double m : mu)
            sum += m;
          s.mu_global_mean        = sum / n;
          s.mu_contact_mean       = mu_c / n;
          s.stick_fraction        = fr[0] / n;
          s.slip_fraction         = fr[1] / n;
          s.separation_fraction   = fr[2] / n;
          s.M_separation_fraction = m_status[separated] / n;
          s.M_stick_fraction      = m_status[stick] / n;
          s.M_slip_fraction       = m_status[slip] / n;
        }
      const double threshold = 0.01;
      const bool   st        = s.M_stick_fraction > threshold,
                 sl          = s.M_slip_fraction > threshold,
                 se          = s.M_separation_fraction > threshold;
      s.regime               = st && sl && se ? "stick-slip-separation"
                               : sl && se     ? "slip-separation"
                               : st && sl     ? "stick-slip"
                               : sl           ? "slip"
                               : st ? (se ? "stick-separation" : "stick")
                               : se ? "separation"
                                    : "none";

      const double spacing  = prm.output.sample_interval * dt;
      const auto   spectrum = amplitude_spectrum(mu, spacing);
      // Ignore the lowest frequencies (trends over the window).
      const double f_min = n > 0 ? 2. / (n * spacing) : 0;
      std::vector<std::pair<double, double>> above;
      above.emplace_back(0., 0.);
      for (const auto &f : spectrum)
        if (f.first >= f_min)
          above.push_back(f);
      s.dominant_frequency_hz = dominant_frequency(above);
      if (!output_directory.empty()
          && Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::ostringstream text;
          text << "frequency_hz,amplitude\n" << std::setprecision(10);
          for (const auto &f : spectrum)
            text << f.first << "," << f.second << "\n";
          write_file_atomically(join_path(output_directory, "spectrum.csv"),
                                text.str());
        }
      s.wall_time_s = run_wall_time;
      s.time_loop_s = loop_wall_time;
      s.dof_steps_per_second
        = loop_wall_time > 0
            ? static_cast<double>(n_dofs()) * step_count / loop_wall_time
            : 0.;
      return s;
    }


    void
    ContactSolver::set_displacement(
      const std::function<Tensor<1, 2>(const Point<2> &)> &field)
    {
      const auto &partitioner = *u.get_partitioner();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : GeometryInfo<2>::vertex_indices())
            {
              const Tensor<1, 2> d = field(cell->vertex(v));
              for (unsigned int c = 0; c < 2; ++c)
                {
                  const auto g = cell->vertex_dof_index(v, c);
                  if (locally_owned.is_element(g))
                    u.local_element(partitioner.global_to_local(g)) = d[c];
                }
            }
      p = 0;
      for (unsigned int i = 0; i < mass.size(); ++i)
        w.local_element(i) = u.local_element(i);
    }


    void
    ContactSolver::add_internal_forces(const bool large)
    {
      // r += K(u_n + beta p_n) (small strain: w holds u + beta p) or the
      // total-Lagrangian internal forces of u and p; ghosts are refreshed
      // first, contributions to ghost rows are sent to their owners after.
      if (large)
        {
          u.update_ghost_values();
          p.update_ghost_values();
          internal_forces_large_deformation();
        }
      else
        {
          w.update_ghost_values();
          internal_forces_small_strain();
        }
      r.compress(VectorOperation::add);
    }


    double
    ContactSolver::max_internal_force()
    {
      r = 0;
      const bool large
        = prm.material.kinematics
          == ContactMaterialParameters::Kinematics::large_deformation;
      add_internal_forces(large);
      const double result = r.linfty_norm();
      r                   = 0;
      return result;
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
