#include <cmath>
#include <deal.II/base/patterns.h>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    namespace Patterns = dealii::Patterns;

    namespace
    {
      constexpr double inf = std::numeric_limits<double>::max();

      std::vector<std::string>
      split(const std::string &text, const char separator)
      {
        std::vector<std::string> parts;
        std::string              current;
        for (const char c : text)
          if (c == separator)
            {
              parts.push_back(current);
              current.clear();
            }
          else
            current += c;
        parts.push_back(current);
        std::vector<std::string> nonempty;
        for (const auto &p : parts)
          if (p.find_first_not_of(" \t") != std::string::npos)
            nonempty.push_back(p);
        return nonempty;
      }

      /// Whitespace- or comma-separated tokens.
      std::vector<std::string>
      tokens(const std::string &text)
      {
        std::vector<std::string> out;
        std::string              current;
        for (const char c : text + " ")
          if (c == ' ' || c == '\t' || c == ',')
            {
              if (!current.empty())
                out.push_back(current);
              current.clear();
            }
          else
            current += c;
        return out;
      }

      double
      to_double(const std::string &token,
                const std::string &parameter,
                const std::string &entry)
      {
        if (token == "*")
          return std::numeric_limits<double>::quiet_NaN();
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(token, &used);
            if (used == token.size() && std::isfinite(value))
              return value;
          }
        catch (...)
          {
          }
        throw InputError("Parameter '" + parameter + "': '" + token
                         + "' in the entry '" + entry + "' is not a number.");
      }

      Point3
      read_point(const std::vector<std::string> &t,
                 const std::size_t               first,
                 const std::string              &parameter,
                 const std::string              &entry)
      {
        return Point3(to_double(t[first], parameter, entry),
                      to_double(t[first + 1], parameter, entry),
                      to_double(t[first + 2], parameter, entry));
      }

      Point3
      parse_point(const std::string &text, const std::string &parameter)
      {
        const auto t = tokens(text);
        if (t.size() != 3)
          throw InputError("Parameter '" + parameter + "' = '" + text
                           + "' must be three numbers 'x, y, z'.");
        return read_point(t, 0, parameter, text);
      }

      std::string
      material_list_message(const std::vector<std::string> &names)
      {
        std::string s;
        for (const auto &n : names)
          s += (s.empty() ? "" : ", ") + n;
        return s;
      }
    } // namespace


    int
    material_index(const std::vector<std::string> &names,
                   const std::string              &name,
                   const std::string              &parameter)
    {
      for (unsigned int i = 0; i < names.size(); ++i)
        if (names[i] == name)
          return i;
      throw InputError("Parameter '" + parameter + "': unknown material '"
                       + name + "'. The materials are: "
                       + material_list_message(names) + ".");
    }


    // ------------------------------------------------------------------
    MaterialParameters
    MaterialParameters::steel()
    {
      MaterialParameters m;
      m.name                 = "steel";
      m.density              = 7800;
      m.youngs_modulus       = 206e9;
      m.poisson_ratio        = 0.28;
      m.hardening            = Hardening::linear;
      m.yield_stress         = 800e6;
      m.hardening_modulus    = 2e9;
      m.bond_breaking_stress = 1.2e9;
      m.bond_energy_density  = 3.5e6;
      return m;
    }


    MaterialParameters
    MaterialParameters::carbon()
    {
      MaterialParameters m;
      m.name                     = "carbon";
      m.density                  = 2100;
      m.youngs_modulus           = 40e9;
      m.poisson_ratio            = 0.4;
      m.hardening                = Hardening::bilinear;
      m.yield_stress             = 32e6;
      m.hardening_modulus        = 1e9;
      m.second_hardening_modulus = 0.1e9;
      m.second_hardening_onset   = 0.05;
      m.bond_breaking_stress     = 100e6;
      m.bond_energy_density      = 1.25e5;
      return m;
    }


    double
    MaterialParameters::p_wave_speed() const
    {
      return std::sqrt((bulk_modulus() + 4. / 3. * shear_modulus()) / density);
    }


    double
    MaterialParameters::yield_stress_at(const double eps_p) const
    {
      switch (hardening)
        {
          case Hardening::elastic:
            return inf;
          case Hardening::linear:
            return yield_stress + hardening_modulus * eps_p;
          case Hardening::bilinear:
            if (eps_p <= second_hardening_onset)
              return yield_stress + hardening_modulus * eps_p;
            return yield_stress + hardening_modulus * second_hardening_onset
                   + second_hardening_modulus
                       * (eps_p - second_hardening_onset);
        }
      return inf;
    }


    void
    MaterialParameters::declare_parameters(ParameterHandler         &prm,
                                           const MaterialParameters &d)
    {
      prm.declare_entry("Density",
                        format_number(d.density),
                        Double(),
                        "Mass density rho (kg/m^3), > 0.");
      prm.declare_entry("Young modulus",
                        format_number(d.youngs_modulus),
                        Double(),
                        "Young's modulus E (Pa), > 0.");
      prm.declare_entry("Poisson ratio",
                        format_number(d.poisson_ratio),
                        Double(),
                        "Poisson's ratio nu, in (-1, 0.5). The pair law "
                        "reproduces Hooke's law with these E and nu.");
      prm.declare_entry(
        "Hardening",
        d.hardening == Hardening::elastic
          ? "elastic"
          : (d.hardening == Hardening::linear ? "linear" : "bilinear"),
        Selection("elastic|linear|bilinear"),
        "Response beyond the elastic range: elastic (no plasticity), "
        "linear (sigma_y = Yield stress + Hardening modulus * eps_p) or "
        "bilinear (slope Second hardening modulus beyond Second hardening "
        "onset). Von Mises plasticity, Wilkins radial return.");
      prm.declare_entry("Yield stress",
                        format_number(d.yield_stress),
                        Double(),
                        "Initial yield stress sigma_y0 (Pa), > 0.");
      prm.declare_entry("Hardening modulus",
                        format_number(d.hardening_modulus),
                        Double(),
                        "Plastic hardening modulus H1 = dsigma_y/deps_p "
                        "(Pa), >= 0. The uniaxial tangent modulus is "
                        "E H1 / (E + H1).");
      prm.declare_entry("Second hardening modulus",
                        format_number(d.second_hardening_modulus),
                        Double(),
                        "Bilinear hardening: H2 = dsigma_y/deps_p beyond "
                        "the onset (Pa), >= 0.");
      prm.declare_entry("Second hardening onset",
                        format_number(d.second_hardening_onset),
                        Double(),
                        "Bilinear hardening: plastic strain where the "
                        "second branch starts, > 0.");
      prm.declare_entry("Bond breaking stress",
                        format_number(d.bond_breaking_stress),
                        Double(),
                        "A bonded pair breaks when the von Mises stress of "
                        "its stress state reaches this value (Pa), > 0 "
                        "(the smaller value of the two materials applies).");
      prm.declare_entry("Bond energy density",
                        format_number(d.bond_energy_density),
                        Double(),
                        "Energy to break a bond per unit volume of the pair "
                        "(J/m^3): the bond energy of pair ij is this times "
                        "S_ij (d_i + d_j)/2. The default is sigma_b^2/(2E) "
                        "with sigma_b the bond breaking stress.");
    }


    void
    MaterialParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &section)
    {
      density                  = prm.get_double("Density");
      youngs_modulus           = prm.get_double("Young modulus");
      poisson_ratio            = prm.get_double("Poisson ratio");
      const std::string h      = prm.get("Hardening");
      hardening                = h == "elastic"  ? Hardening::elastic
                                 : h == "linear" ? Hardening::linear
                                                 : Hardening::bilinear;
      yield_stress             = prm.get_double("Yield stress");
      hardening_modulus        = prm.get_double("Hardening modulus");
      second_hardening_modulus = prm.get_double("Second hardening modulus");
      second_hardening_onset   = prm.get_double("Second hardening onset");
      bond_breaking_stress     = prm.get_double("Bond breaking stress");
      bond_energy_density      = prm.get_double("Bond energy density");

      check_parameter_range(section + "/Density",
                            density,
                            0,
                            inf,
                            true,
                            true,
                            "The density is in kg/m^3.");
      check_parameter_range(section + "/Young modulus",
                            youngs_modulus,
                            0,
                            inf,
                            true,
                            true,
                            "Young's modulus is in Pa.");
      check_parameter_range(section + "/Poisson ratio",
                            poisson_ratio,
                            -1,
                            0.5,
                            true,
                            true,
                            "An isotropic elastic material needs "
                            "-1 < nu < 0.5.");
      check_parameter_range(
        section + "/Yield stress", yield_stress, 0, inf, true, true);
      check_parameter_range(
        section + "/Hardening modulus", hardening_modulus, 0, inf, false, true);
      check_parameter_range(section + "/Second hardening modulus",
                            second_hardening_modulus,
                            0,
                            inf,
                            false,
                            true);
      check_parameter_range(section + "/Second hardening onset",
                            second_hardening_onset,
                            0,
                            inf,
                            true,
                            true);
      check_parameter_range(section + "/Bond breaking stress",
                            bond_breaking_stress,
                            0,
                            inf,
                            true,
                            true);
      check_parameter_range(section + "/Bond energy density",
                            bond_energy_density,
                            0,
                            inf,
                            false,
                            true);
    }


    // ------------------------------------------------------------------
    bool
    Region::contains(const Point3 &p) const
    {
      switch (shape)
        {
          case Shape::box:
            for (unsigned int d = 0; d < 3; ++d)
              if (p[d] < std::min(a[d], b[d]) || p[d] > std::max(a[d], b[d]))
                return false;
            return true;
          case Shape::sphere:
            return p.distance_square(a) <= radius * radius;
          case Shape::cylinder:
            {
              const dealii::Tensor<1, 3> axis = b - a;
              const double               L2   = axis.norm_square();
              const double               s    = (p - a) * axis / L2;
              if (s < 0 || s > 1)
                return false;
              const dealii::Tensor<1, 3> off = (p - a) - s * axis;
              return off.norm_square() <= radius * radius;
            }
        }
      return false;
    }


    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry("Automaton size",
                          "1e-3",
                          Double(),
                          "Automaton size d (m): the distance between "
                          "neighbours of the FCC packing; contact area "
                          "S = d^2/(2 sqrt 2), volume V = d^3/sqrt 2.");
        prm.declare_entry("Domain lower",
                          "0, 0, 0",
                          Patterns::Anything(),
                          "Lower corner of the simulation box (m). In "
                          "periodic directions the box is the period and "
                          "its length must hold a whole number of FCC "
                          "cells (a = d sqrt 2).");
        prm.declare_entry("Domain upper",
                          "0.01, 0.01, 0.01",
                          Patterns::Anything(),
                          "Upper corner of the simulation box (m). In "
                          "non-periodic directions automata must stay "
                          "inside it (leave room for the motion).");
        prm.declare_entry("Periodic x",
                          "false",
                          Bool(),
                          "Periodic boundary in x.");
        prm.declare_entry("Periodic y",
                          "false",
                          Bool(),
                          "Periodic boundary in y.");
        prm.declare_entry("Periodic z",
                          "false",
                          Bool(),
                          "Periodic boundary in z.");
        prm.declare_entry(
          "Bodies",
          "0, 0, 0, 0.01, 0.01, 0.01, steel",
          Patterns::Anything(),
          "Boxes filled with automata on one FCC lattice (origin at "
          "'Domain lower' + a/4 in every direction), separated by ';': "
          "'x0 y0 z0 x1 y1 z1 MATERIAL'. Automata of different bodies are "
          "not bonded at the start.");
        prm.declare_entry(
          "Regions",
          "",
          Patterns::Anything(),
          "Regions applied in order after the packing, separated by ';': "
          "'box x0 y0 z0 x1 y1 z1 M', 'sphere cx cy cz r M', 'cylinder "
          "ax ay az bx by bz r M' (axis from a to b, any direction), where "
          "M is a material name (sets the material) or 'void' (removes "
          "the automata).");
        prm.enter_subsection("Rough interface");
        {
          prm.declare_entry("Enabled",
                            "false",
                            Bool(),
                            "Split the packing into body 0 below and body "
                            "1 above a rough surface z = Height + "
                            "Amplitude * f(x, y), f a sum of random-phase "
                            "cosines with the given wavelength (periodic "
                            "over the box when the wavelength divides it).");
          prm.declare_entry("Height", "0", Double(), "Mean height (m).");
          prm.declare_entry("Amplitude",
                            "0",
                            Double(),
                            "Roughness amplitude (m), >= 0.");
          prm.declare_entry("Wavelength",
                            "1e-3",
                            Double(),
                            "Roughness wavelength (m), > 0.");
          prm.declare_entry("Seed",
                            "1",
                            Integer(0),
                            "Seed of the random phases.");
          prm.declare_entry("Gap",
                            "0",
                            Double(),
                            "Initial gap: body 1 is shifted up by it (m).");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }


    void
    GeometryParameters::parse_parameters(
      ParameterHandler               &prm,
      const std::vector<std::string> &material_names)
    {
      prm.enter_subsection("Geometry");
      {
        automaton_size = prm.get_double("Automaton size");
        check_parameter_range(
          "Geometry/Automaton size", automaton_size, 0, inf, true, true);
        domain_lower
          = parse_point(prm.get("Domain lower"), "Geometry/Domain lower");
        domain_upper
          = parse_point(prm.get("Domain upper"), "Geometry/Domain upper");
        periodic       = {{prm.get_bool("Periodic x"),
                           prm.get_bool("Periodic y"),
                           prm.get_bool("Periodic z")}};
        const double a = automaton_size * std::sqrt(2.);
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double      L = domain_upper[d] - domain_lower[d];
            const std::string name
              = std::string("Geometry/Domain upper (") + "xyz"[d] + ")";
            check_parameter(L > 0,
                            name,
                            "the domain must have a positive length in "
                            "every direction.");
            if (periodic[d])
              {
                const double cells = L / a;
                check_parameter(
                  std::abs(cells - std::round(cells)) < 1e-6 * cells
                    && std::round(cells) >= 2,
                  name,
                  "in a periodic direction the length must be a whole "
                  "number (>= 2) of FCC cells a = d sqrt(2) = "
                    + format_number(a) + " m; the nearest is "
                    + format_number(std::max(2., std::round(cells)) * a)
                    + " m.");
              }
          }

        bodies.clear();
        for (const std::string &entry : split(prm.get("Bodies"), ';'))
          {
            const auto t = tokens(entry);
            if (t.size() != 7)
              throw InputError("Parameter 'Geometry/Bodies': the entry '"
                               + entry
                               + "' must read 'x0 y0 z0 x1 y1 z1 MATERIAL'.");
            Body b;
            b.lower = read_point(t, 0, "Geometry/Bodies", entry);
            b.upper = read_point(t, 3, "Geometry/Bodies", entry);
            b.material
              = material_index(material_names, t[6], "Geometry/Bodies");
            bodies.push_back(b);
          }
        check_parameter(!bodies.empty(),
                        "Geometry/Bodies",
                        "give at least one body.");

        regions.clear();
        for (const std::string &entry : split(prm.get("Regions"), ';'))
          {
            const auto        t = tokens(entry);
            Region            r;
            const std::string p = "Geometry/Regions";
            std::size_t       n = 0;
            if (!t.empty() && t[0] == "box")
              {
                r.shape = Region::Shape::box;
                n       = 8;
              }
            else if (!t.empty() && t[0] == "sphere")
              {
                r.shape = Region::Shape::sphere;
                n       = 6;
              }
            else if (!t.empty() && t[0] == "cylinder")
              {
                r.shape = Region::Shape::cylinder;
                n       = 9;
              }
            else
              throw InputError("Parameter '" + p + "': the entry '" + entry
                               + "' must start with box, sphere or cylinder.");
            if (t.size() != n)
              throw InputError(
                "Parameter '" + p + "': the entry '" + entry + "' has "
                + std::to_string(t.size()) + " fields; expected "
                + std::to_string(n)
                + " ('box x0 y0 z0 x1 y1 z1 M', 'sphere cx cy cz r M' or "
                  "'cylinder ax ay az bx by bz r M').");
            r.a = read_point(t, 1, p, entry);
            if (r.shape == Region::Shape::sphere)
              r.radius = to_double(t[4], p, entry);
            else
              r.b = read_point(t, 4, p, entry);
            if (r.shape == Region::Shape::cylinder)
              {
                r.radius = to_double(t[7], p, entry);
                check_parameter((r.b - r.a).norm() > 0,
                                p,
                                "the cylinder '" + entry
                                  + "' has a zero-length axis.");
              }
            if (r.shape != Region::Shape::box)
              check_parameter(r.radius > 0,
                              p,
                              "the radius in '" + entry
                                + "' must be positive.");
            r.material = t.back() == "void"
                           ? -1
                           : material_index(material_names, t.back(), p);
            regions.push_back(r);
          }

        prm.enter_subsection("Rough interface");
        {
          rough_interface      = prm.get_bool("Enabled");
          interface_height     = prm.get_double("Height");
          roughness_amplitude  = prm.get_double("Amplitude");
          roughness_wavelength = prm.get_double("Wavelength");
          roughness_seed       = prm.get_integer("Seed");
          interface_gap        = prm.get_double("Gap");
          check_parameter_range("Geometry/Rough interface/Amplitude",
                                roughness_amplitude,
                                0,
                                inf,
                                false,
                                true);
          check_parameter_range("Geometry/Rough interface/Wavelength",
                                roughness_wavelength,
                                0,
                                inf,
                                true,
                                true);
          check_parameter_range(
            "Geometry/Rough interface/Gap", interface_gap, 0, inf, false, true);
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    void
    InteractionParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Interaction");
      {
        prm.declare_entry("Rotations",
                          "true",
                          Bool(),
                          "Integrate the rotation of automata (Euler's "
                          "equation). Without rotations the tangential "
                          "increments use translations only.");
        prm.declare_entry("Plasticity",
                          "true",
                          Bool(),
                          "Von Mises plasticity (Wilkins radial return "
                          "adapted to MCA) for materials whose Hardening "
                          "is not 'elastic'. Skipped when every material "
                          "is elastic.");
        prm.declare_entry("Bond breaking",
                          "false",
                          Bool(),
                          "Bonded pairs break when the von Mises stress of "
                          "the pair reaches the Bond breaking stress.");
        prm.declare_entry("Bond formation",
                          "false",
                          Bool(),
                          "Unbonded pairs in compression at the yield "
                          "stress whose plastic heat reaches the fraction "
                          "below of the bond energy become bonded.");
        prm.declare_entry("Friction coefficient",
                          "0.3",
                          Double(),
                          "Amontons-Coulomb coefficient of unbonded pairs "
                          "(|tau| <= mu |sigma|), >= 0.");
        prm.declare_entry("Bond formation heat fraction",
                          "0.5",
                          Double(),
                          "Plastic heat of a pair needed to bond, as a "
                          "fraction of its bond energy (seed: 1/2), >= 0.");
        prm.declare_entry("Skin",
                          "0.2",
                          Double(),
                          "Pair-list skin as a fraction of the automaton "
                          "size: the list holds pairs closer than "
                          "(d_i + d_j)/2 + skin d and is rebuilt when an "
                          "automaton has moved more than skin d / 2. In "
                          "(0, 1].");
        prm.declare_entry("Pair slots",
                          "16",
                          Integer(4, 64),
                          "MPI runs: pair states travel with the automaton "
                          "of smaller id; this is the largest number of "
                          "pairs in which an automaton has the smaller id.");
      }
      prm.leave_subsection();
    }


    void
    InteractionParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Interaction");
      {
        rotations            = prm.get_bool("Rotations");
        plasticity           = prm.get_bool("Plasticity");
        bond_breaking        = prm.get_bool("Bond breaking");
        bond_formation       = prm.get_bool("Bond formation");
        friction_coefficient = prm.get_double("Friction coefficient");
        bond_formation_heat_fraction
          = prm.get_double("Bond formation heat fraction");
        skin       = prm.get_double("Skin");
        pair_slots = prm.get_integer("Pair slots");
        check_parameter_range("Interaction/Friction coefficient",
                              friction_coefficient,
                              0,
                              inf,
                              false,
                              true);
        check_parameter_range("Interaction/Bond formation heat fraction",
                              bond_formation_heat_fraction,
                              0,
                              inf,
                              false,
                              true);
        check_parameter_range("Interaction/Skin", skin, 0, 1, true, false);
      }
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    void
    BoundaryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        prm.declare_entry(
          "Groups",
          "",
          Patterns::Anything(),
          "Groups of automata with a boundary condition, separated by ';': "
          "'NAME TYPE x0 y0 z0 x1 y1 z1 [v1 v2 v3] [then T w1 w2 w3]'. "
          "Automata whose centre lies in the box belong to the group (an "
          "automaton may belong to several). TYPE: fixed (velocity zero), "
          "velocity (prescribed velocity components v, '*' leaves one "
          "free), force (total force v on the group; the group moves as a "
          "rigid loading plate under it and its reaction), damping (F = -v_k m "
          "u_k per component, coefficients in 1/s). "
          "'then T w' switches to the value w at time T (ramped smoothly "
          "over the ramp time).");
        prm.declare_entry("Ramp time",
                          "0",
                          Double(),
                          "Prescribed velocities and forces rise smoothly "
                          "(C1, 3s^2 - 2s^3) from zero over this time (s).");
        prm.declare_entry("Global damping",
                          "0",
                          Double(),
                          "Viscous damping of every automaton, "
                          "F = -c m v (1/s), >= 0.");
      }
      prm.leave_subsection();
    }


    void
    BoundaryParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        ramp_time      = prm.get_double("Ramp time");
        global_damping = prm.get_double("Global damping");
        check_parameter_range(
          "Boundary conditions/Ramp time", ramp_time, 0, inf, false, true);
        check_parameter_range("Boundary conditions/Global damping",
                              global_damping,
                              0,
                              inf,
                              false,
                              true);
        groups.clear();
        const std::string p = "Boundary conditions/Groups";
        for (const std::string &entry : split(prm.get("Groups"), ';'))
          {
            const auto    t = tokens(entry);
            BoundaryGroup g;
            if (t.size() < 8)
              throw InputError("Parameter '" + p + "': the entry '" + entry
                               + "' must read 'NAME TYPE x0 y0 z0 x1 y1 z1 "
                                 "[v1 v2 v3] [then T w1 w2 w3]'.");
            g.name = t[0];
            for (const auto &other : groups)
              check_parameter(other.name != g.name,
                              p,
                              "the group name '" + g.name + "' is used twice.");
            if (t[1] == "fixed")
              g.type = BoundaryGroup::Type::fixed;
            else if (t[1] == "velocity")
              g.type = BoundaryGroup::Type::velocity;
            else if (t[1] == "force")
              g.type = BoundaryGroup::Type::force;
            else if (t[1] == "damping")
              g.type = BoundaryGroup::Type::damping;
            else
              throw InputError("Parameter '" + p + "': unknown type '" + t[1]
                               + "' in '" + entry
                               + "'; use fixed, velocity, force or damping.");
            g.lower = read_point(t, 2, p, entry);
            g.upper = read_point(t, 5, p, entry);
            const std::size_t expected
              = g.type == BoundaryGroup::Type::fixed ? 8 : 11;
            if (t.size() != expected && t.size() != expected + 5)
              throw InputError("Parameter '" + p + "': the entry '" + entry
                               + "' has " + std::to_string(t.size())
                               + " fields; type " + t[1] + " takes "
                               + std::to_string(expected)
                               + " (or 5 more with 'then T w1 w2 w3').");
            if (expected == 11)
              for (unsigned int d = 0; d < 3; ++d)
                g.value[d] = to_double(t[8 + d], p, entry);
            if (g.type == BoundaryGroup::Type::damping
                || g.type == BoundaryGroup::Type::force)
              for (unsigned int d = 0; d < 3; ++d)
                check_parameter(!std::isnan(g.value[d]),
                                p,
                                "'*' is only allowed for velocity groups ('"
                                  + entry + "').");
            if (g.type == BoundaryGroup::Type::damping)
              for (unsigned int d = 0; d < 3; ++d)
                check_parameter(g.value[d] >= 0,
                                p,
                                "damping coefficients must be >= 0 ('" + entry
                                  + "').");
            if (t.size() == expected + 5)
              {
                check_parameter(t[expected] == "then",
                                p,
                                "expected 'then' in '" + entry + "'.");
                g.switch_time = to_double(t[expected + 1], p, entry);
                for (unsigned int d = 0; d < 3; ++d)
                  g.second_value[d] = to_double(t[expected + 2 + d], p, entry);
                for (unsigned int d = 0; d < 3; ++d)
                  check_parameter(std::isnan(g.second_value[d])
                                    == std::isnan(g.value[d]),
                                  p,
                                  "the free ('*') components must be the "
                                  "same before and after 'then' ('"
                                    + entry + "').");
              }
            groups.push_back(g);
          }
        check_parameter(groups.size() <= 32, p, "at most 32 groups.");
      }
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    void
    TimeParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        prm.declare_entry("End time",
                          "1e-6",
                          Double(),
                          "Simulated time (s), > 0.");
        prm.declare_entry("Time step",
                          "0",
                          Double(),
                          "Time step (s). 0 chooses Courant factor * "
                          "d_min / c_p,max. A larger step than 0.5 d_min / "
                          "c_p,max (the sound-crossing time of the "
                          "smallest automaton) is refused.");
        prm.declare_entry("Courant factor",
                          "0.2",
                          Double(),
                          "alpha in dt = alpha d_min / c_p,max when the "
                          "time step is 0; in (0, 0.5].");
      }
      prm.leave_subsection();
    }


    void
    TimeParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        end_time  = prm.get_double("End time");
        time_step = prm.get_double("Time step");
        courant   = prm.get_double("Courant factor");
        check_parameter_range("Time/End time", end_time, 0, inf, true, true);
        check_parameter_range("Time/Time step", time_step, 0, inf, false, true);
        check_parameter_range("Time/Courant factor",
                              courant,
                              0,
                              max_courant,
                              true,
                              false,
                              "The time step must stay below the "
                              "sound-crossing time of an automaton.");
      }
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    void
    McaOutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Output interval",
                          "0",
                          Double(),
                          "Simulated time between particle outputs (s); 0 "
                          "writes the first and last state only.");
        prm.declare_entry("Series interval",
                          "0",
                          Double(),
                          "Simulated time between rows of series.csv (s); "
                          "0 means every 100 steps.");
        prm.declare_entry("Write particles",
                          "true",
                          Bool(),
                          "Write the automata as particles (VTU/PVTU, "
                          "particles.pvd).");
        prm.declare_entry("Write stress",
                          "true",
                          Bool(),
                          "Include the stress tensor, pressure and von "
                          "Mises stress in the particle output (costs a "
                          "stress recovery at output steps).");
        prm.declare_entry("Cross section",
                          "false",
                          Bool(),
                          "Also write the automata of a slab "
                          "(cross_section.pvd), as in seed Fig. 3 and 4.");
        prm.declare_entry("Cross section axis",
                          "x",
                          Selection("x|y|z"),
                          "Normal of the cross-section slab.");
        prm.declare_entry("Cross section position",
                          "0",
                          Double(),
                          "Centre of the slab along its normal (m).");
        prm.declare_entry("Cross section thickness",
                          "0",
                          Double(),
                          "Thickness of the slab (m); 0 means 7 automaton "
                          "layers as in the seed.");
      }
      prm.leave_subsection();
    }


    void
    McaOutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        output_interval         = prm.get_double("Output interval");
        series_interval         = prm.get_double("Series interval");
        write_particles         = prm.get_bool("Write particles");
        write_stress            = prm.get_bool("Write stress");
        cross_section           = prm.get_bool("Cross section");
        cross_section_axis      = prm.get("Cross section axis")[0] - 'x';
        cross_section_position  = prm.get_double("Cross section position");
        cross_section_thickness = prm.get_double("Cross section thickness");
        check_parameter_range(
          "Output/Output interval", output_interval, 0, inf, false, true);
        check_parameter_range(
          "Output/Series interval", series_interval, 0, inf, false, true);
        check_parameter_range("Output/Cross section thickness",
                              cross_section_thickness,
                              0,
                              inf,
                              false,
                              true);
      }
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    void
    AnalysisParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      {
        prm.declare_entry(
          "Type",
          "none",
          Selection("none|uniaxial|pulse|friction"),
          "Headline figures: uniaxial (E, nu, sigma_y and hardening slope "
          "from the reaction of the loaded group and the lateral "
          "contraction), pulse (wave speed from the arrival times at two "
          "probe planes), friction (mu = tangential / normal force on the "
          "loaded group).");
        prm.declare_entry("Axis",
                          "z",
                          Selection("x|y|z"),
                          "Loading axis (uniaxial), propagation axis "
                          "(pulse), normal axis (friction).");
        prm.declare_entry("Loaded group",
                          "top",
                          Patterns::Anything(),
                          "Name of the loaded boundary group.");
        prm.declare_entry("Support group",
                          "bottom",
                          Patterns::Anything(),
                          "Name of the supporting boundary group.");
        prm.declare_entry("Elastic fit fraction",
                          "0.5",
                          Double(),
                          "uniaxial: E and nu are fitted on stresses below "
                          "this fraction of the first yield, in (0, 1).");
        prm.declare_entry("Probe 1",
                          "0",
                          Double(),
                          "pulse: coordinate of the first probe plane (m).");
        prm.declare_entry("Probe 2",
                          "0",
                          Double(),
                          "pulse: coordinate of the second probe plane (m).");
        prm.declare_entry("Averaging start",
                          "0",
                          Double(),
                          "friction: the mean mu is taken from this time "
                          "on (s).");
      }
      prm.leave_subsection();
    }


    void
    AnalysisParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      {
        const std::string t  = prm.get("Type");
        type                 = t == "uniaxial"   ? Type::uniaxial
                               : t == "pulse"    ? Type::pulse
                               : t == "friction" ? Type::friction
                                                 : Type::none;
        axis                 = prm.get("Axis")[0] - 'x';
        loaded_group         = prm.get("Loaded group");
        support_group        = prm.get("Support group");
        elastic_fit_fraction = prm.get_double("Elastic fit fraction");
        probe_1              = prm.get_double("Probe 1");
        probe_2              = prm.get_double("Probe 2");
        averaging_start      = prm.get_double("Averaging start");
        check_parameter_range("Analysis/Elastic fit fraction",
                              elastic_fit_fraction,
                              0,
                              1,
                              true,
                              true);
      }
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    Parameters::Parameters()
    {
      materials = {MaterialParameters::steel(), MaterialParameters::carbon()};
    }


    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      {
        prm.enter_subsection("Steel");
        MaterialParameters::declare_parameters(prm,
                                               MaterialParameters::steel());
        prm.leave_subsection();
        prm.enter_subsection("Carbon");
        MaterialParameters::declare_parameters(prm,
                                               MaterialParameters::carbon());
        prm.leave_subsection();
      }
      prm.leave_subsection();
      GeometryParameters::declare_parameters(prm);
      InteractionParameters::declare_parameters(prm);
      BoundaryParameters::declare_parameters(prm);
      TimeParameters::declare_parameters(prm);
      McaOutputParameters::declare_parameters(prm);
      AnalysisParameters::declare_parameters(prm);
    }


    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      materials = {MaterialParameters::steel(), MaterialParameters::carbon()};
      prm.enter_subsection("Materials");
      {
        prm.enter_subsection("Steel");
        materials[0].parse_parameters(prm, "Materials/Steel");
        prm.leave_subsection();
        prm.enter_subsection("Carbon");
        materials[1].parse_parameters(prm, "Materials/Carbon");
        prm.leave_subsection();
      }
      prm.leave_subsection();
      std::vector<std::string> names;
      for (const auto &m : materials)
        names.push_back(m.name);
      geometry.parse_parameters(prm, names);
      interaction.parse_parameters(prm);
      boundary.parse_parameters(prm);
      time.parse_parameters(prm);
      output.parse_parameters(prm);
      analysis.parse_parameters(prm);

      if (analysis.type == AnalysisParameters::Type::uniaxial
          || analysis.type == AnalysisParameters::Type::friction)
        {
          bool found = false;
          for (const auto &g : boundary.groups)
            found = found || g.name == analysis.loaded_group;
          check_parameter(found,
                          "Analysis/Loaded group",
                          "no boundary group is called '"
                            + analysis.loaded_group + "'.");
        }
    }


    bool
    Parameters::any_plastic() const
    {
      if (!interaction.plasticity)
        return false;
      for (const auto &m : materials)
        if (m.is_plastic())
          return true;
      return false;
    }
  } // namespace mca
} // namespace tribodyn
