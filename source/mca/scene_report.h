// The report of the scene the set-up built (staged loading, inclusions), on
// the screen and in summary.json (private header of source/mca/
// mca_problem.cc).
#ifndef tribodyn_source_mca_scene_report_h
#define tribodyn_source_mca_scene_report_h

#include <deal.II/base/conditional_ostream.h>
#include <tribodyn/core/json.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/inclusions.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Staged loading and inclusions: what the set-up produced.
      void
      report_scene(const AutomatonSystem      &system,
                   const Parameters           &p,
                   dealii::ConditionalOStream &out)
      {
        if (!p.geometry.size_bands.empty())
          {
            out << "Size bands (Geometry/Size bands):";
            for (const auto &band : p.geometry.size_bands)
              out << " [" << band.z_lower << ", " << band.z_upper << ") m "
                  << (1u << band.level) << "d;";
            out << " d elsewhere" << std::endl;
          }
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
            out << " automata: " << counts.inclusions << " of "
                << counts.automata << " in the contacting parts, "
                << 100. * counts.inclusion_volume
                     / std::max(1ull, counts.volume)
                << " % of their volume" << std::endl;
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
              = double(counts.inclusion_volume) / std::max(1ull, counts.volume);
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


      /// The run's figures in summary.json: automata (per size), pairs,
      /// the partition (imbalance at set-up and at the end, rebalances,
      /// owned and ghost automata, memory), time step and rebuilds; a
      /// warning for bonds lost beyond the pair-list range.
      void
      add_run_keys(const AutomatonSystem      &system,
                   const Parameters           &p,
                   const unsigned long         n_steps,
                   const double                imbalance,
                   const MPI_Comm              comm,
                   dealii::ConditionalOStream &pcout,
                   JsonValue                  &summary)
      {
        summary["n_automata"] = system.n_global_automata();
        if (!p.geometry.size_bands.empty())
          {
            // automata of size d, 2d, 4d (Geometry/Size bands)
            std::vector<unsigned long long> per_size(3, 0);
            const auto                      levels = system.size_levels();
            for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
              ++per_size[std::min(levels[k], 2u)];
            dealii::Utilities::MPI::sum(per_size, comm, per_size);
            JsonValue sizes = JsonValue::array();
            for (const unsigned long long n : per_size)
              sizes.push_back(n);
            summary["n_automata_per_size"] = sizes;
          }
        summary["work_imbalance"]     = imbalance;
        const double imbalance_end    = system.work_imbalance();
        summary["work_imbalance_end"] = imbalance_end;
        summary["n_rebalances"]       = system.n_rebalances();
        if (system.n_rebalances() > 0)
          pcout << "Partition weighted anew " << system.n_rebalances()
                << " time(s) (Partition/Rebalance threshold); work imbalance "
                   "at the end "
                << std::setprecision(3) << imbalance_end << std::setprecision(6)
                << std::endl;
        // search cells per deal.II cell and direction (1 or 2: Partition/
        // Mesh cells per rank)
        summary["mesh_cell_split"]
          = system.decomposition().cells_per_mesh_cell();
        summary["n_pairs"]              = system.n_global_pairs();
        summary["n_steps"]              = n_steps;
        summary["dt"]                   = system.time_step();
        summary["critical_dt"]          = system.critical_time_step();
        summary["courant_limit"]        = system.courant_limit();
        summary["end_time"]             = system.time();
        summary["n_pair_list_rebuilds"] = system.n_rebuilds();
        // the pair kernel's pipeline (Partition/Pairs per chunk) for the
        // last pair list, its largest over the ranks
        summary["pipeline_chunks"]
          = dealii::Utilities::MPI::max(system.pipeline_chunks(), comm);
        summary["pipeline_lag"]
          = dealii::Utilities::MPI::max(system.pipeline_lag(), comm);
        const unsigned long long dropped = system.n_dropped_bonds();
        summary["n_dropped_bonds"]       = dropped;
        if (dropped > 0)
          pcout
            << "Warning: " << dropped
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
        // each array's largest share over the ranks (issue #48: where the
        // bytes per automaton go)
        const auto          parts = system.memory_by_part();
        std::vector<double> bytes;
        for (const auto &part : parts)
          bytes.push_back(static_cast<double>(part.second));
        dealii::Utilities::MPI::max(bytes, comm, bytes);
        for (unsigned int k = 0; k < parts.size(); ++k)
          if (bytes[k] > 0)
            summary["memory_bytes_by_part"][parts[k].first] = bytes[k];
      }
    } // namespace


  } // namespace mca
} // namespace tribodyn

#endif
