// TIFF stacks as voxel volumes (issue #51 item 2): the small noisy
// three-level stack of scripts/make_synthetic_images (12 x 10 pixels, 4
// pages; level (i / 4 + r / 3 + k) % 3 of 40, 128, 220 at column i, row r
// from the top, page k) uncompressed, LZW, PackBits, Deflate and 16-bit
// big-endian, each read by read_image_stack() and segmented by Otsu's
// method into three phases, must give that map voxel for voxel with voxel
// (i, j, k) = column i, row 9 - j, page k (y up); grey-level thresholds
// give the same; a crop box gives the window of the full volume; the voxel
// size is the one given ('Pixel size' in x and y, the slice spacing in z).

#include "image_test_tools.h"

#include <tribodyn/homogenization/image_stack.h>
#include <tribodyn/homogenization/voxel_volume.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;
  using tribodyn::homogenization::ImageStackParameters;
  using tribodyn::homogenization::read_image_stack;
  using tribodyn::homogenization::VoxelVolume;

  const auto drawn
    = [](const unsigned int i, const unsigned int r, const unsigned int k) {
        return (i / 4 + r / 3 + k) % 3;
      };
  const auto parameters = [](const std::string &name) {
    ImageStackParameters p;
    p.file          = image_path(name);
    p.segmentation  = ImageStackParameters::Segmentation::otsu;
    p.n_otsu_phases = 3;
    p.pixel_size    = 2e-6; // (the stacks have no resolution tags)
    return p;
  };
  // voxels of v that differ from the drawn map of the box (x0, y0, z0)
  const auto differences = [&](const VoxelVolume &v,
                               const unsigned int x0,
                               const unsigned int y0,
                               const unsigned int z0) {
    unsigned int n = 0;
    for (unsigned int k = 0; k < v.n_voxels(2); ++k)
      for (unsigned int j = 0; j < v.n_voxels(1); ++j)
        for (unsigned int i = 0; i < v.n_voxels(0); ++i)
          n += v.voxel(i, j, k)
               != drawn(x0 + i, y0 + v.n_voxels(1) - 1 - j, z0 + k);
    return n;
  };

  for (const std::string name : {"stack_formats_none.tif",
                                 "stack_formats_lzw.tif",
                                 "stack_formats_packbits.tif",
                                 "stack_formats_deflate.tif",
                                 "stack_formats_grey16.tif"})
    {
      const VoxelVolume v = read_image_stack(parameters(name), 2e-6);
      check(v.n_voxels(0) == 12 && v.n_voxels(1) == 10 && v.n_voxels(2) == 4
              && differences(v, 0, 0, 0) == 0,
            name + ": 12 x 10 x 4 voxels, the drawn map ("
              + std::to_string(differences(v, 0, 0, 0)) + " voxels differ; "
              + v.description() + ")");
      for (unsigned int d = 0; d < 3; ++d)
        check_relative(v.voxel_size(d), 2e-6, 1e-15, name + ": voxel size");
    }
  {
    ImageStackParameters p = parameters("stack_formats_lzw.tif");
    p.segmentation         = ImageStackParameters::Segmentation::thresholds;
    p.thresholds           = {84, 174};
    const VoxelVolume v    = read_image_stack(p, 1e-6);
    check(differences(v, 0, 0, 0) == 0, "thresholds 84, 174: the drawn map");
    p.crop              = {{1, 2, 1, 8, 6, 2}};
    const VoxelVolume w = read_image_stack(p, 1e-6);
    check(w.n_voxels(0) == 8 && w.n_voxels(1) == 6 && w.n_voxels(2) == 2
            && differences(w, 1, 2, 1) == 0,
          "crop 1 2 1 8 6 2: the window of the drawn map ("
            + std::to_string(differences(w, 1, 2, 1)) + " voxels differ)");
  }
  return result();
}
