#ifndef tribodyn_homogenization_volume_source_h
#define tribodyn_homogenization_volume_source_h

#include <deal.II/base/parameter_handler.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/homogenization/voxel_volume.h>

namespace tribodyn
{
  namespace homogenization
  {
    /**
     * One way to make the voxel volume of the subsection "Morphology" of
     * the 3D problem (a generator or a file reader), with its own
     * parameters: the 3D counterpart of MorphologySource. A source is one
     * file in `source/homogenization/volume_sources/` that registers
     * itself in VolumeSources.
     */
    class VolumeSource
    {
    public:
      virtual ~VolumeSource() = default;

      /// Bind its own entries of "Morphology" in @p b (every source's are
      /// declared; the chosen one's are read).
      virtual void
      bind(ParameterBinding &b);

      /// Declare its subsections of "Morphology" (the handler at the top
      /// level), if it has any.
      virtual void
      declare_subsections(dealii::ParameterHandler &prm) const;

      /// After its entries are read, when it is chosen: read its
      /// subsections and check its values against the common ones of
      /// @p common (@p b: the subsection's binding, for the paths in
      /// messages).
      virtual void
      parse(dealii::ParameterHandler         &prm,
            const ParameterBinding           &b,
            const VolumeMorphologyParameters &common);

      /// The volume.
      virtual VoxelVolume
      create(const VolumeMorphologyParameters &common) const = 0;
    };

    /// The 3D morphology sources.
    using VolumeSources = SourceRegistry<VolumeSource>;

    /// The axis choices 'x', 'y', 'z' of the sources' entries.
    inline constexpr SelectionTable<unsigned int, 3> axis_choices{
      {{"x", 0u}, {"y", 1u}, {"z", 2u}}};
  } // namespace homogenization
} // namespace tribodyn

#endif
