#ifndef tribodyn_homogenization_volume_sources_random_inclusions_h
#define tribodyn_homogenization_volume_sources_random_inclusions_h

#include <tribodyn/homogenization/voxel_volume.h>

namespace tribodyn
{
  namespace homogenization
  {
    /// The inclusions of make_random_inclusions(): spheres, or fibres of a
    /// length (voxels) along an axis (0 = x, 1 = y, 2 = z), within a cone
    /// of half-angle cone_angle (degrees) about it when it is above 0.
    struct InclusionShape
    {
      bool         fibres     = false;
      double       length     = 0;
      unsigned int axis       = 2;
      double       cone_angle = 0;
    };

    /**
     * The volume of the sources 'spheres' and 'fibres' (@p shape), of
     * radius, seed and volume fraction from @p p.
     *
     * Random sequential addition of inclusions in the periodic box:
     * spheres of radius r, or (fibres) cylinders of radius r and length
     * l along the axis a, all in voxels. Centres are uniform; a
     * candidate is kept when its distance to every kept inclusion is at
     * least 2 r + 1 voxels (minimum image; for fibres the distance of
     * the axis segments, sqrt(p^2 + max(0, |d_a| - l)^2) with p the
     * distance across the axis and d_a along it), so that no two share a
     * voxel face; inclusions are added until their volume, 4/3 pi r^3
     * or pi r^2 l each, reaches the target fraction. A voxel is
     * heterogeneity when its centre lies inside one (minimum image):
     * an inclusion cut by a face reappears at the opposite one.
     *
     * Misaligned fibres ('Fibre cone half-angle' alpha > 0): each
     * candidate also draws its unit axis n in the cone of half-angle
     * alpha about a (cone_direction(), from a second generator seeded
     * from the seed through std::seed_seq, so that the centres are those
     * of the aligned generator), the distance of two fibres is the distance
     * of their axis segments (segment_distance2()) over the 27 periodic
     * images next to the minimum image, and a voxel is fibre when its centre
     * x has |(x - c).n| <= l/2 and |x - c|^2 - ((x - c).n)^2 <= r^2. The box
     * must hold l |n_d| + 2 r + 1 voxels along every axis d (l along a, l
     * sin(alpha) across), so that no fibre comes within 2 r + 1 of its own
     * periodic image and the 27 images hold the nearest one.
     */
    VoxelVolume
    make_random_inclusions(const VolumeMorphologyParameters &p,
                           const InclusionShape             &shape);
  } // namespace homogenization
} // namespace tribodyn

#endif
