// `set Problem = mca_study`: the automata study driver. Its scenes, the
// decision per scene (run, resume, reuse), the rank groups. Parameters:
// mca_study_parameters.cc; analysis and tables: mca_study_analysis.cc.

#include "mca_study_analysis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/interruption.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/parameter_file.h>
#include <tribodyn/core/version.h>
#include <tribodyn/mca/mca_problem.h>
#include <tribodyn/study/mca_study.h>

namespace tribodyn
{
  namespace study
  {
    using dealii::ParameterHandler;

    namespace
    {
      /// @p verdict() run on the first rank of @p comm alone (it reads a
      /// scene's files), its result sent to the others; an error it throws
      /// is thrown on every rank (an InputError as one), so that none waits
      /// for a result that never comes.
      template <typename Verdict>
      int
      first_rank_verdict(const MPI_Comm comm, const Verdict &verdict)
      {
        int         result = 0, kind = 0;
        std::string message;
        if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              result = verdict();
            }
          catch (const InputError &e)
            {
              kind    = 1;
              message = e.what();
            }
          catch (const std::exception &e)
            {
              kind    = 2;
              message = e.what();
            }
        kind    = dealii::Utilities::MPI::broadcast(comm, kind, 0);
        message = dealii::Utilities::MPI::broadcast(comm, message, 0);
        if (kind == 1)
          throw InputError(message);
        if (kind == 2)
          throw std::runtime_error(message);
        return dealii::Utilities::MPI::broadcast(comm, result, 0);
      }


      /// A directory-name piece of a factor's value or name.
      std::string
      name_piece(const std::string &text)
      {
        std::string piece;
        for (const char c : text)
          piece += std::isalnum(static_cast<unsigned char>(c)) || c == '.'
                       || c == '+' || c == '-'
                     ? c
                     : '-';
        return piece;
      }
    } // namespace


    void
    McaStudyProblem::declare_parameters(ParameterHandler &prm)
    {
      McaStudyParameters::declare_parameters(prm);
    }


    McaStudyProblem::McaStudyProblem(ParameterHandler &prm,
                                     const RunContext &context)
        : context(context)
    {
      parameters.parse_parameters(prm, context.parameter_file);

      // The scenes: every combination of the factors' levels (the first
      // factor slowest) x seeds x bases.
      std::size_t n_levels = 1;
      for (const auto &f : parameters.factors)
        n_levels *= f.values.size();
      for (std::size_t l = 0; l < n_levels; ++l)
        {
          std::vector<std::string> levels(parameters.factors.size());
          std::string              suffix;
          for (std::size_t k = 0, rest = l; k < parameters.factors.size(); ++k)
            {
              const auto &f      = parameters.factors[k];
              std::size_t stride = 1;
              for (std::size_t m = k + 1; m < parameters.factors.size(); ++m)
                stride *= parameters.factors[m].values.size();
              levels[k] = f.values[rest / stride];
              rest %= stride;
              const std::string name = f.path.substr(f.path.rfind('/') + 1);
              suffix += "_" + name_piece(name) + name_piece(levels[k]);
            }
          for (unsigned int s = 0; s < parameters.roughness_seeds.size(); ++s)
            for (unsigned int b = 0; b < parameters.bases.size(); ++b)
              {
                McaScene scene;
                scene.base           = b;
                scene.roughness_seed = parameters.roughness_seeds[s];
                scene.inclusion_seed = parameters.inclusion_seeds[s];
                scene.seed_index     = s;
                scene.level_index    = l;
                scene.levels         = levels;
                scene.name           = parameters.bases[b].name + "_seed"
                             + std::to_string(scene.roughness_seed);
                if (scene.inclusion_seed != scene.roughness_seed)
                  scene.name
                    += "_inclusions" + std::to_string(scene.inclusion_seed);
                scene.name += suffix;
                study_scenes.push_back(scene);
              }
        }

      // Every scene's parameters checked now, before anything is written
      // or run: a fault in the fourth scene's file stops the study here.
      for (const McaScene &scene : study_scenes)
        {
          ParameterHandler scene_prm;
          scene_parameters(scene, scene_prm);
          refuse_repeated_scene(scene, scene_prm);
          RunContext check       = context;
          check.output_directory = scene_directory(scene);
          mca::McaProblem problem(scene_prm, check);
          // (the scene's files read on the first rank alone: the work per
          // rank does not grow with the ranks)
          first_rank_verdict(context.mpi_communicator, [&] {
            std::vector<std::string> changed;
            return int(scene_start(scene, scene_prm, changed));
          });
        }
    }


