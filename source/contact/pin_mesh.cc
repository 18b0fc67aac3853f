// The pin: mesh, materials, element data, lumped mass, contact nodes,
// critical time step (doc/theory/contact.md sections 1 and 2).
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
#include <tribodyn/core/elastic_phase.h>
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


    double
    ContactSolver::contact_face_length() const
    {
      double length = 0;
      for (const ContactNode &node : contact_nodes)
        length += node.length;
      return Utilities::MPI::sum(length, comm);
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
      auto add_phase = [&](const ElasticPhase &phase) {
        stiffness.push_back(phase.C);
        stiffness_z.push_back(phase.c_z);
        density.push_back(phase.density);
      };
      std::ostringstream text;
      text << std::setprecision(4);
      switch (m.type)
        {
          case Type::isotropic:
            add_phase(m.isotropic);
            text << "isotropic (E = " << m.isotropic.youngs_modulus / 1e9
                 << " GPa, nu = " << m.isotropic.poisson_ratio
                 << ", rho = " << m.isotropic.density << ")";
            break;
          case Type::anisotropic:
            check_stiffness(m.anisotropic_stiffness,
                            "'Materials/Anisotropic/Stiffness'");
            stiffness.push_back(m.anisotropic_stiffness);
            stiffness_z.push_back(m.anisotropic_c_z);
            density.push_back(m.density);
            text << "anisotropic (given stiffness)";
            break;
          case Type::engineering_constants:
            {
              add_phase(ElasticPhase(
                TransverselyIsotropicConstants{
                  m.E_L, m.E_T, m.nu_LT, m.nu_TT, m.G_LT, 0},
                m.density,
                "Materials/Engineering constants"));
              check_stiffness(stiffness.back(),
                              "'Materials/Engineering constants'");
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
            // in material-id order (matrix, heterogeneity, or the named
            // list); a pore's entry stays unused: make_mesh() cuts its
            // pixels out
            for (const ElasticPhase &phase : m.composite.phases())
              add_phase(phase);
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
          material_text += ": " + morphology.description();
          pin_width                     = morphology.width();
          const std::vector<bool> pores = prm.material.composite.pores();
          if (std::find(pores.begin(), pores.end(), true) == pores.end())
            create_morphology_mesh(morphology,
                                   prm.geometry.subdivisions_per_pixel,
                                   triangulation);
          else
            make_porous_mesh(morphology, pores);
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
          pin_width = prm.geometry.width;
        }
    }


    void
    ContactSolver::make_porous_mesh(const Morphology        &morphology,
                                    const std::vector<bool> &pores)
    {
      const std::vector<bool> kept = morphology.held_from_top(pores);
      const unsigned int      n_x  = morphology.n_pixels_x(),
                         n_y       = morphology.n_pixels_y();
      unsigned int n_pore = 0, n_loose = 0, n_bottom = 0;
      for (unsigned int j = 0; j < n_y; ++j)
        for (unsigned int i = 0; i < n_x; ++i)
          {
            const unsigned int id   = morphology.pixel(i, j);
            const bool         pore = id < pores.size() && pores[id];
            const bool keep = kept[static_cast<std::size_t>(j) * n_x + i];
            n_pore += pore;
            n_loose += !pore && !keep;
            n_bottom += (j == 0 && keep);
          }
      check_parameter(n_bottom > 0,
                      "Materials/Names",
                      "with the pores (Young modulus 0) cut out of the meso "
                      "pin, no solid pixel of its bottom row is tied to the "
                      "top face through solid pixels: the pin has no contact "
                      "face. Crop another window ('Morphology/Image/Crop') "
                      "or make fewer phases pores.");
      create_morphology_mesh(morphology,
                             prm.geometry.subdivisions_per_pixel,
                             kept,
                             triangulation);
      std::ostringstream text;
      text << std::setprecision(4) << ", pores cut out (" << n_pore
           << " pixels, " << 100. * n_pore / (n_x * n_y) << " %)";
      if (n_loose > 0)
        text << ", and " << n_loose
             << " solid pixels they detach from the top face";
      material_text += text.str();
      if (n_loose > 0 && Utilities::MPI::this_mpi_process(comm) == 0)
        std::cout
          << ("Warning: meso pin: " + std::to_string(n_loose)
              + " solid pixels are tied to the top face by no chain of solid "
                "pixels sharing an edge once the pores are cut out; they would "
                "be loose bodies in the pin and are cut out too.\n");
    }


    void
    ContactSolver::setup_element_data()
    {
      // All cells are identical axis-parallel rectangles: take the shape
      // gradients of the first active cell of the mesh, the same cell on
      // every rank (owned or not: the coarse mesh is known everywhere), so
      // that the element data and the time step have the same bits on any
      // number of ranks (a checkpoint restarts on another number).
      const typename Triangulation<2>::active_cell_iterator first
        = triangulation.begin_active();
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
      std::vector<unsigned int> in_mesh(stiffness.size(), 0);
      for (const unsigned int mat : material_set)
        in_mesh[mat] = 1;
      Utilities::MPI::max(in_mesh, comm, in_mesh);
      material_in_mesh.assign(in_mesh.begin(), in_mesh.end());
      // (the one-material kernels take material 0's stiffness: a pin of
      // another single phase, or ranks each with one phase, take the
      // general path)
      single_material = std::count(in_mesh.begin(), in_mesh.end(), 1u) == 1
                        && in_mesh[0] == 1;
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
                        node.ix     = lx;
                        node.iy     = ly;
                        node.m      = mass[ly];
                        node.x      = face->vertex(v)[0];
                        node.length = 0; // below
                        bottom[ly]  = node;
                      }
                  }
              }
      // Tributary length of each node: half of each bottom face it bounds,
      // the faces of cells owned or ghost (all the cells around an owned
      // node): a whole cell inside, half at the corners and at a void.
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          for (const unsigned int f : GeometryInfo<2>::face_indices())
            if (cell->face(f)->at_boundary()
                && cell->face(f)->boundary_id() == 2)
              for (unsigned int v = 0; v < 2; ++v)
                {
                  const types::global_dof_index gy
                    = cell->face(f)->vertex_dof_index(v, 1);
                  const auto node
                    = locally_owned.is_element(gy)
                        ? bottom.find(partitioner.global_to_local(gy))
                        : bottom.end();
                  if (node != bottom.end())
                    node->second.length += 0.5 * cell_hx;
                }
      top_x_dofs.assign(top_x.begin(), top_x.end());
      top_y_dofs.assign(top_y.begin(), top_y.end());
      contact_nodes.clear();
      for (const auto &b : bottom)
        contact_nodes.push_back(b.second);
      n_contact_nodes_global
        = Utilities::MPI::sum(static_cast<unsigned int>(contact_nodes.size()),
                              comm);
      n_contact_face_ranks_global
        = Utilities::MPI::sum(contact_nodes.empty() ? 0u : 1u, comm);
      if (prm.loading.top_held_in_x)
        for (const unsigned int i : top_x_dofs)
          mass_inverse[i] = 0;

      // Point M: the contact node closest to the middle of the bottom face
      // (the smaller x on a tie).
      const double width      = pin_width;
      double       best       = std::numeric_limits<double>::max();
      int          best_index = -1;
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
        if (material_in_mesh[mat])
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
      c_maximum       = c_max;
      const double b2 = prm.time.beta2;
      const double xi = prm.time.damping * omega_maximum / 2.;
      dt_critical = (std::sqrt(2. * b2 + xi * xi) - xi) / (b2 * omega_maximum);

      dt = prm.time.time_step;
      if (dt > dt_critical)
        {
          if (prm.time.automatic_time_step)
            dt = prm.time.safety_factor * dt_critical;
          else if (prm.time.refuse_unstable_time_step)
            throw InputError(
              "'Time/Time step' = " + format_number(dt)
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
              + " s, or set 'Automatic time step = true'. (The critical "
                "step scales with 'Geometry/Mesh size' and with the square "
                "root of the materials' Density / Young modulus: check them "
                "if it is unexpectedly small.)");
        }
      h = dt * dt * (0.5 + b2);
      // the chosen friction law, for this time step
      friction_law = FrictionLaws::make(prm.contact, dt);
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
    ContactSolver::set_initial_velocity_field(
      const std::function<Tensor<1, 2>(const Point<2> &)> &field)
    {
      const auto &partitioner = *u.get_partitioner();
      initial_velocity_field.assign(mass.size(), 0.);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : GeometryInfo<2>::vertex_indices())
            {
              const Tensor<1, 2> d = field(cell->vertex(v));
              for (unsigned int c = 0; c < 2; ++c)
                {
                  const auto g = cell->vertex_dof_index(v, c);
                  if (locally_owned.is_element(g))
                    initial_velocity_field[partitioner.global_to_local(g)]
                      = d[c];
                }
            }
    }

  } // namespace contact
} // namespace tribodyn
