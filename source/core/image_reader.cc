// Reading PNG (libpng) and TIFF (libtiff) files into a RasterImage (issue
// #19 item 1): grey, indexed or RGB pixels of 8 or 16 bits, the resolution
// tag, and clear refusals of missing, corrupt or unsupported files.
#include <cmath>
#include <csetjmp>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <png.h>
#include <sstream>
#include <tiffio.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/image_morphology.h>

namespace tribodyn
{
  unsigned int
  RasterImage::max_grey() const
  {
    return (kind == Kind::indexed || bit_depth == 8) ? 255 : 65535;
  }


  unsigned int
  RasterImage::grey(const unsigned int i, const unsigned int r) const
  {
    const std::size_t k = static_cast<std::size_t>(r) * width + i;
    const auto luma     = [](const double red, const double g, const double b) {
      return static_cast<unsigned int>(
        std::lround(0.299 * red + 0.587 * g + 0.114 * b));
    };
    switch (kind)
      {
        case Kind::grey:
          return samples[k];
        case Kind::rgb:
          return luma(samples[3 * k], samples[3 * k + 1], samples[3 * k + 2]);
        case Kind::indexed:
          {
            const auto &c = palette[samples[k]];
            return luma(c[0], c[1], c[2]);
          }
      }
    return 0;
  }


  std::string
  RasterImage::description() const
  {
    std::ostringstream s;
    s << format << ", "
      << (kind == Kind::indexed
            ? std::string("indexed (") + std::to_string(palette.size())
                + " colours)"
            : std::to_string(bit_depth) + "-bit "
                + (kind == Kind::grey ? "grey" : "RGB"))
      << ", " << width << " x " << height << " pixels";
    if (n_pages > 1)
      s << ", " << n_pages << " pages";
    return s.str();
  }


  namespace
  {
    /// Where libpng reports an error: the message, then a longjmp back to
    /// read_png().
    struct PngErrorState
    {
      std::string message;
    };

    void
    png_error_handler(png_structp png, png_const_charp message)
    {
      auto *state    = static_cast<PngErrorState *>(png_get_error_ptr(png));
      state->message = message;
      png_longjmp(png, 1);
    }

    void
    png_warning_handler(png_structp, png_const_charp)
    {
    }


    std::string
    corrupt(const std::string &file_name,
            const std::string &format,
            const std::string &parameter,
            const std::string &cause)
    {
      return "The image file '" + file_name + "' (parameter '" + parameter
             + "') is not a readable " + format + " file: " + cause
             + ". Check that the file is complete (not truncated), or save "
               "it again as an 8- or 16-bit grey, indexed or RGB "
             + format + ".";
    }