    void
    McaStudyProblem::refuse_repeated_scene(const McaScene   &scene,
                                           ParameterHandler &prm) const
    {
      // A base without inclusions does not depend on the inclusion seed:
      // on a roughness seed listed twice its scenes would be one scene run
      // twice, and the pairs sharing it would be counted as independent.
      const auto &seeds = parameters.roughness_seeds;
      const bool  repeat
        = std::count(seeds.begin(), seeds.end(), scene.roughness_seed) > 1;
      if (!repeat
          || get_parameter_by_path(prm,
                                   "Geometry/Inclusions/Enabled",
                                   "Study/Bases")
               == "true")
        return;
      throw InputError(
        "'Study/Roughness seeds' lists the seed "
        + std::to_string(scene.roughness_seed)
        + " more than once (with other inclusion seeds), but the base '"
        + parameters.bases[scene.base].name
        + "' has no inclusions ('Geometry/Inclusions/Enabled = false'): its "
          "scenes on that seed would be one scene run again, and the pairs "
          "sharing it would count as independent. Study several inclusion "
          "seeds of one surface with the bases that have inclusions only "
          "(and compare with the other base's scene of that seed from "
          "another study), or list each roughness seed once.");
    }


    std::string
    McaStudyProblem::scene_directory(const McaScene &scene) const
    {
      return join_path(join_path(context.output_directory, "scenes"),
                       scene.name);
    }


    void
    McaStudyProblem::scene_parameters(const McaScene   &scene,
                                      ParameterHandler &prm) const
    {
      const auto &base = parameters.bases[scene.base];
      try
        {
          const ProblemDescription &problem
            = read_parameter_file(base.file, prm);
          if (problem.name != "mca")
            throw InputError("it sets 'Problem = " + problem.name
                             + "'; an automata study runs 'mca' scenes.");
        }
      catch (const InputError &e)
        {
          throw InputError("'Study/Bases': the base scene '" + base.name + "' ("
                           + base.file + ") cannot be used: " + e.what());
        }
      prm.set("Output directory", scene_directory(scene));
      set_parameter_by_path(prm,
                            McaStudyParameters::roughness_seed_path,
                            std::to_string(scene.roughness_seed),
                            "Study/Roughness seeds");
      set_parameter_by_path(prm,
                            McaStudyParameters::inclusion_seed_path,
                            std::to_string(scene.inclusion_seed),
                            "Study/Inclusion seeds");
      for (const auto &[path, value] : parameters.settings)
        set_parameter_by_path(prm, path, value, "Study/Settings");
      for (std::size_t k = 0; k < parameters.factors.size(); ++k)
        set_parameter_by_path(prm,
                              parameters.factors[k].path,
                              scene.levels[k],
                              "Study/Factors");
      if (parameters.end_time > 0)
        set_parameter_by_path(prm,
                              McaStudyParameters::end_time_path,
                              format_number(parameters.end_time),
                              "Time/End time");
      if (parameters.checkpoint_interval > 0)
        set_parameter_by_path(prm,
                              "Checkpoint/Interval",
                              format_number(parameters.checkpoint_interval),
                              "Study/Checkpoint interval");
      set_parameter_by_path(prm, "Checkpoint/Resume", "false", "Study");
    }


