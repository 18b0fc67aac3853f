// Geometric multigrid for the cell problems: the matrix-free operator, the
// level constraints, the V-cycle and CG (declared in cell_multigrid.h).
#include "cell_multigrid.h"

#include "cell_multigrid_galerkin.h"
#include "cell_multigrid_operator.h"
#include "cell_multigrid_periodic.h"

#include <array>
#include <cstring>
#include <deal.II/base/vectorization.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/operators.h>
#include <deal.II/matrix_free/tools.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <deal.II/multigrid/multigrid.h>
#include <limits>
#include <map>
#include <set>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      namespace
      {
        using namespace dealii;
        /// CG runs in double precision; the V-cycle (levels, smoother,
        /// transfer) in LevelNumber, float by default: half the memory
        /// traffic of the preconditioner, which only needs to be a good
        /// approximation.
        using VectorType = LinearAlgebra::distributed::Vector<double>;


        /// The coarsest level solved with a factorization of its matrix
        /// (in double precision; float level vectors are converted).
        template <typename LevelNumber>
        class DirectCoarseSolver
            : public MGCoarseGridBase<
                LinearAlgebra::distributed::Vector<LevelNumber>>
        {
          using LevelVectorType
            = LinearAlgebra::distributed::Vector<LevelNumber>;

        public:
          /// @p zeroed: vector-local indices of the locally owned DoFs
          /// the coarse correction leaves at zero (the periodic problem's
          /// pins, whose rows the factorization keeps with a diagonal
          /// entry only).
          explicit DirectCoarseSolver(
            const TrilinosWrappers::SparseMatrix &matrix,
            std::vector<unsigned int>             zeroed = {})
              : control(1, 0)
              , solver(control)
              , zeroed(std::move(zeroed))
          {
            solver.initialize(matrix);
          }

          void
          operator()(const unsigned int,
                     LevelVectorType       &dst,
                     const LevelVectorType &src) const override
          {
            if (b.size() != src.size())
              {
                b.reinit(src.get_partitioner());
                x.reinit(src.get_partitioner());
              }
            b = src;
            solver.solve(x, b);
            dst = x;
            for (const unsigned int k : zeroed)
              dst.local_element(k) = 0;
          }

        private:
          SolverControl                          control;
          mutable TrilinosWrappers::SolverDirect solver;
          mutable VectorType                     b, x;
          std::vector<unsigned int>              zeroed;
        };


        /// DoFs of level @p level at the vertex @p point, components
        /// @p components.
        template <int dim>
        IndexSet
        pinned_level_dofs(const DoFHandler<dim>           &dofs,
                          const unsigned int               level,
                          const Point<dim>                &point,
                          const std::vector<unsigned int> &components,
                          const double                     tolerance)
        {
          IndexSet pinned(dofs.n_dofs(level));
          for (const auto &cell : dofs.mg_cell_iterators_on_level(level))
            if (cell->level_subdomain_id() != numbers::artificial_subdomain_id)
              for (const unsigned int v : cell->vertex_indices())
                if (cell->vertex(v).distance(point) < tolerance)
                  for (const unsigned int c : components)
                    pinned.add_index(cell->mg_vertex_dof_index(level, v, c));
          return pinned;
        }


        /// The shared matrix-free objects of the multilinear fast path.
        template <int dim, typename LevelNumber>
        struct MultilinearMatrixFree : MultigridCache
        {
          std::shared_ptr<const MatrixFree<dim, double>> fine;
          std::vector<std::shared_ptr<const MatrixFree<dim, LevelNumber>>>
            levels;
        };


        template <int dim, int degree, typename LevelNumber>
        class MultigridSolver : public CellMultigridSolver<dim>
        {
        public:
          using LevelVectorType
            = LinearAlgebra::distributed::Vector<LevelNumber>;
          using FineOperator  = ElasticityOperator<dim, degree, double>;
          using LevelOperator = ElasticityOperator<dim, degree, LevelNumber>;
          using Transfer      = PeriodicTransfer<dim, LevelNumber>;
          static constexpr bool fast_path = FineOperator::fast_path;
          using Smoother
            = PreconditionChebyshev<LevelOperator,
                                    LevelVectorType,
                                    DiagonalMatrix<LevelVectorType>>;

          MultigridSolver(const DoFHandler<dim>                 &dof_handler,
                          const AffineConstraints<double>       &constraints,
                          const LevelConstraintDescription<dim> &description,
                          const StiffnessOverBox<dim>           &stiffness,
                          std::shared_ptr<MultigridCache>       &cache,
                          TimerOutput                           &timer)
              : dof_handler(dof_handler)
          {
            TimerOutput::Scope scope(timer, "multigrid setup");
            typename MatrixFree<dim, double>::AdditionalData data;
            data.tasks_parallel_scheme
              = MatrixFree<dim, double>::AdditionalData::none;
            data.mapping_update_flags = update_gradients | update_JxW_values;
            typename MatrixFree<dim, LevelNumber>::AdditionalData level_data;
            level_data.tasks_parallel_scheme
              = MatrixFree<dim, LevelNumber>::AdditionalData::none;
            level_data.mapping_update_flags = data.mapping_update_flags;
            // the multilinear fast path needs no mapping data (its element
            // matrices are computed directly); other degrees evaluate
            // gradients on every cell
            data.initialize_mapping       = !fast_path;
            level_data.initialize_mapping = !fast_path;
            const QGauss<1> quadrature(degree + 1);
            // Multilinear elements: the operator applies the constraints
            // itself, so the matrix-free objects hold none and are shared by
            // the boundary conditions (built by the first one).
            std::shared_ptr<MultilinearMatrixFree<dim, LevelNumber>> shared;
            bool reuse = false;
            if constexpr (fast_path)
              {
                shared = std::dynamic_pointer_cast<
                  MultilinearMatrixFree<dim, LevelNumber>>(cache);
                reuse = shared != nullptr;
                if (!reuse)
                  cache = shared = std::make_shared<
                    MultilinearMatrixFree<dim, LevelNumber>>();
              }
            AffineConstraints<double> no_constraints;
            no_constraints.close();
            // The periodic problem (multilinear elements): the matrix-free
            // objects hold the periodicity (its masters among the vectors'
            // ghosts), the operator replaces each image's DoFs by its
            // master's.
            periodic = fast_path && description.periodic;
            const AffineConstraints<double> fine_periodicity
              = periodic ? periodic_lines(constraints) : no_constraints;

            // The active mesh.
            {
              std::shared_ptr<const MatrixFree<dim, double>> mf;
              if (reuse)
                mf = shared->fine;
              else
                {
                  auto new_mf = std::make_shared<MatrixFree<dim, double>>();
                  new_mf->reinit(mapping,
                                 dof_handler,
                                 fast_path ? fine_periodicity : constraints,
                                 quadrature,
                                 data);
                  mf = new_mf;
                  if (shared)
                    shared->fine = mf;
                }
              fine_operator.initialize(mf);
              fine_operator.set_stiffness(stiffness);
              // Multilinear elements with pins (SUBC): the finer levels and
              // the active mesh solve the floating problem, the rigid
              // motions projected out (set_up_floating_solve()); only the
              // coarsest level keeps the pins.
              floating = fast_path && !description.pins.empty();
              if (floating)
                {
                  set_up_floating_solve(description, constraints);
                  fine_operator.tabulate_element_matrices(free_constraints);
                }
              else
                fine_operator.tabulate_element_matrices(constraints);
            }

            // The constraints on the levels: the boundary, the pinned
            // vertices, the periodicity.
            const unsigned int n_levels
              = dof_handler.get_triangulation().n_global_levels();
            std::vector<AffineConstraints<double>> periodicity(n_levels);
            if (periodic)
              for (unsigned int level = 0; level < n_levels; ++level)
                {
                  IndexSet relevant;
                  DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                                level,
                                                                relevant);
                  periodicity[level]
                    = level_periodicity(dof_handler, level, relevant);
                }
            mg_constrained_dofs.initialize(dof_handler);
            if (description.zero_boundary)
              {
                std::set<types::boundary_id> faces;
                for (unsigned int id = 0; id < 2 * dim; ++id)
                  faces.insert(id);
                mg_constrained_dofs.make_zero_boundary_constraints(dof_handler,
                                                                   faces);
              }
            const auto &coarse_pins = description.coarse_pins.empty()
                                        ? description.pins
                                        : description.coarse_pins;
            for (unsigned int level = 0; level < (floating ? 1 : n_levels);
                 ++level)
              for (const auto &[point, components] : coarse_pins)
                mg_constrained_dofs.add_boundary_indices(
                  dof_handler,
                  level,
                  pinned_level_dofs(dof_handler,
                                    level,
                                    point,
                                    components,
                                    description.tolerance));

            level_operators.resize(0, n_levels - 1);
            // Multilinear elements: the coarse levels' element matrices are
            // the Galerkin products of the fine ones
            // (cell_multigrid_galerkin.h; contrast-robust), built once for the
            // levels and the coarse matrix. Other degrees: the mean stiffness
            // of a coarse cell.
            std::unique_ptr<GalerkinElementMatrices<dim>> galerkin;
            if constexpr (fast_path)
              {
                const auto fine
                  = dof_handler.get_triangulation().begin(n_levels - 1);
                std::array<double, dim> fine_size;
                for (unsigned int d = 0; d < dim; ++d)
                  fine_size[d]
                    = fine->vertex((1 << dim) - 1)[d] - fine->vertex(0)[d];
                galerkin
                  = std::make_unique<GalerkinElementMatrices<dim>>(stiffness,
                                                                   fine_size);
              }
            AffineConstraints<double> coarse_constraints;
            const auto                level_constraints_of
              = [&](const unsigned int level, auto &constraints) {
                  IndexSet relevant;
                  DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                                level,
                                                                relevant);
                  constraints.reinit(relevant);
                  constraints.add_lines(
                    mg_constrained_dofs.get_boundary_indices(level));
                  if (periodic)
                    for (const auto &line : periodicity[level].get_lines())
                      if (!constraints.is_constrained(line.index))
                        {
                          constraints.add_line(line.index);
                          for (const auto &[master, weight] : line.entries)
                            constraints.add_entry(line.index, master, weight);
                        }
                  constraints.close();
                };
            for (unsigned int level = 0; level < n_levels; ++level)
              {
                AffineConstraints<LevelNumber> level_constraints;
                level_constraints_of(level, level_constraints);
                level_data.mg_level = level;
                std::shared_ptr<const MatrixFree<dim, LevelNumber>> mf;
                if (reuse)
                  mf = shared->levels[level];
                else
                  {
                    auto new_mf
                      = std::make_shared<MatrixFree<dim, LevelNumber>>();
                    // (the fast path: the level's periodicity, or none)
                    const auto reinit = [&](const auto &constraints) {
                      new_mf->reinit(mapping,
                                     dof_handler,
                                     constraints,
                                     quadrature,
                                     level_data);
                    };
                    if (!fast_path)
                      reinit(level_constraints);
                    else if (periodic)
                      reinit(periodicity[level]);
                    else
                      reinit(no_constraints);
                    mf = new_mf;
                    if (shared)
                      shared->levels.push_back(mf);
                  }
                level_operators[level].initialize(mf,
                                                  mg_constrained_dofs,
                                                  level);
                // the coarser levels of the fast path: Galerkin operators
                if (galerkin && level + 1 < n_levels)
                  level_operators[level].tabulate_galerkin_matrices(
                    *galerkin, n_levels - 1 - level, level_constraints);
                else
                  {
                    level_operators[level].set_stiffness(stiffness);
                    level_operators[level].tabulate_element_matrices(
                      level_constraints);
                  }
                level_operators[level].compute_diagonal();
              }

            if (periodic)
              {
                // (without the MGConstrainedDoFs, whose level constraints of
                // the periodic triangulation deal.II's transfer would set to
                // zero: the coarse solver zeroes the pins)
                transfer = std::make_unique<Transfer>();
                // the level vectors of the operators (their ghosts hold the
                // images' masters)
                const auto init
                  = [&](const unsigned int level, LevelVectorType &v) {
                      level_operators[level].initialize_dof_vector(v);
                    };
                transfer->build(dof_handler, init);
                transfer->set_images(init, periodicity);
              }
            else
              {
                transfer = std::make_unique<Transfer>(mg_constrained_dofs);
                transfer->build(dof_handler);
              }

            // Chebyshev smoothing of degree 3 (fewest operator applications
            // per solve of degrees 2-6 on the 1.1e6-DoF bench; with the
            // single-precision V-cycle degrees 2-4 take the same time) over
            // [lambda_max / 15, 1.1 lambda_max] of the Jacobi-preconditioned
            // level operator, lambda_max estimated by 10 CG iterations (15
            // give the same iteration counts and take 0.15 s more there).
            MGLevelObject<typename Smoother::AdditionalData> smoother_data(
              0, n_levels - 1);
            for (unsigned int level = 0; level < n_levels; ++level)
              {
                smoother_data[level].smoothing_range     = 15.;
                smoother_data[level].degree              = 3;
                smoother_data[level].eig_cg_n_iterations = 10;
                smoother_data[level].preconditioner
                  = level_operators[level].get_matrix_diagonal_inverse();
              }
            smoother.initialize(level_operators, smoother_data);

            // The coarsest level's matrix, in double precision (its own
            // operator on level 0), factorized once.
            {
              level_constraints_of(0, coarse_constraints);
              const MPI_Comm comm  = dof_handler.get_communicator();
              const IndexSet owned = dof_handler.locally_owned_mg_dofs(0);
              IndexSet       relevant;
              DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                            0,
                                                            relevant);
              DynamicSparsityPattern dsp(relevant);
              MGTools::make_sparsity_pattern(dof_handler,
                                             dsp,
                                             0,
                                             coarse_constraints);
              SparsityTools::distribute_sparsity_pattern(dsp,
                                                         owned,
                                                         comm,
                                                         relevant);
              coarse_matrix.reinit(owned, owned, dsp, comm);
              if (galerkin)
                assemble_coarse_matrix(*galerkin,
                                       n_levels - 1,
                                       coarse_constraints);
              else
                {
                  data.mg_level           = 0;
                  data.initialize_mapping = true; // compute_matrix integrates
                  auto mf = std::make_shared<MatrixFree<dim, double>>();
                  mf->reinit(
                    mapping, dof_handler, coarse_constraints, quadrature, data);
                  FineOperator coarse_operator;
                  coarse_operator.initialize(mf, mg_constrained_dofs, 0);
                  coarse_operator.set_stiffness(stiffness);
                  MatrixFreeTools::compute_matrix(*mf,
                                                  coarse_constraints,
                                                  coarse_matrix,
                                                  &FineOperator::local_apply,
                                                  &coarse_operator);
                }
              // the periodic problem's coarse pins: left at zero (SUBC's
              // are, bit for bit as before, what the factorization gives)
              std::vector<unsigned int> zeroed;
              if (periodic)
                {
                  const auto &partitioner = *level_operators[0]
                                               .get_matrix_free()
                                               ->get_vector_partitioner();
                  for (const auto dof :
                       mg_constrained_dofs.get_boundary_indices(0))
                    if (partitioner.in_local_range(dof))
                      zeroed.push_back(partitioner.global_to_local(dof));
                }
              coarse = std::make_unique<DirectCoarseSolver<LevelNumber>>(
                coarse_matrix, std::move(zeroed));
            }

            mg_matrix
              = std::make_unique<mg::Matrix<LevelVectorType>>(level_operators);
            multigrid = std::make_unique<Multigrid<LevelVectorType>>(
              *mg_matrix, *coarse, *transfer, smoother, smoother);
            preconditioner = std::make_unique<
              PreconditionMG<dim, LevelVectorType, Transfer>>(dof_handler,
                                                              *multigrid,
                                                              *transfer);
          }

          double
          assemble_rhs(const Tensor<1, CellTraits<dim>::n_voigt> &load,
                       const bool strain_driven) override
          {
            return fine_operator.assemble_rhs(rhs, load, strain_driven);
          }

          void
          solve(SolverControl                 &control,
                TrilinosWrappers::MPI::Vector &solution) override
          {
            VectorType x;
            fine_operator.initialize_dof_vector(x);
            SolverCG<VectorType> cg(control);
            if (floating)
              {
                // CG in the complement of the rigid motions: the load is
                // self-equilibrated (orthogonal to them up to round-off)
                // and every preconditioned residual is projected, so the
                // iterates stay in it; then the rigid motion that puts the
                // pinned DoFs at zero, as the constraints want them.
                project_rigid_motions(rhs);
                const ProjectedPreconditioner projected{this};
                cg.solve(fine_operator, x, rhs, projected);
                fix_pins(x);
              }
            else
              cg.solve(fine_operator, x, rhs, *preconditioner);
            // both vectors hold the locally owned DoFs in the same order
            double *values = solution.trilinos_vector()[0];
            for (unsigned int k = 0; k < x.locally_owned_size(); ++k)
              values[k] = x.local_element(k);
          }

        private:
          /// The rigid motions the floating solve projects out: the
          /// translations and the rotations (SUBC), the translations only
          /// (periodic: rotations are not periodic).
          unsigned int n_rigid = dim * (dim + 1) / 2;

          /// The V-cycle between two projections on the complement of the
          /// rigid motions (symmetric: CG's preconditioner).
          struct ProjectedPreconditioner
          {
            const MultigridSolver *solver;
            void
            vmult(VectorType &dst, const VectorType &src) const
            {
              VectorType &r = solver->projected_residual;
              r             = src;
              solver->project_rigid_motions(r);
              solver->preconditioner->vmult(dst, r);
              solver->project_rigid_motions(dst);
            }
          };

          /// Component @p c at @p x of rigid motion @p k: the translation
          /// e_k (k < dim), else the rotation about axis k - dim (3D; z in
          /// 2D) through the box's centre, e_axis x (x - centre).
          double
          rigid_value(const unsigned int k,
                      const Point<dim>  &x,
                      const unsigned int c) const
          {
            if (k < dim)
              return k == c ? 1. : 0.;
            const unsigned int axis = dim == 2 ? 2 : k - dim;
            const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const double       ya = a < dim ? x[a] - centre[a] : 0;
            const double       yb = b < dim ? x[b] - centre[b] : 0;
            return c == a ? -yb : (c == b ? ya : 0.);
          }

          /**
           * The floating (SUBC) solve: the constraints without the pinned
           * DoFs; the vertex of each owned DoF (the rigid motions are
           * evaluated from it: 8 bytes per DoF instead of a vector per
           * motion) and the inverse Gram matrix of the motions; the owned
           * pinned DoFs with their vertices.
           */
          void
          set_up_floating_solve(
            const LevelConstraintDescription<dim> &description,
            const AffineConstraints<double>       &constraints)
          {
            constexpr unsigned int n_vertices = 1u << dim;
            const MPI_Comm         comm       = dof_handler.get_communicator();
            std::set<types::global_dof_index>    pinned;
            std::vector<types::global_dof_index> dofs(dim * n_vertices);
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (!cell->is_artificial())
                {
                  cell->get_dof_indices(dofs);
                  for (unsigned int v = 0; v < n_vertices; ++v)
                    for (const auto &[point, components] : description.pins)
                      if (cell->vertex(v).distance(point)
                          < description.tolerance)
                        for (const unsigned int c : components)
                          pinned.insert(dofs[dim * v + c]);
                }
            free_constraints.clear();
            free_constraints.reinit(constraints.get_local_lines());
            for (const auto &line : constraints.get_lines())
              if (pinned.count(line.index) == 0)
                {
                  free_constraints.add_line(line.index);
                  free_constraints.add_entries(line.index, line.entries);
                  free_constraints.set_inhomogeneity(line.index,
                                                     line.inhomogeneity);
                }
            free_constraints.close();

            fine_operator.initialize_dof_vector(projected_residual);
            const auto &partitioner = *projected_residual.get_partitioner();
            owned_vertex.assign(partitioner.locally_owned_size() / dim,
                                Point<dim>());
            owned_image_dofs.clear();
            if (periodic)
              n_rigid = dim;
            pinned_dofs.clear();
            Point<dim> lower, upper;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::numeric_limits<double>::max();
                upper[d] = -lower[d];
              }
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  cell->get_dof_indices(dofs);
                  for (unsigned int v = 0; v < n_vertices; ++v)
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                          upper[d] = std::max(upper[d], cell->vertex(v)[d]);
                        }
                      if (!partitioner.in_local_range(dofs[dim * v]))
                        continue;
                      // the components of a vertex are consecutive
                      // vector-local indices (tabulate_cell_dofs() checks)
                      const unsigned int local
                        = partitioner.global_to_local(dofs[dim * v]);
                      AssertThrow(local % dim == 0, ExcInternalError());
                      owned_vertex[local / dim] = cell->vertex(v);
                      if (free_constraints.is_constrained(dofs[dim * v]))
                        for (unsigned int c = 0; c < dim; ++c)
                          owned_image_dofs.push_back(local + c);
                      for (unsigned int c = 0; c < dim; ++c)
                        if (pinned.count(dofs[dim * v + c]))
                          pinned_dofs.emplace_back(local + c, cell->vertex(v));
                    }
                }
            for (unsigned int d = 0; d < dim; ++d)
              centre[d] = 0.5
                          * (Utilities::MPI::min(lower[d], comm)
                             + Utilities::MPI::max(upper[d], comm));
            // G = R^T R over the owned DoFs of all ranks
            // (over the vertices of the periodic space: not the images)
            std::vector<bool> image(owned_vertex.size());
            for (const unsigned int k : owned_image_dofs)
              image[k / dim] = true;
            std::vector<Point<dim>> counted;
            for (unsigned int k = 0; k < owned_vertex.size(); ++k)
              if (!image[k])
                counted.push_back(owned_vertex[k]);
            with_rigid_count([&](auto n) {
              gram_inverse = inverse_gram<decltype(n)::value>(counted);
            });
          }

          /// G^-1, G = R^T R over the vertices @p counted of all ranks.
          template <unsigned int n_rigid>
          FullMatrix<double>
          inverse_gram(const std::vector<Point<dim>> &counted) const
          {
            FullMatrix<double> gram(n_rigid, n_rigid);
            for (const Point<dim> &x : counted)
              for (unsigned int c = 0; c < dim; ++c)
                for (unsigned int i = 0; i < n_rigid; ++i)
                  for (unsigned int j = 0; j < n_rigid; ++j)
                    gram(i, j) += rigid_value(i, x, c) * rigid_value(j, x, c);
            Utilities::MPI::sum(gram, dof_handler.get_communicator(), gram);
            gram.gauss_jordan();
            return gram;
          }

          /// v -= R a, a = G^-1 R^T v: the orthogonal projection of v on
          /// the complement of the rigid motions (two passes over v).
          void
          project_rigid_motions(VectorType &v) const
          {
            with_rigid_count(
              [&](auto n) { project_rigid_motions<decltype(n)::value>(v); });
          }

          /// f(std::integral_constant<unsigned int, n_rigid>()): the
          /// motions' count known to the compiler, as it was before the
          /// periodic problem (SUBC's results bit for bit).
          template <typename F>
          void
          with_rigid_count(const F &f) const
          {
            if (n_rigid == dim)
              f(std::integral_constant<unsigned int, dim>());
            else
              f(std::integral_constant<unsigned int, dim *(dim + 1) / 2>());
          }

          template <unsigned int n_rigid>
          void
          project_rigid_motions(VectorType &v) const
          {
            Vector<double> product(n_rigid), a(n_rigid);
            // (the periodic images of v are zero: they add nothing)
            for (unsigned int k = 0; k < owned_vertex.size(); ++k)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const double value = v.local_element(dim * k + c);
                  for (unsigned int i = 0; i < n_rigid; ++i)
                    product(i) += rigid_value(i, owned_vertex[k], c) * value;
                }
            Utilities::MPI::sum(product,
                                dof_handler.get_communicator(),
                                product);
            gram_inverse.vmult(a, product);
            a *= -1;
            add_rigid_motion<n_rigid>(v, a);
          }

          /// v += R a.
          template <unsigned int n_rigid>
          void
          add_rigid_motion(VectorType &v, const Vector<double> &a) const
          {
            for (unsigned int k = 0; k < owned_vertex.size(); ++k)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  double sum = 0;
                  for (unsigned int i = 0; i < n_rigid; ++i)
                    sum += rigid_value(i, owned_vertex[k], c) * a(i);
                  v.local_element(dim * k + c) += sum;
                }
            // a periodic image is no DoF of the periodic space
            for (const unsigned int k : owned_image_dofs)
              v.local_element(k) = 0;
          }

          /// x += the rigid motion that makes x zero at the pinned DoFs
          /// (the motions' values there form an invertible square system:
          /// the pins remove exactly the rigid motions), by the normal
          /// equations summed over the ranks (each adds the pins it owns).
          void
          fix_pins(VectorType &x) const
          {
            with_rigid_count([&](auto n) { fix_pins<decltype(n)::value>(x); });
          }

          template <unsigned int n_rigid>
          void
          fix_pins(VectorType &x) const
          {
            FullMatrix<double> M(n_rigid, n_rigid);
            Vector<double>     b(n_rigid), a(n_rigid);
            for (const auto &[local, vertex] : pinned_dofs)
              for (unsigned int i = 0; i < n_rigid; ++i)
                {
                  const double r_i = rigid_value(i, vertex, local % dim);
                  b(i) -= r_i * x.local_element(local);
                  for (unsigned int j = 0; j < n_rigid; ++j)
                    M(i, j) += r_i * rigid_value(j, vertex, local % dim);
                }
            const MPI_Comm comm = dof_handler.get_communicator();
            Utilities::MPI::sum(M, comm, M);
            Utilities::MPI::sum(b, comm, b);
            M.gauss_jordan();
            M.vmult(a, b);
            add_rigid_motion<n_rigid>(x, a);
          }

          /// The coarsest level's matrix (level 0, @p depth levels above
          /// the active mesh) from the Galerkin element matrices of its
          /// locally owned cells.
          void
          assemble_coarse_matrix(GalerkinElementMatrices<dim>    &galerkin,
                                 const unsigned int               depth,
                                 const AffineConstraints<double> &constraints)
          {
            constexpr unsigned int n_vertices = 1u << dim;
            constexpr unsigned int n_dofs     = dim * n_vertices;
            const unsigned int     rank = Utilities::MPI::this_mpi_process(
              dof_handler.get_communicator());
            std::vector<types::global_dof_index> dofs(n_dofs);
            FullMatrix<double>                   local(n_dofs, n_dofs);
            for (const auto &cell : dof_handler.mg_cell_iterators_on_level(0))
              if (cell->level_subdomain_id() == rank)
                {
                  const auto &K
                    = galerkin.matrix(depth,
                                      galerkin.id(cell->vertex(0),
                                                  cell->vertex(n_vertices - 1),
                                                  depth));
                  // FEEvaluation's order 2^dim c + v to the cell's DoFs,
                  // vertex by vertex (dim v + c)
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    for (unsigned int j = 0; j < n_dofs; ++j)
                      local(dim * (i % n_vertices) + i / n_vertices,
                            dim * (j % n_vertices) + j / n_vertices)
                        = K[n_dofs * i + j];
                  cell->get_mg_dof_indices(dofs);
                  constraints.distribute_local_to_global(local,
                                                         dofs,
                                                         coarse_matrix);
                }
            coarse_matrix.compress(VectorOperation::add);
          }

          const DoFHandler<dim> &dof_handler;
          /// The floating solve (SUBC, multilinear elements): the active
          /// constraints without the pins; the vertex of each owned DoF
          /// (dim of them), the centre of the rotations and the inverse
          /// Gram matrix of the rigid motions; the owned pinned DoFs and
          /// their vertices; the preconditioner's work vector.
          bool                      floating = false;
          AffineConstraints<double> free_constraints;
          std::vector<Point<dim>>   owned_vertex;
          /// The owned periodic images' DoFs (vector-local; periodic
          /// problem), kept at zero.
          std::vector<unsigned int> owned_image_dofs;
          /// The periodic problem of multilinear elements.
          bool                                             periodic = false;
          Point<dim>                                       centre;
          FullMatrix<double>                               gram_inverse;
          std::vector<std::pair<unsigned int, Point<dim>>> pinned_dofs;
          mutable VectorType                               projected_residual;
          const MappingQ1<dim>                             mapping;
          FineOperator                                     fine_operator;
          VectorType                                       rhs;
          MGConstrainedDoFs                                mg_constrained_dofs;
          MGLevelObject<LevelOperator>                     level_operators;
          std::unique_ptr<Transfer>                        transfer;
          MGSmootherPrecondition<LevelOperator, Smoother, LevelVectorType>
                                                           smoother;
          TrilinosWrappers::SparseMatrix                   coarse_matrix;
          std::unique_ptr<DirectCoarseSolver<LevelNumber>> coarse;
          std::unique_ptr<mg::Matrix<LevelVectorType>>     mg_matrix;
          std::unique_ptr<Multigrid<LevelVectorType>>      multigrid;
          std::unique_ptr<PreconditionMG<dim, LevelVectorType, Transfer>>
            preconditioner;
        };
      } // namespace


      template <int dim>
      std::unique_ptr<CellMultigridSolver<dim>>
      make_cell_multigrid_solver(
        const unsigned int                       fe_degree,
        const bool                               single_precision,
        std::shared_ptr<MultigridCache>         &cache,
        const dealii::DoFHandler<dim>           &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const LevelConstraintDescription<dim>   &level_constraints,
        const StiffnessOverBox<dim>             &stiffness,
        dealii::TimerOutput                     &timer)
      {
        const auto make
          = [&](auto degree,
                auto number) -> std::unique_ptr<CellMultigridSolver<dim>> {
          return std::make_unique<
            MultigridSolver<dim, decltype(degree)::value, decltype(number)>>(
            dof_handler,
            constraints,
            level_constraints,
            stiffness,
            cache,
            timer);
        };
        const auto with_degree
          = [&](auto number) -> std::unique_ptr<CellMultigridSolver<dim>> {
          // trilinear elements only in 3D (one per voxel)
          if constexpr (dim == 3)
            return make(std::integral_constant<int, 1>(), number);
          else
            switch (fe_degree)
              {
                case 1:
                  return make(std::integral_constant<int, 1>(), number);
                case 2:
                  return make(std::integral_constant<int, 2>(), number);
                case 3:
                  return make(std::integral_constant<int, 3>(), number);
                default:
                  return make(std::integral_constant<int, 4>(), number);
              }
        };
        return single_precision ? with_degree(float()) : with_degree(double());
      }


      template std::unique_ptr<CellMultigridSolver<2>>
      make_cell_multigrid_solver<2>(const unsigned int,
                                    const bool,
                                    std::shared_ptr<MultigridCache> &,
                                    const dealii::DoFHandler<2> &,
                                    const dealii::AffineConstraints<double> &,
                                    const LevelConstraintDescription<2> &,
                                    const StiffnessOverBox<2> &,
                                    dealii::TimerOutput &);
      template std::unique_ptr<CellMultigridSolver<3>>
      make_cell_multigrid_solver<3>(const unsigned int,
                                    const bool,
                                    std::shared_ptr<MultigridCache> &,
                                    const dealii::DoFHandler<3> &,
                                    const dealii::AffineConstraints<double> &,
                                    const LevelConstraintDescription<3> &,
                                    const StiffnessOverBox<3> &,
                                    dealii::TimerOutput &);
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn
