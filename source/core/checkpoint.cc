// Checkpoint storage (two slots and an atomically replaced pointer file),
// the Checkpoint parameters and CSV truncation for resumed runs
// (doc/user_guide.md, "Checkpoints").
#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/output_directory.h>
#include <unistd.h>

namespace tribodyn
{
  ParameterBinding
  CheckpointParameters::binding()
  {
    ParameterBinding b("Checkpoint");
    b.add("Interval",
          interval,
          "Simulated time between two checkpoints of the run's state (s), "
          "written to 'Output directory'/checkpoint/ (two slots, switched "
          "atomically: a crash while writing leaves the previous checkpoint "
          "usable). A checkpoint is also written at the end of the run when "
          "the interval is > 0, and always on SIGTERM or SIGINT. 0: no "
          "periodic checkpoints.",
          dealii::Patterns::Double(0.));
    b.add("Resume",
          resume,
          "true: continue from the latest checkpoint in 'Output directory' "
          "(same parameters except the end time, which may be larger, and "
          "this subsection; any number of MPI ranks: the state is "
          "redistributed when the count changed). The CSV series are "
          "continued without duplicate or missing rows and the run reaches "
          "the same result as an uninterrupted one. false: start afresh "
          "(older checkpoints of the directory are forgotten).");
    return b;
  }


