#ifndef tribodyn_mca_inclusions_h
#define tribodyn_mca_inclusions_h

#include <array>
#include <cstdint>
#include <deal.II/base/point.h>
#include <memory>
#include <string>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * A simple shape of the inclusion generator: a carbon cylinder (axis
     * from a to b, flat ends, as Region::Shape::cylinder) or a void sphere
     * (centre a; b == a).
     */
    struct Inclusion
    {
      enum class Shape
      {
        cylinder,
        sphere
      };
      Shape            shape = Shape::cylinder;
      dealii::Point<3> a, b;
      double           radius = 0;

      /// Is @p p inside (boundary included)?
      bool
      contains(const dealii::Point<3> &p) const;
      /// Volume of the whole shape.
      double
      volume() const;
      /// Axis-aligned bounding box [lower, upper] of the shape (exact for
      /// flat-ended cylinders: the end disks reach R sqrt(1 - u_d^2)
      /// beyond the axis ends along direction d).
      std::pair<dealii::Point<3>, dealii::Point<3>>
      bounding_box() const;
    };


    /// Orientation of the cylinder axes.
    enum class InclusionOrientation
    {
      isotropic, ///< uniform on the unit sphere
      x,
      y,
      z
    };


    /// "isotropic", "x", "y" or "z"; anything else is an InputError naming
    /// @p parameter_name.
    InclusionOrientation
    parse_inclusion_orientation(const std::string &text,
                                const std::string &parameter_name);


    /**
     * What to generate. Defaults: seed 000 section 2.2 (cylinders of radius
     * 10 nm and length 70 nm, about 2 % of the contacting part; voids off).
     * Error messages name the parameters by the strings in @p names so that
     * the driver can pass its own prm paths.
     */
    struct InclusionParameters
    {
      /// The box (a contacting part); in periodic directions its size is
      /// the period. Inclusions stay wholly inside it in non-periodic
      /// directions and may cross the faces in periodic ones.
      dealii::Point<3>    lower, upper;
      std::array<bool, 3> periodic = {{false, false, false}};

      double               cylinder_radius = 10e-9;
      double               cylinder_length = 70e-9;
      InclusionOrientation orientation     = InclusionOrientation::isotropic;
      double               cylinder_volume_fraction = 0.02;

      double void_radius          = 20e-9;
      double void_volume_fraction = 0;

      /// Minimum clearance between the surfaces of any two shapes (in
      /// addition to the axis-distance bound 2R; e.g. one automaton size so
      /// that inclusions are separated by matrix automata).
      double gap = 0;

      std::uint64_t seed = 1;
      /// Consecutive rejected trial positions after which one shape is
      /// declared impossible to place (InputError naming the fraction).
      unsigned int max_attempts = 20000;

      /// Parameter names used in error messages.
      struct Names
      {
        std::string cylinder_radius          = "Cylinder radius";
        std::string cylinder_length          = "Cylinder length";
        std::string cylinder_volume_fraction = "Cylinder volume fraction";
        std::string void_radius              = "Void radius";
        std::string void_volume_fraction     = "Void volume fraction";
        std::string gap                      = "Gap";
      } names;
    };


    /**
     * The generated shapes. Primary shapes (one per placed inclusion, their
     * centre inside the box) come first: cylinders, then voids. Then the
     * periodic images of primaries whose bounding box crosses a periodic
     * face: the primary shifted by -+period in each combination of the
     * periodic directions where the shifted bounding box still meets the
     * closed box. A membership test of any point of the box thus needs only
     * the listed shapes.
     */
    struct InclusionSet
    {
      std::vector<Inclusion> shapes;
      /// For each shape, the index of its primary (itself for primaries).
      std::vector<unsigned int> primary;
      unsigned int              n_cylinders = 0, n_voids = 0;
      /// Achieved volume fractions of the box, exact: every primary lies
      /// wholly in the box in non-periodic directions and its parts beyond
      /// a periodic face re-enter through its images (non-overlapping), so
      /// the volume inside the box is n * pi R^2 L (n * 4/3 pi R^3).
      double cylinder_volume_fraction = 0, void_volume_fraction = 0;
    };


    /**
     * Random sequential addition of non-overlapping cylinders, then voids.
     * The number of cylinders is round(target * V_box / (pi R^2 L)) (so the
     * achieved fraction is within half a cylinder of the target), likewise
     * for voids. Non-overlap, for all pairs including periodic images and
     * a shape with its own images: cylinder axes at segment-segment
     * distance >= 2 R + gap (a sufficient condition for flat-ended
     * cylinders), sphere centre to axis >= R_s + R + gap, sphere centres
     * >= 2 R_s + gap.
     *
     * Random numbers: std::mt19937_64 seeded with @p seed, mapped to [0, 1)
     * by the top 53 bits (no std::*_distribution, whose algorithms differ
     * between standard libraries); isotropic directions by rejection from
     * the cube (no trigonometric functions), so results are identical on
     * every platform with IEEE doubles.
     *
     * InputError (naming the parameter) when: a radius, length or fraction
     * is out of range; a shape does not fit in the box; a periodic size is
     * smaller than L + 2R + gap (images beyond the nearest one would be
     * needed); the target fraction is positive but smaller than one shape;
     * or a shape cannot be placed within max_attempts trials (target too
     * dense for random sequential addition).
     */
    InclusionSet
    generate_inclusions(const InclusionParameters &parameters);


    /**
     * Uniform-grid index over a set of shapes for membership queries in
     * O(number of shapes near the point). Each cell lists the shapes whose
     * bounding box meets it. Points are first wrapped into the box in the
     * periodic directions (so a rank can query lattice sites anywhere, as
     * long as its periodic directions match the generator's); points
     * outside the box in non-periodic directions use the nearest cell.
     */
    class InclusionIndex
    {
    public:
      /// @p cell_size <= 0 chooses twice the largest radius (at most
      /// 2^21 cells; larger cells beyond that).
      InclusionIndex(const std::vector<Inclusion> &shapes,
                     const dealii::Point<3>       &lower,
                     const dealii::Point<3>       &upper,
                     const std::array<bool, 3>    &periodic,
                     const double                  cell_size = 0);

      /// Index (into the shapes) of a shape containing @p p, or -1.
      int
      find(const dealii::Point<3> &p) const;

      /// The shapes listed in the cell of @p p (candidates).
      const std::vector<unsigned int> &
      candidates(const dealii::Point<3> &p) const;

      /// Fraction of the box covered by the shapes, by Monte Carlo with
      /// @p n_samples points (statistical error about
      /// sqrt(f (1 - f) / n_samples)); a check of the exact fractions.
      double
      monte_carlo_volume_fraction(const unsigned int  n_samples,
                                  const std::uint64_t seed) const;

    private:
      std::vector<Inclusion>                 shapes;
      dealii::Point<3>                       lower, upper;
      std::array<bool, 3>                    periodic;
      std::array<unsigned int, 3>            n_cells;
      std::array<double, 3>                  cell_width;
      std::vector<std::vector<unsigned int>> cells;

      dealii::Point<3>
      wrap(const dealii::Point<3> &p) const;
      std::size_t
      cell_of(const dealii::Point<3> &wrapped) const;
    };


    /**
     * The inclusions of the packing (Geometry/Inclusions): per contacting
     * part, the generated shapes, their index, the body whose automata they
     * convert and the part's z-range (positions before the interface gap
     * and shift).
     */
    struct InclusionLayout
    {
      struct Part
      {
        unsigned int                    body    = 0;
        double                          z_lower = 0, z_upper = 0;
        InclusionSet                    set;
        std::unique_ptr<InclusionIndex> index;
      };
      std::vector<Part> parts;
      /// Material given to automata inside a cylinder.
      int material = 1;

      /// Is the site @p p of body @p body in a contacting part?
      bool
      in_part(const dealii::Point<3> &p, const unsigned int body) const;
      /// For a site of body @p body: -1 not in a shape, 0 in a cylinder,
      /// 1 in a void.
      int
      shape_at(const dealii::Point<3> &p, const unsigned int body) const;
    };


    /// Closest distance between segments [p0, p1] and [q0, q1].
    double
    segment_segment_distance(const dealii::Point<3> &p0,
                             const dealii::Point<3> &p1,
                             const dealii::Point<3> &q0,
                             const dealii::Point<3> &q1);
  } // namespace mca
} // namespace tribodyn

#endif
