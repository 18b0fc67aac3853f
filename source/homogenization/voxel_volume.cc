// Voxel volumes of the 3D cell problems (issue #51): the common entries of
// "Morphology" and its sources' list (the sources are in volume_sources/),
// the volume, and the raw files with their header.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tribodyn/core/errors.h>
#include <tribodyn/homogenization/volume_source.h>
#include <tribodyn/homogenization/voxel_volume.h>

namespace tribodyn
{
  namespace homogenization
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    VolumeMorphologyParameters::VolumeMorphologyParameters()
        : source(VolumeSources::create("spheres"))
    {
    }


    ParameterBinding
    VolumeMorphologyParameters::binding(std::unique_ptr<VolumeSource> &chosen)
    {
      ParameterBinding b("Morphology");
      VolumeSources::add_generator_entry(
        b, "spheres", "Where the voxels come from: ", chosen);
      const char *axes[3] = {"x", "y", "z"};
      for (unsigned int d = 0; d < 3; ++d)
        b.add(std::string("Voxels in ") + axes[d],
              n_voxels[d],
              std::string("Number of voxels along ") + axes[d]
                + " (generators; a raw file or an image stack gives its "
                  "own size).",
              Patterns::Integer(2));
      b.add("Voxel size",
            voxel_size,
            "Edge of a cubic voxel of the generators (m); of an image stack "
            "the spacing of its pages (z; x and y: 'Image stack/Pixel "
            "size'); a raw file's header gives its own.",
            Patterns::Double(),
            Interval{0, 1e3, true, false});
      b.add("Volume fraction",
            volume_fraction,
            "Target volume fraction of the heterogeneity (material id 1) "
            "of the generators; in [0, 1).",
            Patterns::Double(),
            Interval{0, 1, false, true});
      b.add("Radius",
            radius,
            "Spheres and fibres: radius in voxels (a voxel belongs to an "
            "inclusion when its centre lies inside).",
            Patterns::Double(),
            Interval{0.5, 1e6});
      b.add("Seed",
            random_seed,
            "Spheres and fibres: seed of the random placement (same seed, "
            "same volume).",
            Patterns::Integer(0));
      return b;
    }


    void
    VolumeMorphologyParameters::declare_parameters(ParameterHandler &prm)
    {
      std::unique_ptr<VolumeSource> unused;
      VolumeMorphologyParameters().binding(unused).declare(prm);
      VolumeSources::declare_sources(prm);
    }


    void
    VolumeMorphologyParameters::parse_parameters(ParameterHandler &prm)
    {
      std::unique_ptr<VolumeSource> chosen;
      const ParameterBinding        b = binding(chosen);
      b.parse(prm);
      source = VolumeSources::parse_chosen(std::move(chosen), prm, b, *this);
    }


    VoxelVolume::VoxelVolume(const std::array<unsigned int, 3> &n_voxels,
                             const std::array<double, 3>       &voxel_size,
                             std::vector<std::uint8_t>          ids,
                             const std::string                 &origin)
        : n(n_voxels)
        , h(voxel_size)
        , ids(std::move(ids))
        , origin(origin)
    {
    }


    VoxelVolume
    VoxelVolume::window(const std::array<unsigned int, 3> &first,
                        const std::array<unsigned int, 3> &size) const
    {
      for (unsigned int d = 0; d < 3; ++d)
        if (size[d] == 0 || first[d] + size[d] > n[d])
          throw std::logic_error("VoxelVolume::window(): the window leaves "
                                 "the volume");
      const std::size_t count = std::size_t(size[0]) * size[1] * size[2];
      std::vector<std::uint8_t> window_ids(count);
      std::size_t               m = 0;
      for (unsigned int k = 0; k < size[2]; ++k)
        for (unsigned int j = 0; j < size[1]; ++j)
          for (unsigned int i = 0; i < size[0]; ++i)
            window_ids[m++] = voxel(first[0] + i, first[1] + j, first[2] + k);
      std::ostringstream s;
      s << "window of " << size[0] << " x " << size[1] << " x " << size[2]
        << " voxels from (" << first[0] << ", " << first[1] << ", " << first[2]
        << ") of " << origin;
      return VoxelVolume(size, h, std::move(window_ids), s.str());
    }


