// A new law is one header and one list line (doc/architecture.md, "To add
// X"): this test adds a law to each of the engines' law lists from its own
// file only, the way a contributor would, and checks that the list
// machinery takes it as it takes the shipped ones:
//
// 1. automata friction (FrictionLawList, chosen by Interaction/Friction
//    law): a velocity-weakening law mu(v) = mu_k + (mu_s - mu_k) / (1 +
//    v / v_c) with its own subsection; chosen by name, its entries read,
//    dispatched by with_selected() (its mu at v = v_c is (mu_s + mu_k) / 2
//    exactly), the first law still the default;
// 2. automata moment, bond breaking and bond formation (SwitchedLawList,
//    switched on by the laws' own entries): a law placed first in each
//    family, chosen when its entry switches it on, the family's "none" law
//    otherwise, and an earlier law taking precedence over a later one;
// 3. the pin's friction (contact FrictionLawList, Contact/Friction law):
//    the same velocity-weakening law on a contact node, whose slip
//    multiplier is mu(v) lambda_n exactly, with a stick trial kept;
// 4. an entry of an added law out of range is refused naming its full
//    path (Interaction/Velocity weakening/Critical speed), as the shipped
//    laws' entries are.
// All checks are exact identities (the law's formula evaluated at points
// where it is exact in binary: v = v_c, mu values of few bits).
#include "../test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <limits>
#include <sstream>
#include <tribodyn/contact/friction_laws.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/bond_laws.h>
#include <tribodyn/mca/friction_laws.h>
#include <tribodyn/mca/moment_laws.h>

using tribodyn_test::check;

namespace
{
  /// The test's law: mu(v) = mu_k + (mu_s - mu_k) / (1 + v / v_c), with its
  /// entries in the subsection "Velocity weakening" of @p outer.
  struct VelocityWeakeningParameters
      : tribodyn::BoundLawParameters<VelocityWeakeningParameters>
  {
    double      mu_s = 0.5, mu_k = 0.25, v_c = 2;
    std::string outer;

    explicit VelocityWeakeningParameters(const std::string &outer = "")
        : outer(outer)
    {
    }

    tribodyn::ParameterBinding
    binding()
    {
      tribodyn::ParameterBinding b("Velocity weakening", outer);
      b.add("Static coefficient", mu_s, "mu_s.");
      b.add("Kinetic coefficient", mu_k, "mu_k.");
      b.add("Critical speed",
            v_c,
            "v_c (m/s).",
            dealii::Patterns::Double(),
            tribodyn::Interval{
              0, std::numeric_limits<double>::infinity(), true, true});
      return b;
    }

    double
    mu(const double v) const
    {
      return mu_k + (mu_s - mu_k) / (1 + v / v_c);
    }
  };

  // 1. An automata friction law (include/tribodyn/mca/friction_law.h).
  class VelocityWeakening
  {
  public:
    static constexpr const char *name     = "velocity weakening";
    static constexpr bool        stateful = false;
    struct Parameters : VelocityWeakeningParameters
    {
      Parameters()
          : VelocityWeakeningParameters("Interaction")
      {
      }
    };
    explicit VelocityWeakening(const Parameters &p)
        : p(p)
    {
    }
    void
    register_pair_fields(tribodyn::mca::PairFieldTable &,
                         const std::function<bool()> &)
    {
    }
    void
    start_contact(const unsigned int)
    {
    }
    /// (a stateless law's mu: here at the critical speed)
    double
    coefficient() const
    {
      return p.mu(p.v_c);
    }
    Parameters p;
  };
  using McaFriction
    = tribodyn::mca::FrictionLawList<tribodyn::mca::Coulomb,
                                     tribodyn::mca::RateAndState,
                                     VelocityWeakening>;

