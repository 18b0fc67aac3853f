// The volume source 'fibres': random non-overlapping short fibres, aligned
// or within a cone of orientations.
#include <tribodyn/homogenization/volume_source.h>
#include <tribodyn/homogenization/volume_sources/random_inclusions.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      /// Its length, axis and cone; the common 'Radius', 'Seed' and
      /// 'Volume fraction'.
      class FibresVolume : public VolumeSource
      {
      public:
        InclusionShape shape{true, 16, 2, 0};

        void
        bind(ParameterBinding &b) override
        {
          b.add("Fibre length",
                shape.length,
                "Fibres: length in voxels (flat-ended cylinders).",
                dealii::Patterns::Double(),
                Interval{1, 1e6});
          b.add("Fibre axis",
                shape.axis,
                "Fibres: the axis they are aligned with (or, with 'Fibre cone "
                "half-angle' > 0, the axis of their cone of orientations).",
                axis_choices);
          b.add(
            "Fibre cone half-angle",
            shape.cone_angle,
            "Fibres: half-angle (degrees) of the cone about 'Fibre axis' in "
            "which the fibres' axes are drawn, uniformly over its spherical "
            "cap (the cosine of their angle to the axis uniform in [cos of "
            "the half-angle, 1], the azimuth uniform): 0 = all aligned with "
            "'Fibre axis', 90 = uniformly random orientations in 3D. Above "
            "0 the box must hold a fibre's extent plus 2 Radius + 1 voxels "
            "along every axis.",
            dealii::Patterns::Double(),
            Interval{0, 90});
        }

        VoxelVolume
        create(const VolumeMorphologyParameters &p) const override
        {
          return make_random_inclusions(p, shape);
        }

        bool
        uses_seed() const override
        {
          return true;
        }
      };
    } // namespace

    static const bool fibres_volume_registered = VolumeSources::add(
      {"fibres",
       3,
       "the same with short cylinders along 'Fibre axis', or about it "
       "within 'Fibre cone half-angle'",
       [] { return std::make_unique<FibresVolume>(); }});
  } // namespace homogenization
} // namespace tribodyn