  void
  CheckpointParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    CheckpointParameters().binding().declare(prm);
  }


  void
  CheckpointParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    const ParameterBinding b = binding();
    b.parse(prm);
    check_parameter(std::isfinite(interval) && interval >= 0,
                    b.path("Interval"),
                    "must be a finite time >= 0 (s); got "
                      + format_number(interval) + ".");
  }


  namespace
  {
    // Format 2 frames each rank's file (frame_of() below); format 1 files
    // (no frame) are still read.
    constexpr const char *format_line = "tribodyn checkpoint 2";
    constexpr const char *format_1    = "tribodyn checkpoint 1";

    /// 64-bit FNV-1a hash of @p data.
    std::uint64_t
    fnv1a(const char *data, const std::size_t n)
    {
      std::uint64_t h = 14695981039346656037ull;
      for (std::size_t i = 0; i < n; ++i)
        {
          h ^= static_cast<unsigned char>(data[i]);
          h *= 1099511628211ull;
        }
      return h;
    }

    // A rank's file: "TDYNBLOB", the blob's size and its hash (8 bytes
    // each), then the blob; a file that was overwritten, truncated or
    // changed on disk fails unframe() instead of reaching the engine's
    // archive reader (which may fail in any way on garbage).
    constexpr std::size_t frame_header = 24;

    std::string
    frame_of(const std::string &blob)
    {
      std::string         head("TDYNBLOB");
      const std::uint64_t words[2]
        = {blob.size(), fnv1a(blob.data(), blob.size())};
      head.append(reinterpret_cast<const char *>(words), sizeof(words));
      return head;
    }

    /// Check the frame of a file's content @p file and remove it, leaving
    /// the blob (in place: no copy of a large checkpoint); false if the
    /// frame does not hold.
    bool
    unframe(std::string &file)
    {
      if (file.size() < frame_header || file.compare(0, 8, "TDYNBLOB") != 0)
        return false;
      std::uint64_t words[2];
      std::memcpy(words, file.data() + 8, sizeof(words));
      if (words[0] != file.size() - frame_header
          || words[1] != fnv1a(file.data() + frame_header, words[0]))
        return false;
      file.erase(0, frame_header);
      return true;
    }

    /// Write @p head, then @p content, to @p path through a temporary file
    /// that is flushed to disk (fsync) before the rename: after the rename
    /// the file is complete even if the machine stops.
    void
    write_durably(const std::string &path,
                  const std::string &content,
                  const std::string &head = std::string())
    {
      const std::string temporary = path + ".tmp";
      const int         fd
        = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0)
        throw RunError("Cannot write the checkpoint file '" + temporary
                       + "': " + std::strerror(errno) + ".");
      for (const std::string *part : {&head, &content})
        {
          std::size_t done = 0;
          while (done < part->size())
            {
              const ssize_t n
                = ::write(fd, part->data() + done, part->size() - done);
              if (n < 0 && errno == EINTR)
                continue;
              if (n <= 0)
                {
                  const std::string reason = std::strerror(errno);
                  ::close(fd);
                  std::remove(temporary.c_str());
                  throw RunError("Writing the checkpoint file '" + temporary
                                 + "' failed (" + reason + "; disk full?).");
                }
              done += static_cast<std::size_t>(n);
            }
        }
      const bool synced = ::fsync(fd) == 0;
      ::close(fd);
      if (!synced || std::rename(temporary.c_str(), path.c_str()) != 0)
        {
          std::remove(temporary.c_str());
          throw RunError("Cannot complete the checkpoint file '" + path
                         + "': " + std::strerror(errno) + ".");
        }
    }


    std::string
    read_whole_file(const std::string &path, bool &ok)
    {
      std::ifstream in(path, std::ios::binary);
      ok = static_cast<bool>(in);
      if (!ok)
        return {};
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }
  } // namespace


  CheckpointStore::CheckpointStore(const std::string &output_directory,
                                   const std::string &problem_name,
                                   const MPI_Comm     communicator)
      : path(join_path(output_directory, "checkpoint"))
      , problem(problem_name)
      , comm(communicator)
  {
  }


  std::string
  CheckpointStore::rank_file(const unsigned int slot,
                             const unsigned int rank) const
  {
    std::ostringstream name;
    name << "slot_" << slot << "/rank_" << std::setw(4) << std::setfill('0')
         << rank << ".bin";
    return join_path(path, name.str());
  }


  void
  CheckpointStore::discard()
  {
    assert_output_claimed(path);
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      std::remove(join_path(path, "latest").c_str());
    next_slot = 0;
  }


  void
  CheckpointStore::write(const std::string         &blob,
                         const unsigned long        step,
                         const double               time,
                         const ResumableParameters &parameters)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int slot = next_slot;
    std::string        error;
    assert_output_claimed(path);
    if (rank == 0)
      try
        {
          create_output_directory(
            join_path(path, "slot_" + std::to_string(slot)));
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    throw_collectively(comm, !error.empty(), error);
    try
      {
        write_durably(rank_file(slot, rank), blob, frame_of(blob));
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    throw_collectively(comm, !error.empty(), error);
    if (rank == 0)
      {
        std::ostringstream text;
        text << format_line << "\nproblem = " << problem << "\nslot = " << slot
             << "\nstep = " << step << "\ntime = " << std::setprecision(17)
             << time
             << "\nranks = " << dealii::Utilities::MPI::n_mpi_processes(comm)
             << "\n";
        for (const auto &p : parameters.lines)
          text << "parameter " << p << "\n";
        try
          {
            write_durably(join_path(path, "latest"), text.str());
          }
        catch (const std::exception &e)
          {
            error = e.what();
          }
      }
    throw_collectively(comm, !error.empty(), error);
    next_slot = 1 - slot;
  }


  namespace
  {
    /// The fields of a `latest` file's text (format checked by the caller).
    CheckpointInfo
    parse_checkpoint_info(const std::string &text)
    {
      std::istringstream in(text);
      std::string        line;
      CheckpointInfo     info;
      while (std::getline(in, line))
        {
          if (line.rfind("parameter ", 0) == 0)
            info.parameters.push_back(line.substr(10));
          else if (line.rfind("problem = ", 0) == 0)
            info.problem = line.substr(10);
          else if (line.rfind("slot = ", 0) == 0)
            info.slot = std::stoul(line.substr(7)) == 1 ? 1 : 0;
          else if (line.rfind("step = ", 0) == 0)
            info.step = std::stoul(line.substr(7));
          else if (line.rfind("time = ", 0) == 0)
            info.time = std::stod(line.substr(7));
          else if (line.rfind("ranks = ", 0) == 0)
            info.n_ranks = std::stoul(line.substr(8));
        }
      return info;
    }
  } // namespace


  bool
  read_latest_checkpoint_info(const std::string &output_directory,
                              CheckpointInfo    &info)
  {
    bool              ok   = true;
    const std::string text = read_whole_file(
      join_path(join_path(output_directory, "checkpoint"), "latest"), ok);
    if (!ok
        || (text.rfind(format_line, 0) != 0 && text.rfind(format_1, 0) != 0))
      return false;
    try
      {
        info = parse_checkpoint_info(text);
      }
    catch (const std::exception &)
      {
        return false;
      }
    return info.n_ranks > 0;
  }


  std::vector<std::string>
  CheckpointStore::read(const ResumableParameters &parameters,
                        CheckpointInfo            &info)
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const std::string  latest  = join_path(path, "latest");
    bool               ok      = true;
    std::string        text;
    if (rank == 0)
      text = read_whole_file(latest, ok);
    text              = dealii::Utilities::MPI::broadcast(comm, text, 0);
    const bool framed = text.rfind(format_line, 0) == 0;
    if (!framed && text.rfind(format_1, 0) != 0)
      throw InputError(
        "'Checkpoint/Resume = true' but there is no checkpoint in '" + path
        + "' (file 'latest' missing or not a tribodyn checkpoint). Run "
          "first with 'Checkpoint/Interval' > 0 (or stop a run with "
          "SIGTERM), or set 'Checkpoint/Resume = false'.");

    info                                   = parse_checkpoint_info(text);
    const std::vector<std::string> &stored = info.parameters;
    if (info.problem != problem)
      throw InputError("The checkpoint in '" + path + "' belongs to a '"
                       + info.problem + "' run, not to '" + problem
                       + "': set 'Checkpoint/Resume = false' or choose "
                         "another 'Output directory'.");
    if (info.n_ranks == 0)
      throw InputError("The checkpoint in '" + path
                       + "' does not say how many MPI ranks wrote it (file "
                         "'latest' damaged). Start afresh with "
                         "'Checkpoint/Resume = false'.");
    // The analysis-only entries may change: the resumed run analyses its
    // whole record (saved in the checkpoint) with the new values.
    const std::vector<std::string> names = parameters.differing_in_run(stored);
    if (!names.empty())
      {
        throw InputError(
          "Cannot resume from the checkpoint in '" + path
          + "': these parameters differ from the checkpointed run's: "
          + quoted_names(names)
          + ". A resumed run may change only 'End time' (to a larger value), "
            "the Checkpoint subsection and the entries marked 'Analysis "
            "only' or 'Layout only'; set the others back, or start "
            "afresh with 'Checkpoint/Resume = false'.");
      }

    // This rank's share of the writers' files: r, r + M, ...
    std::vector<std::string> blobs;
    std::string              unreadable, damaged;
    for (unsigned int writer = rank; writer < info.n_ranks; writer += n_ranks)
      {
        const std::string file = rank_file(info.slot, writer);
        blobs.push_back(read_whole_file(file, ok));
        if (!ok && unreadable.empty())
          unreadable = file;
        else if (ok && framed && damaged.empty() && !unframe(blobs.back()))
          damaged = file;
      }
    refuse_collectively(comm,
                        !unreadable.empty(),
                        "The checkpoint in '" + path
                          + "' is incomplete: a rank's file (e.g. '"
                          + unreadable
                          + "') cannot be read. Start afresh with "
                            "'Checkpoint/Resume = false'.");
    refuse_collectively(comm,
                        !damaged.empty(),
                        "The checkpoint in '" + path + "' is damaged: '"
                          + damaged
                          + "' does not hold what was written (its size or "
                            "checksum differ). Start afresh with "
                            "'Checkpoint/Resume = false'.");
    next_slot = 1 - info.slot;
    return blobs;
  }


  void
  read_checkpoint_blobs(
    const MPI_Comm                                                comm,
    const std::vector<std::string>                               &blobs,
    const std::function<void(boost::archive::binary_iarchive &)> &read)
  {
    std::string error;
    for (const std::string &blob : blobs)
      try
        {
          std::istringstream              in(blob, std::ios::binary);
          boost::archive::binary_iarchive archive(in);
          read(archive);
        }
      catch (const InputError &e)
        {
          error = e.what();
          break;
        }
      catch (const std::exception &e)
        {
          error = std::string("The checkpoint cannot be read (") + e.what()
                  + "): it is damaged or from another version of tribodyn. "
                    "Start afresh with 'Checkpoint/Resume = false'.";
          break;
        }
    refuse_collectively(comm, !error.empty(), error);
  }


  std::string
  read_csv_rows(const std::string &path,
                const std::size_t  n_rows,
                const bool         partial_ok)
  {
    std::ifstream in(path);
    std::string   used = path;
    if (!in && partial_ok)
      {
        used = path + ".part";
        in.open(used);
      }
    if (!in)
      throw InputError("Cannot resume: the series '" + path
                       + "' of the checkpointed run is missing. Start afresh "
                         "with 'Checkpoint/Resume = false'.");
    std::string text, line;
    std::size_t rows = 0;
    if (std::getline(in, line))
      text = line + "\n";
    while (rows < n_rows && std::getline(in, line))
      {
        text += line + "\n";
        ++rows;
      }
    if (rows < n_rows)
      throw InputError("Cannot resume: '" + used + "' holds "
                       + std::to_string(rows) + " rows, the checkpoint needs "
                       + std::to_string(n_rows)
                       + " (was the file changed?). Start afresh with "
                         "'Checkpoint/Resume = false'.");
    return text;
  }
} // namespace tribodyn