    unsigned int
    VoxelVolume::n_phases() const
    {
      const unsigned int largest
        = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end());
      return std::max(2u, largest + 1);
    }


    std::vector<double>
    VoxelVolume::phase_fractions() const
    {
      std::vector<double> f(n_phases(), 0.);
      for (const std::uint8_t id : ids)
        f[id] += 1.;
      for (double &x : f)
        x /= ids.size();
      return f;
    }


    namespace
    {
      /// The directory part of @p path ("" or ending with '/').
      std::string
      directory_of(const std::string &path)
      {
        const auto slash = path.find_last_of('/');
        return slash == std::string::npos ? "" : path.substr(0, slash + 1);
      }
    } // namespace


    VoxelVolume
    VoxelVolume::create(const VolumeMorphologyParameters &parameters)
    {
      return parameters.source->create(parameters);
    }


    VoxelVolume
    VoxelVolume::read_raw(const std::string &header_file)
    {
      const std::string header = "the raw volume header '" + header_file
                                 + "' (parameter 'Morphology/Raw header')";
      const std::string where = "T" + header.substr(1);
      std::ifstream     in(header_file);
      if (!in)
        throw InputError("Cannot read " + header
                         + ": it does not exist or is not readable. Give the "
                           "path of an existing header file (relative paths "
                           "are relative to the directory tribodyn runs in).");
      std::array<unsigned int, 3> n{};
      std::array<double, 3>       h{};
      std::string                 type, file;
      bool                        has_size = false, has_h = false;
      std::string                 line;
      unsigned int                line_number = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          line = line.substr(0, line.find('#'));
          if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
          const auto equal = line.find('=');
          const auto trim  = [](std::string s) {
            const auto b = s.find_first_not_of(" \t\r");
            const auto e = s.find_last_not_of(" \t\r");
            return b == std::string::npos ? std::string()
                                           : s.substr(b, e - b + 1);
          };
          const std::string key
            = equal == std::string::npos ? "" : trim(line.substr(0, equal));
          const std::string value
            = equal == std::string::npos ? "" : trim(line.substr(equal + 1));
          const std::string at
            = where + ", line " + std::to_string(line_number) + ": ";
          std::istringstream values(value);
          if (key == "size")
            {
              long long   m[3] = {0, 0, 0};
              std::string rest;
              if (!(values >> m[0] >> m[1] >> m[2]) || (values >> rest)
                  || std::min({m[0], m[1], m[2]}) < 2
                  || std::max({m[0], m[1], m[2]}) > 100000)
                throw InputError(at + "'size = " + value
                                 + "' is not three whole numbers of voxels "
                                   "(nx ny nz), each at least 2. Write e.g. "
                                   "'size = 64 64 32'.");
              for (unsigned int d = 0; d < 3; ++d)
                n[d] = static_cast<unsigned int>(m[d]);
              has_size = true;
            }
          else if (key == "voxel size")
            {
              std::vector<double> v;
              double              x;
              while (values >> x)
                v.push_back(x);
              if (!values.eof() || (v.size() != 1 && v.size() != 3)
                  || *std::min_element(v.begin(), v.end()) <= 0)
                throw InputError(at + "'voxel size = " + value
                                 + "' is not one or three positive lengths "
                                   "(m). Write e.g. 'voxel size = 1e-5'.");
              for (unsigned int d = 0; d < 3; ++d)
                h[d] = v.size() == 1 ? v[0] : v[d];
              has_h = true;
            }
          else if (key == "type")
            type = value;
          else if (key == "file")
            file = value;
          else
            throw InputError(at + "'" + trim(line)
                             + "' is not one of the keys size, voxel size, "
                               "type, file (lines 'key = value'; '#' starts a "
                               "comment).");
        }
      for (const auto &[present, key] :
           {std::pair<bool, std::string>{has_size, "size"},
            {has_h, "voxel size"},
            {!type.empty(), "type"},
            {!file.empty(), "file"}})
        if (!present)
          throw InputError(where + " has no line '" + key
                           + " = ...'. A header gives size, voxel size, type "
                             "and file.");
      if (type != "uint8")
        throw InputError(where + ": 'type = " + type
                         + "' is not supported: tribodyn reads raw volumes of "
                           "material ids, one byte per voxel ('type = "
                           "uint8'). Segment the volume into ids 0, 1, ... "
                           "first.");
      const std::string path
        = file.front() == '/' ? file : directory_of(header_file) + file;
      std::ifstream raw(path, std::ios::binary | std::ios::ate);
      if (!raw)
        throw InputError("Cannot read the raw volume '" + path + "' named by "
                         + header
                         + ": it does not exist or is not readable. Fix the "
                           "line 'file = ...' (relative to the header's "
                           "directory).");
      const std::size_t expected = std::size_t(n[0]) * n[1] * n[2];
      const auto        bytes    = static_cast<std::size_t>(raw.tellg());
      if (bytes != expected)
        throw InputError("The raw volume '" + path + "' named by " + header
                         + " holds " + std::to_string(bytes)
                         + " bytes, but 'size = " + std::to_string(n[0]) + " "
                         + std::to_string(n[1]) + " " + std::to_string(n[2])
                         + "' with 'type = uint8' needs "
                         + std::to_string(expected)
                         + ". Fix the size in the header or the file.");
      std::vector<std::uint8_t> ids(expected);
      raw.seekg(0);
      raw.read(reinterpret_cast<char *>(ids.data()), expected);
      return VoxelVolume(n,
                         h,
                         std::move(ids),
                         "raw volume " + path + " (" + std::to_string(n[0])
                           + " x " + std::to_string(n[1]) + " x "
                           + std::to_string(n[2]) + " voxels)");
    }


    void
    VoxelVolume::write_raw(const std::string &header_file,
                           const std::string &raw_file) const
    {
      std::ofstream raw(raw_file, std::ios::binary);
      raw.write(reinterpret_cast<const char *>(ids.data()), ids.size());
      std::ofstream header(header_file);
      header.precision(17);
      header << "# " << origin << "\nsize = " << n[0] << " " << n[1] << " "
             << n[2] << "\nvoxel size = " << h[0] << " " << h[1] << " " << h[2]
             << "\ntype = uint8\nfile = "
             << raw_file.substr(raw_file.find_last_of('/') + 1) << "\n";
    }
  } // namespace homogenization
} // namespace tribodyn
