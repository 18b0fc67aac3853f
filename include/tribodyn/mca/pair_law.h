// The pair law of the automata as a combination of policies (issue #17
// item 1; design §2: Lethe's contact-force classes templated on the
// model, ASPECT's plug-ins that own their parameters).
//
// The pair kernel (source/mca/pair_kernel.cc) is one template, compiled for
// the combination a scene needs and chosen once per step, in one place:
// AutomatonSystem::evaluate_pairs(), which calls with_chosen() below on
// the scene's choices. Each choice is one of
//
//   choice                   | options (list)                   | chosen by
//   -------------------------|----------------------------------|-----------------------
//   rotations                | off, on (CompileTimeSwitch)      |
//   Interaction/Rotations plastic return           | off, on
//   (CompileTimeSwitch)      | Plasticity and a plastic material in use pair
//   geometry            | UniformPairs, GradedPairs        | Geometry/Size
//   bands
//                            |   (source/mca/pair_geometry.h)   |
//   friction of unbonded     | FrictionLaws (friction_laws.h)   |
//   Interaction/Friction law
//     contacts               |                                  |
//   relative-rotation moment | MomentLaws (moment_laws.h)       | Relative
//   rotation stiffness > 0 bond breaking            | BondBreakingLaws
//   (bond_laws.h)   | Interaction/Bond breaking bond formation           |
//   BondFormationLaws (bond_laws.h)  | Interaction/Bond formation
//
// Inside the kernel a policy's calls are inline, and a "none" law's are
// compiled away with `if constexpr (Law::active)`: no flag is tested per
// pair, nothing is allocated and nothing is dispatched virtually.
//
// Adding a law to a family is one new header (in friction_laws/,
// moment_laws/ or bond_laws/) with the calls of its family, listed below,
// and its name in the family's list (one line of friction_laws.h,
// moment_laws.h or bond_laws.h). Every law owns its parameters (declare /
// parse, inside subsection Interaction) and its per-pair state
// (register_pair_fields(): carried over rebuilds, migration and
// checkpoints by the PairFieldTable).
//
// The calls of each family (besides name, Parameters, the constructor and
// register_pair_fields()):
//  - friction laws: see friction_law.h (stateful, start_contact(),
//    advance() or coefficient()).
//  - moment laws (switched_law_list.h; `needs_rotations`): set_up(springs,
//    S) at construction; separate(p) when a contact opens; trial(p, ...)
//    in pass A (the step's kinematics); moment(p), limit_unbonded(p, ...)
//    in pass C (the unbonded contact's limit, its slip work); energy(p,
//    ...) and stiffnesses() for the energy balance and the tests.
//  - bond breaking: breaks(s_i, s_j, n, sn, am, tau, limit_i, limit_j) per
//    bonded pair, from the automata's stress tensors (eq. 4).
//  - bond formation: forms(sn, sy_i, sy_j, heat, w_b_i, w_b_j, area, r)
//    per unbonded contact.
// A "none" law (active = false) needs only what code outside the kernel
// calls (NoMoment: moment(), stiffnesses()).
//
// The normal and shear response of the pair (seed eqs. 5-7: the series
// springs, the many-body term, the radial return) is not a policy: it is
// the structure of the kernel's passes (doc/theory/mca.md §3).
#ifndef tribodyn_mca_pair_law_h
#define tribodyn_mca_pair_law_h

#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    /// A choice between a feature's absence and its presence, as a
    /// compile-time constant: with_selected(f) calls f(std::false_type) or
    /// f(std::true_type).
    struct CompileTimeSwitch
    {
      bool on;

      template <class F>
      void
      with_selected(const F &f) const
      {
        if (on)
          {
            std::true_type yes;
            f(yes);
          }
        else
          {
            std::false_type no;
            f(no);
          }
      }
    };

    /// A choice given by a function that calls its argument with the
    /// chosen object (e.g. the pair geometry, built for the call).
    template <class Choose>
    struct ChoiceOf
    {
      Choose choose;

      template <class F>
      void
      with_selected(const F &f) const
      {
        choose(f);
      }
    };
    template <class Choose>
    ChoiceOf<Choose>
    choice_of(const Choose &choose)
    {
      return {choose};
    }

    /// Call @p f(chosen...) with the chosen option of each of @p choices
    /// (objects with with_selected(g), which call g with the chosen
    /// option as an lvalue): @p f is compiled for every combination, and
    /// the run-time choice is made here once.
    template <class F>
    void
    with_chosen(const F &f)
    {
      f();
    }
    template <class F, class Choice, class... Choices>
    void
    with_chosen(const F &f, Choice &&choice, Choices &&...choices)
    {
      choice.with_selected([&](auto &&chosen) {
        with_chosen([&](auto &...others) { f(chosen, others...); }, choices...);
      });
    }
  } // namespace mca
} // namespace tribodyn

#endif
