#include <cstdio>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <tribodyn/core/application.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/global_parameters.h>
#include <tribodyn/core/interruption.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/output_directory.h>
#include <tribodyn/core/parameter_file.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/core/version.h>

namespace tribodyn
{
  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out << "tribodyn " << version_string << "\n"
          << "Dynamics of friction in composites: homogenization, explicit "
             "contact with friction, movable cellular automata.\n\n"
          << "Usage:\n"
          << "  tribodyn FILE.prm                 run the problem described "
             "in FILE.prm\n"
          << "  mpirun -np N tribodyn FILE.prm    the same on N MPI ranks\n"
          << "  tribodyn --print-parameters [PROBLEM]\n"
          << "                                    print every parameter with "
             "its documentation and default\n"
          << "  tribodyn --partition-report N FILE.prm\n"
          << "                                    how FILE.prm's scene would "
             "be split over N ranks (mca), without running it\n"
          << "  tribodyn --version | --help\n\n"
          << "Problems:";
      for (const auto &p : registered_problems())
        out << "\n  " << p.name << ": " << p.description;
      out << "\n";
    }


    void
    declare_all(dealii::ParameterHandler &prm, const ProblemDescription &p)
    {
      GlobalParameters::declare_parameters(prm);
      p.declare_parameters(prm);
    }


    void
    print_parameters(std::ostream &out, const std::string &only_problem)
    {
      bool found = only_problem.empty();
      for (const auto &p : registered_problems())
        {
          if (!only_problem.empty() && p.name != only_problem)
            continue;
          found = true;
          dealii::ParameterHandler prm;
          declare_all(prm, p);
          prm.set("Problem", p.name);
          out << "# Parameters of 'set Problem = " << p.name << "' ("
              << p.description << "), tribodyn " << version_number << "\n";
          prm.print_parameters(out, dealii::ParameterHandler::PRM);
          out << "\n";
        }
      if (!found)
        find_problem(only_problem); // throws with the list of problems
    }


    int
    partition_report(const std::string &count,
                     const std::string &file,
                     const MPI_Comm     comm)
    {
      unsigned long n_ranks = 0;
      try
        {
          std::size_t used = 0;
          n_ranks          = std::stoul(count, &used);
          if (used != count.size())
            n_ranks = 0;
        }
      catch (const std::exception &)
        {
          n_ranks = 0;
        }
      if (n_ranks == 0 || n_ranks > 1000000)
        throw InputError("'--partition-report' takes a number of ranks "
                         "between 1 and 10^6 and a parameter file; got '"
                         + count + "'.");
      dealii::ParameterHandler  prm;
      const ProblemDescription &description = read_parameter_file(file, prm);
      if (!description.partition_report)
        throw InputError("'--partition-report' is available for the mca "
                         "problem only; '"
                         + file + "' sets Problem = " + description.name + ".");
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        description.partition_report(prm, n_ranks, std::cout);
      return exit_code::success;
    }


    int
    run_parameter_file(const std::string &file, const MPI_Comm comm)
    {
      dealii::ParameterHandler  prm;
      const ProblemDescription &description = read_parameter_file(file, prm);

      GlobalParameters global;
      global.parse_parameters(prm);

      RunContext context;
      context.mpi_communicator  = comm;
      context.output_directory  = global.output_directory;
      context.parameter_file    = file;
      context.progress_interval = global.progress_interval;
      // parameters.prm: printed when the problem claims its directory,
      // after it has parsed (and completed) the parameters.
      context.parameters_text = [&prm, file]() {
        std::ostringstream used;
        used << "# Parameters used by tribodyn " << version_string << " for '"
             << file << "'\n";
        prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
        return used.str();
      };

      // Nothing is written before the problem has passed every check: it
      // then claims the output directory (output_directory.h), which moves
      // an earlier run's results aside, whole, and writes parameters.prm.
      guard_unclaimed_output_writes();
      std::unique_ptr<Problem> problem = description.create(prm, context);
      problem->run();
      return exit_code::success;
    }
  } // namespace


  int
  run_application(int argc, char **argv)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

    std::vector<std::string> args(argv + 1, argv + argc);
    try
      {
        if (args.empty() || args[0] == "--help" || args[0] == "-h")
          {
            if (root)
              print_usage(args.empty() ? std::cerr : std::cout);
            return args.empty() ? exit_code::input_error : exit_code::success;
          }
        if (args[0] == "--version")
          {
            if (root)
              std::cout << "tribodyn " << version_string << std::endl;
            return exit_code::success;
          }
        if (args[0] == "--print-parameters")
          {
            if (args.size() > 2)
              throw InputError("'--print-parameters' takes at most one "
                               "argument, the problem name.");
            if (root)
              print_parameters(std::cout, args.size() == 2 ? args[1] : "");
            return exit_code::success;
          }
        if (args[0] == "--partition-report")
          {
            if (args.size() != 3)
              throw InputError("Usage: tribodyn --partition-report N "
                               "FILE.prm");
            return partition_report(args[1], args[2], comm);
          }
        if (args[0].size() > 1 && args[0][0] == '-')
          throw InputError("Unknown option '" + args[0]
                           + "'. Run 'tribodyn --help' for the usage.");
        if (args.size() != 1)
          throw InputError(
            "tribodyn takes one parameter file; got "
            + std::to_string(args.size())
            + " arguments. Run 'tribodyn --help' for the usage.");
        return run_parameter_file(args[0], comm);
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "tribodyn: error: " << e.what() << std::endl;
        return exit_code::input_error;
      }
    catch (const Interrupted &e)
      {
        if (root)
          std::cerr << "tribodyn: interrupted: " << e.what() << std::endl;
        return exit_code::interrupted_base + e.signal_number;
      }
    catch (const RunError &e)
      {
        if (root)
          std::cerr << "tribodyn: the run stopped: " << e.what()
                    << " The outputs written so far are kept (the CSV series "
                       "up to the last recorded row); no summary.json is "
                       "written for a run that did not complete."
                    << std::endl;
        return exit_code::run_error;
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::cerr << "tribodyn: internal error (please report it): ";
        e.print_info(std::cerr);
        std::cerr << std::endl;
        return exit_code::internal_error;
      }
    catch (const std::exception &e)
      {
        std::cerr << "tribodyn: internal error (please report it): " << e.what()
                  << std::endl;
        return exit_code::internal_error;
      }
  }
} // namespace tribodyn
