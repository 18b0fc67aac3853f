// The scene's scalars of AutomatonSystem (a base, like AutomatonArrays and
// PairArrays): the constants of its materials and of their pairs' springs,
// the lattice's geometry, the time step and the counters of the run.
#ifndef tribodyn_mca_system_scalars_h
#define tribodyn_mca_system_scalars_h

#include <cstdint>
#include <tribodyn/mca/automaton_arrays.h>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/series_springs.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * Scalars of AutomatonSystem, set by its constructor and its run.
     */
    struct SystemScalars
    {
      // material constants indexed by material
      struct MaterialConstants
      {
        double             rho, G, K, D, two_G, yield0, sigma_b, w_b;
        MaterialParameters m;
      };
      std::vector<MaterialConstants> mc;
      /// The normal springs of each pair of materials (series_springs.h),
      /// by mat_i * n_materials + mat_j.
      std::vector<SeriesSprings> springs;
      unsigned int               n_materials = 0;
      bool   plastic_scene = false, bond_scene = false, rotations = true;
      double d = 0, r0 = 0, S = 0, V = 0, range = 0;
      /// Geometry/Size bands given: automata of several sizes.
      bool graded = false;
      /// Graded pair-list ranges [near a change of size][size level].
      AutomatonArrays::RangeTable graded_range{};

      double dt = 0, critical_dt = 0, current_time = 0;
      /// The largest Courant factor the scene's stiffest automaton allows
      /// (AutomatonSystem::stiffest_courant_limit()).
      double        courant_max  = 0;
      unsigned long n_steps_done = 0;
      /// set_agreed_displacement_since_rebuild()'s value, for the next
      /// step only (negative: not given, step() reduces on its own)
      double agreed_displacement2 = -1;
      /// The displacement_since_rebuild() of the automata where their last
      /// drift measured it on its way (BoundaryLoads::kick_kick_drift());
      /// negative: not known, computed when asked.
      double known_displacement2 = -1;
      /// Velocity Verlet's second half kick of the last step is pending
      /// (AutomatonSystem::step()); the speed limit its deferred kicks
      /// check (negative: step() does not defer), and the automata they
      /// found above it since the driver last asked.
      bool               second_kick_pending  = false;
      double             deferral_speed_limit = -1;
      unsigned int       unstable_since_asked = 0;
      unsigned long long n_global             = 0;
      unsigned int       rebuild_count        = 0;

      /// Volume of local automaton @p k of @p a (AutomatonArrays::volume).
      double
      automaton_volume(const AutomatonArrays &a, const unsigned int k) const
      {
        return a.volume[k & a.volume_mask];
      }
      /// Mass rho V of local automaton @p k of @p a.
      double
      automaton_mass(const AutomatonArrays &a, const unsigned int k) const
      {
        return mc[a.mat[k]].rho * automaton_volume(a, k);
      }
      /// Size 2^L d of local automaton @p k of @p a.
      double
      automaton_size(const AutomatonArrays &a, const unsigned int k) const
      {
        return d
               * (1u << (a.size_level[k]
                         & ~AutomatonArrays::transitional_flag));
      }
      /// Moment of inertia m s^2 / 10 of local automaton @p k of @p a (a
      /// sphere of the automaton's size s).
      double
      automaton_inertia(const AutomatonArrays &a, const unsigned int k) const
      {
        const double s = automaton_size(a, k);
        return automaton_mass(a, k) * s * s / 10;
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