  // 2. A law of a switched family, first in its list: on when its own
  // entry ("<Family> test law") says so.
  template <int family>
  class SwitchedTestLaw
  {
  public:
    static constexpr const char *name   = "test law";
    static constexpr bool        active = true;
    struct Parameters : tribodyn::BoundLawParameters<Parameters>
    {
      bool on = false;
      tribodyn::ParameterBinding
      binding()
      {
        tribodyn::ParameterBinding b("", "Interaction");
        b.add(std::string(family == 0   ? "Moment"
                          : family == 1 ? "Breaking"
                                        : "Formation")
                + " test law",
              on,
              "Switch the test's law on.");
        return b;
      }
      bool
      chosen() const
      {
        return on;
      }
    };
    explicit SwitchedTestLaw(const Parameters &)
    {
    }
    void
    register_pair_fields(tribodyn::mca::PairFieldTable &,
                         const std::function<bool()> &)
    {
    }
    static int
    tag()
    {
      return 100 + family;
    }
  };
  using Moments = tribodyn::mca::SwitchedLawList<SwitchedTestLaw<0>,
                                                 tribodyn::mca::ElasticMoment,
                                                 tribodyn::mca::NoMoment>;
  using Breaking
    = tribodyn::mca::SwitchedLawList<SwitchedTestLaw<1>,
                                     tribodyn::mca::VonMisesBondBreaking,
                                     tribodyn::mca::NoBondBreaking>;
  using Formation
    = tribodyn::mca::SwitchedLawList<SwitchedTestLaw<2>,
                                     tribodyn::mca::PlasticHeatBondFormation,
                                     tribodyn::mca::NoBondFormation>;

  // 3. A contact friction law (include/tribodyn/contact/friction_law.h).
  struct ContactVelocityWeakening : tribodyn::contact::FrictionLawBase
  {
    static constexpr const char *name = "velocity weakening";
    struct Parameters : VelocityWeakeningParameters
    {
      Parameters()
          : VelocityWeakeningParameters("Contact")
      {
      }
    };
    template <class ContactLawParameters>
    ContactVelocityWeakening(const ContactLawParameters &,
                             const Parameters &p,
                             double)
        : p(p)
    {
    }
    double
    tangential(const tribodyn::contact::ContactNode &before,
               const double                          trial,
               const double                          lambda_n,
               tribodyn::contact::ContactStatus     &status) const
    {
      return tribodyn::contact::coulomb_tangential(
        trial, p.mu(std::abs(before.slip_rate)) * lambda_n, status);
    }
    Parameters p;
  };
  using ContactFriction
    = tribodyn::contact::FrictionLawList<tribodyn::contact::Frictionless,
                                         tribodyn::contact::Coulomb,
                                         ContactVelocityWeakening>;
  /// What a contact law's constructor reads of the Contact entries.
  struct ContactEntries
  {
    ContactFriction::Parameters friction;
    double                      friction_coefficient = 0.3;
  };


