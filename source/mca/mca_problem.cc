#include "scene_report.h"

#include <algorithm>
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
#include <sstream>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/interruption.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/plugin_states.h>
#include <tribodyn/core/time_loop.h>
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
      checkpoint_lines = resumable_parameters(prm, "Time/End time");
    }


    namespace
    {
      using PostprocessorList = std::vector<std::unique_ptr<Postprocessor>>;

      /// A run's postprocessors with their registered names (their states
      /// are saved by name: core/plugin_states.h).
      struct Postprocessors
      {
        PostprocessorList        list;
        std::vector<std::string> names;

        auto
        begin() const
        {
          return list.begin();
        }
        auto
        end() const
        {
          return list.end();
        }
      };

      /// What follows the automata in a rank's checkpoint: the rows of
      /// series.csv so far and the postprocessors' states, by name (the
      /// same on every rank).
      void
      write_run_state(boost::archive::binary_oarchive &ar,
                      const Postprocessors            &postprocessors,
                      const std::size_t                series_rows)
      {
        ar << series_rows
           << save_plugin_states(postprocessors.list, postprocessors.names);
      }
      void
      read_run_state(boost::archive::binary_iarchive &ar,
                     const Postprocessors            &postprocessors,
                     std::size_t                     &series_rows)
      {
        PluginStates states;
        ar >> series_rows >> states;
        load_plugin_states(states, postprocessors.list, postprocessors.names);
      }


      /// This rank's checkpoint: the automata, then the run's state.
      std::string
      save_checkpoint_blob(const AutomatonSystem &system,
                           const Postprocessors  &postprocessors,
                           const std::size_t      series_rows)
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
                      const Postprocessors           &postprocessors,
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


      /// The automata run as the common time loop drives it: the system's
      /// step, its health (finiteness and speed of the automata, and the
      /// displacement that decides the next pair-list rebuild, agreed in
      /// the same reduction), the series and visual outputs of the
      /// postprocessors, the checkpoints.
      class AutomataRun : public SteppedRun
      {
      public:
        struct Cadence
        {
          /// Steps between series rows and between visual outputs (0:
          /// only at the start and the end).
          unsigned long series_every, output_every;
          /// Blow-up limit of the automata's speed.
          double v_limit;
        };

        AutomataRun(AutomatonSystem           &system,
                    const Postprocessors      &postprocessors,
                    CsvWriter                 &series,
                    CheckpointStore           &store,
                    const ResumableParameters &checkpoint_lines,
                    dealii::TimerOutput       &timer,
                    const MPI_Comm             comm,
                    const Cadence             &cadence)
            : system(system)
            , postprocessors(postprocessors)
            , series(series)
            , store(store)
            , checkpoint_lines(checkpoint_lines)
            , timer(timer)
            , comm(comm)
            , cadence(cadence)
            , every_step(std::any_of(postprocessors.begin(),
                                     postprocessors.end(),
                                     [](const auto &pp) {
                                       return pp->reads_every_step();
                                     }))
        {
          system.defer_second_kicks(cadence.v_limit);
        }

        /// A fresh run's outputs and series row at t = 0.
        void
        initial_sample()
        {
          write_outputs();
          record_series();
        }

        unsigned long
        steps_done() const override
        {
          return system.step_number();
        }

        double
        time() const override
        {
          return system.time();
        }

        bool
        sample_due(const unsigned long index) const override
        {
          return (index + 1) % cadence.series_every == 0;
        }

        /// A step's second half kick waits for the next step
        /// (AutomatonSystem::step()) unless something reads the automata
        /// right after it: a sample, the run's end, a postprocessor at every
        /// step. The other readers (checkpoints, the instability report)
        /// complete the step first.
        void
        advance(const LoopStep &step) override
        {
          system.step(!(step.sample || step.last || every_step));
        }

        /// The automata's speeds (each step's end once, the step after it
        /// where its second half kick waited) and the displacement that
        /// decides the next rebuild, agreed in one reduction.
        RunHealth
        agree_on_health(const LoopStep &) override
        {
          double          displacement2 = system.displacement_since_rebuild();
          const RunHealth health        = tribodyn::agree_on_health(
            system.take_unstable_count(cadence.v_limit), comm, &displacement2);
          system.set_agreed_displacement_since_rebuild(displacement2);
          return health;
        }

        [[noreturn]] void
        report_instability(const LoopStep &) override
        {
          system.complete_step();
          system.report_instability(cadence.v_limit);
          throw RunError("The automata became unstable.");
        }

        void
        after_step(const LoopStep &) override
        {
          for (const auto &pp : postprocessors)
            pp->after_step();
        }

        void
        sample(const LoopStep &step) override
        {
          record_series();
          if (output_due(step))
            write_outputs();
        }

        void
        end_of_run(const LoopStep &step) override
        {
          if (!step.sample)
            record_series();
          if (!output_due(step))
            write_outputs();
        }

        void
        save_checkpoint() override
        {
          dealii::TimerOutput::Scope scope(timer, "checkpoint");
          system.complete_step();
          series.flush(true);
          store.write(save_checkpoint_blob(system,
                                           postprocessors,
                                           series.n_rows()),
                      system.step_number(),
                      system.time(),
                      checkpoint_lines);
        }

        /// A run that stops early keeps what its samples give
        /// (friction.csv).
        void
        stop_early() override
        {
          system.complete_step();
          for (const auto &pp : postprocessors)
            pp->write_partial_results();
        }

        std::string
        progress_key() const override
        {
          return key_figure;
        }

      private:
        bool
        output_due(const LoopStep &step) const
        {
          return step.sample && cadence.output_every > 0
                 && (step.index + 1) % cadence.output_every == 0;
        }

        void
        write_outputs()
        {
          dealii::TimerOutput::Scope scope(timer, "output");
          for (const auto &pp : postprocessors)
            pp->write_output();
        }

        void
        record_series()
        {
          dealii::TimerOutput::Scope scope(timer, "series");
          const SystemEnergies       e = system.energies();
          const auto forces            = system.boundary_loads().reactions();
          const auto disp = system.boundary_loads().mean_displacements();
          const SeriesSample  sample{system.time(), e, forces, disp};
          std::vector<double> row;
          key_figure.clear();
          for (const auto &pp : postprocessors)
            {
              pp->record(sample, row);
              const std::string figure = pp->key_figure();
              if (!figure.empty())
                key_figure += (key_figure.empty() ? "" : ", ") + figure;
            }
          series.add_row(row);
          series.flush();
        }

        AutomatonSystem           &system;
        const Postprocessors      &postprocessors;
        CsvWriter                 &series;
        CheckpointStore           &store;
        const ResumableParameters &checkpoint_lines;
        dealii::TimerOutput       &timer;
        const MPI_Comm             comm;
        const Cadence              cadence;
        /// A postprocessor reads the automata after every step.
        const bool  every_step;
        std::string key_figure;
      };
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
      const unsigned long n_steps = TimeLoop::n_steps(p.time.end_time, dt);
      report_scene(system, p, pcout);
      const double imbalance = system.work_imbalance();
      pcout << "MCA: " << system.n_global_automata() << " automata, "
            << system.n_global_pairs() << " pairs, " << n_ranks
            << " MPI rank(s)";
      if (n_ranks > 1)
        pcout << " (work imbalance max/mean " << std::setprecision(3)
              << imbalance << std::setprecision(6) << ")";
      pcout << "; dt = " << dt
            << " s (critical d/c_p = " << system.critical_time_step() << " s";
      if (system.courant_limit() < TimeParameters::max_courant)
        pcout << "; this scene's stiffest automaton allows at most "
              << system.courant_limit() << " of it";
      pcout << "), " << n_steps << " steps" << std::endl;

      // The outputs of this run (source/mca/postprocessors/), in order:
      // their series columns side by side in series.csv.
      Postprocessors postprocessors;
      postprocessors.list
        = PostprocessorRegistry::create_all({system, p, comm, out_dir, root},
                                            postprocessors.names,
                                            p.output.postprocessors);
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
      // 0: visual outputs only at the start and the end
      const unsigned long output_every
        = p.output.output_interval > 0
            ? std::max(1ul,
                       static_cast<unsigned long>(
                         std::round(p.output.output_interval / dt)))
            : 0ul;

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
          // A finished run's last checkpoint is resumed only to analyse
          // its record again: with changed analysis-only entries, no step
          // is left to run and the run's end analyses the whole record.
          const bool reanalysis
            = !checkpoint_lines.differing(info.parameters).empty()
              && system.step_number() >= n_steps;
          if (!reanalysis)
            TimeLoop::check_something_to_resume(system.step_number(),
                                                system.time(),
                                                n_steps,
                                                "Time/End time",
                                                p.time.end_time);
          // Every check passed: the output directory may be touched.
          context.claim_output(OutputClaim::resume);
          for (const auto &pp : postprocessors)
            pp->resume_outputs();
          series
            = std::make_unique<CsvWriter>(series_path, columns, root, rows);
          pcout << (reanalysis ? "Re-analysing the finished run's record "
                                 "from its checkpoint at t = "
                               : "Resuming from the checkpoint at t = ")
                << info.time << " s (step " << info.step << ")";
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

      // The steps: the common loop (core/time_loop.h) drives the run below.
      AutomataRun run(system,
                      postprocessors,
                      *series,
                      store,
                      checkpoint_lines,
                      timer,
                      comm,
                      {series_every,
                       output_every,
                       2 * p.geometry.automaton_size
                         / system.critical_time_step()});
      if (system.step_number() == 0)
        run.initial_sample();
      TimeLoopSettings loop_settings;
      loop_settings.n_steps              = n_steps;
      loop_settings.time_step            = dt;
      loop_settings.end_time             = p.time.end_time;
      loop_settings.checkpoint_interval  = checkpoint.interval;
      loop_settings.checkpoint_directory = store.directory();
      loop_settings.show_progress        = root;
      loop_settings.progress_interval    = context.progress_interval;
      loop_settings.label                = "mca";
      loop_settings.timer                = &timer;
      loop_settings.timer_section        = "time steps";
      TimeLoop loop(loop_settings);
      loop.run(run);
      const unsigned long steps_run    = loop.steps_run();
      const double        loop_seconds = loop.step_seconds();
      series->flush(true);

      const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count();
      JsonValue summary = summary_header("mca", comm);
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
