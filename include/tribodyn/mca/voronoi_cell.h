// Convex Voronoi cells of automata (issue #18: volumes and contact areas of
// a packing with automata of several sizes).
#ifndef tribodyn_mca_voronoi_cell_h
#define tribodyn_mca_voronoi_cell_h

#include <tribodyn/mca/vector_algebra.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * A convex polyhedron around an automaton at the origin, cut down to its
     * Voronoi cell by the bisector planes of its neighbours (voro++'s
     * approach: start from a bounding cell, clip by one half-space per
     * neighbour). Each face carries the tag of the plane that made it: the
     * neighbour's index, or -1 for the bounding cell (a free surface).
     *
     * In a uniform FCC packing of automata of size d the cell of an
     * interior automaton is the rhombic dodecahedron of the lattice:
     * volume d³/√2 and 12 faces of area d²/(2√2), the V and S of
     * doc/theory/mca.md §1. With automata of several sizes the Voronoi
     * cells tile the space (mass is conserved), each cell is closed
     * (Σ_faces S n = 0: a homogeneous stress puts no net force on an
     * interior automaton) and the pair vectors r = 2 h n of the shared
     * faces satisfy Σ_pairs S r ⊗ n = V_total I (the virial of a homogeneous
     * stress is exact): the properties the pair law needs across a
     * transition between sizes (test mca_voronoi).
     */
    class VoronoiCell
    {
    public:
      /// The rhombic dodecahedron of an FCC lattice of automata of size
      /// @p size (faces at distance size/2 along the 12 directions
      /// (±1, ±1, 0)/√2 and their permutations), tag -1.
      explicit VoronoiCell(const double size);

      /// Keep the half-space n·x <= @p distance (@p n a unit vector); the
      /// new face gets @p tag. Cuts that remove nothing are ignored.
      void
      clip(const Vec3 &n, const double distance, const int tag);

      /// Clip by the bisector plane of a neighbour at @p r (relative
      /// position), tagged @p tag.
      void
      clip_by_neighbour(const Vec3 &r, const int tag);

      /// Volume of the cell.
      double
      volume() const;

      /// Area of the faces of each tag (tags in increasing order, faces of
      /// one tag summed; faces of negligible area omitted).
      std::vector<std::pair<int, double>>
      face_areas() const;

      /// Area and centroid of the faces of each tag (as face_areas(); the
      /// centroid of the faces of one tag together).
      struct FaceGeometry
      {
        int    tag;
        double area;
        Vec3   centroid;
      };
      std::vector<FaceGeometry>
      face_geometry() const;

      /// Largest distance of a vertex from the origin (a neighbour farther
      /// than twice this cannot cut the cell).
      double
      radius() const;

    private:
      struct Face
      {
        std::vector<Vec3> vertices; ///< ordered around the face
        int               tag;
      };
      std::vector<Face> faces;
      double            scale; ///< length scale of the tolerances
    };
  } // namespace mca
} // namespace tribodyn

#endif