  /// @p Declare's entries read from @p text (inside subsection @p section).
  template <class Declare, class Parse>
  void
  read(const std::string &section,
       const std::string &text,
       const Declare     &declare,
       const Parse       &parse)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection(section);
    declare(prm);
    prm.leave_subsection();
    std::istringstream in("subsection " + section + "\n" + text + "\nend\n");
    prm.parse_input(in);
    prm.enter_subsection(section);
    parse(prm);
    prm.leave_subsection();
  }


  /// A law list's parameters (@p Parameters) read from @p text in
  /// subsection Interaction.
  template <class Parameters>
  Parameters
  interaction(const std::string &text)
  {
    Parameters p;
    read(
      "Interaction",
      text,
      [](auto &prm) { Parameters::declare_parameters(prm); },
      [&](auto &prm) { p.parse_parameters(prm); });
    return p;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 1. automata friction
  {
    const auto chosen = interaction<McaFriction::Parameters>(
      "set Friction law = velocity weakening\n"
      "subsection Velocity weakening\n"
      "set Static coefficient = 0.75\nend");
    McaFriction laws(chosen);
    double      mu = -1;
    laws.with_selected([&](const auto &law) {
      if constexpr (std::is_same_v<std::decay_t<decltype(law)>,
                                   VelocityWeakening>)
        mu = law.coefficient();
    });
    check(std::string(chosen.selected_name()) == "velocity weakening"
            && mu == 0.5,
          "automata friction: the added law chosen by name, its entry "
          "read, dispatched: mu(v_c) = (0.75 + 0.25) / 2 = 0.5 (got "
            + std::to_string(mu) + ")");
    const auto plain = interaction<McaFriction::Parameters>("");
    check(std::string(plain.selected_name()) == "Coulomb",
          "automata friction: the first law (Coulomb) is still the default");
  }

  // 2. the switched families
  {
    const auto on
      = interaction<Moments::Parameters>("set Moment test law = true\n"
                                         "set Relative rotation stiffness = 1");
    const auto elastic
      = interaction<Moments::Parameters>("set Relative rotation stiffness = 1");
    const auto none = interaction<Moments::Parameters>("");
    int        tag  = 0;
    Moments(on).with_selected([&](const auto &law) {
      if constexpr (std::is_same_v<std::decay_t<decltype(law)>,
                                   SwitchedTestLaw<0>>)
        tag = law.tag();
    });
    check(std::string(on.selected_name()) == "test law" && tag == 100
            && std::string(elastic.selected_name()) == "elastic"
            && std::string(none.selected_name()) == "none" && !none.active(),
          "moment: the added law chosen by its entry (before the elastic "
          "one, which is also on), dispatched; elastic and none as before");
    const auto breaking
      = interaction<Breaking::Parameters>("set Breaking test law = true");
    const auto von_mises
      = interaction<Breaking::Parameters>("set Bond breaking = true");
    const auto formation
      = interaction<Formation::Parameters>("set Formation test law = true");
    const auto no_formation = interaction<Formation::Parameters>("");
    check(std::string(breaking.selected_name()) == "test law"
            && std::string(von_mises.selected_name()) == "von Mises"
            && std::string(formation.selected_name()) == "test law"
            && std::string(no_formation.selected_name()) == "none",
          "bond breaking and formation: the added law chosen by its entry; "
          "the shipped laws and none as before");
  }

  // 3. the pin's friction
  {
    ContactEntries contact;
    read(
      "Contact",
      "set Friction law = velocity weakening\n"
      "subsection Velocity weakening\nset Critical speed = 4\nend",
      [](auto &prm) { ContactFriction::declare_parameters(prm); },
      [&](auto &prm) {
        contact.friction.parse_parameters(prm, ContactFriction::entry);
      });
    auto                             law = ContactFriction::make(contact, 1e-9);
    tribodyn::contact::ContactNode   before;
    tribodyn::contact::ContactStatus slip_status = tribodyn::contact::separated,
                                     stick_status
                                     = tribodyn::contact::separated;
    before.slip_rate = -4; // v = v_c: mu = (0.5 + 0.25) / 2 = 0.375
    double slip = 0, stick = 0;
    ContactFriction::visit(law, [&](const auto &l) {
      slip  = l.tangential(before, 10., 8., slip_status);
      stick = l.tangential(before, 1., 8., stick_status);
    });
    check(std::holds_alternative<ContactVelocityWeakening>(law)
            && slip == 0.375 * 8 && slip_status == tribodyn::contact::slip
            && stick == 1. && stick_status == tribodyn::contact::stick,
          "pin friction: the added law made by name; slip at mu(v_c) "
          "lambda_n = 3 (got "
            + std::to_string(slip) + "), a trial of 1 sticks (got "
            + std::to_string(stick) + ")");
  }

  // 4. an added law's entry out of range
  {
    std::string message;
    try
      {
        interaction<McaFriction::Parameters>(
          "set Friction law = velocity weakening\n"
          "subsection Velocity weakening\n"
          "set Critical speed = 0\nend");
      }
    catch (const tribodyn::InputError &e)
      {
        message = e.what();
      }
    check(message.find("'Interaction/Velocity weakening/Critical speed'")
            != std::string::npos,
          "an added law's entry out of range is refused with its path: "
            + message);
  }
  return tribodyn_test::result();
}