    RasterImage
    read_png(std::FILE         *fp,
             const std::string &file_name,
             const std::string &parameter)
    {
      PngErrorState state;
      png_structp   png  = png_create_read_struct(PNG_LIBPNG_VER_STRING,
                                               &state,
                                               png_error_handler,
                                               png_warning_handler);
      png_infop     info = png ? png_create_info_struct(png) : nullptr;
      if (!png || !info)
        throw RunError("libpng could not allocate its structures.");
      // What is written after setjmp lives on the heap behind a pointer set
      // before it: after a longjmp, locals changed since setjmp have
      // indeterminate values, memory does not.
      struct Data
      {
        RasterImage            image;
        std::vector<png_bytep> rows;
        std::vector<png_byte>  buffer;
      };
      const auto data = std::make_unique<Data>();
      if (setjmp(png_jmpbuf(png)))
        {
          png_destroy_read_struct(&png, &info, nullptr);
          throw InputError(corrupt(file_name, "PNG", parameter, state.message));
        }
      RasterImage            &image  = data->image;
      std::vector<png_bytep> &rows   = data->rows;
      std::vector<png_byte>  &buffer = data->buffer;
      png_init_io(png, fp);
      png_set_sig_bytes(png, 8); // read_raster_image() read them
      png_read_info(png, info);
      png_uint_32 width = 0, height = 0;
      int         depth = 0, colour = 0, interlace = 0;
      png_get_IHDR(png,
                   info,
                   &width,
                   &height,
                   &depth,
                   &colour,
                   &interlace,
                   nullptr,
                   nullptr);
      image.format = "PNG";
      image.width  = width;
      image.height = height;
      if (colour == PNG_COLOR_TYPE_PALETTE)
        {
          image.kind           = RasterImage::Kind::indexed;
          png_colorp palette   = nullptr;
          int        n_colours = 0;
          png_get_PLTE(png, info, &palette, &n_colours);
          for (int c = 0; c < n_colours; ++c)
            image.palette.push_back(
              {{palette[c].red, palette[c].green, palette[c].blue}});
          if (depth < 8)
            png_set_packing(png); // one index per byte
          image.bit_depth = 8;
        }
      else
        {
          image.kind = (colour & PNG_COLOR_MASK_COLOR)
                         ? RasterImage::Kind::rgb
                         : RasterImage::Kind::grey;
          if (depth < 8)
            png_set_expand_gray_1_2_4_to_8(png);
          image.bit_depth = depth == 16 ? 16 : 8;
        }
      if (colour & PNG_COLOR_MASK_ALPHA)
        png_set_strip_alpha(png);
      png_set_interlace_handling(png);
      png_read_update_info(png, info);

      const std::size_t row_bytes = png_get_rowbytes(png, info);
      buffer.resize(row_bytes * height);
      rows.resize(height);
      for (png_uint_32 r = 0; r < height; ++r)
        rows[r] = buffer.data() + r * row_bytes;
      png_read_image(png, rows.data());
      png_read_end(png, nullptr);

      png_uint_32 x_resolution = 0, y_resolution = 0;
      int         unit = 0;
      if (png_get_pHYs(png, info, &x_resolution, &y_resolution, &unit)
          && unit == PNG_RESOLUTION_METER && x_resolution > 0
          && y_resolution > 0)
        {
          image.pixel_width  = 1. / x_resolution;
          image.pixel_height = 1. / y_resolution;
        }
      png_destroy_read_struct(&png, &info, nullptr);

      const unsigned int channels
        = image.kind == RasterImage::Kind::rgb ? 3 : 1;
      const unsigned int bytes = image.bit_depth / 8;
      image.samples.resize(static_cast<std::size_t>(width) * height * channels);
      for (std::size_t k = 0; k < image.samples.size(); ++k)
        {
          const std::size_t r = k / (std::size_t(width) * channels);
          const std::size_t c = k % (std::size_t(width) * channels);
          const png_byte   *p = rows[r] + c * bytes;
          image.samples[k]    = bytes == 2 ? (p[0] << 8) | p[1] : p[0];
          if (image.kind == RasterImage::Kind::indexed
              && image.samples[k] >= image.palette.size())
            throw InputError(corrupt(file_name,
                                     "PNG",
                                     parameter,
                                     "a pixel's palette index is beyond the "
                                     "palette"));
        }
      return std::move(image);
    }


    /// libtiff's last error message (its handlers are global).
    std::string tiff_message;

    void
    tiff_error_handler(const char *module, const char *format, va_list args)
    {
      char text[512];
      std::vsnprintf(text, sizeof(text), format, args);
      tiff_message
        = (module ? std::string(module) + ": " : std::string()) + text;
    }

    void
    tiff_warning_handler(const char *, const char *, va_list)
    {
    }


