// The volume source 'image stack': a multi-page TIFF segmented into phases
// (its subsection 'Morphology/Image stack': ImageStackParameters).
#include <tribodyn/homogenization/image_stack.h>
#include <tribodyn/homogenization/volume_source.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class ImageStackVolume : public VolumeSource
      {
      public:
        ImageStackParameters stack;

        void
        declare_subsections(dealii::ParameterHandler &prm) const override
        {
          ImageStackParameters::declare_parameters(prm);
        }

        void
        parse(dealii::ParameterHandler &prm,
              const ParameterBinding &,
              VolumeMorphologyParameters &) override
        {
          stack.parse_parameters(prm, true);
        }

        VoxelVolume
        create(const VolumeMorphologyParameters &p) const override
        {
          return read_image_stack(stack, p.voxel_size);
        }
      };
    } // namespace

    static const bool image_stack_volume_registered = VolumeSources::add(
      {"image stack",
       5,
       "a multi-page TIFF segmented into phases, subsection 'Image stack'",
       [] { return std::make_unique<ImageStackVolume>(); }});
  } // namespace homogenization
} // namespace tribodyn
