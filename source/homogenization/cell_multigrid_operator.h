// The matrix-free plane-strain elasticity operator of the cell problems'
// geometric multigrid (issue #19 item 4): the general FEEvaluation kernel
// and the bilinear fast path. Private to source/homogenization/
// cell_multigrid.cc.
#ifndef tribodyn_source_homogenization_cell_multigrid_operator_h
#define tribodyn_source_homogenization_cell_multigrid_operator_h

#include "cell_multigrid.h"

#include <array>
#include <cmath>
#include <cstring>
#include <deal.II/base/vectorization.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/operators.h>
#include <deal.II/matrix_free/tools.h>
#include <map>
#include <memory>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      using dealii::AffineConstraints;
      using dealii::DiagonalMatrix;
      using dealii::ExcInternalError;
      using dealii::ExcMessage;
      using dealii::FEEvaluation;
      using dealii::MatrixFree;
      using dealii::SymmetricTensor;
      using dealii::VectorizedArray;
      using dealii::VectorOperation;
      namespace EvaluationFlags     = dealii::EvaluationFlags;
      namespace LinearAlgebra       = dealii::LinearAlgebra;
      namespace MatrixFreeOperators = dealii::MatrixFreeOperators;
      namespace MatrixFreeTools     = dealii::MatrixFreeTools;
      namespace numbers             = dealii::numbers;
      namespace types               = dealii::types;
      namespace Utilities           = dealii::Utilities;

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
        tabulate_element_matrices(const AffineConstraints<Number> &constraints)
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
              for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
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
                        const auto             K = bilinear_element_matrix(key);
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
                if (constraints.is_constrained(partitioner.local_to_global(k)))
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
                    const double dy = (vx ? xi : 1 - xi) * (vy ? 1. : -1.) / hy;
                    B[0][v]         = dx;
                    B[2][v]         = dy;
                    B[1][4 + v]     = dy;
                    B[2][4 + v]     = dx;
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
                            || (constraints.get_constraint_entries(dof)->empty()
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
          for (unsigned int batch = range.first; batch < range.second; ++batch)
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


    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
