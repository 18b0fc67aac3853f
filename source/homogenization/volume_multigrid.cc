// Geometric multigrid for the cell problems of voxel volumes (declared in
// volume_multigrid.h): the matrix-free operator, the level constraints,
// the V-cycle and CG. The structure is that of the 2D solver
// (cell_multigrid.cc), with deal.II's general FEEvaluation kernel.
#include "volume_multigrid.h"

#include <array>
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

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      namespace
      {
        using namespace dealii;
        using VectorType      = LinearAlgebra::distributed::Vector<double>;
        using LevelNumber     = float;
        using LevelVectorType = LinearAlgebra::distributed::Vector<float>;

        /**
         * 3D elasticity, int eps(v) : C eps(u), trilinear elements, one
         * constant stiffness per cell: the 21 entries C_ij (i <= j) of the
         * cell's Voigt matrix, stored per cell batch.
         */
        template <typename Number>
        class VolumeElasticityOperator
            : public MatrixFreeOperators::
                Base<3, LinearAlgebra::distributed::Vector<Number>>
        {
        public:
          using Vector    = LinearAlgebra::distributed::Vector<Number>;
          using Scalar    = VectorizedArray<Number>;
          using Tensor2   = SymmetricTensor<2, 3, Scalar>;
          using FEEval    = FEEvaluation<3, 1, 2, 3, Number>;
          using Stiffness = std::array<Scalar, 21>;

          /// Index of C_ij (i <= j) in a Stiffness.
          static constexpr unsigned int
          entry(const unsigned int i, const unsigned int j)
          {
            return i <= j ? i * 6 - i * (i - 1) / 2 + (j - i)
                          : j * 6 - j * (j - 1) / 2 + (i - j);
          }

          /// Evaluate @p stiffness on the box of every cell.
          void
          set_stiffness(const StiffnessOverBox3D &stiffness)
          {
            const auto &mf = *this->get_matrix_free();
            coefficient.resize(mf.n_cell_batches());
            for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
              for (unsigned int lane = 0;
                   lane < mf.n_active_entries_per_cell_batch(batch);
                   ++lane)
                {
                  const auto cell = mf.get_cell_iterator(batch, lane);
                  // vertices 0 and 7 of an axis-parallel box: its lower
                  // and upper corners
                  const VoigtMatrix6 C
                    = stiffness(cell->vertex(0), cell->vertex(7));
                  for (unsigned int i = 0; i < 6; ++i)
                    for (unsigned int j = i; j < 6; ++j)
                      coefficient[batch][entry(i, j)][lane] = C[i][j];
                }
          }

          /// sigma = C eps for a Voigt strain (engineering shears), as a
          /// symmetric tensor.
          static Tensor2
          stress(const Stiffness &c, const std::array<Scalar, 6> &e)
          {
            std::array<Scalar, 6> s;
            for (unsigned int i = 0; i < 6; ++i)
              {
                s[i] = c[entry(i, 0)] * e[0];
                for (unsigned int j = 1; j < 6; ++j)
                  s[i] += c[entry(i, j)] * e[j];
              }
            Tensor2 t;
            t[0][0] = s[0];
            t[1][1] = s[1];
            t[2][2] = s[2];
            t[1][2] = s[3];
            t[0][2] = s[4];
            t[0][1] = s[5];
            return t;
          }

          void
          local_apply(FEEval &phi) const
          {
            const Stiffness &c = coefficient[phi.get_current_cell_index()];
            phi.evaluate(EvaluationFlags::gradients);
            for (const unsigned int q : phi.quadrature_point_indices())
              {
                const Tensor2               g = phi.get_symmetric_gradient(q);
                const std::array<Scalar, 6> e = {{g[0][0],
                                                  g[1][1],
                                                  g[2][2],
                                                  Number(2) * g[1][2],
                                                  Number(2) * g[0][2],
                                                  Number(2) * g[0][1]}};
                phi.submit_symmetric_gradient(stress(c, e), q);
              }
            phi.integrate(EvaluationFlags::gradients);
          }

          /// Right-hand side of a unit load (see VolumeMultigridSolver).
          double
          assemble_rhs(Vector             &rhs,
                       const VoigtVector6 &load,
                       const bool          strain_driven) const
          {
            const auto &mf = *this->get_matrix_free();
            mf.initialize_dof_vector(rhs);
            FEEval                phi(mf);
            double                scale = 0;
            std::array<Scalar, 6> l;
            for (unsigned int i = 0; i < 6; ++i)
              l[i] = Number(load[i]);
            for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
              {
                phi.reinit(batch);
                Tensor2 s;
                if (strain_driven)
                  s = -stress(coefficient[batch], l);
                else
                  {
                    s[0][0] = l[0];
                    s[1][1] = l[1];
                    s[2][2] = l[2];
                    s[1][2] = l[3];
                    s[0][2] = l[4];
                    s[0][1] = l[5];
                  }
                for (const unsigned int q : phi.quadrature_point_indices())
                  phi.submit_symmetric_gradient(s, q);
                phi.integrate(EvaluationFlags::gradients);
                for (unsigned int i = 0; i < phi.dofs_per_cell; ++i)
                  for (unsigned int lane = 0;
                       lane < mf.n_active_entries_per_cell_batch(batch);
                       ++lane)
                    scale += phi.begin_dof_values()[i][lane]
                             * phi.begin_dof_values()[i][lane];
                phi.distribute_local_to_global(rhs);
              }
            rhs.compress(VectorOperation::add);
            return std::sqrt(
              Utilities::MPI::sum(scale, rhs.get_mpi_communicator()));
          }

          void
          compute_diagonal() override
          {
            this->inverse_diagonal_entries
              = std::make_shared<DiagonalMatrix<Vector>>();
            Vector &diagonal = this->inverse_diagonal_entries->get_vector();
            this->initialize_dof_vector(diagonal);
            MatrixFreeTools::compute_diagonal(
              *this->get_matrix_free(),
              diagonal,
              &VolumeElasticityOperator::local_apply,
              this);
            this->set_constrained_entries_to_one(diagonal);
            for (unsigned int i = 0; i < diagonal.locally_owned_size(); ++i)
              diagonal.local_element(i) = Number(1) / diagonal.local_element(i);
          }

        private:
          void
          apply_add(Vector &dst, const Vector &src) const override
          {
            this->data->cell_loop(&VolumeElasticityOperator::cell_range,
                                  this,
                                  dst,
                                  src);
          }

          void
          cell_range(const MatrixFree<3, Number>                 &data,
                     Vector                                      &dst,
                     const Vector                                &src,
                     const std::pair<unsigned int, unsigned int> &range) const
          {
            FEEval phi(data);
            for (unsigned int batch = range.first; batch < range.second;
                 ++batch)
              {
                phi.reinit(batch);
                phi.read_dof_values(src);
                local_apply(phi);
                phi.distribute_local_to_global(dst);
              }
          }

          std::vector<Stiffness> coefficient;
        };


        /// The coarsest level solved with a factorization of its matrix
        /// (in double; the float level vectors are converted).
        class VolumeDirectCoarseSolver
            : public MGCoarseGridBase<LevelVectorType>
        {
        public:
          explicit VolumeDirectCoarseSolver(
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
        IndexSet
        pinned_level_dofs_3d(const DoFHandler<3>             &dofs,
                             const unsigned int               level,
                             const Point<3>                  &point,
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


        class Solver : public VolumeMultigridSolver
        {
        public:
          using FineOperator  = VolumeElasticityOperator<double>;
          using LevelOperator = VolumeElasticityOperator<LevelNumber>;
          using Transfer      = MGTransferMatrixFree<3, LevelNumber>;
          using Smoother
            = PreconditionChebyshev<LevelOperator,
                                    LevelVectorType,
                                    DiagonalMatrix<LevelVectorType>>;

          Solver(const DoFHandler<3>             &dof_handler,
                 const AffineConstraints<double> &constraints,
                 const VolumeLevelConstraints    &description,
                 const StiffnessOverBox3D        &stiffness,
                 TimerOutput                     &timer)
          {
            TimerOutput::Scope scope(timer, "multigrid setup");
            const QGauss<1>    quadrature(2);
            typename MatrixFree<3, double>::AdditionalData data;
            data.tasks_parallel_scheme
              = MatrixFree<3, double>::AdditionalData::none;
            data.mapping_update_flags = update_gradients | update_JxW_values;
            typename MatrixFree<3, LevelNumber>::AdditionalData level_data;
            level_data.tasks_parallel_scheme
              = MatrixFree<3, LevelNumber>::AdditionalData::none;
            level_data.mapping_update_flags = data.mapping_update_flags;

            // The active mesh, in double precision (CG's operator).
            {
              auto mf = std::make_shared<MatrixFree<3, double>>();
              mf->reinit(mapping, dof_handler, constraints, quadrature, data);
              fine_operator.initialize(mf);
              fine_operator.set_stiffness(stiffness);
            }

            // The constraints on the levels: the boundary (KUBC), the
            // pinned vertices (SUBC).
            const unsigned int n_levels
              = dof_handler.get_triangulation().n_global_levels();
            mg_constrained_dofs.initialize(dof_handler);
            if (description.zero_boundary)
              mg_constrained_dofs.make_zero_boundary_constraints(
                dof_handler, {0, 1, 2, 3, 4, 5});
            for (unsigned int level = 0; level < n_levels; ++level)
              for (const auto &[point, components] : description.pins)
                mg_constrained_dofs.add_boundary_indices(
                  dof_handler,
                  level,
                  pinned_level_dofs_3d(dof_handler,
                                       level,
                                       point,
                                       components,
                                       description.tolerance));
            const auto level_constraints_of
              = [&](const unsigned int level, auto &c) {
                  IndexSet relevant;
                  DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                                level,
                                                                relevant);
                  c.reinit(relevant);
                  c.add_lines(mg_constrained_dofs.get_boundary_indices(level));
                  c.close();
                };

            level_operators.resize(0, n_levels - 1);
            for (unsigned int level = 0; level < n_levels; ++level)
              {
                AffineConstraints<LevelNumber> level_constraints;
                level_constraints_of(level, level_constraints);
                level_data.mg_level = level;
                auto mf = std::make_shared<MatrixFree<3, LevelNumber>>();
                mf->reinit(mapping,
                           dof_handler,
                           level_constraints,
                           quadrature,
                           level_data);
                level_operators[level].initialize(mf,
                                                  mg_constrained_dofs,
                                                  level);
                level_operators[level].set_stiffness(stiffness);
                level_operators[level].compute_diagonal();
              }

            transfer = std::make_unique<Transfer>(mg_constrained_dofs);
            transfer->build(dof_handler);

            // Chebyshev of degree 3 over [lambda_max / 15, 1.1 lambda_max]
            // of the Jacobi-preconditioned level operator, as in 2D.
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

            // The coarsest level's matrix, in double, factorized once.
            {
              AffineConstraints<double> coarse_constraints;
              level_constraints_of(0, coarse_constraints);
              data.mg_level = 0;
              auto mf       = std::make_shared<MatrixFree<3, double>>();
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
              coarse
                = std::make_unique<VolumeDirectCoarseSolver>(coarse_matrix);
            }

            mg_matrix
              = std::make_unique<mg::Matrix<LevelVectorType>>(level_operators);
            multigrid = std::make_unique<Multigrid<LevelVectorType>>(
              *mg_matrix, *coarse, *transfer, smoother, smoother);
            preconditioner
              = std::make_unique<PreconditionMG<3, LevelVectorType, Transfer>>(
                dof_handler, *multigrid, *transfer);
          }

          double
          assemble_rhs(const VoigtVector6 &load,
                       const bool          strain_driven) override
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
          const MappingQ1<3>           mapping;
          FineOperator                 fine_operator;
          VectorType                   rhs;
          MGConstrainedDoFs            mg_constrained_dofs;
          MGLevelObject<LevelOperator> level_operators;
          std::unique_ptr<Transfer>    transfer;
          MGSmootherPrecondition<LevelOperator, Smoother, LevelVectorType>
                                                       smoother;
          TrilinosWrappers::SparseMatrix               coarse_matrix;
          std::unique_ptr<VolumeDirectCoarseSolver>    coarse;
          std::unique_ptr<mg::Matrix<LevelVectorType>> mg_matrix;
          std::unique_ptr<Multigrid<LevelVectorType>>  multigrid;
          std::unique_ptr<PreconditionMG<3, LevelVectorType, Transfer>>
            preconditioner;
        };
      } // namespace


      std::unique_ptr<VolumeMultigridSolver>
      make_volume_multigrid_solver(
        const dealii::DoFHandler<3>             &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const VolumeLevelConstraints            &level_constraints,
        const StiffnessOverBox3D                &stiffness,
        dealii::TimerOutput                     &timer)
      {
        return std::make_unique<Solver>(
          dof_handler, constraints, level_constraints, stiffness, timer);
      }
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn
