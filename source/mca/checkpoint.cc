// Checkpoints of the automata: the whole state of this rank between two
// steps, as a Boost binary archive. Between two pair-list rebuilds the state
// lives in the flat arrays of AutomatonSystem (the ParticleHandler is empty:
// it only carries migrating automata during a rebuild), and the p4est mesh
// and its partition are rebuilt identically by setup() on the same number
// of ranks, so saving the arrays and restoring them after setup() continues
// the run bit for bit. A partition weighted anew during the run
// (automaton_partition.cc) is rebuilt by replaying the weights this rank gave.
// On another number of ranks the saved arrays are read one writer at a time and
// turned into records sent to the new owners (redistribution.cc).
//
// What is saved: the run's counters (MCA_CHECKPOINT_STATE below), every
// per-automaton array but the scratch ones (AutomatonSystem::
// register_automaton_fields()), the pair list, the persistent pair fields
// (register_pair_fields()) and the pair lists of the automata
// (MCA_CHECKPOINT_PAIR_LISTS). A new per-automaton array or persistent pair
// field is registered, nothing else; a new counter goes into the list
// below. The ctest mca_restart_* tests compare a resumed run with an
// uninterrupted one and fail if something is missed. Per-step pair buffers
// (pair_dr, step_normals) and the rebuild's transient lists (kept_states,
// kept_keys, old_pairs, old_flags) are rebuilt before use and are not
// saved, nor is mb_shape (a scratch field, derived from mb_state on
// resume); the material constants (mc, springs) come from the parameters.
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/array.hpp>
#include <boost/serialization/binary_object.hpp>
#include <boost/serialization/vector.hpp>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/automaton_system.h>
#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      // 2: with the relative-rotation moments (pair_moment); 3: size levels
      // and volumes of the automata (graded scenes); 4: the rebalances of
      // the partition; 5: the friction law's pair state (Dieterich's theta);
      // 6: the run's state that follows is the postprocessors' (in list
      // order, source/mca/mca_problem.cc)
      // 7: the pair-level energy (many-body offsets of the sides, mu,
      // kappa, gamma, G of the automata, switching and many-body work);
      // 8: which automata are many-body uniform; 9: that derived from
      // lambda on resume (sync_many_body_shapes()), not saved; 10: the
      // per-automaton arrays from their table (automaton_fields), after the
      // group reactions; 11: the works of the physical balance
      // (plastic_work_flow_rule, friction_work_law); 12: the sides'
      // many-body offsets stored once the side states are; 13: the
      // postprocessors' states by name (core/plugin_states.h); 14: the
      // groups' displacements as sums of this rank's drifts (the automata's
      // own only where an output reads them: the parameters, which a
      // resumed run may not change, decide it alike); 15: the sides'
      // normal stresses stored with their many-body offsets, their common
      // part until then (PairArrays::sig_e)
      constexpr unsigned int state_version = 15;

      // Scalars and vectors of trivially copyable types as raw bytes (fast
      // and exact); anything else through Boost's own serialization.
      template <typename T>
      void
      put(boost::archive::binary_oarchive &ar, const T &value)
      {
        ar << value;
      }
      template <typename T>
      void
      put(boost::archive::binary_oarchive &ar, const std::vector<T> &vec)
      {
        if constexpr (std::is_trivially_copyable<T>::value)
          {
            const std::size_t n = vec.size();
            ar << n;
            if (n > 0)
              ar << boost::serialization::make_binary_object(
                const_cast<T *>(vec.data()), n * sizeof(T));
          }
        else
          ar << vec;
      }
      template <typename T>
      void
      get(boost::archive::binary_iarchive &ar, T &value)
      {
        ar >> value;
      }
      template <typename T>
      void
      get(boost::archive::binary_iarchive &ar, std::vector<T> &vec)
      {
        if constexpr (std::is_trivially_copyable<T>::value)
          {
            std::size_t n = 0;
            ar >> n;
            vec.resize(n);
            if (n > 0)
              ar >> boost::serialization::make_binary_object(vec.data(),
                                                             n * sizeof(T));
          }
        else
          ar >> vec;
      }
    } // namespace

// The state of AutomatonSystem carried from one step to the next.
// clang-format off
#define MCA_CHECKPOINT_STATE(apply)                                           \
  /* counters and accumulators */                                             \
  apply(n_owned) apply(n_local) apply(current_time) apply(n_steps_done)       \
  apply(rebuild_count) apply(work)                                            \
  /* whether the pairs store their sides' many-body offsets (every rank or    \
     none: decided together at each rebuild) */                               \
  apply(mb_stored)                                                            \
  apply(dropped_bonds) apply(any_changed)                                     \
  /* the partition: weights of each rebalance (replayed on resume) */         \
  apply(partition.state().rebalance_count)                                    \
  apply(partition.state().partition_imbalance)                                \
  apply(partition.state().rebalance_history)                                  \
  /* staged loading and energy bookkeeping */                                 \
  apply(loads.state().first_contact_time)                                     \
  apply(loads.state().f_damp_rebuild) apply(loads.state().group_reaction)    \
  apply(loads.state().group_displacement)
// (then the automata, from automaton_fields; the pairs: the list, the
// persistent fields from pair_fields, the lists of the automata)
#define MCA_CHECKPOINT_PAIRS(apply)                                           \
  apply(pi) apply(pj) apply(pshift)
#define MCA_CHECKPOINT_PAIR_LISTS(apply)                                      \
  apply(beta_i) apply(beta_j) apply(i_pairs_first) apply(i_pairs_count)       \
  apply(j_pairs_first) apply(j_pairs)
    // clang-format on


    void
    AutomatonSystem::save_state(boost::archive::binary_oarchive &ar) const
    {
      ar << state_version << n_ranks << dt << n_global;
#define MCA_PUT(member) put(ar, member);
      MCA_CHECKPOINT_STATE(MCA_PUT)
      automaton_fields.save(ar);
      MCA_CHECKPOINT_PAIRS(MCA_PUT)
      pair_fields.for_each_array([&](const auto &a) { put(ar, a); },
                                 [&](const auto &a) { put(ar, a); });
      MCA_CHECKPOINT_PAIR_LISTS(MCA_PUT)
#undef MCA_PUT
      // the ghost lists of the point-to-point updates
      put(ar, partition.neighbours().ghost_offsets());
      const auto       &send    = partition.neighbours().ghost_send_indices();
      const std::size_t n_lists = send.size();
      ar << n_lists;
      for (const auto &list : send)
        put(ar, list);
    }


    void
    AutomatonSystem::read_saved_arrays(
      boost::archive::binary_iarchive        &ar,
      const bool                              same_ranks,
      std::vector<unsigned int>              &offsets,
      std::vector<std::vector<unsigned int>> &send)
    {
      unsigned int       version = 0, saved_ranks = 0;
      double             saved_dt     = 0;
      unsigned long long saved_global = 0;
      ar >> version >> saved_ranks >> saved_dt >> saved_global;
      if (version != state_version || (same_ranks && saved_ranks != n_ranks)
          || saved_dt != dt || saved_global != n_global)
        throw InputError(
          "The checkpoint does not fit this run (it has "
          + std::to_string(saved_global) + " automata and dt = "
          + format_number(saved_dt) + " s, format " + std::to_string(version)
          + "; this run " + std::to_string(n_global) + ", " + format_number(dt)
          + " s, format " + std::to_string(state_version)
          + "). Resume with the parameters of the checkpointed run and this "
            "version of tribodyn.");
#define MCA_GET(member) get(ar, member);
      MCA_CHECKPOINT_STATE(MCA_GET)
      automaton_fields.load(ar);
      MCA_CHECKPOINT_PAIRS(MCA_GET)
      pair_fields.for_each_array([&](auto &a) { get(ar, a); },
                                 [&](auto &a) { get(ar, a); });
      // (stored shear factors: the saved rank had them; once stored they
      // stay, also over the files a rank absorbs: all 1 where not saved)
      if (!tau_scale_i.empty())
        shear_factors = true;
      else if (shear_factors)
        {
          tau_scale_i.assign(pi.size(), 1.);
          tau_scale_j.assign(pi.size(), 1.);
        }
      MCA_CHECKPOINT_PAIR_LISTS(MCA_GET)
#undef MCA_GET
      // (derived from the lists read: the pair kernel's pipeline)
      chunk_for_pipeline(n_owned);
      sync_many_body_shapes();
      get(ar, offsets);
      std::size_t n_lists = 0;
      ar >> n_lists;
      send.assign(n_lists, {});
      for (auto &list : send)
        get(ar, list);
    }


    void
    AutomatonSystem::load_state(boost::archive::binary_iarchive &ar)
    {
      std::vector<unsigned int>              offsets;
      std::vector<std::vector<unsigned int>> send;
      read_saved_arrays(ar, true, offsets, send);
      // the checkpointed partition (the saved arrays are numbered by its
      // cells)
      if (!partition.state().rebalance_history.empty())
        partition.replay_rebalances();
      partition.restore_ghost_lists(std::move(send), std::move(offsets));
    }


    void
    AutomatonSystem::absorb_state(boost::archive::binary_iarchive &ar)
    {
      std::vector<unsigned int>              offsets;
      std::vector<std::vector<unsigned int>> send;
      read_saved_arrays(ar, false, offsets, send);
      absorb_current_arrays();
    }

#undef MCA_CHECKPOINT_STATE
#undef MCA_CHECKPOINT_PAIRS
#undef MCA_CHECKPOINT_PAIR_LISTS
  } // namespace mca
} // namespace tribodyn
