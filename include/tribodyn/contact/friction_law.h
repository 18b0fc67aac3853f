// Friction laws of the contact pin as types (issue #20 item 1): the contact
// loops (node-wise closed form and projected Gauss-Seidel,
// source/contact/contact_constraint.cc) are instantiated on the law the
// run chose, once per step (no run-time dispatch per node).
//
// A law is a class derived from FrictionLawBase with
//  - `static constexpr const char *name`: its name in `Contact/Friction
//    law` (and in summary.json);
//  - `struct Parameters` with `static declare_parameters(prm)` and
//    `parse_parameters(prm)`, called in subsection Contact (a law with
//    constants of its own declares a subsection for them);
//  - a constructor `Law(const ContactLawParameters &contact, const
//    Parameters &own, double dt)` (a template on the first argument: the
//    shared entries of Contact, e.g. `Friction coefficient`);
//  - `double tangential(const ContactNode &before, double trial, double
//    lambda_n, ContactStatus &status) const`: the tangential multiplier of
//    a node in contact, given its state before the step, the stick trial
//    and the normal multiplier (sets status to stick or slip);
//  - optionally (FrictionLawBase's do nothing): `begin_step(const PlaneStep
//    &)` (constants of the step), `end_step(ContactNode &, double dt)` (its
//    state per node after the step, called for every node, in contact or
//    not: the node's law_state, checkpointed with the node),
//    `report(summary, figures, comm)` (its figures at the end of the run),
//    `for_each_counter(f)` (f(name, RunCounter &) for each count the law
//    keeps over the run: checkpointed by name, so that a resumed run
//    reports what the uninterrupted one does).
// A new law is one header in include/tribodyn/contact/friction_laws/ and
// its name in the list of friction_laws.h.
#ifndef tribodyn_contact_friction_law_h
#define tribodyn_contact_friction_law_h

#include <array>
#include <cmath>
#include <mpi.h>
#include <ostream>
#include <tribodyn/core/json.h>
#include <tribodyn/core/law_selection.h>
#include <utility>
#include <variant>

namespace tribodyn
{
  namespace contact
  {
    /// Status of a contact node after the step (values written in the
    /// outputs).
    enum ContactStatus : unsigned char
    {
      separated = 0,
      stick     = 1,
      slip      = 2
    };

    /// Time constant t* of the regularized law during slip.
    enum class RegularizationRate
    {
      plane_speed,    ///< t* = L*/|V(t)| (seed eq. (4))
      local_slip_rate ///< t* = L*/|[u']| of the node (Prakash-Clifton)
    };

    /// Friction state tau of a node that comes back into contact.
    enum class RecontactState
    {
      reset_to_zero,
      keep,
      reset_to_mu_sigma
    };

    /**
     * A contact node of the pin's bottom face (owned by this rank): its
     * dofs, lumped mass, position and tributary length, and its state from
     * one step to the next. for_each_state_field() is the one description
     * of that state (checkpoints).
     */
    struct ContactNode
    {
      unsigned int ix = 0, iy = 0;
      double       m = 0;
      double       x = 0;
      /// Length of the contact face the node stands for (half of each
      /// adjacent face): the contact pressure is lambda_n / length.
      double        length   = 0;
      double        lambda_n = 0, lambda_t = 0, tau = 0;
      ContactStatus status = separated;
      /// |slip increment| / dt of the last step (local slip rate).
      double slip_rate = 0;
      /// State variables of the friction law (e.g. rate and state: theta).
      std::array<double, 2> law_state = {{0, 0}};

      /// Call @p f(name, value) for every state variable (status as a
      /// double: the caller writes and reads doubles).
      template <class F>
      void
      for_each_state_field(const F &f)
      {
        f("lambda_n", lambda_n);
        f("lambda_t", lambda_t);
        f("tau", tau);
        double s = status;
        f("status", s);
        status = static_cast<ContactStatus>(int(s));
        f("slip_rate", slip_rate);
        f("law_state_0", law_state[0]);
        f("law_state_1", law_state[1]);
      }

