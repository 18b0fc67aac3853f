// The FCC packing of the automata (source/mca/packing.cc).
#ifndef tribodyn_mca_packing_h
#define tribodyn_mca_packing_h

#include <cstdint>
#include <functional>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/vector_algebra.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /// One automaton of the packing.
    struct PackedAutomaton
    {
      Point3        position;
      std::uint32_t id       = 0; ///< index of the FCC lattice site
      unsigned char material = 0;
      unsigned char body     = 0;
      /// 1: in a contacting part of Geometry/Inclusions; 2: in a part and
      /// converted by an inclusion (cylinder or void: voids are not added).
      unsigned char part = 0;
      /// Size 2^level d (Geometry/Size bands).
      unsigned char level = 0;
      /// Near a change of size (GeometryParameters::near_size_change): its
      /// volume and areas come from its Voronoi cell.
      bool transitional = false;
    };

    /**
     * FCC packing of the bodies with the regions applied, restricted to the
     * automata whose (final) position lies in the box [@p lower, @p upper):
     * the lattice sites of that box only are enumerated, so that each rank
     * packs its own cells. The id of an automaton is the index of its
     * lattice site (the same on any partition). Regions are tested with
     * their periodic images.
     *
     * @p continued: the sites of the lattice continued beyond the bodies
     * and the box's non-periodic sides, as if everything were filled
     * (no bodies, regions or inclusions; the band at the bodies' top or
     * bottom goes on; the upper body of a rough interface still moved by
     * its gap and shift): the Voronoi cells of automata on a free surface
     * are those of the continued lattice, as a surface automaton of a
     * uniform lattice keeps its whole dodecahedron. Sites outside the
     * box's lattice get the id outside_lattice.
     */
    void
    pack_box(const GeometryParameters                           &geometry,
             const Point3                                       &lower,
             const Point3                                       &upper,
             const std::function<void(const PackedAutomaton &)> &add,
             const bool continued = false);

    /// Id of a site of the continued lattice outside the box.
    constexpr std::uint32_t outside_lattice = 0xffffffffu;

    /**
     * Largest rise max_{x,y} [h(x, y) - h(x, y - @p shift_y)] of the rough
     * surface of @p geometry over its shifted copy (0 without a rough
     * interface): the upper body of the staged friction loading, shifted by
     * @p shift_y and lifted by more than this plus d, touches nowhere.
     */
    double
    rough_surface_rise(const GeometryParameters &geometry,
                       const double              shift_y);

    /// Lowest and highest z of the rough interface of @p geometry (its
    /// height plus the amplitude times the surface's extremes, before the
    /// upper body is lifted).
    std::pair<double, double>
    rough_surface_range(const GeometryParameters &geometry);

    /// The whole packing (tests and small scenes), in id order.
    std::vector<PackedAutomaton>
    pack_automata(const GeometryParameters &geometry,
                  const unsigned int        n_materials);
  } // namespace mca
} // namespace tribodyn

#endif
