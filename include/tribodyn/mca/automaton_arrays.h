// The automata of a rank as flat arrays (design §6; doc/theory/mca.md §1):
// a base of AutomatonSystem that holds its per-automaton state, indexed by
// a local automaton index, and the per-step buffers of the pair kernel
// per automaton. Between two pair-list rebuilds the owned automata come
// first (along the space-filling curve of their cells), then the ghosts.
#ifndef tribodyn_mca_automaton_arrays_h
#define tribodyn_mca_automaton_arrays_h

#include <algorithm>
#include <array>
#include <cstdint>
#include <deal.II/base/exceptions.h>
#include <tribodyn/mca/automaton_fields.h>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/vector_algebra.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * Per-automaton arrays of AutomatonSystem (owned first, then ghosts),
     * with the flags packed into them.
     */
    /// The many-body energy of an automaton, kappa G^2 (doc/theory/mca.md
    /// §8.4): G = sum g m over its weighted sides (g = beta / h, m a side's
    /// many-body part), gamma = sum g; lambda = S / g of its sides where
    /// that and m are the same on all (a uniform automaton), else 0.
    struct ManyBodyState
    {
      double kappa = 0, gamma = 0, G = 0, lambda = 0;
    };

    /// Whether S / g and the many-body part m are the same on all weighted
    /// sides of an automaton (uniform; opened: it was at the start of the
    /// step, and a side opened in pass A).
    enum class ManyBodyShape : std::uint8_t
    {
      general,
      uniform,
      opened
    };

    struct AutomatonArrays
    {
      unsigned int               n_owned = 0, n_local = 0;
      std::vector<std::uint32_t> id;
      /// Global order key: curve index of the cell << 16 | rank of the id
      /// within the cell (lives during a rebuild only).
      std::vector<std::uint64_t> order;
      std::vector<unsigned int>  cell_of; ///< local cell (at the rebuild)
      std::vector<Point3>        x;
      /// Positions at the last rebuild, for the skin test only (single
      /// precision: a test against skin d / 2).
      std::vector<std::array<float, 3>> x_at_rebuild;
      /// v: velocity (the drift of a step is dt v); f: pair forces, then
      /// (BoundaryLoads::apply_forces()) the total force of the kicks.
      std::vector<Vec3> v, w, f, torque, u;
      /// Whether u, each automaton's displacement since the start, is
      /// stored: where an output reads it (Parameters::
      /// displacements_needed(); a resumed run has the parameters of the
      /// run it resumes). Elsewhere u stays empty (24 bytes per automaton
      /// neither kept nor written by the drift).
      bool u_stored = true;
      /// material index; body index, with elastic_flag for the automata
      /// of elastic regions
      std::vector<unsigned char> mat, body;
      /// size level L (size 2^L d), with transitional_flag
      std::vector<unsigned char> size_level;
      /// Volume of each owned automaton in graded scenes (2^3L d^3/sqrt 2
      /// of its size level L; its Voronoi cell's near a change of size);
      /// elsewhere the one volume V = d^3/sqrt 2 of all, volume_mask 0:
      /// automaton k's is volume[k & volume_mask] either way (a load, no
      /// branch: the kernel's arithmetic compiles as with a stored volume
      /// per automaton; SystemScalars::automaton_volume()).
      std::vector<double>        volume;
      unsigned int               volume_mask = ~0u;
      std::vector<std::uint32_t> groups;
      std::vector<double>        eps_p, sigma_y;
      /// Per-step exchange buffers (stride given by their use).
      std::vector<double> plast;       ///< sigma_m trial, M
      std::vector<double> bond_buffer; ///< stress tensor (6), yield stress
      /// Per local automaton, bond scenes whose breaking criterion screens
      /// its pairs: the criterion's figures of its stress tensor
      /// (screen_size floats, e.g. VonMisesBondBreaking::screen_figures()).
      std::vector<float> stress_screen;
      /// Per automaton: the volumetric strain increment, then the
      /// mean-stress increment (exchanged with the ghosts).
      std::vector<double> dsm;
      /// Per owned automaton: the sum of S dq over its sides in a step
      /// (the work of its many-body part, doc/theory/mca.md §8.4; its own,
      /// not exchanged).
      std::vector<double> side_dq;
      /// Many-body energy (doc/theory/mca.md §8.4): mean-stress increments
      /// of each local automaton since the last rebuild (mu_a; a side's
      /// many-body stress is D mu_a + its offset, PairArrays::mb_i), and
      /// the many-body state of each owned one.
      std::vector<double> mb_mu;
      /// The offset c of the many-body stress of every side of each local
      /// automaton (its sides' many-body part is D mu_a + c), while the
      /// pairs do not store their sides' own (PairArrays::mb_stored
      /// false): until a scene can have an event that moves one side's
      /// offset, all sides of an automaton share it (a rebuild folds D mu
      /// into it as into the pairs' offsets). Empty once they do.
      std::vector<double>        mb_offset;
      std::vector<ManyBodyState> mb_state;
      /// Per owned automaton: its ManyBodyShape. The many-body work of
      /// the weighted sides of a uniform automaton over a step is the
      /// change of kappa G^2 exactly (no per-side sums: doc/theory/mca.md
      /// §8.4); set by update_many_body_state(). The events that move one
      /// side's m or g end it: an opening in pass A marks it opened (the
      /// end of the pass completes it), those of pass C set lambda = 0
      /// (a store in the struct they update anyway; a store to this array
      /// there costs 5 % of a plastic kernel), seen at the kernel's end.
      std::vector<ManyBodyShape> mb_shape;
      /// Stress tensors T (eq. 4) of the owned automata: the plastic
      /// trial in pass B, the final one in pass C of bond scenes.
      std::vector<Mat3> trial;
      /// Per local automaton, plastic bond kernels: 1 where pass C must
      /// sum the final tensor anew (a plastic return, an unbonded contact
      /// or an elastic region: pass B's trial is not the final one there).
      std::vector<unsigned char> stress_anew;
      /// Inverse fabric tensors (plastic and bond scenes, which need the
      /// stress every step; otherwise computed when a stress is asked).
      std::vector<Sym3> fabric_inverse;
      /// Owned automata whose contacts or bonds changed (weights stale).
      std::vector<unsigned char> changed;
      bool                       any_changed = true;
      /// Every per-automaton array, registered once with its kind
      /// (AutomatonSystem::register_automaton_fields(): the one list of
      /// what an automaton carries, what is checkpointed and what is
      /// counted as memory).
      AutomatonFieldTable automaton_fields;

      /// Is local automaton @p k owned by this rank?
      bool
      owned(const unsigned int k) const
      {
        return k < n_owned;
      }
      /// Bit of body[k] marking an automaton of an elastic region.
      static constexpr unsigned char elastic_flag = 0x80;
      /// Body index of local automaton @p k.
      unsigned int
      body_index(const unsigned int k) const
      {
        return body[k] & ~elastic_flag;
      }
      /// Does local automaton @p k belong to an elastic region?
      bool
      elastic(const unsigned int k) const
      {
        return (body[k] & elastic_flag) != 0;
      }
      /// Bit of size_level[k] marking an automaton near a change of size.
      static constexpr unsigned char transitional_flag = 0x80;
      /// Is local automaton @p k near a change of size?
      bool
      transitional(const unsigned int k) const
      {
        return (size_level[k] & transitional_flag) != 0;
      }
      /// Pair-list ranges [near a change of size][size level].
      using RangeTable = std::array<std::array<double, 8>, 2>;
      /// Pair-list range of two automata (or of an automaton and the
      /// summary of a cell, cell_level_summary()) of size-level bytes @p a
      /// and @p b: that of the larger size, near a change of size if
      /// either is.
      static double
      pair_list_range(const RangeTable   &ranges,
                      const unsigned char a,
                      const unsigned char b)
      {
        const unsigned int level
          = std::max(a & ~transitional_flag, b & ~transitional_flag);
        return ranges[((a | b) & transitional_flag) != 0][level];
      }
      /// The size-level summary of a group of automata (a cell's, a bin's)
      /// with one more of size-level byte @p b: the largest level, and the
      /// transitional flag if any has it. pair_list_range() of a summary
      /// bounds that of each automaton it summarizes (the ranges grow with
      /// the level and near a change of size).
      static unsigned char
      merge_level_summary(const unsigned char summary, const unsigned char b)
      {
        return std::max<unsigned char>(summary & ~transitional_flag,
                                       b & ~transitional_flag)
               | ((summary | b) & transitional_flag);
      }
      /// A ghost is sent when its squared distance to a cell of the
      /// receiving rank is below this factor times its squared reach: the
      /// margin covers the round-off of the cells' boxes.
      static constexpr double ghost_reach_margin = 1 + 1e-12;

      // ---- read access (public in AutomatonSystem; owned automata:
      // index < n_owned)
      unsigned int
      n_owned_automata() const
      {
        return n_owned;
      }
      unsigned int
      n_ghost_automata() const
      {
        return n_local - n_owned;
      }
      const std::vector<Point3> &
      positions() const
      {
        return x;
      }
      /// Displacement accumulated since the start (unaffected by periodic
      /// wrapping), where the scene's outputs read it (u_stored; empty
      /// otherwise).
      const std::vector<Vec3> &
      displacements() const
      {
        Assert(u_stored,
               dealii::ExcMessage("no output of this scene reads "
                                  "the displacements: not stored"));
        return u;
      }
      const std::vector<std::uint32_t> &
      ids() const
      {
        return id;
      }
      const std::vector<Vec3> &
      velocities() const
      {
        return v;
      }
      /// Plastic strain of local automaton @p k (0 in elastic scenes,
      /// which do not store it).
      double
      plastic_strain(const unsigned int k) const
      {
        return eps_p.empty() ? 0. : eps_p[k];
      }
      const std::vector<unsigned char> &
      materials() const
      {
        return mat;
      }
      const std::vector<Vec3> &
      angular_velocities() const
      {
        return w;
      }
      /// Pair forces on the local automata at the last evaluation (owned:
      /// complete; tests).
      const std::vector<Vec3> &
      forces() const
      {
        return f;
      }
      /// Size level L (size 2^L d) of each local automaton.
      std::vector<unsigned int>
      size_levels() const
      {
        std::vector<unsigned int> out(size_level.size());
        for (unsigned int k = 0; k < out.size(); ++k)
          out[k] = size_level[k] & ~transitional_flag;
        return out;
      }
      /// Pair torques on the local automata at the last evaluation (owned:
      /// complete).
      const std::vector<Vec3> &
      torques() const
      {
        return torque;
      }

      // ---- one automaton's share of a step's loops (AutomatonSystem::step(),
      // BoundaryLoads::kick_kick_drift(), the health check), written once
      /// The drift x += dt v of owned automaton @p k (and of its
      /// displacement u where @p with_u, std::true_type or std::false_type);
      /// returns the move dt v.
      template <class WithU>
      Vec3
      drift(const unsigned int k, const double dt, WithU)
      {
        Vec3 dx;
        for (unsigned int c = 0; c < 3; ++c)
          {
            dx[c] = dt * v[k][c];
            x[k][c] += dx[c];
            if constexpr (WithU::value)
              u[k][c] += dx[c];
          }
        return dx;
      }
      /// Squared displacement of owned automaton @p k since the last
      /// pair-list rebuild.
      double
      displacement2_since_rebuild(const unsigned int k) const
      {
        double d2 = 0;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const double e = x[k][c] - x_at_rebuild[k][c];
            d2 += e * e;
          }
        return d2;
      }
      /// Is the velocity |v| or the surface speed |w| @p half of local
      /// automaton @p k (@p half: half its size) above the speed whose
      /// square is @p limit2, or not finite? (Written so that NaN counts.)
      bool
      too_fast(const unsigned int k,
               const double       limit2,
               const double       half) const
      {
        const double s = dot(v[k], v[k]);
        const double r = dot(w[k], w[k]) * half * half;
        return !(s <= limit2 && r <= limit2);
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
