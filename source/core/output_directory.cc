// Claiming an output directory: a run moves an earlier run's files aside,
// whole, only once it has passed every check (see output_directory.h).

#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iostream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/output_directory.h>

namespace tribodyn
{
  namespace fs = std::filesystem;

  namespace
  {
    struct ClaimRegistry
    {
      bool                  guard_on = false;
      std::vector<fs::path> claimed;
    };

    ClaimRegistry &
    claims()
    {
      static ClaimRegistry r;
      return r;
    }

    fs::path
    normalized(const std::string &path)
    {
      return fs::absolute(fs::path(path)).lexically_normal();
    }

    /// Is @p inner @p outer or below it?
    bool
    lies_in(const fs::path &inner, const fs::path &outer)
    {
      auto i = inner.begin();
      for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
        {
          if (o->empty()) // a trailing separator
            continue;
          if (i == inner.end() || *i != *o)
            return false;
        }
      return true;
    }

    /// The entries of @p directory except those named in @p skipped.
    std::vector<fs::path>
    entries_except(const fs::path                 &directory,
                   const std::vector<std::string> &skipped)
    {
      std::vector<fs::path> entries;
      for (const auto &e : fs::directory_iterator(directory))
        {
          const std::string name = e.path().filename().string();
          bool              skip = false;
          for (const auto &s : skipped)
            skip = skip || name == s;
          if (!skip)
            entries.push_back(e.path());
        }
      return entries;
    }


    /// Move @p entries into @p to (created).
    void
    move_entries(const std::vector<fs::path> &entries, const fs::path &to)
    {
      fs::create_directories(to);
      for (const auto &e : entries)
        fs::rename(e, to / e.filename());
    }


    /// Rank 0's part of claim_output_directory(); returns an error message
    /// or an empty string.
    std::string
    claim_on_root(const std::string              &directory,
                  const OutputClaim               how,
                  const std::string              &parameters_text,
                  const std::vector<std::string> &kept)
    {
      try
        {
          create_output_directory(directory);
          const fs::path dir = directory;
          if (how == OutputClaim::fresh)
            {
              std::vector<std::string> skipped = kept;
              skipped.push_back(previous_run_folder);
              const std::vector<fs::path> earlier
                = entries_except(dir, skipped);
              if (!earlier.empty())
                {
                  const fs::path previous = dir / previous_run_folder;
                  if (fs::exists(dir / "summary.json"))
                    {
                      // A finished run replaces the one kept before it.
                      fs::remove_all(previous);
                      move_entries(earlier, previous);
                      std::cout << "The finished run that was in '" << directory
                                << "' moved to '" << previous.string() << "/'."
                                << std::endl;
                    }
                  else
                    {
                      const fs::path unfinished = previous / "unfinished";
                      fs::remove_all(unfinished);
                      move_entries(earlier, unfinished);
                      std::cout << "The unfinished run that was in '"
                                << directory << "' moved to '"
                                << unfinished.string() << "/'." << std::endl;
                    }
                }
            }
          else if (fs::exists(dir / "summary.json"))
            fs::rename(dir / "summary.json", dir / "summary.previous_leg.json");
          claims().claimed.push_back(normalized(directory));
          if (!parameters_text.empty())
            write_file_atomically(join_path(directory, "parameters.prm"),
                                  parameters_text);
        }
      catch (const fs::filesystem_error &e)
        {
          return "Cannot prepare the output directory '" + directory
                 + "' for the run: " + e.what()
                 + ". Check that 'Output directory' is writable, or choose "
                   "another one.";
        }
      catch (const std::exception &e)
        {
          return e.what();
        }
      return "";
    }
  } // namespace


  void
  claim_output_directory(const std::string              &directory,
                         const OutputClaim               how,
                         const std::string              &parameters_text,
                         const MPI_Comm                  comm,
                         const std::vector<std::string> &kept)
  {
    const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    std::string error
      = root ? claim_on_root(directory, how, parameters_text, kept) : "";
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    if (!root)
      claims().claimed.push_back(normalized(directory));
  }


  void
  guard_unclaimed_output_writes()
  {
    claims().guard_on = true;
  }


  void
  assert_output_claimed(const std::string &path)
  {
    const ClaimRegistry &r = claims();
    if (!r.guard_on)
      return;
    const fs::path p = normalized(path);
    for (const auto &d : r.claimed)
      if (lies_in(p, d))
        return;
    // An internal error, found on the process that writes (rank 0) only:
    // end every rank now rather than leave the others waiting in a
    // collective call.
    std::cerr << "tribodyn: internal error (please report it): tribodyn "
                 "wrote '"
              << path
              << "' before claiming its output directory: a refusal after "
                 "this point would have touched an earlier run's results."
              << std::endl;
    MPI_Abort(MPI_COMM_WORLD, exit_code::internal_error);
  }
} // namespace tribodyn
