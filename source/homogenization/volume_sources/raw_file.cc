// The volume source 'raw file': material ids read from a raw volume with a
// header (VoxelVolume::read_raw()).
#include <tribodyn/core/errors.h>
#include <tribodyn/homogenization/volume_source.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class RawFileVolume : public VolumeSource
      {
      public:
        /// Path of the header file.
        std::string header;

        void
        bind(ParameterBinding &b) override
        {
          b.add("Raw header",
                header,
                "Raw file: the header file of the volume (lines 'size = nx ny "
                "nz', 'voxel size = h' or 'hx hy hz' in m, 'type = uint8', "
                "'file = NAME' relative to the header); the raw file holds one "
                "material id per voxel, x fastest, then y, then z.",
                dealii::Patterns::FileName());
        }

        void
        parse(dealii::ParameterHandler &,
              const ParameterBinding &b,
              VolumeMorphologyParameters &) override
        {
          check_parameter(!header.empty(),
                          b.path("Raw header"),
                          "give the header file of the raw volume ('Generator "
                          "= raw file' reads it).");
        }

        VoxelVolume
        create(const VolumeMorphologyParameters &) const override
        {
          return VoxelVolume::read_raw(header);
        }
      };
    } // namespace

    static const bool raw_file_volume_registered = VolumeSources::add(
      {"raw file",
       4,
       "material ids read from the raw volume that 'Raw header' describes",
       [] { return std::make_unique<RawFileVolume>(); }});
  } // namespace homogenization
} // namespace tribodyn
