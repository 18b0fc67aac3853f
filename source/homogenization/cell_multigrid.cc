// Geometric multigrid for the cell problems: the matrix-free operator, the
// level constraints, the V-cycle and CG (declared in cell_multigrid.h).
#include "cell_multigrid.h"

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


        /**
         * Plane-strain elasticity, int eps(v) : C eps(u), with one constant
         * stiffness per cell: on the active mesh or on one level of the
         * hierarchy (whichever MatrixFree object it is initialized with).
         * C is symmetric: its six distinct entries are stored per cell
         * batch (C00, C01, C02, C11, C12, C22 of the Voigt matrix acting on
         * (eps_xx, eps_yy, gamma_xy)). @p Number: double on the active
         * mesh (CG's operator), float on the levels (the V-cycle).
         */
        template <int degree, typename Number>
        class ElasticityOperator
            : public MatrixFreeOperators::
                Base<2, LinearAlgebra::distributed::Vector<Number>>
        {
        public:
          using VectorType = LinearAlgebra::distributed::Vector<Number>;
          using Scalar     = VectorizedArray<Number>;
          using Tensor2    = SymmetricTensor<2, 2, Scalar>;
          using FEEval     = FEEvaluation<2, degree, degree + 1, 2, Number>;
          using Stiffness  = std::array<Scalar, 6>;

          /// Evaluate @p stiffness on the box of every cell.
          void
          set_stiffness(const StiffnessOverBox &stiffness)
          {
            const auto &mf = *this->get_matrix_free();
            coefficient.resize(mf.n_cell_batches());
            for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
              for (unsigned int lane = 0;
                   lane < mf.n_active_entries_per_cell_batch(batch);
                   ++lane)
                {
                  const auto cell = mf.get_cell_iterator(batch, lane);
                  // Vertices 0 and 3 of an axis-parallel rectangle are its
                  // lower-left and upper-right corners.
                  const VoigtMatrix C
                    = stiffness(cell->vertex(0), cell->vertex(3));
                  Stiffness &c = coefficient[batch];
                  c[0][lane]   = C[0][0];
                  c[1][lane]   = C[0][1];
                  c[2][lane]   = C[0][2];
                  c[3][lane]   = C[1][1];
                  c[4][lane]   = C[1][2];
                  c[5][lane]   = C[2][2];
                }
          }

          /// sigma = C eps of a Voigt strain, as a symmetric tensor.
          static Tensor2
          stress(const Stiffness &c,
                 const Scalar    &exx,
                 const Scalar    &eyy,
                 const Scalar    &gxy)
          {
            Tensor2 s;
            s[0][0] = c[0] * exx + c[1] * eyy + c[2] * gxy;
            s[1][1] = c[1] * exx + c[3] * eyy + c[4] * gxy;
            s[0][1] = c[2] * exx + c[4] * eyy + c[5] * gxy;
            return s;
          }

          /// The cell integral on the values in @p phi (also used for the
          /// diagonal and the coarse matrix).
          void
          local_apply(FEEval &phi) const
          {
            local_apply(phi, coefficient[phi.get_current_cell_index()]);
          }

          /// The same with the stiffness @p c.
          static void
          local_apply(FEEval &phi, const Stiffness &c)
          {
            phi.evaluate(EvaluationFlags::gradients);
            for (const unsigned int q : phi.quadrature_point_indices())
              {
                const Tensor2 e = phi.get_symmetric_gradient(q);
                phi.submit_symmetric_gradient(
                  stress(c, e[0][0], e[1][1], Number(2) * e[0][1]), q);
              }
            phi.integrate(EvaluationFlags::gradients);
          }

          /**
           * Bilinear elements (degree 1) on the pixel grid: every cell of a
           * level has the same rectangle, so its 8 x 8 element matrix
           * depends on the cell's stiffness only. The distinct stiffnesses
           * (the phases on the active mesh; the mixtures of coarse cells)
           * get their element matrix once (bilinear_element_matrix(), in
           * FEEvaluation's DoF order); the cell loop then multiplies by it:
           * 64 multiply-adds per cell instead of the general
           * evaluate/integrate. MatrixFree's mapping data are not needed
           * (nor computed) for it.
           */
          void
          tabulate_element_matrices(
            const AffineConstraints<Number> &constraints)
          {
            if constexpr (degree == 1)
              {
                const auto &mf = *this->get_matrix_free();
                std::map<std::array<double, 6>, unsigned int> index_of;
                std::vector<unsigned int>                     matrix_of_cell;
                element_matrices.clear();
                element_stiffness.clear();
                {
                  const auto cell = mf.get_cell_iterator(0, 0);
                  cell_size       = {{cell->vertex(3)[0] - cell->vertex(0)[0],
                                      cell->vertex(3)[1] - cell->vertex(0)[1]}};
                }
                for (unsigned int batch = 0; batch < mf.n_cell_batches();
                     ++batch)
                  for (unsigned int lane = 0;
                       lane < mf.n_active_entries_per_cell_batch(batch);
                       ++lane)
                    {
                      std::array<double, 6> key;
                      for (unsigned int k = 0; k < 6; ++k)
                        key[k] = coefficient[batch][k][lane];
                      const auto [it, inserted]
                        = index_of.emplace(key, element_matrices.size());
                      if (inserted)
                        {
                          const auto K = bilinear_element_matrix(key);
                          std::array<Number, 64> k;
                          for (unsigned int i = 0; i < 64; ++i)
                            k[i] = Number(K[i]);
                          element_matrices.push_back(k);
                          element_stiffness.push_back(key);
                        }
                      matrix_of_cell.push_back(it->second);
                    }
                AssertThrow(element_matrices.size() < (1u << 24),
                            ExcMessage("too many distinct cell stiffnesses"));
                tabulate_cell_dofs(constraints, matrix_of_cell);
                // the locally owned constrained DoFs: identity rows
                const auto &partitioner = *mf.get_vector_partitioner();
                constrained_owned.clear();
                for (unsigned int k = 0; k < partitioner.locally_owned_size();
                     ++k)
                  if (constraints.is_constrained(
                        partitioner.local_to_global(k)))
                    constrained_owned.push_back(k);
              }
          }

          /**
           * The 8 x 8 stiffness matrix (row-major) of a bilinear element of
           * the size cell_size with the plane-strain stiffness @p c (C00,
           * C01, C02, C11, C12, C22), by 2 x 2 Gauss quadrature as
           * FEEvaluation integrates it, in FEEvaluation's DoF order 4
           * component + vertex (vertices lexicographic): K = sum_q w_q B_q^T
           * C B_q, B = [[dN/dx, 0], [0, dN/dy], [dN/dy, dN/dx]].
           */
          std::array<double, 64>
          bilinear_element_matrix(const std::array<double, 6> &c) const
          {
            const double C[3][3]
              = {{c[0], c[1], c[2]}, {c[1], c[3], c[4]}, {c[2], c[4], c[5]}};
            const double hx = cell_size[0], hy = cell_size[1];
            const double g[2]
              = {0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)};
            std::array<double, 64> K{};
            for (const double xi : g)
              for (const double eta : g)
                {
                  double B[3][8] = {};
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      const unsigned int vx = v & 1, vy = v >> 1;
                      const double       dx
                        = (vx ? 1. : -1.) / hx * (vy ? eta : 1 - eta);
                      const double dy
                        = (vx ? xi : 1 - xi) * (vy ? 1. : -1.) / hy;
                      B[0][v]     = dx;
                      B[2][v]     = dy;
                      B[1][4 + v] = dy;
                      B[2][4 + v] = dx;
                    }
                  const double w = 0.25 * hx * hy;
                  for (unsigned int i = 0; i < 8; ++i)
                    for (unsigned int j = 0; j < 8; ++j)
                      {
                        double sum = 0;
                        for (unsigned int a = 0; a < 3; ++a)
                          for (unsigned int b = 0; b < 3; ++b)
                            sum += B[a][i] * C[a][b] * B[b][j];
                        K[8 * i + j] += w * sum;
                      }
                }
            return K;
          }

          /**
           * Degree 1: the DoFs of every cell (CellIndices) in FEEvaluation's
           * order 4 c + v (component-major, vertices in lexicographic order;
           * FESystem numbers them vertex by vertex, 2 v + c, so that the two
           * components of a vertex are consecutive, also as vector-local
           * indices: both owned or both ghosts of the same rank), with its
           * element matrix @p matrix_of_cell. Constrained DoFs (all
           * homogeneous here: boundary and pins) are read as zero and not
           * written, as MatrixFree does.
           */
          void
          tabulate_cell_dofs(const AffineConstraints<Number> &constraints,
                             const std::vector<unsigned int> &matrix_of_cell)
          {
            const auto        &mf          = *this->get_matrix_free();
            const auto        &partitioner = *mf.get_vector_partitioner();
            const unsigned int level       = mf.get_mg_level();
            cells.clear();
            std::vector<types::global_dof_index> dofs(8);
            for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
              for (unsigned int lane = 0;
                   lane < mf.n_active_entries_per_cell_batch(batch);
                   ++lane)
                {
                  const auto cell = mf.get_cell_iterator(batch, lane);
                  if (level == numbers::invalid_unsigned_int)
                    cell->get_dof_indices(dofs);
                  else
                    cell->get_mg_dof_indices(dofs);
                  CellIndices cell_indices;
                  cell_indices.matrix      = matrix_of_cell[cells.size()];
                  cell_indices.constrained = 0;
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      const unsigned int x
                        = partitioner.global_to_local(dofs[2 * v]);
                      AssertThrow(partitioner.global_to_local(dofs[2 * v + 1])
                                    == x + 1,
                                  ExcInternalError());
                      cell_indices.vertex[v] = x;
                      for (unsigned int c = 0; c < 2; ++c)
                        {
                          const auto dof = dofs[2 * v + c];
                          AssertThrow(
                            !constraints.is_constrained(dof)
                              || constraints.is_identity_constrained(dof)
                              || (constraints.get_constraint_entries(dof)
                                    ->empty()
                                  && constraints.get_inhomogeneity(dof) == 0),
                            ExcInternalError());
                          if (constraints.is_constrained(dof))
                            cell_indices.constrained |= 1u << (4 * c + v);
                        }
                    }
                  cells.push_back(cell_indices);
                }
          }

          /// Right-hand side of a unit load (see CellMultigridSolver).
          double
          assemble_rhs(VectorType        &rhs,
                       const VoigtVector &load,
                       const bool         strain_driven) const
          {
            const auto &mf = *this->get_matrix_free();
            mf.initialize_dof_vector(rhs);
            if constexpr (degree == 1)
              return assemble_rhs_bilinear(rhs, load, strain_driven);
            FEEval phi(mf);
            double scale = 0;
            for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
              {
                phi.reinit(batch);
                const Scalar l0 = Number(load[0]), l1 = Number(load[1]),
                             l2 = Number(load[2]);
                Tensor2 s;
                if (strain_driven)
                  s = -stress(coefficient[batch], l0, l1, l2);
                else
                  {
                    s[0][0] = l0;
                    s[1][1] = l1;
                    s[0][1] = l2;
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

          /**
           * Degree 1: the load of a cell is its element matrix times the
           * nodal values of the affine displacement of its constant strain
           * (E, or C^-1 Sigma for SUBC): Q1 holds affine fields exactly, so
           * K u_E = int B^T C E. Relative to the cell's corner (K ignores
           * translations), u_E is the same on every cell: one load vector
           * per distinct element matrix.
           */
          double
          assemble_rhs_bilinear(VectorType        &rhs,
                                const VoigtVector &load,
                                const bool         strain_driven) const
          {
            std::vector<std::array<double, 8>> loads(element_matrices.size());
            for (unsigned int m = 0; m < element_matrices.size(); ++m)
              {
                VoigtVector strain = load;
                if (!strain_driven)
                  {
                    const auto &c = element_stiffness[m];
                    VoigtMatrix C;
                    C[0][0] = c[0];
                    C[0][1] = C[1][0] = c[1];
                    C[0][2] = C[2][0] = c[2];
                    C[1][1]           = c[3];
                    C[1][2] = C[2][1] = c[4];
                    C[2][2]           = c[5];
                    strain            = invert(C) * load;
                  }
                double u[8];
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    const double x = (v & 1) * cell_size[0];
                    const double y = (v >> 1) * cell_size[1];
                    u[v]           = strain[0] * x + 0.5 * strain[2] * y;
                    u[4 + v]       = 0.5 * strain[2] * x + strain[1] * y;
                  }
                const double sign = strain_driven ? -1. : 1.;
                for (unsigned int i = 0; i < 8; ++i)
                  {
                    double sum = 0;
                    for (unsigned int j = 0; j < 8; ++j)
                      sum += double(element_matrices[m][8 * i + j]) * u[j];
                    loads[m][i] = sign * sum;
                  }
              }
            double scale = 0;
            for (const CellIndices &cell : cells)
              {
                const auto &f = loads[cell.matrix];
                for (unsigned int i = 0; i < 8; ++i)
                  {
                    scale += f[i] * f[i];
                    if (!cell.is_constrained(i))
                      rhs.local_element(cell.dof(i)) += Number(f[i]);
                  }
              }
            rhs.compress(VectorOperation::add);
            return std::sqrt(
              Utilities::MPI::sum(scale, rhs.get_mpi_communicator()));
          }

          void
          compute_diagonal() override
          {
            if constexpr (degree == 1)
              {
                // The diagonal of the assembled operator from the element
                // matrices' diagonals.
                this->inverse_diagonal_entries
                  = std::make_shared<DiagonalMatrix<VectorType>>();
                VectorType &diagonal
                  = this->inverse_diagonal_entries->get_vector();
                this->initialize_dof_vector(diagonal);
                for (const CellIndices &cell : cells)
                  for (unsigned int i = 0; i < 8; ++i)
                    if (!cell.is_constrained(i))
                      diagonal.local_element(cell.dof(i))
                        += element_matrices[cell.matrix][9 * i];
                diagonal.compress(VectorOperation::add);
                for (const unsigned int k : constrained_owned)
                  diagonal.local_element(k) = 1;
                for (unsigned int i = 0; i < diagonal.locally_owned_size(); ++i)
                  diagonal.local_element(i)
                    = Number(1) / diagonal.local_element(i);
                return;
              }
            this->inverse_diagonal_entries
              = std::make_shared<DiagonalMatrix<VectorType>>();
            VectorType &diagonal = this->inverse_diagonal_entries->get_vector();
            this->initialize_dof_vector(diagonal);
            MatrixFreeTools::compute_diagonal(*this->get_matrix_free(),
                                              diagonal,
                                              &ElasticityOperator::local_apply,
                                              this);
            this->set_constrained_entries_to_one(diagonal);
            for (unsigned int i = 0; i < diagonal.locally_owned_size(); ++i)
              diagonal.local_element(i) = Number(1) / diagonal.local_element(i);
          }

        private:
          void
          apply_add(VectorType &dst, const VectorType &src) const override
          {
            if constexpr (degree == 1)
              apply_add_bilinear(dst, src);
            else
              this->data->cell_loop(&ElasticityOperator::cell_range,
                                    this,
                                    dst,
                                    src);
          }

          /// Degree 1: gather, multiply by the cell's element matrix,
          /// scatter; ghost values exchanged as MatrixFree's cell loop does.
          /// The product y = sum_j x_j K(:, j) (K is symmetric: its rows are
          /// its columns) is eight multiply-adds of 8-vectors, which the
          /// compiler vectorizes; constrained DoFs read 0 and are not
          /// written.
          void
          apply_add_bilinear(VectorType &dst, const VectorType &src) const
          {
            const bool src_had_ghosts = src.has_ghost_elements();
            if (!src_had_ghosts)
              src.update_ghost_values();
            dst.zero_out_ghost_values();
            const Number *in  = src.begin();
            Number       *out = dst.begin();
            // eight Numbers in one SIMD register (GCC's vector extension)
            typedef Number Column
              __attribute__((vector_size(8 * sizeof(Number))));
            for (const CellIndices &cell : cells)
              {
                Number x[8];
                if (cell.constrained == 0) // all but the boundary's cells
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      x[v]     = in[cell.vertex[v]];
                      x[4 + v] = in[cell.vertex[v] + 1];
                    }
                else
                  for (unsigned int i = 0; i < 8; ++i)
                    x[i] = cell.is_constrained(i) ? Number(0) : in[cell.dof(i)];
                const Number *K = element_matrices[cell.matrix].data();
                Column        y = {};
                for (unsigned int j = 0; j < 8; ++j)
                  {
                    Column column;
                    std::memcpy(&column, K + 8 * j, sizeof(Column));
                    y += column * x[j];
                  }
                if (cell.constrained == 0)
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      out[cell.vertex[v]] += y[v];
                      out[cell.vertex[v] + 1] += y[4 + v];
                    }
                else
                  for (unsigned int i = 0; i < 8; ++i)
                    if (!cell.is_constrained(i))
                      out[cell.dof(i)] += y[i];
              }
            // constrained rows: the identity (the MatrixFree objects hold
            // no constraints, see MultigridCache)
            for (const unsigned int k : constrained_owned)
              out[k] += in[k];
            dst.compress(VectorOperation::add);
            if (!src_had_ghosts)
              src.zero_out_ghost_values();
          }

          void
          cell_range(const MatrixFree<2, Number>                 &data,
                     VectorType                                  &dst,
                     const VectorType                            &src,
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
          /// Degree 1: the distinct element matrices (row-major), and per
          /// locally owned cell (in the order of the cell batches and their
          /// lanes) its matrix and its DoFs.
          std::vector<std::array<Number, 64>> element_matrices;
          /// Degree 1: a locally owned cell's DoFs and element matrix.
          struct CellIndices
          {
            /// vector-local index of component 0 at each vertex (component
            /// 1 is the next one)
            std::array<unsigned int, 4> vertex;
            /// index of its element matrix
            unsigned int matrix : 24;
            /// bit 4 c + v: DoF (c, v) constrained
            unsigned int constrained : 8;

            bool
            is_constrained(const unsigned int i) const
            {
              return (constrained >> i) & 1u;
            }
            /// vector-local index of DoF i = 4 c + v
            unsigned int
            dof(const unsigned int i) const
            {
              return vertex[i % 4] + i / 4;
            }
          };
          std::vector<CellIndices> cells;
          /// Degree 1: vector-local indices of the locally owned
          /// constrained DoFs.
          std::vector<unsigned int> constrained_owned;
          /// The six stiffness entries of each element matrix, and the
          /// cells' size along x and y.
          std::vector<std::array<double, 6>> element_stiffness;
          std::array<double, 2>              cell_size = {{0, 0}};
        };


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


        /// DoFs of level @p level at the vertices @p pin designates.
        IndexSet
        pinned_level_dofs(const DoFHandler<2>                   &dofs,
                          const unsigned int                     level,
                          const LevelConstraintDescription::Pin &pin,
                          const double                           tolerance)
        {
          IndexSet pinned(dofs.n_dofs(level));
          for (const auto &cell : dofs.mg_cell_iterators_on_level(level))
            if (cell->level_subdomain_id() != numbers::artificial_subdomain_id)
              for (const unsigned int v : cell->vertex_indices())
                if (cell->vertex(v).distance(pin.point) < tolerance)
                  for (const unsigned int c : pin.components)
                    pinned.add_index(cell->mg_vertex_dof_index(level, v, c));
          return pinned;
        }


        /// The shared matrix-free objects of the bilinear fast path.
        template <typename LevelNumber>
        struct BilinearMatrixFree : MultigridCache
        {
          std::shared_ptr<const MatrixFree<2, double>>                   fine;
          std::vector<std::shared_ptr<const MatrixFree<2, LevelNumber>>> levels;
        };


        template <int degree, typename LevelNumber>
        class MultigridSolver : public CellMultigridSolver
        {
        public:
          using LevelVectorType
            = LinearAlgebra::distributed::Vector<LevelNumber>;
          using FineOperator  = ElasticityOperator<degree, double>;
          using LevelOperator = ElasticityOperator<degree, LevelNumber>;
          using Transfer      = MGTransferMatrixFree<2, LevelNumber>;
          using Smoother
            = PreconditionChebyshev<LevelOperator,
                                    LevelVectorType,
                                    DiagonalMatrix<LevelVectorType>>;

          MultigridSolver(const DoFHandler<2>              &dof_handler,
                          const AffineConstraints<double>  &constraints,
                          const LevelConstraintDescription &description,
                          const StiffnessOverBox           &stiffness,
                          std::shared_ptr<MultigridCache>  &cache,
                          TimerOutput                      &timer)
              : dof_handler(dof_handler)
          {
            TimerOutput::Scope scope(timer, "multigrid setup");
            typename MatrixFree<2, double>::AdditionalData data;
            data.tasks_parallel_scheme
              = MatrixFree<2, double>::AdditionalData::none;
            data.mapping_update_flags = update_gradients | update_JxW_values;
            typename MatrixFree<2, LevelNumber>::AdditionalData level_data;
            level_data.tasks_parallel_scheme
              = MatrixFree<2, LevelNumber>::AdditionalData::none;
            level_data.mapping_update_flags = data.mapping_update_flags;
            // the bilinear fast path needs no mapping data (its element
            // matrices are computed directly); other degrees evaluate
            // gradients on every cell
            data.initialize_mapping       = degree > 1;
            level_data.initialize_mapping = degree > 1;
            const QGauss<1> quadrature(degree + 1);
            // Bilinear elements: the operator applies the constraints
            // itself, so the matrix-free objects hold none and are shared by
            // the boundary conditions (built by the first one).
            std::shared_ptr<BilinearMatrixFree<LevelNumber>> shared;
            bool                                             reuse = false;
            if constexpr (degree == 1)
              {
                shared
                  = std::dynamic_pointer_cast<BilinearMatrixFree<LevelNumber>>(
                    cache);
                reuse = shared != nullptr;
                if (!reuse)
                  cache = shared
                    = std::make_shared<BilinearMatrixFree<LevelNumber>>();
              }
            AffineConstraints<double> no_constraints;
            no_constraints.close();
            AffineConstraints<LevelNumber> no_level_constraints;
            no_level_constraints.close();

            // The active mesh.
            {
              std::shared_ptr<const MatrixFree<2, double>> mf;
              if (reuse)
                mf = shared->fine;
              else
                {
                  auto new_mf = std::make_shared<MatrixFree<2, double>>();
                  new_mf->reinit(mapping,
                                 dof_handler,
                                 degree == 1 ? no_constraints : constraints,
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
              mg_constrained_dofs.make_zero_boundary_constraints(dof_handler,
                                                                 {0, 1, 2, 3});
            for (unsigned int level = 0; level < n_levels; ++level)
              for (const auto &pin : description.pins)
                mg_constrained_dofs.add_boundary_indices(
                  dof_handler,
                  level,
                  pinned_level_dofs(
                    dof_handler, level, pin, description.tolerance));

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
                std::shared_ptr<const MatrixFree<2, LevelNumber>> mf;
                if (reuse)
                  mf = shared->levels[level];
                else
                  {
                    auto new_mf
                      = std::make_shared<MatrixFree<2, LevelNumber>>();
                    new_mf->reinit(mapping,
                                   dof_handler,
                                   degree == 1 ? no_level_constraints
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
              auto mf = std::make_shared<MatrixFree<2, double>>();
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
            preconditioner
              = std::make_unique<PreconditionMG<2, LevelVectorType, Transfer>>(
                dof_handler, *multigrid, *transfer);
          }

          double
          assemble_rhs(const VoigtVector &load,
                       const bool         strain_driven) override
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
          const DoFHandler<2>         &dof_handler;
          const MappingQ1<2>           mapping;
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
          std::unique_ptr<PreconditionMG<2, LevelVectorType, Transfer>>
            preconditioner;
        };
      } // namespace


      std::unique_ptr<CellMultigridSolver>
      make_cell_multigrid_solver(
        const unsigned int                       fe_degree,
        const bool                               single_precision,
        std::shared_ptr<MultigridCache>         &cache,
        const dealii::DoFHandler<2>             &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const LevelConstraintDescription        &level_constraints,
        const StiffnessOverBox                  &stiffness,
        dealii::TimerOutput                     &timer)
      {
        const auto make
          = [&](auto degree,
                auto number) -> std::unique_ptr<CellMultigridSolver> {
          return std::make_unique<
            MultigridSolver<decltype(degree)::value, decltype(number)>>(
            dof_handler,
            constraints,
            level_constraints,
            stiffness,
            cache,
            timer);
        };
        const auto with_degree = [&](auto number) {
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
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn
