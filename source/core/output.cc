#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <sys/stat.h>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/output_directory.h>
#include <tribodyn/core/version.h>
#include <unistd.h>

namespace tribodyn
{
  namespace
  {
    double
    seconds_now()
    {
      return std::chrono::duration<double>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
    }
  } // namespace


  void
  write_file_atomically(const std::string &path, const std::string &content)
  {
    assert_output_claimed(path);
    const std::string temporary
      = path + ".tmp." + std::to_string(static_cast<long>(getpid()));
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out)
        throw InputError("Cannot write the output file '" + path
                         + "' (opening '" + temporary
                         + "' failed: " + std::strerror(errno)
                         + "). Check that 'Output directory' is writable and "
                           "that the disk is not full.");
      out << content;
      out.flush();
      if (!out)
        throw InputError("Writing the output file '" + path
                         + "' failed (disk full?).");
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        throw InputError("Cannot rename '" + temporary + "' to '" + path
                         + "': " + std::strerror(errno) + ".");
      }
  }


  template <int dim, int spacedim>
  void
  write_vtu_file(const dealii::DataOutInterface<dim, spacedim> &data_out,
                 const std::string                             &path,
                 const MPI_Comm                                 comm)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        data_out.write_vtu_in_parallel(path, comm);
        return;
      }
    std::ostringstream out;
    data_out.write_vtu(out);
    write_file_atomically(path, out.str());
  }

  template void
  write_vtu_file(const dealii::DataOutInterface<2, 2> &,
                 const std::string &,
                 const MPI_Comm);
  template void
  write_vtu_file(const dealii::DataOutInterface<3, 3> &,
                 const std::string &,
                 const MPI_Comm);


  void
  create_output_directory(const std::string &directory)
  {
    if (directory.empty())
      throw InputError("Parameter 'Output directory' is empty: give the "
                       "directory where the results should be written.");
    // Create every component of the path in turn (mkdir -p).
    std::string partial;
    std::size_t position = 0;
    while (position != std::string::npos)
      {
        position = directory.find('/', position + 1);
        partial  = directory.substr(0, position);
        if (partial.empty())
          continue;
        if (mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST)
          throw InputError("Cannot create the output directory '" + directory
                           + "' (at '" + partial + "': " + std::strerror(errno)
                           + "). Set 'Output directory' to a writable path.");
      }
    struct stat info;
    if (stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
      throw InputError("'Output directory' = '" + directory
                       + "' exists but is not a directory.");
    if (access(directory.c_str(), W_OK) != 0)
      throw InputError("The output directory '" + directory
                       + "' is not writable. Set 'Output directory' to a "
                         "writable path.");
  }


  void
  run_plot_script(const std::string &script_in,
                  const std::string &default_script,
                  const std::string &parameter,
                  const std::string &directory)
  {
    std::string script = script_in;
    if (script == "none")
      return;
    const std::string python
      = file_exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    if (script == "auto")
      {
        char          buffer[4096];
        const ssize_t n
          = readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
        const std::string executable(buffer, n > 0 ? n : 0);
        script = executable.substr(0, executable.find_last_of('/'))
                 + "/../scripts/" + default_script;
        if (!file_exists(script))
          {
            std::cout << "No plots: scripts/" << default_script
                      << " not found next to the executable (set '" << parameter
                      << "')." << std::endl;
            return;
          }
        if (std::system(
              (python + " -c 'import matplotlib' >/dev/null 2>&1").c_str())
            != 0)
          {
            std::cout << "No plots: python3 with matplotlib is not "
                         "available (Debian: python3-matplotlib)."
                      << std::endl;
            return;
          }
      }
    const std::string command
      = python + " '" + script + "' '" + directory + "'";
    if (std::system(command.c_str()) != 0)
      std::cout << "The plot script failed: " << command << std::endl;
  }


  bool
  file_exists(const std::string &path)
  {
    struct stat info;
    return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
  }


  bool
  read_csv_columns(const std::string                &path,
                   const std::vector<std::string>   &names,
                   std::vector<std::vector<double>> &columns)
  {
    columns.assign(names.size(), {});
    std::ifstream in(path);
    std::string   line;
    if (!std::getline(in, line))
      return false;
    const auto header = dealii::Utilities::split_string_list(line, ',');
    std::vector<std::size_t> index;
    for (const std::string &name : names)
      {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it == header.end())
          return false;
        index.push_back(it - header.begin());
      }
    while (std::getline(in, line))
      {
        const auto fields = dealii::Utilities::split_string_list(line, ',');
        if (fields.size() != header.size())
          break; // a partly written last line
        try
          {
            for (std::size_t c = 0; c < index.size(); ++c)
              columns[c].push_back(std::stod(fields[index[c]]));
          }
        catch (const std::exception &)
          {
            columns.assign(names.size(), {});
            return false;
          }
      }
    return true;
  }


  std::string
  join_path(const std::string &directory, const std::string &file)
  {
    if (directory.empty() || directory.back() == '/')
      return directory + file;
    return directory + "/" + file;
  }


  CsvWriter::CsvWriter(const std::string              &path,
                       const std::vector<std::string> &columns,
                       const bool                      active,
                       const double min_seconds_between_flushes)
      : path_name(path)
      , n_columns(columns.size())
      , is_active(active)
      , min_interval(min_seconds_between_flushes)
  {
    for (unsigned int i = 0; i < columns.size(); ++i)
      text += (i > 0 ? "," : "") + columns[i];
    text += "\n";
    dirty = true;
    flush(true);
  }


  CsvWriter::CsvWriter(const std::string              &path,
                       const std::vector<std::string> &columns,
                       const bool                      active,
                       const std::size_t               rows_kept,
                       const double min_seconds_between_flushes)
      : path_name(path)
      , n_columns(columns.size())
      , row_count(rows_kept)
      , is_active(active)
      , min_interval(min_seconds_between_flushes)
  {
    if (!is_active)
      return;
    std::string header;
    for (unsigned int i = 0; i < columns.size(); ++i)
      header += (i > 0 ? "," : "") + columns[i];
    text = read_csv_rows(path, rows_kept);
    if (text.compare(0, header.size() + 1, header + "\n") != 0)
      throw InputError("Cannot resume: the header of '" + path
                       + "' differs from this run's columns. Start afresh "
                         "with 'Checkpoint/Resume = false'.");
    dirty = true;
    flush(true);
  }


  CsvWriter::~CsvWriter()
  {
    try
      {
        flush(true);
      }
    catch (...)
      {
        // A destructor must not throw; the file keeps its last good state.
      }
  }


  void
  CsvWriter::add_row(const std::vector<double> &values)
  {
    add_row({}, values);
  }


  void
  CsvWriter::add_row(const std::vector<std::string> &labels,
                     const std::vector<double>      &values)
  {
    if (labels.size() + values.size() != n_columns)
      throw std::logic_error("CsvWriter: row of "
                             + std::to_string(labels.size() + values.size())
                             + " entries for " + std::to_string(n_columns)
                             + " columns in " + path_name);
    ++row_count;
    if (!is_active)
      return;
    std::ostringstream row;
    row << std::setprecision(10);
    bool first = true;
    for (const auto &l : labels)
      {
        row << (first ? "" : ",") << l;
        first = false;
      }
    for (const double v : values)
      {
        row << (first ? "" : ",") << v;
        first = false;
      }
    row << "\n";
    text += row.str();
    dirty = true;
  }


  void
  CsvWriter::flush(const bool force)
  {
    if (!is_active || !dirty || path_name.empty())
      return;
    const double now = seconds_now();
    if (!force && now - last_flush_time < min_interval)
      return;
    write_file_atomically(path_name, text);
    last_flush_time = now;
    dirty           = false;
  }


  const std::string &
  CsvWriter::path() const
  {
    return path_name;
  }


  PvdWriter::PvdWriter(const std::string &path, const bool active)
      : path_name(path)
      , is_active(active)
  {
  }


  void
  PvdWriter::restore(const std::vector<std::pair<double, std::string>> &entries)
  {
    records = entries;
  }


  void
  PvdWriter::add(const double time, const std::string &file_name)
  {
    records.emplace_back(time, file_name);
    write();
  }


  void
  PvdWriter::write() const
  {
    if (!is_active || records.empty())
      return;
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    out << std::setprecision(12);
    for (const auto &r : records)
      out << "    <DataSet timestep=\"" << r.first
          << "\" group=\"\" part=\"0\" file=\"" << r.second << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    write_file_atomically(path_name, out.str());
  }


  JsonValue
  summary_header(const std::string &problem, const MPI_Comm comm)
  {
    JsonValue header           = JsonValue::object();
    header["problem"]          = problem;
    header["tribodyn_version"] = version_string;
    header["n_mpi_ranks"]      = dealii::Utilities::MPI::n_mpi_processes(comm);
    return header;
  }
} // namespace tribodyn
