// Periodic cell problems on the geometric multigrid of multilinear
// elements (issue #51 item 3): the periodicity of every level of the voxel
// (pixel) hierarchy, and the level transfer between the periodic spaces.
// The operator's part (an image's DoFs replaced by its master's in the cell
// table) is ElasticityOperator::tabulate_cell_dofs(); the theory is in
// doc/theory/homogenization.md, "Solver". Private to
// source/homogenization/cell_multigrid.cc.
#ifndef tribodyn_source_homogenization_cell_multigrid_periodic_h
#define tribodyn_source_homogenization_cell_multigrid_periodic_h

#include "cell_multigrid_operator.h"

#include <array>
#include <cmath>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mg_level_object.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      using dealii::DoFHandler;
      using dealii::IndexSet;
      using dealii::MGLevelObject;
      using dealii::MGTransferMatrixFree;

      /**
       * Periodicity on level @p level of a box mesh with periodic faces:
       * the DoFs of each locally relevant vertex on an upper face
       * constrained to those of its image with every such coordinate on
       * the lower face (0), the vertex DoFTools::
       * make_periodicity_constraints() chains it to on the active mesh
       * (there, too, the upper faces' DoFs are the images: measured).
       * Found by the vertices' lattice coordinates (every cell of a
       * level is the same box), the same on every rank; the images of
       * the locally owned cells' vertices are among the level's ghosts
       * (the periodic faces are registered with the triangulation).
       */
      template <int dim>
      AffineConstraints<double>
      level_periodicity(const DoFHandler<dim> &dofs,
                        const unsigned int     level,
                        const IndexSet        &relevant)
      {
        const auto &tria = dofs.get_triangulation();
        // the coarse cells exist on every rank: the box and the size of
        // this level's cells
        std::array<double, dim> upper{}, h{};
        for (const auto &cell : tria.cell_iterators_on_level(0))
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              upper[d] = std::max(upper[d], cell->vertex(v)[d]);
        const auto            coarse = tria.begin(0);
        std::array<long, dim> n{};
        for (unsigned int d = 0; d < dim; ++d)
          {
            h[d] = (coarse->vertex((1 << dim) - 1)[d] - coarse->vertex(0)[d])
                   / double(1u << level);
            n[d] = std::lround(upper[d] / h[d]);
          }
        using Key = std::array<long, dim>;
        std::map<Key, std::array<types::global_dof_index, dim>> vertex_dofs;
        std::set<Key>                                           owned;
        std::vector<types::global_dof_index>                    cell_dofs(
          dofs.get_fe().n_dofs_per_cell());
        for (const auto &cell : dofs.mg_cell_iterators_on_level(level))
          if (cell->level_subdomain_id() != numbers::artificial_subdomain_id)
            {
              cell->get_mg_dof_indices(cell_dofs);
              for (const unsigned int v : cell->vertex_indices())
                {
                  Key key;
                  for (unsigned int d = 0; d < dim; ++d)
                    key[d] = std::lround(cell->vertex(v)[d] / h[d]);
                  // only the faces' vertices are images or masters
                  bool on_face = false;
                  for (unsigned int d = 0; d < dim; ++d)
                    on_face = on_face || key[d] == 0 || key[d] == n[d];
                  if (!on_face)
                    continue;
                  auto &entry = vertex_dofs[key];
                  for (unsigned int c = 0; c < dim; ++c)
                    entry[c] = cell_dofs[dim * v + c];
                  if (cell->is_locally_owned_on_level())
                    owned.insert(key);
                }
            }
        AffineConstraints<double> periodicity(relevant);
        for (const auto &[key, image_dofs] : vertex_dofs)
          {
            Key  master = key;
            bool image  = false;
            for (unsigned int d = 0; d < dim; ++d)
              if (key[d] == n[d])
                {
                  master[d] = 0;
                  image     = true;
                }
            if (!image)
              continue;
            const auto found = vertex_dofs.find(master);
            if (found == vertex_dofs.end())
              {
                AssertThrow(owned.count(key) == 0,
                            ExcMessage("The periodic image of a locally "
                                       "owned vertex is not among the "
                                       "level's ghosts."));
                continue;
              }
            for (unsigned int c = 0; c < dim; ++c)
              {
                periodicity.add_line(image_dofs[c]);
                periodicity.add_entry(image_dofs[c], found->second[c], 1.);
              }
          }
        periodicity.close();
        return periodicity;
      }


      /// The lines of @p constraints that are periodic images (one entry
      /// of weight 1, no inhomogeneity).
      inline AffineConstraints<double>
      periodic_lines(const AffineConstraints<double> &constraints)
      {
        AffineConstraints<double> lines(constraints.get_local_lines());
        for (const auto &line : constraints.get_lines())
          if (line.entries.size() == 1 && line.entries[0].second == 1.
              && line.inhomogeneity == 0)
            {
              lines.add_line(line.index);
              lines.add_entry(line.index, line.entries[0].first, 1.);
            }
        lines.close();
        return lines;
      }


      /**
       * The matrix-free level transfer of a periodic problem. The level
       * operators act on the periodic space: a periodic image's DoF is
       * kept at zero and its cells read and write its master's
       * (ElasticityOperator::tabulate_cell_dofs()). Prolongation is that
       * of deal.II after the coarse images take their masters' values
       * (the coarse function made periodic), the fine images set to zero
       * after it; restriction, its transpose: deal.II's of the fine
       * vector with its images at zero, then each coarse image's value
       * folded into its master.
       */
      template <int dim, typename Number>
      class PeriodicTransfer : public MGTransferMatrixFree<dim, Number>
      {
      public:
        using VectorType = LinearAlgebra::distributed::Vector<Number>;
        using Base       = MGTransferMatrixFree<dim, Number>;
        using Base::Base;

        /// The owned images of each level (vector-local index) with their
        /// masters (owned or ghosts) in the vectors @p init makes (the
        /// level operators'), from the levels' @p periodicity
        /// (level_periodicity()).
        void
        set_images(
          const std::function<void(const unsigned int, VectorType &)> &init,
          const std::vector<AffineConstraints<double>> &periodicity)
        {
          const unsigned int n_levels = periodicity.size();
          periodic                    = true;
          images.resize(0, n_levels - 1);
          scratch.resize(0, n_levels - 1);
          for (unsigned int level = 0; level < n_levels; ++level)
            {
              init(level, scratch[level]);
              const auto &partitioner = *scratch[level].get_partitioner();
              images[level].clear();
              for (const auto &line : periodicity[level].get_lines())
                if (partitioner.in_local_range(line.index)
                    && line.entries.size() == 1)
                  images[level].emplace_back(
                    partitioner.global_to_local(line.index),
                    partitioner.global_to_local(line.entries[0].first));
            }
        }

        void
        prolongate(const unsigned int to_level,
                   VectorType        &dst,
                   const VectorType  &src) const override
        {
          if (!periodic)
            return Base::prolongate(to_level, dst, src);
          dst = Number(0);
          prolongate_and_add(to_level, dst, src);
        }

        void
        prolongate_and_add(const unsigned int to_level,
                           VectorType        &dst,
                           const VectorType  &src) const override
        {
          if (!periodic)
            return Base::prolongate_and_add(to_level, dst, src);
          VectorType &coarse = scratch[to_level - 1];
          coarse.copy_locally_owned_data_from(src);
          coarse.update_ghost_values();
          for (const auto &[image, master] : images[to_level - 1])
            coarse.local_element(image) = coarse.local_element(master);
          coarse.zero_out_ghost_values();
          coarse.update_ghost_values();
          Base::prolongate_and_add(to_level, dst, coarse);
          for (const auto &[image, master] : images[to_level])
            dst.local_element(image) = 0;
        }

        void
        restrict_and_add(const unsigned int from_level,
                         VectorType        &dst,
                         const VectorType  &src) const override
        {
          if (!periodic)
            return Base::restrict_and_add(from_level, dst, src);
          VectorType &fine = scratch[from_level];
          fine.copy_locally_owned_data_from(src);
          for (const auto &[image, master] : images[from_level])
            fine.local_element(image) = 0;
          VectorType &coarse = scratch[from_level - 1];
          coarse             = Number(0);
          Base::restrict_and_add(from_level, coarse, fine);
          coarse.zero_out_ghost_values();
          for (const auto &[image, master] : images[from_level - 1])
            {
              coarse.local_element(master) += coarse.local_element(image);
              coarse.local_element(image) = 0;
            }
          coarse.compress(VectorOperation::add);
          for (unsigned int k = 0; k < coarse.locally_owned_size(); ++k)
            dst.local_element(k) += coarse.local_element(k);
        }

      private:
        bool periodic = false;
        MGLevelObject<std::vector<std::pair<unsigned int, unsigned int>>>
                                          images;
        mutable MGLevelObject<VectorType> scratch;
      };
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
