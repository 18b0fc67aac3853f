// Checkpoint storage (two slots and an atomically replaced pointer file),
// the Checkpoint parameters, CSV truncation for resumed runs, and the
// SIGTERM/SIGINT handling of long runs (doc/user_guide.md, "Checkpoints").
#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <functional>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/output_directory.h>
#include <tribodyn/core/parameter_renames.h>
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
    /// Parameter lines as a run of any version compares them: renamed
    /// entries in their current names (with_current_names()), a value that
    /// is one number in one spelling ("0.5e6" and "5e5", as defaults were
    /// written before and after they came from the parameter structs),
    /// sorted.
    std::vector<std::string>
    comparable_lines(const std::vector<std::string> &lines)
    {
      std::vector<std::string> out;
      for (std::string line : with_current_names(lines))
        {
          const auto eq = line.find(" = ");
          if (eq != std::string::npos)
            {
              const std::string value = line.substr(eq + 3);
              try
                {
                  std::size_t  used = 0;
                  const double x    = std::stod(value, &used);
                  if (used == value.size())
                    {
                      line = line.substr(0, eq + 3) + exact_number(x);
                    }
                }
              catch (const std::exception &)
                {
                  // not a number: compared as written
                }
            }
          out.push_back(line);
        }
      std::sort(out.begin(), out.end());
      return out;
    }
  } // namespace


  std::vector<std::string>
  resumable_parameter_lines(std::istream      &short_prm,
                            const std::string &end_time_entry,
                            double            *end_time)
  {
    std::vector<std::string> sections, lines;
    std::string              line;
    auto                     trim = [](const std::string &s) {
      const auto b = s.find_first_not_of(" \t");
      const auto e = s.find_last_not_of(" \t\r");
      return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    };
    while (std::getline(short_prm, line))
      {
        line = trim(line);
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(trim(line.substr(11)));
        else if (line == "end" && !sections.empty())
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const auto  eq = line.find('=');
            std::string path;
            for (const auto &s : sections)
              path += s + "/";
            path += trim(line.substr(4, eq - 4));
            lines.push_back(path + " = "
                            + (eq == std::string::npos
                                 ? std::string()
                                 : trim(line.substr(eq + 1))));
          }
      }
    // a run written before a rename reads as one of the current names
    std::vector<std::string> kept;
    for (const std::string &l : comparable_lines(lines))
      {
        const std::string path = l.substr(0, l.find(" = "));
        if (path == end_time_entry && end_time != nullptr)
          *end_time = std::stod(l.substr(l.find(" = ") + 3));
        if (path == end_time_entry || path == "Progress interval"
            || path == "Output directory" || path.rfind("Checkpoint/", 0) == 0)
          continue;
        kept.push_back(l);
      }
    return kept;
  }


  ResumableParameters
  resumable_parameters(dealii::ParameterHandler &prm,
                       const std::string        &end_time_entry)
  {
    ResumableParameters r;
    std::ostringstream  text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    std::istringstream short_prm(text.str());
    r.lines = resumable_parameter_lines(short_prm, end_time_entry);
    // Every entry's default, from deal.II's JSON description of the
    // declared tree (an entry is an object with a "default_value").
    std::ostringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    std::vector<std::string>                                       lines;
    const std::function<void(const nlohmann::json &, std::string)> walk
      = [&](const nlohmann::json &node, const std::string &path) {
          for (auto it = node.begin(); it != node.end(); ++it)
            if (it.value().is_object())
              {
                if (it.value().contains("default_value"))
                  {
                    lines.push_back(
                      path + it.key() + " = "
                      + it.value()["default_value"].get<std::string>());
                    const auto doc    = it.value().find("documentation");
                    const auto tagged = [&doc, &it](const char *tag) {
                      return doc != it.value().end() && doc->is_string()
                             && doc->get<std::string>().find(tag)
                                  != std::string::npos;
                    };
                    if (tagged(ParameterBinding::analysis_only_tag))
                      r.analysis_only.push_back(path + it.key());
                    if (tagged(ParameterBinding::layout_only_tag))
                      r.layout_only.push_back(path + it.key());
                  }
                else
                  walk(it.value(), path + it.key() + "/");
              }
        };
    walk(nlohmann::json::parse(json.str()), "");
    r.defaults = comparable_lines(lines);
    std::sort(r.analysis_only.begin(), r.analysis_only.end());
    std::sort(r.layout_only.begin(), r.layout_only.end());
    return r;
  }


  std::string
  quoted_names(const std::vector<std::string> &names)
  {
    std::string list;
    for (const std::string &name : names)
      list += (list.empty() ? "'" : ", '") + name + "'";
    return list;
  }


  std::vector<std::string>
  ResumableParameters::differing_in_run(
    const std::vector<std::string> &stored) const
  {
    std::vector<std::string> names;
    for (const std::string &name : differing(stored))
      if (!std::binary_search(analysis_only.begin(), analysis_only.end(), name))
        names.push_back(name);
    return names;
  }


  std::vector<std::string>
  ResumableParameters::differing(const std::vector<std::string> &stored) const
  {
    // Both sides without the lines that say "this entry is at its
    // default": what remains is each run's choices (the stored lines in
    // today's names and spellings first; this run's are already).
    const auto choices = [this](const std::vector<std::string> &comparable) {
      std::set<std::string> kept;
      for (const std::string &l : comparable)
        if (!std::binary_search(defaults.begin(), defaults.end(), l))
          kept.insert(l);
      return kept;
    };
    const std::set<std::string> a = choices(comparable_lines(stored)),
                                b = choices(lines);
    std::set<std::string> names;
    for (const auto &s : a)
      if (!b.count(s))
        names.insert(s.substr(0, s.find(" = ")));
    for (const auto &s : b)
      if (!a.count(s))
        names.insert(s.substr(0, s.find(" = ")));
    // (the work's layout: never a difference)
    for (const std::string &name : layout_only)
      names.erase(name);
    return {names.begin(), names.end()};
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
      // a checkpoint written before a rename: its lines in today's names
      info.parameters = comparable_lines(info.parameters);
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


  // ---- interruptions

  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;

    void
    record_signal(int signal_number)
    {
      // A second signal stops at once (no checkpoint): the usual
      // "press Ctrl-C twice".
      if (received_signal != 0)
        {
          std::signal(signal_number, SIG_DFL);
          std::raise(signal_number);
          return;
        }
      received_signal = signal_number;
    }
  } // namespace


  namespace
  {
    bool acknowledged = false;
    /// Handlers alive: a study installs them around its scenes, each
    /// scene's time loop inside; a signal the outer ones recorded (between
    /// two scenes, during a scene's set-up) is not forgotten by the inner.
    unsigned int handler_depth = 0;
  } // namespace


  InterruptHandlers::InterruptHandlers()
  {
    if (handler_depth++ == 0)
      {
        received_signal = 0;
        acknowledged    = false;
      }
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = record_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, &previous_term);
    sigaction(SIGINT, &action, &previous_int);
  }


  InterruptHandlers::~InterruptHandlers()
  {
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGINT, &previous_int, nullptr);
    if (--handler_depth > 0)
      return; // the outer handlers act on a pending signal
    const int pending = received_signal;
    received_signal   = 0;
    if (pending != 0 && !acknowledged)
      std::raise(pending);
  }


  void
  InterruptHandlers::acknowledge()
  {
    acknowledged = true;
  }


  int
  local_interrupt_signal()
  {
    return received_signal;
  }


  Interrupted::Interrupted(const int signal, const std::string &message)
      : std::runtime_error(message)
      , signal_number(signal)
  {
  }


  RunHealth
  agree_on_health(const double   local_badness,
                  const MPI_Comm comm,
                  double        *shared_max)
  {
    double values[3] = {local_badness >= 0 ? local_badness : 1e300,
                        static_cast<double>(received_signal),
                        shared_max ? *shared_max : 0.};
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      MPI_Allreduce(
        MPI_IN_PLACE, values, shared_max ? 3 : 2, MPI_DOUBLE, MPI_MAX, comm);
    RunHealth h;
    h.badness = values[0];
    h.signal  = static_cast<int>(values[1]);
    if (shared_max)
      *shared_max = values[2];
    return h;
  }
} // namespace tribodyn
