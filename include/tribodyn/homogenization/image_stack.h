#ifndef tribodyn_homogenization_image_stack_h
#define tribodyn_homogenization_image_stack_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/image_morphology.h>
#include <tribodyn/core/parameter_binding.h>

namespace tribodyn
{
  namespace homogenization
  {
    class VoxelVolume;

    /**
     * Parameters of the subsection "Morphology/Image stack" of the 3D
     * problem (`set Morphology/Generator = image stack`, issue #51 item 2):
     * a multi-page TIFF, one page per z-slice, segmented into phases as the
     * 2D images are (SegmentationParameters: thresholds, Otsu's method or a
     * colour table), optionally cropped to a box of voxels. The voxel size
     * in x and y is 'Pixel size' or the stack's resolution tags, in z
     * 'Morphology/Voxel size'.
     */
    struct ImageStackParameters : SegmentationParameters
    {
      /// Path of the multi-page TIFF (relative to the working directory).
      std::string file;
      /// Voxel size in x and y (m); 0 takes it from the resolution tags.
      double pixel_size = 0;
      /// Crop box in voxels: first column, first row (from the top of a
      /// page), first page, then the numbers of columns, rows and pages;
      /// all zero: the whole stack.
      std::array<unsigned int, 6> crop = {{0, 0, 0, 0, 0, 0}};

      /// The entries of "Morphology/Image stack", bound to the members
      /// above (their initial values are the defaults).
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Parse the subsection; check it when it is @p used (the generator
      /// is 'image stack').
      void
      parse_parameters(dealii::ParameterHandler &prm, const bool used);
    };

    /**
     * Read the stack @p parameters name, crop and segment it into a voxel
     * volume whose voxels are parameters.pixel_size (or, when it is 0, the
     * stack's resolution tags) wide in x and y and @p voxel_size deep in
     * z: voxel (i, j, k) is
     * column i, row n_y - 1 - j (rows counted from the top of the window)
     * of page k of the window, so that x runs along the rows, y up the
     * pages as they are displayed and z through the stack. Throws
     * InputError naming 'Morphology/Image stack/...' for a missing,
     * corrupt or unsupported file, pages of different sizes, fewer than two
     * pages, columns or rows in the window, a crop box outside the stack, a
     * phase left empty, or more than 255 phases; naming 'Pixel size' a
     * stack without resolution tags when it is 0, and one whose tags
     * disagree with it by more than 0.1 % otherwise.
     */
    VoxelVolume
    read_image_stack(const ImageStackParameters &parameters,
                     const double                voxel_size);
  } // namespace homogenization
} // namespace tribodyn

#endif