    McaStudyProblem::Start
    McaStudyProblem::scene_start(const McaScene           &scene,
                                 ParameterHandler         &prm,
                                 std::vector<std::string> &changed) const
    {
      const std::string         dir = scene_directory(scene);
      const ResumableParameters wanted
        = resumable_parameters(prm, McaStudyParameters::end_time_path);
      const double end_time = std::stod(get_parameter_by_path(
        prm, McaStudyParameters::end_time_path, "Time/End time"));

      // A finished run of these parameters to this end time: reused. Its
      // parameters.prm is read as text, so that a scene written by a
      // version before a parameter was renamed or added (at its default
      // here) is still recognised.
      bool finished = false;
      if (file_exists(join_path(dir, "summary.json"))
          && file_exists(join_path(dir, "parameters.prm")))
        {
          std::ifstream in(join_path(dir, "parameters.prm"));
          double        old_end = -1;
          const auto    lines
            = resumable_parameter_lines(in,
                                        McaStudyParameters::end_time_path,
                                        &old_end);
          if (std::abs(old_end - end_time) <= 1e-12 * end_time
              && wanted.differing_in_run(lines).empty())
            {
              if (wanted.same_as(lines))
                return Start::reuse;
              finished = true;
              changed  = wanted.differing(lines);
            }
        }
      // An interrupted run (or a shorter finished one) with a checkpoint
      // of these parameters before the end time: resumed. A finished one
      // that differs only in how its record is analysed, with its
      // checkpoint at the end time: resumed there to analyse it again.
      CheckpointInfo info;
      if (read_latest_checkpoint_info(dir, info) && info.problem == "mca"
          && wanted.differing_in_run(info.parameters).empty())
        {
          if (info.time < end_time * (1 - 1e-12))
            return Start::resume;
          if (finished)
            return Start::reanalyse;
        }
      // A finished run that differs only in how its record is analysed,
      // but without the checkpoint to analyse it again from (its
      // summary.json and series copied without checkpoints/, as data/
      // keeps them): not run again silently (an hour's scene overwritten),
      // refused.
      if (finished)
        {
          throw InputError(
            "Scene " + scene.name + ": the finished run in " + dir
            + " differs from this study only in the analysis-only "
            + quoted_names(changed)
            + ", but it has no checkpoint at its end time to analyse its "
              "record again from (was it copied without its checkpoint/ "
              "directory?). Copy its checkpoint/ in beside its "
              "summary.json, or set those entries as its parameters.prm "
              "has them to reuse it as it is, or remove "
            + dir + " to run the scene again.");
        }
      return Start::fresh;
    }


