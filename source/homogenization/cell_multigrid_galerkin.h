// The Galerkin coarse operators of the cell problems' geometric multigrid
// (issue #51 item 5, contrast-robust iteration counts): the element matrix
// of a coarse cell is P^T K P over the fine elements it covers, instead of
// the element matrix of their mean stiffness. Private to
// source/homogenization/cell_multigrid.cc.
//
// On the uniformly refined box the multilinear prolongation of a coarse
// cell's DoFs touches only the fine cells inside it, so the level operator
// A_l = P^T A_{l+1} P is assembled from element matrices
//
//     K_coarse = sum over the 2^dim children c of P_c^T K_c P_c,
//
// P_c the values of the coarse cell's multilinear shape functions at the
// vertices of child c (per component). Recursively, a cell's matrix
// depends only on the pattern of the finest elements under it, which the
// stiffness function gives: no communication, and the distinct patterns
// are few (a cell of one phase has the one rediscretized matrix: P^T K P
// of a uniform stiffness is the coarse cell's own Q1 matrix, as the
// 2^dim-point Gauss rule integrates the fine products exactly).
#ifndef tribodyn_source_homogenization_cell_multigrid_galerkin_h
#define tribodyn_source_homogenization_cell_multigrid_galerkin_h

#include "cell_multigrid_operator.h"

#include <array>
#include <map>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      template <int dim>
      class GalerkinElementMatrices
      {
        using Element = ElasticityOperator<dim, 1, double>;

      public:
        static constexpr unsigned int n_vertices = Element::n_vertices;
        static constexpr unsigned int n_dofs     = Element::n_dofs;
        static constexpr unsigned int n_voigt    = Element::n_voigt;
        using Matrix = typename Element::template ElementMatrix<double>;

        /// @p stiffness of the active elements, of the size @p fine_size.
        GalerkinElementMatrices(const StiffnessOverBox<dim>   &stiffness,
                                const std::array<double, dim> &fine_size)
            : stiffness(stiffness)
            , fine_size(fine_size)
        {
          // p[c][v][V]: coarse shape function V at vertex v of child c, in
          // the coarse cell's unit coordinates xi_e = (c_e + v_e) / 2
          for (unsigned int c = 0; c < n_vertices; ++c)
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (unsigned int V = 0; V < n_vertices; ++V)
                {
                  double value = 1;
                  for (unsigned int e = 0; e < dim; ++e)
                    {
                      const double xi = 0.5 * (((c >> e) & 1) + ((v >> e) & 1));
                      value *= ((V >> e) & 1) ? xi : 1 - xi;
                    }
                  p[c][v][V] = value;
                }
        }

        /// The index of the element matrix of the cell of corners @p lower
        /// and @p upper, @p depth levels above the active mesh (0: an
        /// active element).
        unsigned int
        id(const dealii::Point<dim> &lower,
           const dealii::Point<dim> &upper,
           const unsigned int        depth)
        {
          if (matrices.size() <= depth)
            {
              matrices.resize(depth + 1);
              children_index.resize(depth + 1);
            }
          if (depth == 0)
            {
              const auto                         C = stiffness(lower, upper);
              typename Element::StiffnessEntries key;
              for (unsigned int i = 0; i < n_voigt; ++i)
                for (unsigned int j = i; j < n_voigt; ++j)
                  key[Element::entry(i, j)] = C[i][j];
              const auto [it, inserted]
                = fine_index.emplace(key, matrices[0].size());
              if (inserted)
                matrices[0].push_back(Element::element_matrix(key, fine_size));
              return it->second;
            }
          std::array<unsigned int, n_vertices> children;
          for (unsigned int c = 0; c < n_vertices; ++c)
            {
              dealii::Point<dim> child_lower, child_upper;
              for (unsigned int e = 0; e < dim; ++e)
                {
                  const double middle = 0.5 * (lower[e] + upper[e]);
                  child_lower[e]      = ((c >> e) & 1) ? middle : lower[e];
                  child_upper[e]      = ((c >> e) & 1) ? upper[e] : middle;
                }
              children[c] = id(child_lower, child_upper, depth - 1);
            }
          const auto [it, inserted]
            = children_index[depth].emplace(children, matrices[depth].size());
          if (inserted)
            matrices[depth].push_back(restrict(children, depth - 1));
          return it->second;
        }

        const Matrix &
        matrix(const unsigned int depth, const unsigned int id) const
        {
          return matrices[depth][id];
        }

      private:
        /// sum_c P_c^T K_c P_c of the children's matrices (at @p depth),
        /// in FEEvaluation's DoF order 2^dim component + vertex.
        Matrix restrict(const std::array<unsigned int, n_vertices> &children,
                        const unsigned int                          depth) const
        {
          Matrix coarse{};
          for (unsigned int c = 0; c < n_vertices; ++c)
            {
              const Matrix &K = matrices[depth][children[c]];
              // T = K P_c (n_dofs x n_dofs), P_c block diagonal by
              // component
              std::array<double, n_dofs * n_dofs> T{};
              for (unsigned int i = 0; i < n_dofs; ++i)
                for (unsigned int b = 0; b < dim; ++b)
                  for (unsigned int V = 0; V < n_vertices; ++V)
                    {
                      double sum = 0;
                      for (unsigned int v = 0; v < n_vertices; ++v)
                        sum += K[n_dofs * i + n_vertices * b + v] * p[c][v][V];
                      T[n_dofs * i + n_vertices * b + V] = sum;
                    }
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int U = 0; U < n_vertices; ++U)
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    {
                      double sum = 0;
                      for (unsigned int u = 0; u < n_vertices; ++u)
                        sum
                          += p[c][u][U] * T[n_dofs * (n_vertices * a + u) + j];
                      coarse[n_dofs * (n_vertices * a + U) + j] += sum;
                    }
            }
          return coarse;
        }

        const StiffnessOverBox<dim>  &stiffness;
        const std::array<double, dim> fine_size;
        double                        p[n_vertices][n_vertices][n_vertices];
        std::map<typename Element::StiffnessEntries, unsigned int> fine_index;
        /// Per depth >= 1: the children's matrices -> the matrix.
        std::vector<
          std::map<std::array<unsigned int, n_vertices>, unsigned int>>
                                         children_index;
        std::vector<std::vector<Matrix>> matrices;
      };
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
