#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>
#include <tribodyn/core/version.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/friction_observer.h>
#include <tribodyn/mca/inclusions.h>
#include <tribodyn/mca/mca_problem.h>
#include <tribodyn/mca/scene_analyses.h>

namespace tribodyn
{
  namespace mca
  {
    void
    McaProblem::declare_parameters(dealii::ParameterHandler &prm)
    {
      Parameters::declare_parameters(prm);
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
             "curve, emulated):\n"
          << "  owned automata per rank: min " << f.owned_min << ", mean "
          << f.owned_mean << ", max " << f.owned_max << " (imbalance max/mean "
          << f.owned_max / f.owned_mean << ")\n"
          << "  ghosts per rank:         min " << f.ghosts_min << ", mean "
          << f.ghosts_mean << ", max " << f.ghosts_max << "\n"
          << "  ghost/owned ratio (mean): " << f.ghosts_mean / f.owned_mean
          << "\n"
          << "  memory per rank (estimate, largest rank): "
          << f.bytes_per_rank_max / 1048576. << " MiB ("
          << AutomatonSystem::bytes_per_owned_automaton
          << " B per owned automaton, "
          << AutomatonSystem::bytes_per_ghost_automaton << " B per ghost)"
          << std::endl;
    }


    McaProblem::McaProblem(dealii::ParameterHandler &prm,
                           const RunContext         &context)
        : context(context)
    {
      parameters.parse_parameters(prm);
    }


    namespace
    {
      /// Staged loading and inclusions: what the set-up produced.
      void
      report_scene(const AutomatonSystem      &system,
                   const Parameters           &p,
                   dealii::ConditionalOStream &out)
      {
        if (p.loading.enabled)
          out << "Friction loading: separation " << p.geometry.interface_gap
              << " m, shift " << p.geometry.interface_shift_y
              << " m along y, damping of the loading layers "
              << p.loading_damping << " 1/s"
              << (p.loading.damping > 0 ? " (given)"
                                        : " (seed criterion c_p / (2 h))")
              << std::endl;
        if (const auto *layout = p.geometry.inclusion_layout.get())
          {
            const auto counts = system.contacting_part_counts();
            out << "Inclusions:";
            for (const auto &part : layout->parts)
              out << " body " << part.body << ": " << part.set.n_cylinders
                  << " cylinders (" << 100 * part.set.cylinder_volume_fraction
                  << " % of the "
                  << "part's box), " << part.set.n_voids << " voids ("
                  << 100 * part.set.void_volume_fraction << " %);";
            out << " automata: " << counts.second << " of " << counts.first
                << " in the contacting parts = "
                << 100. * counts.second / std::max(1ull, counts.first) << " %"
                << std::endl;
          }
      }


      void
      add_scene_keys(const AutomatonSystem &system,
                     const Parameters      &p,
                     JsonValue             &summary)
      {
        summary["contact_time"] = system.contact_time() >= 0
                                    ? JsonValue(system.contact_time())
                                    : JsonValue();
        if (p.loading.enabled)
          {
            summary["loading_damping"]    = p.loading_damping;
            summary["loading_separation"] = p.geometry.interface_gap;
            summary["loading_shift_y"]    = p.geometry.interface_shift_y;
          }
        if (const auto *layout = p.geometry.inclusion_layout.get())
          {
            const auto counts = system.contacting_part_counts();
            summary["inclusion_volume_fraction"]
              = double(counts.second) / std::max(1ull, counts.first);
            double f = 0, fv = 0;
            for (const auto &part : layout->parts)
              {
                f += part.set.cylinder_volume_fraction / layout->parts.size();
                fv += part.set.void_volume_fraction / layout->parts.size();
              }
            summary["inclusion_volume_fraction_generated"] = f;
            summary["void_volume_fraction_generated"]      = fv;
          }
        else
          summary["inclusion_volume_fraction"] = 0.;
      }


      /// Energy balance since the start (the scene starts at rest and
      /// unstressed): kinetic + elastic + plastic + friction + damped =
      /// work of the loads; and the pairs' side of it (their work on the
      /// automata against what they stored or dissipated).
      void
      add_energy_balance(const SystemEnergies &e,
                         JsonValue            &summary,
                         std::ostream         &figures)
      {
        const double stored = e.kinetic + e.elastic + e.plastic_work
                              + e.friction_work + e.damped_work;
        summary["load_work"]               = e.load_work;
        summary["damped_work"]             = e.damped_work;
        summary["pair_work"]               = e.pair_work;
        summary["energy_balance_residual"] = stored - e.load_work;
        summary["energy_balance_relative"]
          = e.load_work != 0 ? (stored - e.load_work) / std::abs(e.load_work)
                             : 0.;
        figures << "Energy: load work " << e.load_work << " J = kinetic "
                << e.kinetic << " + elastic " << e.elastic << " + plastic "
                << e.plastic_work << " + friction " << e.friction_work
                << " + damped " << e.damped_work << " J + residual "
                << e.load_work - stored << " J" << std::endl;
      }
    } // namespace


