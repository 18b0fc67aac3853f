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
    /// The 3D morphology sources.
    using VolumeSources = SourceRegistry<VolumeSource>;

    /// The axis choices 'x', 'y', 'z' of the sources' entries.
    inline constexpr SelectionTable<unsigned int, 3> axis_choices{
      {{"x", 0u}, {"y", 1u}, {"z", 2u}}};
  } // namespace homogenization
} // namespace tribodyn

#endif
