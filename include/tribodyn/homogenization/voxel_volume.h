#ifndef tribodyn_homogenization_voxel_volume_h
#define tribodyn_homogenization_voxel_volume_h

#include <array>
#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/homogenization/image_stack.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /**
     * Parameters of the subsection "Morphology" of the 3D problem (`set
     * Problem = volume_homogenization`): a box of voxels, generated
     * (laminate, random spheres, aligned or misaligned fibres) or read from
     * a raw volume described by a small header file or from a multi-page
     * TIFF.
     */
    struct VolumeMorphologyParameters
    {
      enum class Generator
      {
        laminate,   ///< layers through the whole box, normal to x, y or z
        spheres,    ///< random non-overlapping spheres (periodic placement)
        fibres,     ///< the same with short cylinders (aligned or in a cone)
        raw_file,   ///< material ids read from a raw volume with a header
        image_stack ///< a multi-page TIFF, segmented (ImageStackParameters)
      };

      Generator                   generator = Generator::spheres;
      std::array<unsigned int, 3> n_voxels  = {{32, 32, 32}};
      /// Edge of a (cubic) voxel of the generators and image stacks (m).
      double voxel_size = 1e-5;
      /// Target volume fraction of the heterogeneity (phase 1).
      double volume_fraction = 0.2;
      /// Laminate: axis of the layers' normal (0 = x, 1 = y, 2 = z) and
      /// the number of (matrix, heterogeneity) periods along it.
      unsigned int laminate_normal  = 2;
      unsigned int laminate_periods = 1;
      /// Spheres and fibres: radius in voxels and the seed of the
      /// placement; fibres: length in voxels and axis (0 = x, 1 = y, 2 = z).
      double        radius       = 4;
      std::uint64_t random_seed  = 1;
      double        fibre_length = 16;
      unsigned int  fibre_axis   = 2;
      /// Fibres: half-angle (degrees) of the cone about fibre_axis within
      /// which their axes are drawn uniformly over the spherical cap; 0 =
      /// all aligned with fibre_axis, 90 = uniformly random in 3D.
      double fibre_cone_angle = 0;
      /// Raw file: path of the header file.
      std::string raw_header;
      /// Image stack: the subsection "Morphology/Image stack".
      ImageStackParameters image_stack;

      /// The entries of "Morphology", bound to the members above.
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
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

      /// Build the volume the parameters describe.
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
