// Multi-page TIFF stacks as 3D voxel volumes (issue #51 item 2): the
// parameters, the crop box, and the segmentation of the 2D images
// (segment_pixels() in source/core/image_morphology.cc) applied to every
// page.
#include <array>
#include <cmath>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/homogenization/image_stack.h>
#include <tribodyn/homogenization/voxel_volume.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      /// The subsection of the stack's entries (the binding's and the
      /// messages' path).
      const std::string section = "Morphology/Image stack/";
    } // namespace


    ParameterBinding
    ImageStackParameters::binding()
    {
      ParameterBinding b(section);
      b.add("File",
            file,
            "Multi-page TIFF ('Generator = image stack'), one page per "
            "z-slice, the first page at z = 0: 8- or 16-bit grey (indexed "
            "and RGB pages are read as in 2D), uncompressed, LZW, Deflate or "
            "PackBits, in strips; every page of the same size and pixel "
            "type. Voxel (i, j, k) is column i of page k, row j counted from "
            "the bottom of the page (y up, as in 2D). The voxels are 'Pixel "
            "size' wide in x and y and 'Morphology/Voxel size' (the spacing "
            "of the pages) deep in z.",
            dealii::Patterns::FileName());
      b.add("Pixel size",
            pixel_size,
            "Size of a pixel of the pages in m: the voxel size in x and y. 0 "
            "takes it from the stack's resolution tags (TIFF "
            "XResolution/YResolution with ResolutionUnit inch or cm, the "
            "same on every page), as 'Morphology/Image/Pixel size' does in "
            "2D; a stack without them is refused. A size given here must "
            "agree with the tags when the stack has them (to 0.1 %). The "
            "spacing of the pages (z), which no TIFF tag holds, is "
            "'Morphology/Voxel size'.",
            dealii::Patterns::Double(0));
      add_to(b);
      b.add("Crop",
            "",
            "Optional box of the stack, in voxels: first column, first row "
            "(from the top of a page), first page, then the numbers of "
            "columns, rows and pages (each at least 2). Empty: the whole "
            "stack.",
            dealii::Patterns::Anything(),
            [this, path = b.path("Crop")](const std::string &text) {
              const std::vector<double> c     = parse_number_list(text, path);
              bool                      valid = c.empty() || c.size() == 6;
              for (unsigned int k = 0; valid && k < c.size(); ++k)
                valid = c[k] == std::floor(c[k]) && c[k] >= (k < 3 ? 0 : 2)
                        && c[k] <= 1e6;
              check_parameter(valid,
                              path,
                              "give six whole numbers (first column, first "
                              "row, first page, then columns >= 2, rows >= "
                              "2, pages >= 2) or nothing for the whole "
                              "stack.");
              crop = {{0, 0, 0, 0, 0, 0}};
              for (unsigned int k = 0; k < c.size(); ++k)
                crop[k] = static_cast<unsigned int>(c[k]);
            });
      return b;
    }


    void
    ImageStackParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      ImageStackParameters().binding().declare(prm);
    }


    void
    ImageStackParameters::parse_parameters(dealii::ParameterHandler &prm,
                                           const bool                used)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      if (!used)
        return;
      check_parameter(!file.empty(),
                      b.path("File"),
                      "'Generator = image stack' needs the path of a "
                      "multi-page TIFF.");
      check(b);
    }


    namespace
    {
      /// The voxel size of the stack @p image: 'Pixel size' or the
      /// resolution tags in x and y, @p slice_spacing in z.
      std::array<double, 3>
      stack_voxel_size(const RasterImage          &image,
                       const ImageStackParameters &p,
                       const double                slice_spacing)
      {
        const bool tagged = image.pixel_width > 0 && image.pixel_height > 0;
        const std::string tags
          = tagged ? format_number(image.pixel_width) + " x "
                       + format_number(image.pixel_height) + " m"
                   : std::string();
        check_parameter(p.pixel_size > 0 || tagged,
                        section + "Pixel size",
                        "the image stack '" + p.file
                          + "' has no resolution tags (XResolution and "
                            "YResolution with ResolutionUnit inch or cm), so "
                            "the size of its voxels in x and y is unknown. "
                            "Give the size of a pixel in m (the spacing of "
                            "the pages, z, is 'Morphology/Voxel size'), or "
                            "write the tags into every page of the stack.");
        if (p.pixel_size > 0 && tagged)
          for (const double tag : {image.pixel_width, image.pixel_height})
            check_parameter(std::abs(tag - p.pixel_size) <= 1e-3 * p.pixel_size,
                            section + "Pixel size",
                            format_number(p.pixel_size)
                              + " m disagrees with the resolution tags of "
                                "the image stack '"
                              + p.file + "', pixels of " + tags
                              + ". Set 'Pixel size = 0' to take the tags' "
                                "size, or correct the tags (XResolution, "
                                "YResolution, ResolutionUnit) of every page "
                                "if the size given is the right one.");
        if (p.pixel_size > 0)
          return {{p.pixel_size, p.pixel_size, slice_spacing}};
        return {{image.pixel_width, image.pixel_height, slice_spacing}};
      }
    } // namespace


    VoxelVolume
    read_image_stack(const ImageStackParameters &p, const double voxel_size)
    {
      const RasterImage image
        = read_raster_image(p.file, section + "File", true);
      check_parameter(image.n_pages >= 2 && image.width >= 2
                        && image.height >= 2,
                      section + "File",
                      "the image '" + p.file + "' (" + image.description()
                        + ") is not a stack of at least 2 pages of at least "
                          "2 x 2 pixels: a voxel volume needs two voxels "
                          "along each axis. Give a multi-page TIFF, one page "
                          "per z-slice.");
      PixelWindow w{0, 0, 0, image.width, image.height, image.n_pages};
      if (p.crop[3] > 0)
        {
          w = PixelWindow{
            p.crop[0], p.crop[1], p.crop[2], p.crop[3], p.crop[4], p.crop[5]};
          check_parameter(
            std::size_t(w.x0) + w.nx <= image.width
              && std::size_t(w.y0) + w.ny <= image.height
              && std::size_t(w.z0) + w.nz <= image.n_pages,
            section + "Crop",
            "the box (" + std::to_string(w.x0) + ", " + std::to_string(w.y0)
              + ", " + std::to_string(w.z0) + ", " + std::to_string(w.nx) + ", "
              + std::to_string(w.ny) + ", " + std::to_string(w.nz)
              + ") does not fit in the stack '" + p.file + "' of "
              + std::to_string(image.width) + " x "
              + std::to_string(image.height) + " pixels and "
              + std::to_string(image.n_pages)
              + " pages. Give first column, first row, first page, columns, "
                "rows and pages inside the stack.");
        }
      const std::array<double, 3> h = stack_voxel_size(image, p, voxel_size);
      const PixelPhases phases = segment_pixels(image, w, p, section, p.file);
      check_parameter(phases.n_phases <= 256,
                      section + "Segmentation",
                      "it gives " + std::to_string(phases.n_phases)
                        + " phases; a voxel volume holds at most 256 "
                          "(material ids 0 to 255).");

      // pages in z, rows from the top of a page turned to y up
      std::vector<std::uint8_t> ids(phases.ids.size());
      for (unsigned int k = 0, n = 0; k < w.nz; ++k)
        for (unsigned int r = 0; r < w.ny; ++r)
          for (unsigned int i = 0; i < w.nx; ++i, ++n)
            ids[(std::size_t(k) * w.ny + (w.ny - 1 - r)) * w.nx + i]
              = static_cast<std::uint8_t>(phases.ids[n]);
      std::ostringstream d;
      d << "image stack " << p.file << " (" << image.description();
      if (p.crop[3] > 0)
        d << ", crop " << w.x0 << " " << w.y0 << " " << w.z0 << " " << w.nx
          << " " << w.ny << " " << w.nz;
      d << "; voxels " << format_number(h[0]) << " x " << format_number(h[1])
        << " x " << format_number(h[2]) << " m, "
        << (p.pixel_size > 0 ? "x and y given" : "x and y from its tags")
        << "; " << phases.how << ")";
      return VoxelVolume({{w.nx, w.ny, w.nz}}, h, std::move(ids), d.str());
    }
  } // namespace homogenization
} // namespace tribodyn
