// Geometric multigrid for the cell problems: the matrix-free operator, the
// level constraints, the V-cycle and CG (declared in cell_multigrid.h).
#include "cell_multigrid.h"

#include "cell_multigrid_operator.h"

#include <array>
#include <cstring>
#include <deal.II/base/vectorization.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
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
          explicit DirectCoarseSolver(
            const TrilinosWrappers::SparseMatrix &matrix)
              : control(1, 0)
              , solver(control)
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
          }

        private:
          SolverControl                          control;
          mutable TrilinosWrappers::SolverDirect solver;
          mutable VectorType                     b, x;
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
          using Transfer      = MGTransferMatrixFree<dim, LevelNumber>;
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
            AffineConstraints<LevelNumber> no_level_constraints;
            no_level_constraints.close();

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
                                 fast_path ? no_constraints : constraints,
                                 quadrature,
                                 data);
                  mf = new_mf;
                  if (shared)
                    shared->fine = mf;
                }
              fine_operator.initialize(mf);
              fine_operator.set_stiffness(stiffness);
              fine_operator.tabulate_element_matrices(constraints);
            }

            // The constraints on the levels: the boundary, the pinned
            // vertices (the triangulation has no periodic faces here).
            const unsigned int n_levels
              = dof_handler.get_triangulation().n_global_levels();
            mg_constrained_dofs.initialize(dof_handler);
            if (description.zero_boundary)
              {
                std::set<types::boundary_id> faces;
                for (unsigned int id = 0; id < 2 * dim; ++id)
                  faces.insert(id);
                mg_constrained_dofs.make_zero_boundary_constraints(dof_handler,
                                                                   faces);
              }
            for (unsigned int level = 0; level < n_levels; ++level)
              for (const auto &[point, components] : description.pins)
                mg_constrained_dofs.add_boundary_indices(
                  dof_handler,
                  level,
                  pinned_level_dofs(dof_handler,
                                    level,
                                    point,
                                    components,
                                    description.tolerance));

            level_operators.resize(0, n_levels - 1);
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
                    new_mf->reinit(mapping,
                                   dof_handler,
                                   fast_path ? no_level_constraints
                                             : level_constraints,
                                   quadrature,
                                   level_data);
                    mf = new_mf;
                    if (shared)
                      shared->levels.push_back(mf);
                  }
                level_operators[level].initialize(mf,
                                                  mg_constrained_dofs,
                                                  level);
                level_operators[level].set_stiffness(stiffness);
                level_operators[level].tabulate_element_matrices(
                  level_constraints);
                level_operators[level].compute_diagonal();
              }

            transfer = std::make_unique<Transfer>(mg_constrained_dofs);
            transfer->build(dof_handler);

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
              data.mg_level           = 0;
              data.initialize_mapping = true; // compute_matrix integrates
              auto mf = std::make_shared<MatrixFree<dim, double>>();
              mf->reinit(
                mapping, dof_handler, coarse_constraints, quadrature, data);
              FineOperator coarse_operator;
              coarse_operator.initialize(mf, mg_constrained_dofs, 0);
              coarse_operator.set_stiffness(stiffness);
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
              MatrixFreeTools::compute_matrix(*mf,
                                              coarse_constraints,
                                              coarse_matrix,
                                              &FineOperator::local_apply,
                                              &coarse_operator);
              coarse = std::make_unique<DirectCoarseSolver<LevelNumber>>(
                coarse_matrix);
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
            cg.solve(fine_operator, x, rhs, *preconditioner);
            // both vectors hold the locally owned DoFs in the same order
            double *values = solution.trilinos_vector()[0];
            for (unsigned int k = 0; k < x.locally_owned_size(); ++k)
              values[k] = x.local_element(k);
          }

        private:
          const DoFHandler<dim>       &dof_handler;
          const MappingQ1<dim>         mapping;
          FineOperator                 fine_operator;
          VectorType                   rhs;
          MGConstrainedDoFs            mg_constrained_dofs;
          MGLevelObject<LevelOperator> level_operators;
          std::unique_ptr<Transfer>    transfer;
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
