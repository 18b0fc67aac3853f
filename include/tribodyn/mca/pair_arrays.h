// The state of the pairs of a rank as flat arrays (design §6;
// doc/theory/mca.md §1, §3): a base of AutomatonSystem that holds the state
// of each pair of the pair list (pair_list.h, indexed by the same pair
// number), the table of its persistent fields (pair_fields.h: what a pair
// carries over rebuilds, migration and checkpoints) and the records that
// carry them over a rebuild.
#ifndef tribodyn_mca_pair_arrays_h
#define tribodyn_mca_pair_arrays_h

#include <cstdint>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/vector_algebra.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /// One pair as seen by tests (AutomatonSystem::pair_views()).
    struct PairView
    {
      std::uint64_t id_i, id_j;
      bool          bonded;
      double        sigma; ///< mean of the two sides
      Vec3          tau;
      double        heat;
      double        distance;
      /// Relative-rotation moment K_ij on i (-K_ij on j); zero when
      /// Interaction/Relative rotation stiffness is 0.
      Vec3 moment;
    };

    /**
     * Per-pair state of AutomatonSystem, indexed by pair (PairList).
     */
    struct PairArrays
    {
      std::vector<unsigned char> bonded, in_contact;
      /// Moment arm q_i of side i (q_j = r - q_i): stored only where the
      /// two halves of a pair can differ in stiffness (materials of other
      /// shear moduli). Where every pair's halves are equally stiff the
      /// series springs split each increment in half and q_i = r / 2 at
      /// all times (a new pair starts at half its distance): q_stored is
      /// false, the array empty (8 bytes a pair neither kept nor streamed)
      /// and moment_arm() gives r / 2.
      std::vector<double> q_i, heat;
      bool                q_stored = true;
      /// Normal stress of each side, sigma_i and sigma_j: stored where the
      /// pairs store their sides' many-body offsets (mb_stored). Until
      /// then every pair is a bonded pair of one material from the start
      /// (no event), so both sides took the same elastic increments 2G de
      /// and each side the many-body increments D dmu of its automaton:
      /// sigma_s = sig_e + m_s, with m_s = D mu + c of the side's automaton
      /// (AutomatonSystem::side_sigma()). Then only the common part sig_e
      /// is stored and sig_i, sig_j are empty (8 bytes a pair less, and
      /// pass C reads one number where it added to two).
      std::vector<double> sig_i, sig_j, sig_e;
      /// Many-body part m of each side's normal stress, as its offset from
      /// D mu of the side's automaton (doc/theory/mca.md §8.4). Stored
      /// (mb_stored) together with the shear factors, from the rebuild at
      /// which a scene can first have an event that moves one side's
      /// offset apart from the other sides of its automaton (a plastic
      /// return, a bond switch, a contact that starts or opens); until
      /// then every side of automaton a has the offset
      /// AutomatonArrays::mb_offset[a] and the arrays stay empty (16
      /// bytes per pair neither kept nor moved: an elastic bulk of one
      /// material, all bonded).
      std::vector<double> mb_i, mb_j;
      bool                mb_stored = false;
      /// This step's normal increment dr and t . du of the pairs that may
      /// release energy in pass C (2 per pair; pair_kernel.cc).
      std::vector<double> pair_dr;
      /// Plastic and bond kernels: this step's distance r and unit normal n
      /// of every pair (4 blocks of the pair count: r, n_x, n_y, n_z), as
      /// pass A computes them, for passes B, C and bond switching (the same
      /// bits as computing them anew; pair_kernel.cc).
      std::vector<double> step_normals;
      /// Shear stresses: tau_i = tau_scale_i tau, tau_j = tau_scale_j tau.
      /// The two sides' shear stresses are always parallel (the series
      /// springs set them equal; the plastic correction and the Coulomb
      /// limit of each side only scale them), so one vector (odd under
      /// i <-> j) and two factors hold both: 40 instead of 48 bytes.
      /// Only an event (a plastic return, a Coulomb limit, a release) sets
      /// a factor other than 1: until a scene can have one, the factors
      /// are all 1 and their arrays stay empty (shear_factors false; 16
      /// bytes per pair saved and not streamed: an elastic bulk of one
      /// material, all bonded; AutomatonSystem::allocate_side_states()).
      VectorArray         tau;
      std::vector<double> tau_scale_i, tau_scale_j;
      bool                shear_factors = false;
      /// Graded scenes: contact area S_ij and half rest length of each pair
      /// (empty otherwise: S and r0).
      std::vector<double> pair_area, pair_half_rest;
      /// Graded scenes: offset e_ij of the pair's Voronoi face centroid
      /// from the line of centres, where its forces act (zero on a
      /// dodecahedron; doc/theory/mca.md §9).
      VectorArray         face_offset;
      std::vector<double> beta_i, beta_j;
      /// Rate-dependent friction laws: mu of each pair in this step.
      std::vector<double> pair_mu;

      /// The persistent pair fields above with their relabelling rules
      /// (register_pair_fields(): the one list of what a pair carries).
      PairFieldTable pair_fields;
      /// Pair states received over a rebuild: records of
      /// pair_fields.width() doubles in id order (kept_states), and their
      /// keys (smaller id << 32 | larger id) with the record index, sorted.
      std::vector<double>                                  kept_states;
      std::vector<std::pair<std::uint64_t, std::uint32_t>> kept_keys;
      /// This rank's old pairs by their ids (12 bytes each: this list is
      /// part of the memory peak of a rebuild).
      struct OldPair
      {
        std::uint32_t lo, hi; ///< smaller and larger id
        std::uint32_t index;  ///< into the old pair arrays
      };
      std::vector<OldPair> old_pairs;
      /// Per old pair: 1 = its i had the larger id.
      std::vector<unsigned char> old_flags;

      /// Moment arm q of side @p side (0: i, 1: j) of pair @p p at distance
      /// @p r.
      double
      moment_arm(const unsigned int p,
                 const double       r,
                 const unsigned int side) const
      {
        const double qi = q_stored ? q_i[p] : 0.5 * r;
        return side == 0 ? qi : r - qi;
      }
      /// Shear factor of side @p side (0: i, 1: j) of pair @p p.
      double
      shear_factor(const unsigned int p, const unsigned int side) const
      {
        if (!shear_factors)
          return 1.;
        return side == 0 ? tau_scale_i[p] : tau_scale_j[p];
      }
      /// Shear stress of side @p side (0: i, 1: j) of pair @p p.
      Vec3
      side_shear(const unsigned int p, const unsigned int side) const
      {
        const double a = shear_factor(p, side);
        return {{a * tau.component[0][p],
                 a * tau.component[1][p],
                 a * tau.component[2][p]}};
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