      /// The number of state variables for_each_state_field() visits.
      static unsigned int
      n_state_fields()
      {
        ContactNode  node;
        unsigned int n = 0;
        node.for_each_state_field([&](const char *, double &) { ++n; });
        return n;
      }
    };

    /// The plane's motion over the current step.
    struct PlaneStep
    {
      double dt = 0;
      /// Displacement of the plane over the step.
      double slide = 0;
      /// |Sliding velocity| (the loading's nominal speed).
      double speed = 0;
      /// Whether the plane moves at the constant Sliding velocity.
      bool constant_velocity = true;
      /// The scheme's update of a node's displacement by its multiplier
      /// over the step: Delta u = h lambda / m.
      double h = 0;
    };

    /// Coulomb's cone: stick (the trial) while |trial| <= limit, else slip
    /// at the limit with the trial's sign.
    inline double
    coulomb_tangential(const double   trial,
                       const double   limit,
                       ContactStatus &status)
    {
      if (std::abs(trial) <= limit)
        {
          status = stick;
          return trial;
        }
      status = slip;
      return (trial >= 0 ? 1. : -1.) * limit;
    }

    /// A count a law keeps over the run (e.g. the tabulated law's clamped
    /// evaluations): this leg's count on this rank, and the total of the
    /// legs before the run was resumed (the same on every rank).
    struct RunCounter
    {
      unsigned long long leg = 0, earlier = 0;

      /// The run's total (collective).
      unsigned long long
      total(const MPI_Comm comm) const
      {
        unsigned long long sum = 0;
        MPI_Allreduce(&leg, &sum, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
        return sum + earlier;
      }
    };

    /// Defaults of the optional members of a law.
    struct FrictionLawBase
    {
      template <class F>
      void
      for_each_counter(const F &) const
      {
      }
      void
      begin_step(const PlaneStep &)
      {
      }
      void
      end_step(ContactNode &, const double) const
      {
      }
      void
      report(JsonValue &, std::ostream &, const MPI_Comm) const
      {
      }
    };

    /**
     * The laws a run may choose from (`Contact/Friction law`), the
     * parameters of each, and the chosen one, made for the run.
     */
    template <class... Laws>
    class FrictionLawList
    {
    public:
      using Selection  = LawSelection<Laws...>;
      using Parameters = typename Selection::Parameters;
      /// The law of a run (monostate until made).
      using Variant = std::variant<std::monostate, Laws...>;

      /// The entry that chooses the law, in subsection Contact.
      static constexpr const char *entry = "Friction law";

      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        Parameters::declare_parameters(
          prm,
          entry,
          Selection::name(0),
          "Friction law of the contact nodes (doc/theory/contact.md Sec. "
          "4); each law's constants are in its own entries.");
      }

      /// Parameters choosing @p Law (the struct's default, e.g. for
      /// parameters not read from a file).
      template <class Law>
      static Parameters
      choosing()
      {
        Parameters p;
        p.template select<Law>();
        return p;
      }

      /// The chosen law for a run with time step @p dt.
      template <class ContactLawParameters>
      static Variant
      make(const ContactLawParameters &contact, const double dt)
      {
        Variant v;
        make_each(v, contact, dt, std::index_sequence_for<Laws...>());
        return v;
      }

      /// Call @p f with the law in @p v (made by make()).
      template <class V, class F>
      static void
      visit(V &v, const F &f)
      {
        std::visit(
          [&](auto &law) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(law)>,
                                          std::monostate>)
              f(law);
          },
          v);
      }

    private:
      template <class ContactLawParameters, std::size_t... I>
      static void
      make_each(Variant                    &v,
                const ContactLawParameters &contact,
                const double                dt,
                std::index_sequence<I...>)
      {
        ((contact.friction.selected == I ? (void)v.template emplace<I + 1>(
            contact, std::get<I>(contact.friction.laws), dt)
                                         : void()),
         ...);
      }
    };
  } // namespace contact
} // namespace tribodyn

#endif
