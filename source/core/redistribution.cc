// Records of a checkpoint sent to the ranks owning their place (restart on
// another number of ranks).
#include <algorithm>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/rtree.h>
#include <map>
#include <tribodyn/core/redistribution.h>

namespace tribodyn
{
  template <int dim>
  std::vector<double>
  route_records_by_point(
    const std::vector<double>                   &records,
    const unsigned int                           stride,
    const std::vector<dealii::BoundingBox<dim>> &owned_boxes,
    const MPI_Comm                               comm)
  {
    namespace bgi = boost::geometry::index;
    // Boxes widened by 1e-9 of their size: a point on a face is inside.
    std::vector<dealii::BoundingBox<dim>> boxes;
    for (const auto &box : owned_boxes)
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
        boxes.emplace_back(corners);
      }
    const auto tree
      = dealii::GridTools::build_global_description_tree(boxes, comm);

    std::map<unsigned int, std::vector<double>>                    out;
    std::vector<std::pair<dealii::BoundingBox<dim>, unsigned int>> hits;
    for (std::size_t o = 0; o + stride <= records.size(); o += stride)
      {
        dealii::Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = records[o + d];
        hits.clear();
        tree.query(bgi::intersects(p), std::back_inserter(hits));
        std::vector<unsigned int> ranks;
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


  template std::vector<double>
  route_records_by_point<2>(const std::vector<double> &,
                            const unsigned int,
                            const std::vector<dealii::BoundingBox<2>> &,
                            const MPI_Comm);
  template std::vector<double>
  route_records_by_point<3>(const std::vector<double> &,
                            const unsigned int,
                            const std::vector<dealii::BoundingBox<3>> &,
                            const MPI_Comm);
} // namespace tribodyn
