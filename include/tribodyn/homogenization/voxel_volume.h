#ifndef tribodyn_homogenization_voxel_volume_h
#define tribodyn_homogenization_voxel_volume_h

#include <array>
#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <vector>

namespace tribodyn
{
  template <typename Map, typename Common>
  class SourceBase;

  namespace homogenization
  {
    struct VolumeMorphologyParameters;
    class VoxelVolume;

    /// A source of the voxel volume of the 3D problem's "Morphology"
    /// (homogenization/volume_source.h): one file in
    /// `source/homogenization/volume_sources/` that registers itself in
    /// VolumeSources.
    using VolumeSource = SourceBase<VoxelVolume, VolumeMorphologyParameters>;

    /**
     * Parameters of the subsection "Morphology" of the 3D problem (`set
     * Problem = volume_homogenization`): a box of voxels, generated
     * (laminate, random spheres, aligned or misaligned fibres) or read from
     * a raw volume described by a small header file or from a multi-page
     * TIFF. The volume is made by a source (`Generator`:
     * homogenization/volume_source.h), which owns its own entries; the
     * entries here are common to the sources (the radius and the seed to
     * the two random generators, spheres and fibres).
     */
    struct VolumeMorphologyParameters
    {
      std::array<unsigned int, 3> n_voxels = {{32, 32, 32}};
      /// Edge of a (cubic) voxel of the generators and image stacks (m).
      double voxel_size = 1e-5;
      /// Target volume fraction of the heterogeneity (phase 1).
      double volume_fraction = 0.2;
      /// Spheres and fibres: radius in voxels and the seed of the
      /// placement.
      double        radius      = 4;
      std::uint64_t random_seed = 1;

      /// The chosen source with its parameters (by default 'spheres').
      std::shared_ptr<const VolumeSource> source;

      VolumeMorphologyParameters();

      /// The common entries of "Morphology", bound to the members above,
      /// and `Generator`, which makes the chosen source in @p chosen.
      ParameterBinding
      binding(std::unique_ptr<VolumeSource> &chosen);

      /// Declare the common entries and every registered source's.
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Read the common entries, then the chosen source's.
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * A box of n_x by n_y by n_z voxels, each holding a material id (0 to
     * 255). Voxel (i, j, k) covers [i h_x, (i+1) h_x] x [j h_y, (j+1) h_y]
     * x [k h_z, (k+1) h_z]; the ids are stored with x fastest, then y,
     * then z (the layout of the raw files).
     */
    class VoxelVolume
    {
    public:
      VoxelVolume(const std::array<unsigned int, 3> &n_voxels,
                  const std::array<double, 3>       &voxel_size,
                  std::vector<std::uint8_t>          ids,
                  const std::string                 &origin);

      /// Build the volume the parameters describe (their source's).
      static VoxelVolume
      create(const VolumeMorphologyParameters &parameters);

      /**
       * Read a raw volume through its header file @p header_file, lines
       * `key = value` ('#' starts a comment):
       *
       *   size       = 64 48 32   # voxels along x, y, z
       *   voxel size = 1e-5       # m: one value (cubic) or three
       *   type       = uint8      # one byte per voxel: its material id
       *   file       = volume.raw # relative to the header's directory
       *
       * Refuses (InputError naming the file, the cause and the fix) a
       * missing file or key, a malformed value, another type, or a data
       * file whose size is not n_x n_y n_z bytes.
       */
      static VoxelVolume
      read_raw(const std::string &header_file);

      /// Write the volume as a raw file and its header (readable by
      /// read_raw()).
      void
      write_raw(const std::string &header_file,
                const std::string &raw_file) const;

      unsigned int
      n_voxels(const unsigned int axis) const
      {
        return n[axis];
      }
      double
      voxel_size(const unsigned int axis) const
      {
        return h[axis];
      }
      double
      length(const unsigned int axis) const
      {
        return n[axis] * h[axis];
      }
      std::uint8_t
      voxel(const unsigned int i,
            const unsigned int j,
            const unsigned int k) const
      {
        return ids[(std::size_t(k) * n[1] + j) * n[0] + i];
      }
      /// The window of @p size voxels whose first voxel is @p first (it
      /// must lie in the volume): the crops of an RVE-size study.
      VoxelVolume
      window(const std::array<unsigned int, 3> &first,
             const std::array<unsigned int, 3> &size) const;
      /// Number of phases: the largest material id plus one (at least 2).
      unsigned int
      n_phases() const;
      /// Volume fraction of the voxels of each material id.
      std::vector<double>
      phase_fractions() const;
      /// One-line description for the screen and summary.json.
      const std::string &
      description() const
      {
        return origin;
      }

    private:
      std::array<unsigned int, 3> n;
      std::array<double, 3>       h;
      std::vector<std::uint8_t>   ids;
      std::string                 origin;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
