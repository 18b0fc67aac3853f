// Records of a checkpoint sent to the ranks owning their place (restart on
// another number of ranks).
#include <algorithm>
#include <deal.II/grid/grid_tools.h>
#include <map>
#include <tribodyn/core/redistribution.h>

namespace tribodyn
{
  namespace
  {
    template <int dim>
    std::vector<dealii::BoundingBox<dim>>
    owned_boxes(const dealii::Triangulation<dim> &mesh,
                const unsigned int                box_level)
    {
      const auto boxes = dealii::GridTools::compute_mesh_predicate_bounding_box(
        mesh,
        std::function<bool(
          const typename dealii::Triangulation<dim>::active_cell_iterator &)>(
          [](const auto &cell) { return cell->is_locally_owned(); }),
        box_level,
        true,
        64);
      std::vector<dealii::BoundingBox<dim>> widened;
      for (const auto &box : boxes)
        {
          auto   corners = box.get_boundary_points();
          double size    = 0;
          for (unsigned int d = 0; d < dim; ++d)
            size = std::max(size, corners.second[d] - corners.first[d]);
          for (unsigned int d = 0; d < dim; ++d)
            {
              corners.first[d] -= 1e-9 * size;
              corners.second[d] += 1e-9 * size;
            }
          widened.emplace_back(corners);
        }
      return widened;
    }
  } // namespace


  template <int dim>
  PointRouter<dim>::PointRouter(const dealii::Triangulation<dim> &mesh,
                                const unsigned int                box_level,
                                const MPI_Comm                    comm)
      : comm(comm)
      , tree(dealii::GridTools::build_global_description_tree(
          owned_boxes(mesh, box_level),
          comm))
  {
  }


  template <int dim>
  std::vector<double>
  PointRouter<dim>::route(const std::vector<double> &records,
                          const unsigned int         stride) const
  {
    namespace bgi = boost::geometry::index;
    std::map<unsigned int, std::vector<double>>                    out;
    std::vector<std::pair<dealii::BoundingBox<dim>, unsigned int>> hits;
    std::vector<unsigned int>                                      ranks;
    for (std::size_t o = 0; o + stride <= records.size(); o += stride)
      {
        dealii::Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = records[o + d];
        hits.clear();
        tree.query(bgi::intersects(p), std::back_inserter(hits));
        ranks.clear();
        for (const auto &hit : hits)
          ranks.push_back(hit.second);
        std::sort(ranks.begin(), ranks.end());
        ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
        for (const unsigned int r : ranks)
          {
            auto &buf = out[r];
            buf.insert(buf.end(),
                       records.begin() + o,
                       records.begin() + o + stride);
          }
      }
    const auto          in = dealii::Utilities::MPI::some_to_some(comm, out);
    std::vector<double> received;
    for (const auto &entry : in)
      received.insert(received.end(), entry.second.begin(), entry.second.end());
    return received;
  }


  template class PointRouter<2>;
  template class PointRouter<3>;
} // namespace tribodyn