    void
    McaProblem::run()
    {
      const auto     start = std::chrono::steady_clock::now();
      const MPI_Comm comm  = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(comm);
      dealii::ConditionalOStream pcout(std::cout, root);
      dealii::TimerOutput        timer(comm,
                                pcout,
                                dealii::TimerOutput::summary,
                                dealii::TimerOutput::wall_times);
      const std::string         &out_dir = context.output_directory;
      const Parameters          &p       = parameters;

      AutomatonSystem system(p, comm);
      {
        dealii::TimerOutput::Scope scope(timer, "setup (packing, pair list)");
        system.setup();
      }
      const double dt = system.time_step();
      const auto   n_steps
        = static_cast<unsigned long>(std::ceil(p.time.end_time / dt - 1e-9));
      report_scene(system, p, pcout);
      pcout << "MCA: " << system.n_global_automata() << " automata, "
            << system.n_global_pairs() << " pairs, " << n_ranks
            << " MPI rank(s); dt = " << dt
            << " s (critical d/c_p = " << system.critical_time_step() << " s), "
            << n_steps << " steps" << std::endl;

      // Series
      std::vector<std::string> columns = {"time",
                                          "kinetic_energy",
                                          "elastic_energy",
                                          "plastic_work",
                                          "friction_work",
                                          "n_bonded_pairs",
                                          "n_unbonded_contacts",
                                          "load_work",
                                          "damped_work",
                                          "pair_work"};
      for (const auto &g : p.boundary.groups)
        for (const char *c : {"fx", "fy", "fz", "ux", "uy", "uz"})
          columns.push_back(g.name + "_" + c);
      const bool friction
        = p.analysis.type == AnalysisParameters::Type::friction;
      int loaded = -1;
      for (unsigned int g = 0; g < p.boundary.groups.size(); ++g)
        if (p.boundary.groups[g].name == p.analysis.loaded_group)
          loaded = g;
      if (friction)
        columns.push_back("mu");
      CsvWriter series(join_path(out_dir, "series.csv"), columns, root);
      PvdWriter pvd(join_path(out_dir, "particles.pvd"), root);
      PvdWriter pvd_slab(join_path(out_dir, "cross_section.pvd"), root);
      PvdWriter pvd_pairs(join_path(out_dir, "unbonded_pairs.pvd"), root);

      std::unique_ptr<UniaxialAnalysis> uniaxial;
      std::unique_ptr<PulseAnalysis>    pulse;
      if (p.analysis.type == AnalysisParameters::Type::uniaxial)
        uniaxial = std::make_unique<UniaxialAnalysis>(system, p, comm);
      if (p.analysis.type == AnalysisParameters::Type::pulse)
        pulse = std::make_unique<PulseAnalysis>(system, p, comm);
      FrictionObserver friction_observer(p, loaded);
      bool             staged = false;
      for (const auto &g : p.boundary.groups)
        staged = staged || g.switch_on_contact;

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
      unsigned int output_number = 0;
      const bool   need_stress   = p.output.write_stress;

      auto write_outputs = [&]() {
        dealii::TimerOutput::Scope scope(timer, "output");
        if (p.output.write_particles)
          pvd.add(system.time(),
                  system.write_particles(
                    out_dir, "particles", output_number, need_stress));
        if (p.output.cross_section)
          {
            const double th = p.output.cross_section_thickness > 0
                                ? p.output.cross_section_thickness
                                : 7 * p.geometry.automaton_size / std::sqrt(2.);
            const double lo = p.output.cross_section_position - th / 2,
                         hi = p.output.cross_section_position + th / 2;
            pvd_slab.add(system.time(),
                         system.write_particles(out_dir,
                                                "cross_section",
                                                output_number,
                                                need_stress,
                                                true,
                                                p.output.cross_section_axis,
                                                lo,
                                                hi));
            pvd_pairs.add(
              system.time(),
              system.write_unbonded_pairs(out_dir,
                                          "unbonded_pairs",
                                          output_number,
                                          p.output.cross_section_axis,
                                          lo,
                                          hi));
          }
        ++output_number;
      };

      std::string key_figure;
      auto        record_series = [&]() {
        dealii::TimerOutput::Scope scope(timer, "series");
        const SystemEnergies       e      = system.energies();
        const auto                 forces = system.group_forces();
        const auto                 disp   = system.group_displacements();
        std::vector<double>        row    = {system.time(),
                                             e.kinetic,
                                             e.elastic,
                                             e.plastic_work,
                                             e.friction_work,
                                             double(e.n_bonded),
                                             double(e.n_unbonded_contacts),
                                             e.load_work,
                                             e.damped_work,
                                             e.pair_work};
        for (unsigned int g = 0; g < forces.size(); ++g)
          {
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(forces[g][c]);
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(disp[g][c]);
          }
        if (friction && loaded >= 0)
          {
            // With a staged loading, mu is recorded from the first contact
            // of the bodies on (before it the layers carry no load).
            double mu = 0;
            if (!staged || system.contact_time() >= 0)
              {
                mu = friction_observer.record(system.time(), forces, e);
                friction_observer.record_layer(system.time(), system, comm);
              }
            row.push_back(mu);
            key_figure = "mu = " + format_number(mu);
          }
        series.add_row(row);
        series.flush();
        if (uniaxial)
          uniaxial->record();
      };

      ProgressReporter progress(
        std::cout, root, p.time.end_time, context.progress_interval, "mca");
      write_outputs();
      record_series();
      const auto loop_start = std::chrono::steady_clock::now();
      {
        dealii::TimerOutput::Scope scope(timer, "time steps");
        for (unsigned long s = 1; s <= n_steps; ++s)
          {
            system.step();
            if (pulse)
              pulse->record(system.time());
            if (s % series_every == 0 || s == n_steps)
              {
                timer.leave_subsection("time steps");
                record_series();
                if (s % output_every == 0 || s == n_steps)
                  write_outputs();
                timer.enter_subsection("time steps");
              }
            progress.update(s, system.time(), key_figure);
          }
      }
      const double loop_seconds
        = std::chrono::duration<double>(std::chrono::steady_clock::now()
                                        - loop_start)
            .count();
      progress.update(n_steps, system.time(), key_figure, true);
      series.flush(true);

      const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count();
      std::ostringstream figures_early;
      figures_early << std::setprecision(6);
      JsonValue summary                = JsonValue::object();
      summary["problem"]               = "mca";
      summary["tribodyn_version"]      = version_string;
      summary["n_mpi_ranks"]           = n_ranks;
      summary["n_automata"]            = system.n_global_automata();
      summary["n_pairs"]               = system.n_global_pairs();
      summary["n_steps"]               = n_steps;
      summary["dt"]                    = dt;
      summary["critical_dt"]           = system.critical_time_step();
      summary["end_time"]              = system.time();
      summary["n_pair_list_rebuilds"]  = system.n_rebuilds();
      const unsigned long long dropped = system.n_dropped_bonds();
      summary["n_dropped_bonds"]       = dropped;
      if (dropped > 0)
        pcout << "Warning: " << dropped
              << " bonded pair(s) were stretched beyond the pair-list range "
                 "(automaton size times 1 + Interaction/Skin) and their bonds "
                 "were lost. With Bond breaking = false this is a large "
                 "deformation the list cannot follow: raise Interaction/Skin."
              << std::endl;
      summary["n_ghost_automata_max"]
        = dealii::Utilities::MPI::max(system.n_ghost_automata(), comm);
      summary["n_owned_automata_min"]
        = dealii::Utilities::MPI::min(system.n_owned_automata(), comm);
      summary["n_owned_automata_max"]
        = dealii::Utilities::MPI::max(system.n_owned_automata(), comm);
      summary["memory_bytes_max"] = dealii::Utilities::MPI::max(
        static_cast<double>(system.memory_consumption()), comm);
      summary["wall_time_s"] = wall;
      summary["time_loop_s"] = loop_seconds;
      summary["automaton_steps_per_second"]
        = loop_seconds > 0
            ? double(system.n_global_automata()) * n_steps / loop_seconds
            : 0.;
      summary["automaton_steps_per_second_per_rank"]
        = loop_seconds > 0 ? double(system.n_global_automata()) * n_steps
                               / loop_seconds / n_ranks
                           : 0.;
      {
        const SystemEnergies e         = system.energies();
        summary["kinetic_energy"]      = e.kinetic;
        summary["elastic_energy"]      = e.elastic;
        summary["plastic_work"]        = e.plastic_work;
        summary["friction_work"]       = e.friction_work;
        summary["n_bonded_pairs"]      = e.n_bonded;
        summary["n_unbonded_contacts"] = e.n_unbonded_contacts;
        add_energy_balance(e, summary, figures_early);
        const auto forces = system.group_forces();
        JsonValue  groups = JsonValue::object();
        for (unsigned int g = 0; g < forces.size(); ++g)
          groups[p.boundary.groups[g].name]
            = json_array({forces[g][0], forces[g][1], forces[g][2]});
        summary["group_forces"] = groups;
      }
      add_scene_keys(system, p, summary);
      std::ostringstream figures;
      figures << std::setprecision(6) << figures_early.str();
      if (uniaxial)
        uniaxial->finish(summary, figures);
      if (pulse)
        pulse->finish(summary, figures);
      if (friction)
        friction_observer.finish(out_dir, root, summary, figures);
      pcout << figures.str();
      pcout << "Throughput: "
            << double(system.n_global_automata()) * n_steps
                 / std::max(loop_seconds, 1e-300) / n_ranks
            << " automaton-steps/s per rank" << std::endl;
      if (root)
        write_file_atomically(join_path(out_dir, "summary.json"),
                              summary.dump() + "\n");
    }


    static const bool registered = register_problem(
      {"mca",
       "3D movable cellular automata: bonded automata with many-body pair "
       "law, rotations, von Mises plasticity, bond breaking and formation "
       "(seed 000)",
       &McaProblem::declare_parameters,
       [](dealii::ParameterHandler &prm,
          const RunContext         &context) -> std::unique_ptr<Problem> {
         return std::make_unique<McaProblem>(prm, context);
       },
       &McaProblem::print_partition_report});
  } // namespace mca
} // namespace tribodyn
