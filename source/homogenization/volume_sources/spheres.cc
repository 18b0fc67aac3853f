// The volume source 'spheres': random non-overlapping spheres.
#include <tribodyn/homogenization/volume_source.h>
#include <tribodyn/homogenization/volume_sources/random_inclusions.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      /// Of the common 'Radius', 'Seed' and 'Volume fraction'.
      class SpheresVolume : public VolumeSource
      {
      public:
        VoxelVolume
        create(const VolumeMorphologyParameters &p) const override
        {
          return make_random_inclusions(p, InclusionShape());
        }

        bool
        uses_seed() const override
        {
          return true;
        }
      };
    } // namespace

    static const bool spheres_volume_registered = VolumeSources::add(
      {"spheres",
       2,
       "random non-overlapping spheres of the heterogeneity, placed "
       "periodically",
       [] { return std::make_unique<SpheresVolume>(); }});
  } // namespace homogenization
} // namespace tribodyn