    /**
     * Read the current page (directory) of @p tif. @p refuse makes the
     * InputError of a layout tribodyn does not read (and closes the file),
     * @p unreadable that of a row libtiff cannot decode.
     */
    template <typename Refuse, typename Unreadable>
    RasterImage
    read_tiff_page(TIFF             *tif,
                   const Refuse     &refuse,
                   const Unreadable &unreadable)
    {
      std::uint32_t width = 0, height = 0;
      std::uint16_t bits = 1, samples_per_pixel = 1, photometric = 0,
                    planar = PLANARCONFIG_CONTIG, sample_format = 1, extra = 0;
      std::uint16_t *extra_types = nullptr;
      TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width);
      TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
      TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
      TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &samples_per_pixel);
      TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
      TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &sample_format);
      TIFFGetFieldDefaulted(tif, TIFFTAG_EXTRASAMPLES, &extra, &extra_types);
      if (!TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &photometric))
        throw refuse("it has no PhotometricInterpretation tag");
      if (TIFFIsTiled(tif))
        throw refuse("it is tiled");
      if (width == 0 || height == 0)
        throw refuse("it has no pixels");
      if (bits != 8 && bits != 16)
        throw refuse(std::to_string(bits) + " bits per sample");
      if (sample_format != SAMPLEFORMAT_UINT)
        throw refuse("its samples are not unsigned integers");
      if (planar != PLANARCONFIG_CONTIG && samples_per_pixel > 1)
        throw refuse("its colour planes are stored separately");

      RasterImage image;
      image.format          = "TIFF";
      image.width           = width;
      image.height          = height;
      image.bit_depth       = bits;
      unsigned int channels = 1;
      bool         invert   = false;
      switch (photometric)
        {
          case PHOTOMETRIC_MINISWHITE:
            invert = true;
            [[fallthrough]];
          case PHOTOMETRIC_MINISBLACK:
            image.kind = RasterImage::Kind::grey;
            break;
          case PHOTOMETRIC_RGB:
            image.kind = RasterImage::Kind::rgb;
            channels   = 3;
            break;
          case PHOTOMETRIC_PALETTE:
            {
              image.kind         = RasterImage::Kind::indexed;
              std::uint16_t *red = nullptr, *green = nullptr, *blue = nullptr;
              if (!TIFFGetField(tif, TIFFTAG_COLORMAP, &red, &green, &blue))
                throw refuse("it is indexed but has no ColorMap");
              // ColorMap entries are 16-bit: scale to 8 bits.
              for (unsigned int c = 0; c < (1u << bits); ++c)
                image.palette.push_back(
                  {{red[c] / 257u, green[c] / 257u, blue[c] / 257u}});
              break;
            }
          default:
            throw refuse("photometric interpretation "
                         + std::to_string(photometric)
                         + " (only grey, palette and RGB are read)");
        }
      if (samples_per_pixel < channels || samples_per_pixel > channels + extra)
        throw refuse(std::to_string(samples_per_pixel) + " samples per pixel");

      const tmsize_t             line_size = TIFFScanlineSize(tif);
      std::vector<unsigned char> line(line_size);
      image.samples.resize(static_cast<std::size_t>(width) * height * channels);
      for (std::uint32_t r = 0; r < height; ++r)
        {
          tiff_message.clear();
          if (TIFFReadScanline(tif, line.data(), r) < 0)
            throw unreadable(r);
          for (std::uint32_t i = 0; i < width; ++i)
            for (unsigned int c = 0; c < channels; ++c)
              {
                const std::size_t s = std::size_t(i) * samples_per_pixel + c;
                std::uint16_t     v = 0;
                if (bits == 16)
                  std::memcpy(&v, line.data() + 2 * s, 2); // host order
                else
                  v = line[s];
                if (invert)
                  v = static_cast<std::uint16_t>(image.max_grey() - v);
                image.samples[(std::size_t(r) * width + i) * channels + c] = v;
              }
        }

      float         x_resolution = 0, y_resolution = 0;
      std::uint16_t unit = RESUNIT_INCH;
      TIFFGetFieldDefaulted(tif, TIFFTAG_RESOLUTIONUNIT, &unit);
      if (TIFFGetField(tif, TIFFTAG_XRESOLUTION, &x_resolution)
          && TIFFGetField(tif, TIFFTAG_YRESOLUTION, &y_resolution)
          && x_resolution > 0 && y_resolution > 0
          && (unit == RESUNIT_INCH || unit == RESUNIT_CENTIMETER))
        {
          const double length = unit == RESUNIT_INCH ? 0.0254 : 0.01;
          image.pixel_width   = length / x_resolution;
          image.pixel_height  = length / y_resolution;
        }
      return image;
    }


    /// Read the first page of a TIFF, or with @p all_pages every page, one
    /// below the other (RasterImage::n_pages).
    RasterImage
    read_tiff(const std::string &file_name,
              const std::string &parameter,
              const bool         all_pages)
    {
      TIFFSetErrorHandler(tiff_error_handler);
      TIFFSetWarningHandler(tiff_warning_handler);
      tiff_message.clear();
      TIFF *tif = TIFFOpen(file_name.c_str(), "r");
      if (!tif)
        throw InputError(corrupt(file_name, "TIFF", parameter, tiff_message));
      unsigned int page  = 0;
      const auto   where = [&]() {
        return page > 0 ? "page " + std::to_string(page) + " (from 0): "
                          : std::string();
      };
      const auto refuse = [&](const std::string &cause) {
        TIFFClose(tif);
        return InputError("The image file '" + file_name + "' (parameter '"
                          + parameter
                          + "') is a TIFF that tribodyn does not "
                            "read: "
                          + where() + cause
                          + ". Save it as an uncompressed, LZW, Deflate "
                            "or PackBits TIFF in strips with 8- or 16-bit "
                            "grey, indexed or RGB pixels (or as a PNG).");
      };
      const auto unreadable = [&](const std::uint32_t row) {
        TIFFClose(tif);
        return InputError(corrupt(file_name,
                                  "TIFF",
                                  parameter,
                                  where() + "row " + std::to_string(row) + ": "
                                    + tiff_message));
      };
      RasterImage       image = read_tiff_page(tif, refuse, unreadable);
      const std::string first = image.description();
      while (all_pages && TIFFReadDirectory(tif))
        {
          ++page;
          const RasterImage next = read_tiff_page(tif, refuse, unreadable);
          if (next.width != image.width || next.height != image.height
              || next.kind != image.kind || next.bit_depth != image.bit_depth
              || next.palette != image.palette)
            {
              TIFFClose(tif);
              throw InputError(
                "The image file '" + file_name + "' (parameter '" + parameter
                + "') is not a stack of equal pages: page "
                + std::to_string(page) + " (from 0) is '" + next.description()
                + "' but page 0 '" + first
                + "'. Save every slice of the stack with the same "
                  "width, height and pixel type (crop or pad the slices "
                  "that differ).");
            }
          // (a stack's voxel size in x and y, read by image_stack.cc)
          if (next.pixel_width != image.pixel_width
              || next.pixel_height != image.pixel_height)
            {
              TIFFClose(tif);
              const auto resolution = [](const RasterImage &i) {
                return i.pixel_width > 0 && i.pixel_height > 0
                         ? "pixels of " + format_number(i.pixel_width) + " x "
                             + format_number(i.pixel_height)
                             + " m in its resolution tags"
                         : std::string("no resolution tags");
              };
              throw InputError(
                "The image file '" + file_name + "' (parameter '" + parameter
                + "') is not a stack of equal pages: page "
                + std::to_string(page) + " (from 0) has " + resolution(next)
                + " but page 0 " + resolution(image)
                + ". Write the same XResolution, YResolution and "
                  "ResolutionUnit (inch or cm) into every page, or none into "
                  "any.");
            }
          image.samples.insert(image.samples.end(),
                               next.samples.begin(),
                               next.samples.end());
          ++image.n_pages;
        }
      if (all_pages && !tiff_message.empty())
        {
          TIFFClose(tif);
          throw InputError(corrupt(file_name,
                                   "TIFF",
                                   parameter,
                                   "the directory after page "
                                     + std::to_string(page) + ": "
                                     + tiff_message));
        }
      TIFFClose(tif);
      return image;
    }
  } // namespace


  RasterImage
  read_raster_image(const std::string &file_name,
                    const std::string &parameter,
                    const bool         all_pages)
  {
    std::FILE *fp = std::fopen(file_name.c_str(), "rb");
    if (!fp)
      throw InputError("Cannot read the image file '" + file_name
                       + "' (parameter '" + parameter
                       + "'): it does not exist or is not readable. Give "
                         "the path of a PNG or TIFF file, relative to the "
                         "directory tribodyn runs in.");
    unsigned char     signature[8] = {0};
    const std::size_t n            = std::fread(signature, 1, 8, fp);
    if (n == 8 && png_sig_cmp(signature, 0, 8) == 0)
      {
        RasterImage image;
        try
          {
            image = read_png(fp, file_name, parameter);
          }
        catch (...)
          {
            std::fclose(fp);
            throw;
          }
        std::fclose(fp);
        return image;
      }
    std::fclose(fp);
    if (n >= 4
        && ((signature[0] == 'I' && signature[1] == 'I' && signature[2] == 42
             && signature[3] == 0)
            || (signature[0] == 'M' && signature[1] == 'M' && signature[2] == 0
                && signature[3] == 42)))
      return read_tiff(file_name, parameter, all_pages);
    throw InputError("The image file '" + file_name + "' (parameter '"
                     + parameter
                     + "') has an unsupported format: it is neither a PNG "
                       "nor a TIFF (its first bytes are no PNG or TIFF "
                       "signature). Convert it to PNG or TIFF.");
  }


} // namespace tribodyn
