#ifndef tribodyn_core_redistribution_h
#define tribodyn_core_redistribution_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/rtree.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  /**
   * Restart on another number of ranks (doc/user_guide.md, "Checkpoints"):
   * records of a checkpoint written on N ranks go to the ranks of this run
   * whose part of the mesh holds their place.
   *
   * Built once (collective): the boxes of the cells this rank owns, merged
   * at refinement level @p box_level (GridTools::
   * compute_mesh_predicate_bounding_box()), widened by 1e-9 of their size
   * so that a point on a face is inside, and exchanged into deal.II's
   * global description R-tree (GridTools::build_global_description_tree()).
   */
  template <int dim>
  class PointRouter
  {
  public:
    PointRouter(const dealii::Triangulation<dim> &mesh,
                const unsigned int                box_level,
                const MPI_Comm                    comm);

    /**
     * Collective: send each record (@p stride doubles, its point first,
     * @p dim coordinates) to every rank with a box holding its point. Points
     * on the border of two ranks' parts reach both: the receiver keeps what
     * it owns (the caller's test) and the callers check the global counts.
     * Returns the records received, flat, in the order of the sending
     * ranks.
     */
    std::vector<double>
    route(const std::vector<double> &records, const unsigned int stride) const;

  private:
    MPI_Comm                                                         comm;
    dealii::RTree<std::pair<dealii::BoundingBox<dim>, unsigned int>> tree;
  };
} // namespace tribodyn

#endif