    void
    McaStudyProblem::run_scene(const McaScene &scene,
                               const MPI_Comm  group) const
    {
      const bool group_root
        = dealii::Utilities::MPI::this_mpi_process(group) == 0;
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(group);
      const std::string dir = scene_directory(scene);

      ParameterHandler prm;
      scene_parameters(scene, prm);
      std::vector<std::string> changed;
      // (changed: on the group's first rank, which prints it)
      const int         start = first_rank_verdict(group, [&] {
        return int(scene_start(scene, prm, changed));
      });
      const std::string how   = start == int(Start::reuse)       ? "reused"
                                : start == int(Start::resume)    ? "resumed"
                                : start == int(Start::reanalyse) ? "reanalysed"
                                                                 : "run";
      if (group_root)
        {
          std::cout << "Scene " << scene.name << ": "
                    << (start == int(Start::reuse)
                          ? "reused (a finished run of the same parameters "
                            "in "
                              + dir + ")"
                        : start == int(Start::resume)
                          ? "resumed from its checkpoint in " + dir
                        : start == int(Start::reanalyse)
                          ? "re-analysed (a finished run in " + dir
                              + " whose analysis-only " + quoted_names(changed)
                              + " changed: resumed from its checkpoint at "
                                "the end time, no step run)"
                          : "run in " + dir)
                    << " on " << n_ranks << " MPI rank(s)" << std::endl;
        }
      if (start == int(Start::reuse))
        {
          if (group_root)
            tag_scene_summary(dir, scene, parameters);
          return;
        }
      if (start == int(Start::resume) || start == int(Start::reanalyse))
        set_parameter_by_path(prm, "Checkpoint/Resume", "true", "Study");

      RunContext scene_context       = context;
      scene_context.mpi_communicator = group;
      scene_context.output_directory = dir;
      scene_context.parameters_text  = [&prm, &scene]() {
        std::ostringstream used;
        used << "# Parameters used by tribodyn " << version_string
             << " for scene '" << scene.name << "' of an mca study\n";
        prm.print_parameters(used, ParameterHandler::ShortPRM);
        return used.str();
      };

      // Each leg's cost, beside the scene's directory (which a fresh run
      // moves aside): what the study reports as core-hours.
      const auto start_time = std::chrono::steady_clock::now();
      auto       book_leg   = [&](const std::string &end) {
        if (!group_root)
          return;
        const double wall = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start_time)
                              .count();
        append_scene_leg(dir + ".legs.csv",
                         {how == "run" ? "fresh" : how, n_ranks, wall, end});
      };
      try
        {
          mca::McaProblem problem(prm, scene_context);
          problem.run();
        }
      catch (const Interrupted &)
        {
          book_leg("interrupted");
          throw;
        }
      catch (...)
        {
          book_leg("failed");
          throw;
        }
      book_leg("finished");
      if (group_root)
        tag_scene_summary(dir, scene, parameters);
    }


    void
    McaStudyProblem::run()
    {
      const auto         start = std::chrono::steady_clock::now();
      const MPI_Comm     world = context.mpi_communicator;
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(world);
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(world);
      const unsigned int n_groups
        = std::max(1u, n_ranks / parameters.ranks_per_scene);
      const unsigned int color
        = std::min(rank / parameters.ranks_per_scene, n_groups - 1);
      MPI_Comm group;
      MPI_Comm_split(world, color, rank, &group);

      if (rank == 0)
        std::cout << "MCA study: " << study_scenes.size() << " scenes ("
                  << parameters.bases.size() << " bases x "
                  << parameters.roughness_seeds.size() << " seeds x "
                  << study_scenes.size()
                       / (parameters.bases.size()
                          * parameters.roughness_seeds.size())
                  << " factor levels) on " << n_groups
                  << " group(s) of MPI ranks; results in "
                  << context.output_directory << std::endl;
      // The study's own files; its scenes claim their own directories.
      context.claim_output(OutputClaim::fresh, {"scenes"});

      // SIGTERM/SIGINT between two scenes or during a scene's set-up stops
      // the study there; during a scene's time loop, the scene saves a
      // checkpoint first.
      const InterruptHandlers interrupt_handlers;
      int                     interrupted = 0;
      std::vector<double>     failed(study_scenes.size(), 0.);
      std::string             failures;
      for (unsigned int i = 0; i < study_scenes.size() && interrupted == 0; ++i)
        {
          if (i % n_groups != color)
            continue;
          const RunHealth health = agree_on_health(0., group);
          if (health.signal != 0)
            {
              interrupted = health.signal;
              break;
            }
          try
            {
              run_scene(study_scenes[i], group);
            }
          catch (const Interrupted &e)
            {
              interrupted = e.signal_number;
            }
          catch (const std::exception &e)
            {
              // A scene that fails (an instability, a damaged checkpoint)
              // does not stop the others; the study reports it.
              failed[i] = 1;
              if (dealii::Utilities::MPI::this_mpi_process(group) == 0)
                std::cerr << "tribodyn: scene " << study_scenes[i].name
                          << " failed: " << e.what() << std::endl;
            }
        }
      MPI_Comm_free(&group);

      // Every group here: did one stop on a signal, did scenes fail?
      interrupted = dealii::Utilities::MPI::max(interrupted, world);
      {
        std::vector<double> any(failed.size());
        dealii::Utilities::MPI::max(failed, world, any);
        failed.swap(any);
      }
      if (interrupted != 0)
        {
          InterruptHandlers::acknowledge();
          throw Interrupted(
            interrupted,
            "signal " + std::to_string(interrupted)
              + " received: the scenes that were running saved checkpoints. "
                "Run the same study again to resume them and to run the "
                "rest; finished scenes are reused.");
        }
      for (unsigned int i = 0; i < study_scenes.size(); ++i)
        if (failed[i] > 0)
          failures += (failures.empty() ? "" : ", ") + study_scenes[i].name;

      const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count();
      if (rank == 0)
        {
          std::vector<std::string> directories;
          for (const McaScene &scene : study_scenes)
            directories.push_back(scene_directory(scene));
          McaStudyAnalysis analysis(parameters, study_scenes, directories);
          analysis.write(context.output_directory, wall, n_ranks, std::cout);
          run_plot_script(parameters.plot_script,
                          "plot_mca_study",
                          "Study/Plot script",
                          context.output_directory);
        }
      MPI_Barrier(world);
      if (!failures.empty())
        throw RunError("the scenes " + failures
                       + " failed (their messages are above); the study's "
                         "tables hold the others. Fix the cause and run the "
                         "study again: finished scenes are reused.");
    }


    namespace
    {
      const bool mca_study_registered = register_problem(
        {"mca_study",
         "automata study (seed 000's question): base scenes x roughness "
         "seeds x factors on groups of MPI ranks, paired differences with "
         "error bars; resumes where it was stopped",
         &McaStudyProblem::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(new McaStudyProblem(prm, context));
         }});
    } // namespace
  }   // namespace study
} // namespace tribodyn
