#include "pair_energy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/vector_algebra.h>
#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    AutomatonSystem::RangeTable
    AutomatonSystem::pair_list_ranges(const Parameters &prm)
    {
      const auto  &g     = prm.geometry;
      const double range = g.automaton_size * (1 + prm.interaction.skin);
      RangeTable   r;
      for (unsigned int L = 0; L < r[0].size(); ++L)
        {
          r[0][L] = range * (1u << L);
          r[1][L] = g.transition_face_factor() * (1u << L) * range;
        }
      return r;
    }


    AutomatonSystem::AutomatonSystem(const Parameters &parameters,
                                     const MPI_Comm    communicator)
        : prm(parameters)
        , comm(communicator)
        , n_ranks(dealii::Utilities::MPI::n_mpi_processes(communicator))
        , rank(dealii::Utilities::MPI::this_mpi_process(communicator))
        , partition(parameters,
                    communicator,
                    static_cast<AutomatonArrays &>(*this),
                    static_cast<const SystemScalars &>(*this))
        , friction_laws(parameters.interaction.friction)
        , moment_laws(parameters.interaction.moment)
        , breaking_laws(parameters.interaction.bond_breaking)
        , formation_laws(parameters.interaction.bond_formation)
        , loads(parameters.boundary,
                communicator,
                static_cast<AutomatonArrays &>(*this),
                static_cast<const SystemScalars &>(*this))
    {
      const auto &g   = prm.geometry;
      d               = g.automaton_size;
      r0              = d / 2;
      S               = d * d / (2 * std::sqrt(2.));
      V               = d * d * d / std::sqrt(2.);
      range           = d * (1 + prm.interaction.skin);
      pairs_per_chunk = prm.partition.pairs_per_chunk;
      graded          = !g.size_bands.empty();
      // (one volume for all outside graded scenes)
      if (!graded)
        {
          volume.assign(1, V);
          volume_mask = 0;
        }
      graded_range = pair_list_ranges(prm);
      rotations    = prm.interaction.rotations;
      for (const auto &m : prm.materials)
        {
          MaterialConstants k;
          k.m       = m;
          k.rho     = m.density;
          k.G       = m.shear_modulus();
          k.K       = m.bulk_modulus();
          k.D       = m.many_body_coefficient();
          k.two_G   = 2 * k.G;
          k.yield0  = m.is_plastic() ? m.yield_stress
                                     : std::numeric_limits<double>::max();
          k.sigma_b = m.bond_breaking_stress;
          k.w_b     = m.bond_energy_density;
          mc.push_back(k);
        }
      n_materials = mc.size();
      for (const auto &a : mc)
        for (const auto &b : mc)
          {
            const double ki = a.two_G / r0, kj = b.two_G / r0;
            springs.push_back({ki, kj, 1. / (ki + kj), 1. / ki, 1. / kj});
          }
      // The relative-rotation moment's springs (doc/theory/mca.md §3),
      // from the normal ones; a moment law that follows the relative
      // rotation needs rotations (parsing refuses it without).
      moment_laws.with_selected([&](auto &law) {
        if (law.needs_rotations && !rotations)
          throw InputError(
            "Parameter 'Interaction/Relative rotation stiffness' > 0 needs "
            "'Interaction/Rotations = true' (the moment follows the "
            "relative rotation of the automata): switch rotations on, or "
            "set the stiffness to 0.");
        law.set_up(springs, S);
      });
      u_stored = prm.displacements_needed();
      register_automaton_fields();
      register_pair_fields();
    }


    void
    AutomatonSystem::register_pair_fields()
    {
      // What a pair carries from one pair list to the next (migration,
      // rebuild, checkpoint), in this order; the value of a new pair; the
      // rule when its sides exchange (doc/theory/mca.md §3). Bonds and
      // contacts of the initial pairs are set by restore_pair_states().
      const auto c = [](VectorArray &a) {
        return std::vector<std::vector<double> *>{&a.component[0],
                                                  &a.component[1],
                                                  &a.component[2]};
      };
      pair_fields.add({"bonded", Relabel::even, 0, {}, &bonded, {}, {}});
      pair_fields.add(
        {"in_contact", Relabel::even, 0, {}, &in_contact, {}, {}});
      // q_i of a new pair: half the distance (stored where the halves can
      // differ in stiffness, PairArrays::q_stored)
      pair_fields.add({"q_i",
                       Relabel::complement,
                       0.5,
                       {&q_i},
                       nullptr,
                       [this] { return q_stored; },
                       {}});
      // the normal stress of each side, or, until the pairs store their
      // sides' many-body offsets, the part the two sides share
      // (PairArrays::sig_e)
      pair_fields.add({"sigma",
                       Relabel::sides,
                       0,
                       {&sig_i, &sig_j},
                       nullptr,
                       [this] { return mb_stored; },
                       {}});
      pair_fields.add({"sigma (common part)",
                       Relabel::even,
                       0,
                       {&sig_e},
                       nullptr,
                       [this] { return !mb_stored; },
                       {}});
      pair_fields.add({"heat",
                       Relabel::even,
                       0,
                       {&heat},
                       nullptr,
                       [this] { return bond_scene || !heat.empty(); },
                       {}});
      // the many-body part of each side's normal stress (its offset from
      // D mu of the side's automaton, which a rebuild folds into it)
      pair_fields.add({"many_body",
                       Relabel::sides,
                       0,
                       {&mb_i, &mb_j},
                       nullptr,
                       [this] { return mb_stored; },
                       {}});
      pair_fields.add({"tau", Relabel::odd, 0, c(tau), nullptr, {}, {}});
      pair_fields.add({"tau_scale",
                       Relabel::sides,
                       1,
                       {&tau_scale_i, &tau_scale_j},
                       nullptr,
                       [this] { return shear_factors; },
                       {}});
      // the moment law's state (the moment K_ij), if it has one
      moment_laws.register_pair_fields(pair_fields);
      // graded scenes: the geometry of each pair (even: it has no sides)
      pair_fields.add({"area",
                       Relabel::even,
                       0,
                       {&pair_area},
                       nullptr,
                       [this] { return graded; },
                       [this](const unsigned p) { return new_pair_area(p); }});
      pair_fields.add(
        {"half_rest",
         Relabel::even,
         0,
         {&pair_half_rest},
         nullptr,
         [this] { return graded; },
         [this](const unsigned p) { return new_pair_half_rest(p); }});
      // (a global vector, the same seen from either side)
      pair_fields.add({"face_offset",
                       Relabel::even,
                       0,
                       c(face_offset),
                       nullptr,
                       [this] { return graded; },
                       {}});
      // the friction law's state (Dieterich: theta), if it has one
      friction_laws.register_pair_fields(pair_fields);
    }


    void
    AutomatonSystem::register_automaton_fields()
    {
      // In checkpoint order. identity: sized, ordered and checkpointed
      // with the automaton, its id and position the head of a migration
      // record; carried: in the record too; step: checkpointed only;
      // scratch: per-step buffers, counted as memory only. to_ghosts: in
      // the record of a ghost (the pair law and the list need them).
      using Kind = AutomatonFieldKind;
      auto &t    = automaton_fields;

      t.add("id", Kind::identity, id).to_ghosts = true;
      // (the global order key: set at a rebuild, read by the ghosts' ranks)
      t.add("order", Kind::step, order).to_ghosts = true;
      t.add("cell", Kind::identity, cell_of);
      t.add("position", Kind::identity, x).to_ghosts = true;
      t.add("position at rebuild", Kind::step, x_at_rebuild);
      t.add("velocity", Kind::carried, v);
      t.add("angular velocity", Kind::carried, w);
      t.add("force", Kind::carried, f);
      t.add("torque", Kind::carried, torque);
      t.add("displacement", Kind::carried, u, 0, [this] { return u_stored; });
      t.add("material", Kind::carried, mat).to_ghosts          = true;
      t.add("body", Kind::carried, body).to_ghosts             = true;
      t.add("size level", Kind::carried, size_level).to_ghosts = true;
      // (graded scenes: one for all elsewhere, automaton_volume(); a new
      // automaton of the uniform packing: d^3 / sqrt 2)
      t.add("volume", Kind::carried, volume, V, [this] { return graded; });
      t.add("groups", Kind::carried, groups);
      t.add("plastic strain", Kind::carried, eps_p, 0, [this] {
        return plastic_scene;
      });
      t.add("yield stress", Kind::carried, sigma_y, 0, [this] {
        return plastic_scene;
      });
      t.add("many-body mean stress", Kind::step, mb_mu);
      // (the sides' common many-body offset while the pairs store none)
      t.add("many-body offset",
            Kind::carried,
            mb_offset,
            0,
            [this] { return !mb_stored; })
        .to_ghosts
        = true;
      t.add("many-body state", Kind::step, mb_state);
      t.add("inverse fabric", Kind::step, fabric_inverse);
      t.add("neighbourhood changed", Kind::step, changed);
      t.add("damping force", Kind::step, loads.state().f_damp);
      for (auto *buffer : {&plast, &bond_buffer, &dsm, &side_dq})
        t.add("buffer", Kind::scratch, *buffer);
      t.add("many-body shape", Kind::scratch, mb_shape);
      t.add("stress", Kind::scratch, trial);
      t.add("stress anew", Kind::scratch, stress_anew);
      t.add("stress screen", Kind::scratch, stress_screen);
    }


    void
    AutomatonSystem::pack_owned_cells()
    {
      const auto &g = prm.geometry;
      // The upper body of a rough interface is moved up by the gap: it
      // must stay in the box (checked on every rank alike).
      if (g.rough_interface && g.interface_gap > 0)
        for (const Body &b : g.bodies)
          if (std::min(b.upper[2], g.domain_upper[2]) + g.interface_gap
                > g.domain_upper[2]
              && !g.periodic[2])
            throw InputError(
              "Parameter 'Geometry/Rough interface/Gap' moves the upper body "
              "through the top of the box (Geometry/Domain upper): raise "
              "the box's upper z by the gap, or lower the bodies.");
      const Decomposition         &cells = partition.cells();
      std::vector<PackedAutomaton> packed;
      for (unsigned int c = 0; c < cells.n_owned_cells(); ++c)
        {
          Point3 lower, upper;
          cells.cell_box(cells.cell_coordinates(c), lower, upper);
          pack_box(g, lower, upper, [&](const PackedAutomaton &a) {
            // the decomposition decides the cell of points on cell faces
            if (cells.local_cell(a.position) == c)
              packed.push_back(a);
          });
        }
      const unsigned int n = packed.size();
      automaton_fields.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto &a = packed[k];
          id[k]         = a.id;
          x[k]          = a.position;
          mat[k]        = a.material;
          body[k]       = a.body;
          size_level[k] = a.level | (a.transitional ? transitional_flag : 0);
          // (graded scenes; near a change of size: the Voronoi volume, at
          // set-up)
          if (graded)
            volume[k] = V * (1u << (3 * a.level));
          for (const Region &r : prm.interaction.elastic_regions)
            if (r.contains(a.position))
              body[k] |= elastic_flag;
          cell_of[k]         = cells.local_cell(a.position);
          std::uint32_t mask = 0;
          for (unsigned int gi = 0; gi < prm.boundary.groups.size(); ++gi)
            {
              const auto &grp = prm.boundary.groups[gi];
              bool        in  = true;
              for (unsigned int e = 0; e < 3; ++e)
                if (a.position[e] < grp.lower[e]
                    || a.position[e] > grp.upper[e])
                  in = false;
              if (in)
                mask |= (1u << gi);
            }
          groups[k] = mask;
        }
      n_owned = n_local = n;
      // Contacting parts and their inclusion automata (achieved fraction):
      // counts, and volumes in automata of d (an automaton of 2^L d
      // stands for 8^L of them).
      unsigned long long counts[4] = {0, 0, 0, 0};
      for (const auto &a : packed)
        if (a.part > 0)
          {
            const unsigned long long volume = 1ull << (3 * a.level);
            counts[0] += 1;
            counts[1] += a.part == 2;
            counts[2] += volume;
            counts[3] += a.part == 2 ? volume : 0;
          }
      dealii::Utilities::MPI::sum(
        dealii::ArrayView<const unsigned long long>(counts, 4),
        comm,
        dealii::ArrayView<unsigned long long>(counts, 4));
      part_counts = {counts[0], counts[1], counts[2], counts[3]};
    }


    void
    AutomatonSystem::setup()
    {
      // The partition is weighted by the automata each cell will hold (the
      // same packing, counted before it is done): a cell's work is that of
      // its automata and their pairs, and an empty cell costs about an
      // eighth of one automaton (its bins, its share of the ghost layer).
      const auto &g = prm.geometry;
      partition.setup([&](const std::array<unsigned int, 3> &ijk,
                          const Point3                      &lower,
                          const Point3                      &upper) {
        unsigned int                n = 0;
        std::array<unsigned int, 3> home;
        pack_box(g, lower, upper, [&](const PackedAutomaton &a) {
          n += partition.cells().structured_cell(a.position, home)
               && home == ijk;
        });
        return cost_model::cost_per_automaton * n + 1;
      });
      pack_owned_cells();
      n_global = dealii::Utilities::MPI::sum<unsigned long long>(n_owned, comm);

      partition.state().partition_imbalance = work_imbalance();
      if (n_global == 0)
        throw InputError(
          "The packing is empty: no FCC site of spacing Geometry/Automaton "
          "size lies inside a body of Geometry/Bodies within the box "
          "Geometry/Domain lower and Domain upper (or every one was "
          "removed by a void region). Check the boxes and the automaton "
          "size.");

      // Which features does the scene need? (materials used anywhere; the
      // same on every rank, and on a resume, which packs the same scene
      // first.) The moment arms are stored only where a pair's two halves
      // can differ in stiffness: materials of other shear moduli
      // (PairArrays::q_stored).
      std::vector<unsigned int> used(prm.materials.size(), 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        used[mat[k]] = 1;
      dealii::Utilities::MPI::max(used, comm, used);
      double       c_max = 0;
      unsigned int first = n_materials;
      plastic_scene      = false;
      q_stored           = false;
      for (unsigned int m = 0; m < prm.materials.size(); ++m)
        if (used[m])
          {
            c_max = std::max(c_max, prm.materials[m].p_wave_speed());
            if (prm.interaction.plasticity && prm.materials[m].is_plastic())
              plastic_scene = true;
            if (first == n_materials)
              first = m;
            q_stored = q_stored || mc[m].two_G != mc[first].two_G;
          }
      bond_scene = prm.interaction.bond_switching_on();
      // current yield stresses and plastic strains: plastic scenes only
      // (otherwise the initial ones of the materials, and none)
      if (plastic_scene)
        {
          sigma_y.resize(n_owned);
          for (unsigned int k = 0; k < n_owned; ++k)
            sigma_y[k] = mc[mat[k]].yield0;
          eps_p.assign(n_owned, 0.);
        }
      critical_dt = d / c_max;
      if (prm.time.time_step == 0)
        dt = prm.time.courant * critical_dt;
      else
        {
          dt = prm.time.time_step;
          if (dt > TimeParameters::max_courant * critical_dt)
            throw InputError(
              "Parameter 'Time/Time step' = " + format_number(dt)
              + " s is too large: the limit is "
              + format_number(TimeParameters::max_courant * critical_dt)
              + " s, half the sound-crossing time d_min / c_p,max = "
              + format_number(critical_dt)
              + " s of the smallest automaton. Use a smaller step or 0 "
                "(automatic).");
        }

      loads.count_members();

      rebuild(true);

      // The limit of the step where some automaton is stiffer than the
      // uniform lattice's (at a change of size its faces and moments are
      // larger for its inertia; doc/theory/mca.md §6).
      courant_max = stiffest_courant_limit(used);
      if (dt > courant_max * critical_dt * (1 + 1e-12))
        {
          const bool  given = prm.time.time_step > 0;
          std::string m
            = std::string("Parameter '")
              + (given ? "Time/Time step' = " + format_number(dt) + " s"
                       : "Time/Courant factor' = "
                           + format_number(prm.time.courant))
              + " is too large for this scene: its stiffest automaton (at a "
                "change of size, or of material) allows a Courant factor of "
              + format_number(courant_max)
              + " (dt = " + format_number(courant_max * critical_dt)
              + " s), less than the uniform lattice's "
              + format_number(TimeParameters::max_courant)
              + " (its springs and relative-rotation moments are stiffer "
                "for its inertia; doc/stability.md). ";
          m += given ? "Use a time step of at most "
                         + format_number(courant_max * critical_dt)
                         + " s or 0 with 'Time/Courant factor' <= "
                         + format_number(courant_max) + "."
                     : "Set 'Time/Courant factor' to at most "
                         + format_number(courant_max) + ".";
          throw InputError(m);
        }
    }


    void
    AutomatonSystem::step(const bool may_defer)
    {
      // Rebuild the pair list when an automaton moved more than skin/2 (the
      // last step's end complete first: the rebuild reorders the automata
      // and their forces).
      {
        double max_disp2 = agreed_displacement2;
        if (max_disp2 < 0)
          {
            max_disp2 = displacement_since_rebuild();
            if (n_ranks > 1)
              max_disp2 = dealii::Utilities::MPI::max(max_disp2, comm);
          }
        agreed_displacement2 = -1;
        const double limit   = 0.5 * prm.interaction.skin * d;
        if (max_disp2 > limit * limit)
          {
            complete_step();
            rebuild(false);
          }
      }
      const double t      = current_time;
      known_displacement2 = -1;
      if (second_kick_pending)
        {
          // The last step's second half kick, this step's first half kick
          // and its drift in one pass (f holds the pair and external
          // forces of the last step).
          const KickDriftFigures figures
            = loads.kick_kick_drift(work, deferral_speed_limit);
          second_kick_pending = false;
          unstable_since_asked += figures.unstable;
          known_displacement2 = figures.max_displacement2;
        }
      else
        {
          // First half kick (f holds the pair and external forces of the
          // last step).
          loads.half_kick(work);
          loads.apply_constraints(t + 0.5 * dt, work);
          // Drift (the pair kernel takes the increment as dt v again); the
          // automata's displacements where an output reads them, the
          // groups' as their automata move.
          const auto drift_all = [&](auto with_u) {
            for (unsigned int k = 0; k < n_owned; ++k)
              loads.book_displacement(k, drift(k, dt, with_u));
          };
          if (u_stored)
            drift_all(std::true_type());
          else
            drift_all(std::false_type());
        }
      current_time = t + dt;
      evaluate_pairs(dt);
      detect_first_contact();
      loads.apply_forces(current_time);
      ++n_steps_done;
      // The second half kick: now, or with the next step's first
      // (kick_kick_drift()) where the driver lets it wait.
      second_kick_pending = true;
      if (!(may_defer && deferral_speed_limit >= 0
            && loads.may_kick_kick_drift()))
        complete_step();
      // Finiteness and growth: checked by the driver after each step
      // (count_unstable_automata(), source/mca/stability.cc).
    }


    void
    AutomatonSystem::complete_step()
    {
      if (!second_kick_pending)
        return;
      loads.half_kick(work);
      loads.apply_constraints(current_time, work);
      second_kick_pending = false;
      // (the velocities of this step's end, which no deferred kick counts)
      if (deferral_speed_limit >= 0)
        unstable_since_asked += count_unstable_automata(deferral_speed_limit);
    }


    void
    AutomatonSystem::defer_second_kicks(const double speed_limit)
    {
      AssertThrow(speed_limit >= 0, dealii::ExcInternalError());
      deferral_speed_limit = speed_limit;
    }


    unsigned int
    AutomatonSystem::take_unstable_count(const double limit)
    {
      unsigned int n       = unstable_since_asked;
      unstable_since_asked = 0;
      // (counted at complete_step() where the kicks are deferred)
      if (!second_kick_pending && deferral_speed_limit < 0)
        n += count_unstable_automata(limit);
      return n;
    }


    void
    AutomatonSystem::detect_first_contact()
    {
      if (!loads.waits_for_contact())
        return;
      // Before the bodies touch, every unbonded pair in contact joins the
      // two bodies (pairs within a body start bonded).
      unsigned int touching = 0;
      for (unsigned int p = 0; p < pi.size() && !touching; ++p)
        touching = !bonded[p] && in_contact[p];
      if (n_ranks > 1)
        touching = dealii::Utilities::MPI::max(touching, comm);
      if (touching)
        loads.set_contact_time(current_time);
    }


    double
    AutomatonSystem::displacement_since_rebuild() const
    {
      if (known_displacement2 >= 0)
        return known_displacement2;
      double max_disp2 = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        max_disp2 = std::max(max_disp2, displacement2_since_rebuild(k));
      return max_disp2;
    }


    void
    AutomatonSystem::set_agreed_displacement_since_rebuild(
      const double max_displacement2)
    {
      agreed_displacement2 = max_displacement2;
    }


    SystemEnergies
    AutomatonSystem::energies() const
    {
      SystemEnergies e;
      double         kinetic = 0, elastic = pair_elastic_energy();
      for (unsigned int k = 0; k < n_owned; ++k)
        kinetic += 0.5 * mass_of(k) * dot(v[k], v[k])
                   + 0.5 * inertia_of(k) * dot(w[k], w[k]);
      if (moment_laws.active())
        elastic += pair_moment_energy();
      unsigned long long nb = 0, nu = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        // each pair counted once: by the owner of i (or of j when i is a
        // periodic image of an owned automaton on the same rank)
        if (owned(pi[p]))
          {
            if (bonded[p])
              ++nb;
            else if (in_contact[p])
              ++nu;
          }
      // the energies of this rank, then its works (one list: Work)
      std::array<double, 2 + n_works> sums{};
      sums[0] = kinetic;
      sums[1] = elastic;
      std::copy(work.begin(), work.end(), sums.begin() + 2);
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums),
                                  comm,
                                  dealii::ArrayView<double>(sums));
      unsigned long long counts[2] = {nb, nu};
      dealii::Utilities::MPI::sum(
        dealii::ArrayView<const unsigned long long>(counts, 2),
        comm,
        dealii::ArrayView<unsigned long long>(counts, 2));
      const double *ws = sums.data() + 2;
      for (const LedgerEntry &entry : energy_ledger)
        if (entry.work < n_works)
          e[entry.term] = ws[entry.work];
      e[Energy::kinetic]    = sums[0];
      e[Energy::elastic]    = sums[1];
      e[Energy::n_bonded]   = counts[0];
      e[Energy::n_unbonded] = counts[1];
      return e;
    }


    unsigned long long
    AutomatonSystem::n_global_pairs() const
    {
      unsigned long long n = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        n += owned(pi[p]);
      return dealii::Utilities::MPI::sum(n, comm);
    }


    unsigned long long
    AutomatonSystem::n_dropped_bonds() const
    {
      return dealii::Utilities::MPI::sum(dropped_bonds, comm);
    }


    std::vector<std::pair<std::string, std::size_t>>
    AutomatonSystem::memory_by_part() const
    {
      std::vector<std::pair<std::string, std::size_t>> parts;
      automaton_fields.memory_by_field(parts);
      pair_fields.memory_by_field(parts);
      PairList::memory_by_part(parts);
      add_memory_part(parts,
                      "pair step buffers (distance, normal, mu)",
                      pair_dr,
                      step_normals,
                      pair_mu);
      add_memory_part(parts, "pair side factors (beta)", beta_i, beta_j);
      add_memory_part(parts, "kept pair states", kept_states, kept_keys);
      parts.emplace_back("background mesh and cell tables",
                         partition.cells().memory_consumption());
      return parts;
    }


    std::size_t
    AutomatonSystem::memory_consumption() const
    {
      std::size_t bytes = 0;
      for (const auto &part : memory_by_part())
        bytes += part.second;
      return bytes;
    }


    std::vector<unsigned int>
    AutomatonSystem::bonded_neighbour_counts() const
    {
      std::vector<unsigned int> n(n_local, 0);
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (bonded[p])
          {
            ++n[pi[p]];
            ++n[pj[p]];
          }
      return n;
    }


    std::vector<unsigned int>
    AutomatonSystem::unbonded_contact_counts() const
    {
      std::vector<unsigned int> n(n_local, 0);
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (!bonded[p] && in_contact[p])
          {
            ++n[pi[p]];
            ++n[pj[p]];
          }
      return n;
    }


    std::vector<AutomatonSystem::ContactLine>
    AutomatonSystem::unbonded_contact_lines() const
    {
      std::vector<ContactLine> lines;
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (!bonded[p] && in_contact[p] && owned(pi[p]))
          lines.push_back({partition.cells().wrap(x[pi[p]]),
                           pair_vector(p),
                           0.5 * (side_sigma(p, 0) + side_sigma(p, 1))});
      return lines;
    }


    std::vector<AutomatonSystem::PairView>
    AutomatonSystem::pair_views() const
    {
      std::vector<PairView> out;
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          PairView pv;
          pv.id_i   = id[pi[p]];
          pv.id_j   = id[pj[p]];
          pv.bonded = bonded[p];
          pv.sigma  = 0.5 * (side_sigma(p, 0) + side_sigma(p, 1));
          for (unsigned int c = 0; c < 3; ++c)
            pv.tau[c] = 0.5 * (shear_factor(p, 0) + shear_factor(p, 1))
                        * tau.component[c][p];
          pv.heat     = heat.empty() ? 0. : heat[p];
          pv.distance = pair_distance(p);
          moment_laws.with_selected(
            [&](const auto &law) { pv.moment = law.moment(p); });
          out.push_back(pv);
        }
      return out;
    }


    void
    AutomatonSystem::set_pair_heat(const double value)
    {
      heat.assign(pi.size(), value);
    }
  } // namespace mca
} // namespace tribodyn
