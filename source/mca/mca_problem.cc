#include "scene_report.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>
#include <tribodyn/core/version.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/mca_problem.h>
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    void
    McaProblem::declare_parameters(dealii::ParameterHandler &prm)
    {
      Parameters::declare_parameters(prm);
      CheckpointParameters::declare_parameters(prm);
    }


    void
    McaProblem::print_partition_report(dealii::ParameterHandler &handler,
                                       const unsigned int        n_ranks,
                                       std::ostream             &out)
    {
      Parameters p;
      p.parse_parameters(handler);
      const auto f = AutomatonSystem::partition_report(p, n_ranks);
      out << std::setprecision(4) << "Partition of " << f.n_automata
          << " automata over " << n_ranks
          << " ranks (p4est's partition of the cells along its space-filling "
             "curve, weighted by the automata they hold; emulated):\n";
      if (!p.geometry.size_bands.empty())
        out << "  automata per size: " << f.n_per_size[0] << " of d, "
            << f.n_per_size[1] << " of 2d, " << f.n_per_size[2]
            << " of 4d (Geometry/Size bands; cells sized for the largest "
               "pair distance, "
            << p.geometry.largest_pair_distance() / p.geometry.automaton_size
            << " d)\n";
      out << "  owned automata per rank: min " << f.owned_min << ", mean "
          << f.owned_mean << ", max " << f.owned_max << " (imbalance max/mean "
          << f.owned_max / f.owned_mean << ")\n"
          << "  ghosts per rank:         min " << f.ghosts_min << ", mean "
          << f.ghosts_mean << ", max " << f.ghosts_max << "\n"
          << "  ghost/owned ratio (mean): " << f.ghosts_mean / f.owned_mean
          << " (" << f.whole_cell_ghosts_mean / f.owned_mean
          << " if whole cells were sent)\n"
          << "  memory per rank (estimate, largest rank): "
          << f.bytes_per_rank_max / 1048576. << " MiB ("
          << cost_model::bytes_per_owned_automaton << " B per owned automaton, "
          << cost_model::bytes_per_ghost_automaton << " B per ghost"
          << (p.interaction.relative_rotation_on()
                ? ", + "
                    + std::to_string(
                      static_cast<int>(cost_model::bytes_per_automaton_moments))
                    + " B each for the relative-rotation moments"
                : std::string())
          << ")" << std::endl;
    }


    McaProblem::McaProblem(dealii::ParameterHandler &prm,
                           const RunContext         &context)
        : context(context)
    {
      parameters.parse_parameters(prm);
      checkpoint.parse_parameters(prm);
      checkpoint_lines = resumable_parameter_lines(prm, "Time/End time");
    }


    namespace
    {
      using PostprocessorList = std::vector<std::unique_ptr<Postprocessor>>;

      /// What follows the automata in a rank's checkpoint: the rows of
      /// series.csv so far and the postprocessors' states, in list order
      /// (the same on every rank).
      void
      write_run_state(boost::archive::binary_oarchive &ar,
                      const PostprocessorList         &postprocessors,
                      const std::size_t                series_rows)
      {
        ar << series_rows;
        for (const auto &pp : postprocessors)
          pp->save(ar);
      }
      void
      read_run_state(boost::archive::binary_iarchive &ar,
                     const PostprocessorList         &postprocessors,
                     std::size_t                     &series_rows)
      {
        ar >> series_rows;
        for (const auto &pp : postprocessors)
          pp->load(ar);
      }


      /// This rank's checkpoint: the automata, then the run's state.
      std::string
      save_checkpoint_blob(const AutomatonSystem   &system,
                           const PostprocessorList &postprocessors,
                           const std::size_t        series_rows)
      {
        std::ostringstream out(std::ios::binary);
        {
          boost::archive::binary_oarchive ar(out);
          system.save_state(ar);
          write_run_state(ar, postprocessors, series_rows);
        }
        return out.str();
      }


      /**
       * Restore the checkpoint this rank read: on the number of ranks that
       * wrote it, its own state (@p blobs holds one); on another number,
       * the states of its share of the writers, redistributed over this
       * run's partition (AutomatonSystem::absorb_state()), with the run's
       * own state taken from the writer of rank 0 (read by rank 0).
       */
      void
      load_checkpoint(const std::vector<std::string> &blobs,
                      const bool                      same_ranks,
                      AutomatonSystem                &system,
                      const PostprocessorList        &postprocessors,
                      std::size_t                    &series_rows,
                      const MPI_Comm                  comm)
      {
        const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
        std::string run_state;
        read_checkpoint_blobs(comm, blobs, [&](auto &ar) {
          if (same_ranks)
            system.load_state(ar);
          else
            system.absorb_state(ar);
          read_run_state(ar, postprocessors, series_rows);
          if (!same_ranks && root && run_state.empty())
            {
              // writer 0's run state again, to be sent to every rank
              std::ostringstream out(std::ios::binary);
              {
                boost::archive::binary_oarchive copy(out);
                write_run_state(copy, postprocessors, series_rows);
              }
              run_state = out.str();
            }
        });
        if (same_ranks)
          return;
        run_state = dealii::Utilities::MPI::broadcast(comm, run_state, 0);
        read_checkpoint_blobs(comm, {run_state}, [&](auto &ar) {
          read_run_state(ar, postprocessors, series_rows);
        });
        system.redistribute_absorbed();
      }
    } // namespace


    void
    McaProblem::run()
    {
      const MPI_Comm comm = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      dealii::ConditionalOStream pcout(std::cout, root);
      auto                       timer = std::make_unique<dealii::TimerOutput>(
        comm,
        pcout,
        dealii::TimerOutput::summary,
        dealii::TimerOutput::wall_times);
      try
        {
          run_with_timer(*timer);
        }
      catch (...)
        {
          // No timing table (and no MPI exchange in its destructor while an
          // exception is in flight) for a run that failed.
          timer->disable_output();
          timer.reset();
          throw;
        }
    }


    void
    McaProblem::run_with_timer(dealii::TimerOutput &timer)
    {
      const auto     start = std::chrono::steady_clock::now();
      const MPI_Comm comm  = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(comm);
      dealii::ConditionalOStream pcout(std::cout, root);
      const std::string         &out_dir = context.output_directory;
      const Parameters          &p       = parameters;

      p.geometry.check_memory_per_rank(n_ranks);
      AutomatonSystem system(p, comm);
      {
        dealii::TimerOutput::Scope scope(timer, "setup (packing, pair list)");
        system.setup();
      }
      const double dt = system.time_step();
      check_parameter(p.time.end_time / dt < 1e12,
                      "Time/End time",
                      "the run would take "
                        + format_number(p.time.end_time / dt)
                        + " steps of dt = " + format_number(dt)
                        + " s (limit 1e12): lower the end time.");
      const auto n_steps
        = static_cast<unsigned long>(std::ceil(p.time.end_time / dt - 1e-9));
      report_scene(system, p, pcout);
      const double imbalance = system.work_imbalance();
      pcout << "MCA: " << system.n_global_automata() << " automata, "
            << system.n_global_pairs() << " pairs, " << n_ranks
            << " MPI rank(s)";
      if (n_ranks > 1)
        pcout << " (work imbalance max/mean " << std::setprecision(3)
              << imbalance << std::setprecision(6) << ")";
      pcout << "; dt = " << dt
            << " s (critical d/c_p = " << system.critical_time_step() << " s), "
            << n_steps << " steps" << std::endl;

      // The outputs of this run (source/mca/postprocessors/), in order:
      // their series columns side by side in series.csv.
      const PostprocessorList postprocessors
        = PostprocessorRegistry::create_all({system, p, comm, out_dir, root});
      std::vector<std::string> columns;
      for (const auto &pp : postprocessors)
        for (const auto &c : pp->series_columns())
          columns.push_back(c);

      const unsigned long series_every
        = p.output.series_interval > 0
            ? std::max(1ul,
                       static_cast<unsigned long>(
                         std::round(p.output.series_interval / dt)))
            : 100ul;
      const unsigned long output_every
        = p.output.output_interval > 0
            ? std::max(1ul,
                       static_cast<unsigned long>(
                         std::round(p.output.output_interval / dt)))
            : n_steps;

      // A fresh start, or the state of the latest checkpoint.
      CheckpointStore            store(out_dir, "mca", comm);
      std::unique_ptr<CsvWriter> series;
      const std::string          series_path = join_path(out_dir, "series.csv");
      if (checkpoint.resume)
        {
          CheckpointInfo info;
          std::size_t    rows  = 0;
          const auto     blobs = store.read(checkpoint_lines, info);
          load_checkpoint(
            blobs, info.n_ranks == n_ranks, system, postprocessors, rows, comm);
          if (system.step_number() >= n_steps)
            throw InputError("Nothing to resume: the checkpoint is at step "
                             + std::to_string(system.step_number())
                             + " (t = " + format_number(system.time())
                             + " s), at or beyond 'Time/End time' = "
                             + format_number(p.time.end_time)
                             + " s. Raise the end time to continue the run.");
          // Every check passed: the output directory may be touched.
          context.claim_output(OutputClaim::resume);
          for (const auto &pp : postprocessors)
            pp->resume_outputs();
          series
            = std::make_unique<CsvWriter>(series_path, columns, root, rows);
          pcout << "Resuming from the checkpoint at t = " << info.time
                << " s (step " << info.step << ")";
          if (info.n_ranks != n_ranks)
            pcout << ", written by " << info.n_ranks
                  << " MPI rank(s): automata and pair states redistributed "
                     "over "
                  << n_ranks;
          pcout << std::endl;
        }
      else
        {
          context.claim_output(OutputClaim::fresh);
          store.discard();
          series = std::make_unique<CsvWriter>(series_path, columns, root);
        }

      auto write_outputs = [&]() {
        dealii::TimerOutput::Scope scope(timer, "output");
        for (const auto &pp : postprocessors)
          pp->write_output();
      };

      std::string key_figure;
      auto        record_series = [&]() {
        dealii::TimerOutput::Scope scope(timer, "series");
        const SystemEnergies       e      = system.energies();
        const auto                 forces = system.group_forces();
        const auto                 disp   = system.group_displacements();
        const SeriesSample         sample{system.time(), e, forces, disp};
        std::vector<double>        row;
        key_figure.clear();
        for (const auto &pp : postprocessors)
          {
            pp->record(sample, row);
            const std::string figure = pp->key_figure();
            if (!figure.empty())
              key_figure += (key_figure.empty() ? "" : ", ") + figure;
          }
        series->add_row(row);
        series->flush();
      };

      // Flush the series and save the state after the current step.
      auto save_checkpoint = [&]() {
        dealii::TimerOutput::Scope scope(timer, "checkpoint");
        series->flush(true);
        store.write(save_checkpoint_blob(system,
                                         postprocessors,
                                         series->n_rows()),
                    system.step_number(),
                    system.time(),
                    checkpoint_lines);
      };

      ProgressReporter progress(
        std::cout, root, p.time.end_time, context.progress_interval, "mca");
      progress.set_start_time(system.time());
      const unsigned long first_step = system.step_number() + 1;
      if (first_step == 1)
        {
          write_outputs();
          record_series();
        }
      // Blow-up limit: twice the largest P-wave speed (d / critical dt).
      const double v_limit
        = 2 * p.geometry.automaton_size / system.critical_time_step();
      const double interval = checkpoint.interval;
      double       next_checkpoint
        = interval > 0
            ? (std::floor(system.time() / interval + 1e-9) + 1) * interval
            : std::numeric_limits<double>::max();
      // SIGTERM/SIGINT: polled between steps (checkpoint, clean stop).
      const InterruptHandlers interrupt_handlers;
      const auto              loop_start = std::chrono::steady_clock::now();
      // A run that stops early keeps what its samples give (friction.csv).
      auto write_partial_results = [&]() {
        for (const auto &pp : postprocessors)
          pp->write_partial_results();
      };
      timer.enter_subsection("time steps");
      for (unsigned long s = first_step; s <= n_steps; ++s)
        {
          system.step();
          for (const auto &pp : postprocessors)
            pp->after_step();
          // Every step: finiteness and speed of the automata, signals and
          // the displacement that decides the next step's pair-list
          // rebuild, agreed by all ranks in one small MPI_Allreduce.
          double          displacement2 = system.displacement_since_rebuild();
          const RunHealth health
            = agree_on_health(system.count_unstable_automata(v_limit),
                              comm,
                              &displacement2);
          system.set_agreed_displacement_since_rebuild(displacement2);
          if (health.badness > 0)
            {
              write_partial_results();
              system.report_instability(v_limit);
            }
          const bool regular = s % series_every == 0;
          const bool regular_output
            = regular && p.output.output_interval > 0 && s % output_every == 0;
          const bool last = s == n_steps;
          timer.leave_subsection("time steps");
          if (regular)
            record_series();
          if (regular_output)
            write_outputs();
          // Checkpoint at the interval, at the end and on a signal: before
          // the end-of-run outputs, which a longer run would not write.
          if ((interval > 0
               && (system.time() >= next_checkpoint - 0.5 * dt || last))
              || health.signal != 0)
            {
              save_checkpoint();
              while (next_checkpoint <= system.time() + 0.5 * dt)
                next_checkpoint += interval;
            }
          if (health.signal != 0)
            {
              InterruptHandlers::acknowledge();
              write_partial_results();
            }
          if (health.signal != 0)
            throw Interrupted(
              health.signal,
              "signal " + std::to_string(health.signal) + " received at step "
                + std::to_string(s) + " (t = " + format_number(system.time())
                + " s); the state was saved in '" + store.directory()
                + "': continue with 'Checkpoint/Resume = true'.");
          if (last && !regular)
            record_series();
          if (last && !regular_output)
            write_outputs();
          timer.enter_subsection("time steps");
          progress.update(s, system.time(), key_figure);
        }
      timer.leave_subsection("time steps");
      const unsigned long steps_run = n_steps + 1 - first_step;
      const double        loop_seconds
        = std::chrono::duration<double>(std::chrono::steady_clock::now()
                                        - loop_start)
            .count();
      progress.update(n_steps, system.time(), key_figure, true);
      series->flush(true);

      const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count();
      JsonValue summary           = JsonValue::object();
      summary["problem"]          = "mca";
      summary["tribodyn_version"] = version_string;
      summary["n_mpi_ranks"]      = n_ranks;
      add_run_keys(system, p, n_steps, imbalance, comm, pcout, summary);
      summary["wall_time_s"] = wall;
      summary["time_loop_s"] = loop_seconds;
      summary["automaton_steps_per_second"]
        = loop_seconds > 0
            ? double(system.n_global_automata()) * steps_run / loop_seconds
            : 0.;
      summary["automaton_steps_per_second_per_rank"]
        = loop_seconds > 0 ? double(system.n_global_automata()) * steps_run
                               / loop_seconds / n_ranks
                           : 0.;
      add_scene_keys(system, p, summary);
      std::ostringstream figures;
      figures << std::setprecision(6);
      for (const auto &pp : postprocessors)
        pp->finish(summary, figures);
      pcout << figures.str();
      pcout << "Throughput: "
            << double(system.n_global_automata()) * steps_run
                 / std::max(loop_seconds, 1e-300) / n_ranks
            << " automaton-steps/s per rank" << std::endl;
      if (root)
        write_file_atomically(join_path(out_dir, "summary.json"),
                              summary.dump() + "\n");
      pcout << "Results in " << out_dir << std::endl;
    }


    static const bool mca_problem_registered = register_problem(
      {"mca",
       "3D movable cellular automata: bonded automata with many-body pair "
       "law, rotations, von Mises plasticity, bond breaking and formation "
       "(seed 000)",
       &McaProblem::declare_parameters,
       [](dealii::ParameterHandler &prm,
          const RunContext         &context) -> std::unique_ptr<Problem> {
         return std::make_unique<McaProblem>(prm, context);
       },
       &McaProblem::print_partition_report,
       &Parameters::declare_material_sections});
  } // namespace mca
} // namespace tribodyn
