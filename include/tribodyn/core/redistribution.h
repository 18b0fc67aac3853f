#ifndef tribodyn_core_redistribution_h
#define tribodyn_core_redistribution_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <vector>

namespace tribodyn
{
  /**
   * Restart on another number of ranks (doc/user_guide.md, "Checkpoints"):
   * records of a checkpoint written on N ranks go to the ranks of this run
   * whose part of the mesh holds their place.
   *
   * Each record is @p stride doubles, its point first (@p dim coordinates).
   * @p owned_boxes cover the cells this rank owns (from
   * GridTools::compute_mesh_predicate_bounding_box()); they are exchanged
   * once (deal.II's global description R-tree, GridTools::
   * build_global_description_tree()), and a record is sent to every rank
   * with a box holding its point within the relative tolerance 1e-9 of
   * the box's size. Points on the border of two ranks' parts reach both:
   * the receiver keeps what it owns (the caller's test) and the callers
   * check the global counts. Returns the records received, flat, in the
   * order of the sending ranks.
   */
  template <int dim>
  std::vector<double>
  route_records_by_point(
    const std::vector<double>                   &records,
    const unsigned int                           stride,
    const std::vector<dealii::BoundingBox<dim>> &owned_boxes,
    const MPI_Comm                               comm);
} // namespace tribodyn

#endif
