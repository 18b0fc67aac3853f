// The matrix-free elasticity operator of the cell problems' geometric
// multigrid (issue #19 item 4; 3D: issue #51), for dim = 2 (plane strain)
// and 3: the general FEEvaluation kernel and the fast path of multilinear
// elements. Private to source/homogenization/cell_multigrid.cc.
#ifndef tribodyn_source_homogenization_cell_multigrid_operator_h
#define tribodyn_source_homogenization_cell_multigrid_operator_h

#include "cell_multigrid.h"

#include <array>
#include <cmath>
#include <cstdint>
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
#include <tribodyn/homogenization/volume_properties.h>
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

      /// The Voigt index of the shear of the plane of axes (@p i, @p j),
      /// i != j: xy in 2D; yz, xz, xy in 3D.
      template <int dim>
      constexpr unsigned int
      voigt_shear(const unsigned int i, const unsigned int j)
      {
        return dim == 2 ? 2 : 3 + (3 - i - j);
      }

      /**
       * y = K x for the element matrix @p K (n x n, row-major) of a
       * multilinear element: K is symmetric (its rows are its columns), so
       * y = sum_j x_j K(:, j) is n multiply-adds of n-vectors, in chunks of
       * eight Numbers that the compiler vectorizes (GCC's vector
       * extension). The sum over j runs in four independent partial sums
       * (columns j = p, p + 4, ...), added pairwise at the end: with one
       * sum per chunk, each multiply-add waited for the previous one (3
       * chains of 24 dependent FMAs a cell in 3D, bound by the FMA latency,
       * not by its throughput). The mesh's operator (ElasticityOperator)
       * and the voxel grid's (voxel_grid_solver.cc) share it.
       */
      template <typename Number, unsigned int n>
      inline void
      multiply_element_matrix(const Number *K, const Number *x, Number *y)
      {
        typedef Number Column __attribute__((vector_size(8 * sizeof(Number))));
        constexpr unsigned int n_chunks  = n / 8;
        constexpr unsigned int n_partial = 4;
        static_assert(n % 8 == 0 && n % n_partial == 0 && n_partial == 4,
                      "whole chunks and column groups, summed pairwise below");
        Column partial[n_partial][n_chunks] = {};
        for (unsigned int j = 0; j < n; j += n_partial)
          for (unsigned int p = 0; p < n_partial; ++p)
            for (unsigned int b = 0; b < n_chunks; ++b)
              {
                Column column;
                std::memcpy(&column, K + n * (j + p) + 8 * b, sizeof(Column));
                partial[p][b] += column * x[j + p];
              }
        for (unsigned int b = 0; b < n_chunks; ++b)
          {
            const Column sum = (partial[0][b] + partial[1][b])
                               + (partial[2][b] + partial[3][b]);
            std::memcpy(y + 8 * b, &sum, sizeof(Column));
          }
      }

      /**
       * y_t = K x_t for @p count cells t of the same element matrix @p K
       * (as multiply_element_matrix()): each column of K is loaded once for
       * all of them, and their sums are the independent chains that the
       * partial sums are for one cell.
       */
      template <typename Number, unsigned int n, unsigned int count>
      inline void
      multiply_element_matrices(const Number *K, Number (*x)[n], Number (*y)[n])
      {
        typedef Number Column __attribute__((vector_size(8 * sizeof(Number))));
        constexpr unsigned int n_chunks = n / 8;
        static_assert(n % 8 == 0, "whole chunks");
        // (unrolled, so that the count x n_chunks sums stay in registers)
        Column sum[count][n_chunks] = {};
        for (unsigned int j = 0; j < n; ++j)
          {
#pragma GCC unroll 8
            for (unsigned int b = 0; b < n_chunks; ++b)
              {
                Column column;
                std::memcpy(&column, K + n * j + 8 * b, sizeof(Column));
#pragma GCC unroll 8
                for (unsigned int t = 0; t < count; ++t)
                  sum[t][b] += column * x[t][j];
              }
          }
        for (unsigned int t = 0; t < count; ++t)
          std::memcpy(y[t], sum[t], sizeof(sum[t]));
      }

      /**
       * Elasticity, int eps(v) : C eps(u), with one constant stiffness per
       * cell: on the active mesh or on one level of the hierarchy
       * (whichever MatrixFree object it is initialized with). C is
       * symmetric: the n (n + 1) / 2 entries C_ij, i <= j, of its n x n
       * Voigt matrix (n = 3 in 2D, 6 in 3D) are stored per cell batch, row
       * by row (in 2D C00, C01, C02, C11, C12, C22 acting on (eps_xx,
       * eps_yy, gamma_xy)). @p Number: double on the active mesh (CG's
       * operator), float on the levels (the V-cycle).
       */
      template <int dim, int degree, typename Number>
      class ElasticityOperator
          : public MatrixFreeOperators::
              Base<dim, LinearAlgebra::distributed::Vector<Number>>
      {
      public:
        static constexpr unsigned int n_voigt = CellTraits<dim>::n_voigt;
        using VectorType = LinearAlgebra::distributed::Vector<Number>;
        using Scalar     = VectorizedArray<Number>;
        using Tensor2    = SymmetricTensor<2, dim, Scalar>;
        using FEEval     = FEEvaluation<dim, degree, degree + 1, dim, Number>;
        using Stiffness  = std::array<Scalar, n_voigt *(n_voigt + 1) / 2>;
        /// Multilinear elements take the tabulated fast path (below).
        static constexpr bool         fast_path  = degree == 1;
        static constexpr unsigned int n_vertices = 1u << dim;
        /// DoFs of a multilinear element: 8 in 2D, 24 in 3D.
        static constexpr unsigned int n_dofs = dim * n_vertices;
        /// The entries C_ij (i <= j) of a Voigt stiffness.
        using StiffnessEntries = std::array<double, n_voigt *(n_voigt + 1) / 2>;
        template <typename T>
        using ElementMatrix = std::array<T, n_dofs * n_dofs>;

        /// Index of C_ij in a Stiffness.
        static constexpr unsigned int
        entry(const unsigned int i, const unsigned int j)
        {
          return i <= j ? i * n_voigt - i * (i - 1) / 2 + (j - i) : entry(j, i);
        }

        /// Evaluate @p stiffness on the box of every cell.
        void
        set_stiffness(const StiffnessOverBox<dim> &stiffness)
        {
          const auto &mf = *this->get_matrix_free();
          coefficient.resize(mf.n_cell_batches());
          for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
            for (unsigned int lane = 0;
                 lane < mf.n_active_entries_per_cell_batch(batch);
                 ++lane)
              {
                const auto cell = mf.get_cell_iterator(batch, lane);
                // The first and the last vertex of an axis-parallel box
                // are its lower and upper corners.
                const auto C
                  = stiffness(cell->vertex(0), cell->vertex((1 << dim) - 1));
                for (unsigned int i = 0; i < n_voigt; ++i)
                  for (unsigned int j = i; j < n_voigt; ++j)
                    coefficient[batch][entry(i, j)][lane] = C[i][j];
              }
        }

        /// sigma = C eps of a Voigt strain @p e (engineering shears), as a
        /// symmetric tensor.
        static Tensor2
        stress(const Stiffness &c, const std::array<Scalar, n_voigt> &e)
        {
          std::array<Scalar, n_voigt> s;
          for (unsigned int i = 0; i < n_voigt; ++i)
            {
              s[i] = c[entry(i, 0)] * e[0];
              for (unsigned int j = 1; j < n_voigt; ++j)
                s[i] += c[entry(i, j)] * e[j];
            }
          Tensor2 t;
          for (unsigned int i = 0; i < dim; ++i)
            {
              t[i][i] = s[i];
              for (unsigned int j = i + 1; j < dim; ++j)
                t[i][j] = s[voigt_shear<dim>(i, j)];
            }
          return t;
        }

        /// The Voigt strain of a symmetric gradient.
        static std::array<Scalar, n_voigt>
        voigt_strain(const Tensor2 &g)
        {
          std::array<Scalar, n_voigt> e;
          for (unsigned int i = 0; i < dim; ++i)
            {
              e[i] = g[i][i];
              for (unsigned int j = i + 1; j < dim; ++j)
                e[voigt_shear<dim>(i, j)] = Number(2) * g[i][j];
            }
          return e;
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
            phi.submit_symmetric_gradient(
              stress(c, voigt_strain(phi.get_symmetric_gradient(q))), q);
          phi.integrate(EvaluationFlags::gradients);
        }

        /**
         * Multilinear elements (degree 1) on the pixel or voxel grid:
         * every cell of a level is the same box, so its element matrix
         * (8 x 8 in 2D, 24 x 24 in 3D) depends on the cell's stiffness
         * only. The distinct stiffnesses (the phases on the active mesh;
         * the mixtures of coarse cells) get their element matrix once
         * (element_matrix(), in FEEvaluation's DoF order); the cell loop
         * then multiplies by it: n^2 multiply-adds per cell instead of the
         * general evaluate/integrate. MatrixFree's mapping data are not
         * needed (nor computed) for it.
         */
        void
        tabulate_element_matrices(const AffineConstraints<Number> &constraints)
        {
          if constexpr (fast_path)
            {
              const auto &mf = *this->get_matrix_free();
              std::map<StiffnessEntries, unsigned int> index_of;
              std::vector<unsigned int>                matrix_of_cell;
              element_matrices.clear();
              element_stiffness.clear();
              // (a rank may own no cell of the coarsest levels)
              if (mf.n_cell_batches() > 0)
                {
                  const auto cell = mf.get_cell_iterator(0, 0);
                  for (unsigned int d = 0; d < dim; ++d)
                    cell_size[d]
                      = cell->vertex(n_vertices - 1)[d] - cell->vertex(0)[d];
                }
              for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
                for (unsigned int lane = 0;
                     lane < mf.n_active_entries_per_cell_batch(batch);
                     ++lane)
                  {
                    StiffnessEntries key;
                    for (unsigned int k = 0; k < key.size(); ++k)
                      key[k] = coefficient[batch][k][lane];
                    const auto [it, inserted]
                      = index_of.emplace(key, element_matrices.size());
                    if (inserted)
                      {
                        const auto            K = element_matrix(key);
                        ElementMatrix<Number> k;
                        for (unsigned int i = 0; i < K.size(); ++i)
                          k[i] = Number(K[i]);
                        element_matrices.push_back(k);
                        element_stiffness.push_back(key);
                      }
                    matrix_of_cell.push_back(it->second);
                  }
              tabulate_cells(constraints, matrix_of_cell);
              // The cell loop, the diagonal and the right-hand side read
              // the element matrices and element_stiffness from here on:
              // the per-cell stiffness (21 numbers a cell in 3D, 56 B per
              // DoF in double) is not kept.
              std::vector<Stiffness>().swap(coefficient);
            }
        }

        /**
         * Degree 1, a level of the hierarchy @p depth levels above the
         * active mesh: each cell's element matrix is the Galerkin one of
         * @p galerkin (P^T K P of the fine elements it covers), instead of
         * that of the mean stiffness. Not for the active mesh (no
         * stiffness entries: no right-hand side).
         */
        template <class Galerkin>
        void
        tabulate_galerkin_matrices(Galerkin                        &galerkin,
                                   const unsigned int               depth,
                                   const AffineConstraints<Number> &constraints)
        {
          const auto                          &mf = *this->get_matrix_free();
          std::map<unsigned int, unsigned int> index_of;
          std::vector<unsigned int>            matrix_of_cell;
          element_matrices.clear();
          element_stiffness.clear();
          for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
            for (unsigned int lane = 0;
                 lane < mf.n_active_entries_per_cell_batch(batch);
                 ++lane)
              {
                const auto         cell = mf.get_cell_iterator(batch, lane);
                const unsigned int id
                  = galerkin.id(cell->vertex(0),
                                cell->vertex(n_vertices - 1),
                                depth);
                const auto [it, inserted]
                  = index_of.emplace(id, element_matrices.size());
                if (inserted)
                  {
                    const auto           &K = galerkin.matrix(depth, id);
                    ElementMatrix<Number> k;
                    for (unsigned int i = 0; i < K.size(); ++i)
                      k[i] = Number(K[i]);
                    element_matrices.push_back(k);
                  }
                matrix_of_cell.push_back(it->second);
              }
          tabulate_cells(constraints, matrix_of_cell);
        }


        /**
         * The element stiffness matrix (row-major) of a multilinear element
         * of the size cell_size with the stiffness @p c (the entries C_ij,
         * i <= j), by 2^dim-point Gauss quadrature as FEEvaluation
         * integrates it, in FEEvaluation's DoF order 2^dim component +
         * vertex (vertices lexicographic, x fastest): K = sum_q w_q B_q^T C
         * B_q, with the Voigt strain B of the shape functions: dN_v/dx_c
         * on the normal strain c of component c, and on the shear of the
         * plane (i, j) dN_v/dx_j for component i and dN_v/dx_i for
         * component j. dN_v/dx_d = (+-1 / h_d) times the product over the
         * other axes e of (xi_e or 1 - xi_e), multiplied in the order of
         * the axes.
         */
        ElementMatrix<double>
        element_matrix(const StiffnessEntries &c) const
        {
          return element_matrix(c, cell_size);
        }

        /// The same for a cell of the size @p cell_size.
        static ElementMatrix<double>
        element_matrix(const StiffnessEntries        &c,
                       const std::array<double, dim> &cell_size)
        {
          double C[n_voigt][n_voigt];
          for (unsigned int a = 0; a < n_voigt; ++a)
            for (unsigned int b = 0; b < n_voigt; ++b)
              C[a][b] = c[entry(a, b)];
          const double g[2]
            = {0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)};
          double w = 1. / n_vertices;
          for (unsigned int d = 0; d < dim; ++d)
            w *= cell_size[d];
          ElementMatrix<double> K{};
          // the quadrature points, x slowest
          for (unsigned int q = 0; q < n_vertices; ++q)
            {
              double xi[dim];
              for (unsigned int d = 0; d < dim; ++d)
                xi[d] = g[(q >> (dim - 1 - d)) & 1];
              double B[n_voigt][n_dofs] = {};
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  // the factors from x to z, left to right: in 2D
                  // (+-1 / h_x) (eta or 1 - eta) and (xi or 1 - xi) (+-1) /
                  // h_y
                  double grad[dim];
                  for (unsigned int d = 0; d < dim; ++d)
                    for (unsigned int e = 0; e < dim; ++e)
                      {
                        const double sign = ((v >> e) & 1) ? 1. : -1.;
                        const double factor
                          = ((v >> e) & 1) ? xi[e] : 1 - xi[e];
                        if (e == 0)
                          grad[d] = e == d ? sign / cell_size[e] : factor;
                        else
                          grad[d] = e == d ? grad[d] * sign / cell_size[e]
                                           : grad[d] * factor;
                      }
                  for (unsigned int i = 0; i < dim; ++i)
                    {
                      B[i][n_vertices * i + v] = grad[i];
                      for (unsigned int j = i + 1; j < dim; ++j)
                        {
                          B[voigt_shear<dim>(i, j)][n_vertices * i + v]
                            = grad[j];
                          B[voigt_shear<dim>(i, j)][n_vertices * j + v]
                            = grad[i];
                        }
                    }
                }
              for (unsigned int i = 0; i < n_dofs; ++i)
                for (unsigned int j = 0; j < n_dofs; ++j)
                  {
                    double sum = 0;
                    for (unsigned int a = 0; a < n_voigt; ++a)
                      for (unsigned int b = 0; b < n_voigt; ++b)
                        sum += B[a][i] * C[a][b] * B[b][j];
                    K[n_dofs * i + j] += w * sum;
                  }
            }
          return K;
        }

        /**
         * Degree 1: the DoFs of every cell (CellIndices) in FEEvaluation's
         * order 2^dim c + v (component-major, vertices in lexicographic
         * order; FESystem numbers them vertex by vertex, dim v + c, so
         * that the components of a vertex are consecutive, also as
         * vector-local indices: all owned or all ghosts of the same rank),
         * with its element matrix @p matrix_of_cell. Homogeneously
         * constrained DoFs (boundary and pins) are read as zero and not
         * written, as MatrixFree does. A vertex whose DoFs are periodic
         * images (each constrained to one DoF with weight 1: its master
         * vertex's) takes its master's DoFs: the cell reads and adds to
         * them, so the cell loop applies C^T K C of the periodic space
         * (the MatrixFree object holds the periodicity, so that the
         * masters are among the vector's ghosts).
         */
        void
        tabulate_cells(const AffineConstraints<Number> &constraints,
                       const std::vector<unsigned int> &matrix_of_cell)
        {
          tabulate_cell_dofs(constraints, matrix_of_cell);
          // the locally owned constrained DoFs: identity rows (added by
          // the cell loop, but for those the MatrixFree object holds as
          // constrained, the periodic images: Base::vmult() adds them)
          const auto       &mf          = *this->get_matrix_free();
          const auto       &partitioner = *mf.get_vector_partitioner();
          std::vector<bool> in_matrix_free(partitioner.locally_owned_size());
          for (const unsigned int k : mf.get_constrained_dofs())
            in_matrix_free[k] = true;
          constrained_owned.clear();
          identity_rows.clear();
          for (unsigned int k = 0; k < partitioner.locally_owned_size(); ++k)
            if (constraints.is_constrained(partitioner.local_to_global(k)))
              {
                constrained_owned.push_back(k);
                if (!in_matrix_free[k])
                  identity_rows.push_back(k);
              }
        }

        void
        tabulate_cell_dofs(const AffineConstraints<Number> &constraints,
                           const std::vector<unsigned int> &matrix_of_cell)
        {
          const auto        &mf          = *this->get_matrix_free();
          const auto        &partitioner = *mf.get_vector_partitioner();
          const unsigned int level       = mf.get_mg_level();
          cells.clear();
          cells.reserve(matrix_of_cell.size());
          std::vector<types::global_dof_index> dofs(n_dofs);
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
                for (unsigned int v = 0; v < n_vertices; ++v)
                  {
                    // a periodic image: its master vertex's DoFs
                    const bool image
                      = constraints.is_identity_constrained(dofs[dim * v]);
                    const auto master = [&](const types::global_dof_index dof) {
                      return image
                               ? (*constraints.get_constraint_entries(dof))[0]
                                   .first
                               : dof;
                    };
                    const unsigned int x
                      = partitioner.global_to_local(master(dofs[dim * v]));
                    cell_indices.vertex[v] = x;
                    for (unsigned int c = 0; c < dim; ++c)
                      {
                        const auto dof = dofs[dim * v + c];
                        AssertThrow(
                          image == constraints.is_identity_constrained(dof),
                          ExcInternalError());
                        AssertThrow(partitioner.global_to_local(master(dof))
                                      == x + c,
                                    ExcInternalError());
                        AssertThrow(
                          image || !constraints.is_constrained(dof)
                            || (constraints.get_constraint_entries(dof)->empty()
                                && constraints.get_inhomogeneity(dof) == 0),
                          ExcInternalError());
                        if (!image && constraints.is_constrained(dof))
                          cell_indices.constrained |= 1u
                                                      << (n_vertices * c + v);
                      }
                  }
                cells.push_back(cell_indices);
              }
        }

        /// Right-hand side of a unit load (see CellMultigridSolver).
        double
        assemble_rhs(VectorType                       &rhs,
                     const dealii::Tensor<1, n_voigt> &load,
                     const bool                        strain_driven) const
        {
          const auto &mf = *this->get_matrix_free();
          mf.initialize_dof_vector(rhs);
          if constexpr (fast_path)
            return assemble_rhs_bilinear(rhs, load, strain_driven);
          FEEval                      phi(mf);
          double                      scale = 0;
          std::array<Scalar, n_voigt> l;
          for (unsigned int i = 0; i < n_voigt; ++i)
            l[i] = Number(load[i]);
          for (unsigned int batch = 0; batch < mf.n_cell_batches(); ++batch)
            {
              phi.reinit(batch);
              Tensor2 s;
              if (strain_driven)
                s = -stress(coefficient[batch], l);
              else
                // the stress tensor of the Voigt stress l
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    s[i][i] = l[i];
                    for (unsigned int j = i + 1; j < dim; ++j)
                      s[i][j] = l[voigt_shear<dim>(i, j)];
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
        assemble_rhs_bilinear(VectorType                       &rhs,
                              const dealii::Tensor<1, n_voigt> &load,
                              const bool strain_driven) const
        {
          std::vector<std::array<double, n_dofs>> loads;
          for (unsigned int m = 0; m < element_matrices.size(); ++m)
            loads.push_back(element_load(element_matrices[m],
                                         element_stiffness[m],
                                         load,
                                         strain_driven,
                                         cell_size));
          double scale = 0;
          for (const CellIndices &cell : cells)
            {
              const auto &f = loads[cell.matrix];
              for (unsigned int i = 0; i < n_dofs; ++i)
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

        /// The load of one element of stiffness @p c and element matrix
        /// @p K (see assemble_rhs_bilinear()), of the size @p cell_size.
        static std::array<double, n_dofs>
        element_load(const ElementMatrix<Number>      &K,
                     const StiffnessEntries           &c,
                     const dealii::Tensor<1, n_voigt> &load,
                     const bool                        strain_driven,
                     const std::array<double, dim>    &cell_size)
        {
          dealii::Tensor<1, n_voigt> strain = load;
          if (!strain_driven)
            {
              dealii::Tensor<2, n_voigt> C;
              for (unsigned int a = 0; a < n_voigt; ++a)
                for (unsigned int b = 0; b < n_voigt; ++b)
                  C[a][b] = c[entry(a, b)];
              if constexpr (dim == 2)
                strain = invert(C) * load;
              else
                strain = invert6(C) * load;
            }
          // u_c = sum_d eps_cd x_d at the vertices, eps_cd = gamma_cd/2
          double u[n_dofs];
          for (unsigned int v = 0; v < n_vertices; ++v)
            for (unsigned int c = 0; c < dim; ++c)
              {
                double sum = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const double e = c == d
                                       ? strain[c]
                                       : 0.5 * strain[voigt_shear<dim>(c, d)];
                    const double x = ((v >> d) & 1) * cell_size[d];
                    sum            = d == 0 ? e * x : sum + e * x;
                  }
                u[n_vertices * c + v] = sum;
              }
          const double               sign = strain_driven ? -1. : 1.;
          std::array<double, n_dofs> f;
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              double sum = 0;
              for (unsigned int j = 0; j < n_dofs; ++j)
                sum += double(K[n_dofs * i + j]) * u[j];
              f[i] = sign * sum;
            }
          return f;
        }

        void
        compute_diagonal() override
        {
          if constexpr (fast_path)
            {
              // The diagonal of the assembled operator from the element
              // matrices' diagonals.
              this->inverse_diagonal_entries
                = std::make_shared<DiagonalMatrix<VectorType>>();
              VectorType &diagonal
                = this->inverse_diagonal_entries->get_vector();
              this->initialize_dof_vector(diagonal);
              for (const CellIndices &cell : cells)
                for (unsigned int i = 0; i < n_dofs; ++i)
                  if (!cell.is_constrained(i))
                    diagonal.local_element(cell.dof(i))
                      += element_matrices[cell.matrix][(n_dofs + 1) * i];
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
          if constexpr (fast_path)
            apply_add_bilinear(dst, src);
          else
            this->data->cell_loop(&ElasticityOperator::cell_range,
                                  this,
                                  dst,
                                  src);
        }

        /// Degree 1: gather, multiply by the cell's element matrix
        /// (multiply_element_matrix()), scatter; ghost values exchanged as
        /// MatrixFree's cell loop does. Constrained DoFs read 0 and are not
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
          for (const CellIndices &cell : cells)
            {
              Number x[n_dofs];
              if (cell.constrained == 0) // all but the boundary's cells
                for (unsigned int v = 0; v < n_vertices; ++v)
                  for (unsigned int c = 0; c < dim; ++c)
                    x[n_vertices * c + v] = in[cell.vertex[v] + c];
              else
                for (unsigned int i = 0; i < n_dofs; ++i)
                  x[i] = cell.is_constrained(i) ? Number(0) : in[cell.dof(i)];
              Number y[n_dofs];
              multiply_element_matrix<Number, n_dofs>(
                element_matrices[cell.matrix].data(), x, y);
              if (cell.constrained == 0)
                for (unsigned int v = 0; v < n_vertices; ++v)
                  for (unsigned int c = 0; c < dim; ++c)
                    out[cell.vertex[v] + c] += y[n_vertices * c + v];
              else
                for (unsigned int i = 0; i < n_dofs; ++i)
                  if (!cell.is_constrained(i))
                    out[cell.dof(i)] += y[i];
            }
          // constrained rows: the identity (the MatrixFree objects hold
          // no constraints but the periodicity, see MultigridCache)
          for (const unsigned int k : identity_rows)
            out[k] += in[k];
          dst.compress(VectorOperation::add);
          if (!src_had_ghosts)
            src.zero_out_ghost_values();
        }

        void
        cell_range(const MatrixFree<dim, Number>               &data,
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
        std::vector<ElementMatrix<Number>> element_matrices;
        /// Degree 1: a locally owned cell's DoFs and element matrix.
        struct CellIndices
        {
          /// vector-local index of component 0 at each vertex (component
          /// c is the c-th next one)
          std::array<unsigned int, n_vertices> vertex;
          /// index of its element matrix
          unsigned int matrix;
          /// bit 2^dim c + v: DoF (c, v) constrained
          std::uint32_t constrained;

          bool
          is_constrained(const unsigned int i) const
          {
            return (constrained >> i) & 1u;
          }
          /// vector-local index of DoF i = 2^dim c + v
          unsigned int
          dof(const unsigned int i) const
          {
            return vertex[i % n_vertices] + i / n_vertices;
          }
        };
        std::vector<CellIndices> cells;
        /// Degree 1: vector-local indices of the locally owned
        /// constrained DoFs, and of those whose identity row the cell loop
        /// adds (not the MatrixFree object's constrained DoFs).
        std::vector<unsigned int> constrained_owned, identity_rows;
        /// The stiffness entries of each element matrix, and the cells'
        /// size along each axis.
        std::vector<StiffnessEntries> element_stiffness;
        std::array<double, dim>       cell_size = {};
      };


    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
