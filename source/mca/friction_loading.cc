// Subsection "Friction loading": the staged loading protocol of seed 000
// Sec. 2.2 (separate, shift, approach until touching, then pressure and
// sliding with smooth ramps, damped loading layers), expressed as boundary
// groups that switch when the bodies first touch.

#include "parameter_tools.h"

#include <cmath>
#include <deal.II/base/patterns.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    using namespace parameter_tools;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;

    ParameterBinding
    FrictionLoadingParameters::binding()
    {
      ParameterBinding b("Friction loading");
      b.add("Enabled",
            enabled,
            "The staged loading of seed 000 Sec. 2.2 for a rough interface "
            "(Geometry/Rough interface, periodic in x and y): the bodies "
            "start in full contact, are separated along z and shifted along "
            "y (at the packing), approach at -+Approach velocity until they "
            "touch, then the top and bottom loading layers carry the "
            "Pressure and slide at +-Sliding velocity (symmetric), ramped "
            "over Boundary conditions/Ramp time from the contact, damped "
            "along z. It adds the boundary groups top, top_load, "
            "top_damping, bottom, bottom_load, bottom_damping (use "
            "'Analysis/Loaded group = top').");
      b.add("Separation",
            separation,
            "Gap along z between the bodies before the approach (m), >= 0; "
            "0 = the largest rise of the lower surface over the shifted "
            "upper one plus 1.25 d (no pair in contact range at the start).",
            Double(),
            Interval{0, inf, false, true});
      b.add("Shift",
            shift_fraction,
            "Shift of the upper body along y, as a fraction of the box width "
            "(seed: one half), in [0, 1).",
            Double(),
            Interval{0, 1});
      b.add("Loading layer thickness",
            layer_layers,
            "Automaton layers of the top and bottom loading layers: layers of "
            "the automata at the bodies' faces (spacing a/2 = d/sqrt 2 for "
            "automata of d, 2^L a/2 where a size band of 2^L d reaches the "
            "face).",
            Integer(1));
      b.add("Approach velocity",
            approach_velocity,
            "Velocity V_z of each loading layer during the approach (m/s), > "
            "0.",
            Double(),
            Interval{0, inf, true, true});
      b.add("Pressure",
            pressure,
            "Nominal normal pressure on the loading layers after contact "
            "(Pa), > 0: a force Pressure x (box area in x, y) on each layer.",
            Double(),
            Interval{0, inf, true, true});
      b.add("Sliding velocity",
            sliding_velocity,
            "Sliding velocity V_y of each loading layer after contact (m/s; "
            "top +V_y, bottom -V_y), >= 0.",
            Double(),
            Interval{0, inf, false, true});
      b.add("Sliding delay",
            sliding_delay,
            "Time from the contact to the start of the sliding (s), >= 0: "
            "over it the layers carry the Pressure at rest along y, then "
            "the Sliding velocity ramps in over Boundary conditions/Ramp "
            "time. 0 = the sliding ramps in with the pressure (the seed). "
            "With a slow Sliding velocity, the peak of mu after the sliding "
            "starts (summary.json: mu_peak) is the scene's static friction "
            "coefficient (the breakaway).",
            Double(),
            Interval{0, inf, false, true});
      b.add("Damping",
            damping,
            "Viscous damping coefficient along z of the loading layers (1/s, "
            "force -c m v_z), >= 0; 0 = the seed's criterion c = c_p / (2 h) "
            "with h the layer thickness (a longitudinal wave is damped by e "
            "in amplitude after travelling twice the specimen height; "
            "doc/theory/mca.md).",
            Double(),
            Interval{0, inf, false, true});
      return b;
    }


    void
    FrictionLoadingParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      FrictionLoadingParameters().binding().declare(prm);
    }


    void
    FrictionLoadingParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    namespace
    {
      BoundaryGroup
      make_group(const std::string           &name,
                 const BoundaryGroup::Type    type,
                 const double                 z_lower,
                 const double                 z_upper,
                 const std::array<double, 3> &before,
                 const std::array<double, 3> &after)
      {
        const double  big = std::numeric_limits<double>::max();
        BoundaryGroup g;
        g.name              = name;
        g.type              = type;
        g.lower             = Point3(-big, -big, z_lower);
        g.upper             = Point3(big, big, z_upper);
        g.value             = before;
        g.second_value      = after;
        g.switch_on_contact = type != BoundaryGroup::Type::damping;
        g.switch_time       = g.switch_on_contact ? 0 : -1;
        return g;
      }
    } // namespace


    /// Apply the friction loading to the geometry (gap, shift) and add its
    /// boundary groups (called by Parameters::parse_parameters).
    void
    apply_friction_loading(Parameters &p)
    {
      const auto &L = p.loading;
      if (!L.enabled)
        return;
      auto             &g = p.geometry;
      const std::string s = "Friction loading/Enabled";
      check_parameter(g.rough_interface,
                      s,
                      "the staged loading needs two bodies meeting along a "
                      "rough surface: enable Geometry/Rough interface.");
      check_parameter(g.periodic[0] && g.periodic[1] && !g.periodic[2],
                      s,
                      "the staged loading needs a box periodic in x and y "
                      "and not in z (Geometry/Periodic x, y, z).");
      check_parameter(g.interface_gap == 0,
                      "Geometry/Rough interface/Gap",
                      "must be 0 with the staged loading (its Separation "
                      "sets the gap).");
      const double d = g.automaton_size, a = d * std::sqrt(2.);
      g.interface_shift_y
        = L.shift_fraction * (g.domain_upper[1] - g.domain_lower[1]);
      // Automatic separation: the shifted upper surface clears the lower
      // one by 1.25 d everywhere (no pair within the contact range d), so
      // that the approach starts at once and lasts ~0.25 d / V_z.
      g.interface_gap
        = L.separation > 0
            ? L.separation
            : rough_surface_rise(g, g.interface_shift_y) + 1.25 * d;

      // Lattice planes z_m = z0 + a/4 + m a/2; the bodies span the planes
      // in [z_min, z_max). The lattice of 2^L d (a band of level L at the
      // bodies' bottom or top face) keeps every 2^L-th of them, and its
      // automaton layers are 2^L a/2 apart: the loading layers are counted
      // in layers of the automata at each face.
      double z_min = std::numeric_limits<double>::max(), z_max = -z_min;
      for (const Body &b : g.bodies)
        {
          z_min = std::min(z_min, std::max(b.lower[2], g.domain_lower[2]));
          z_max = std::max(z_max, std::min(b.upper[2], g.domain_upper[2]));
        }
      const double z0 = g.domain_lower[2] + a / 4;
      const auto   spacing
        = [&](const double z) { return (1u << g.size_level(z)) * a / 2; };
      const double s_bottom = spacing(z_min), s_top = spacing(z_max - 1e-9 * a);
      const double bottom
        = z0 + std::ceil((z_min - z0) / s_bottom - 1e-9) * s_bottom;
      const double top
        = z0 + (std::ceil((z_max - z0) / s_top - 1e-9) - 1) * s_top;
      const double h_bottom = (L.layer_layers - 0.5) * s_bottom;
      const double h_top    = (L.layer_layers - 0.5) * s_top;
      check_parameter(top - bottom > L.layer_layers * (s_bottom + s_top),
                      "Friction loading/Loading layer thickness",
                      "the two loading layers would meet: the bodies are "
                      "only "
                        + std::to_string(
                          int(std::round((top - bottom) / (a / 2))) + 1)
                        + " automaton layers (of d) high.");
      check_parameter(top + g.interface_gap < g.domain_upper[2],
                      "Geometry/Domain upper",
                      "the upper body, lifted by the separation "
                        + format_number(g.interface_gap)
                        + " m, must stay in the box: raise the box's upper "
                          "z above "
                        + format_number(top + g.interface_gap + a / 4) + " m.");

      // Seed criterion: c = c_p / (2 h_l), h_l = n a / 2 (doc/theory/mca.md),
      // with n layers of the automata at the faces (2^L a / 2 apart; the
      // bottom layer's, the thinner if the two differ).
      // (c_p of the material of the first body: the bases are steel)
      const double c_p     = p.materials[g.bodies[0].material].p_wave_speed();
      const double h_layer = L.layer_layers * std::min(s_bottom, s_top);
      p.loading_damping    = L.damping > 0 ? L.damping : c_p / (2 * h_layer);

      const double nan = std::numeric_limits<double>::quiet_NaN();
      const double big = std::numeric_limits<double>::max();
      const double F   = L.pressure * (g.domain_upper[0] - g.domain_lower[0])
                       * (g.domain_upper[1] - g.domain_lower[1]);
      const double Vz = L.approach_velocity, Vy = L.sliding_velocity;
      const double c      = p.loading_damping;
      using T             = BoundaryGroup::Type;
      const double top_lo = top + g.interface_gap - h_top,
                   bot_hi = bottom + h_bottom;
      auto &groups        = p.boundary.groups;
      for (const auto &existing : groups)
        for (const char *name : {"top",
                                 "top_load",
                                 "top_damping",
                                 "top_approach",
                                 "bottom",
                                 "bottom_load",
                                 "bottom_damping",
                                 "bottom_approach"})
          check_parameter(existing.name != name,
                          "Boundary conditions/Groups",
                          std::string("the group name '") + name
                            + "' is taken by the friction loading.");
      // The sliding starts at the contact, or Sliding delay after it: then
      // the approach along z (released at the contact) and the sliding
      // along x, y (switched later) are two groups on the same automata.
      const double delay   = L.sliding_delay;
      const double z_first = delay > 0 ? nan : -Vz;
      groups.push_back(make_group(
        "top", T::velocity, top_lo, big, {{0, 0, z_first}}, {{0, Vy, nan}}));
      groups.back().switch_time = delay;
      groups.push_back(make_group(
        "top_load", T::force, top_lo, big, {{0, 0, 0}}, {{0, 0, -F}}));
      groups.push_back(make_group(
        "top_damping", T::damping, top_lo, big, {{0, 0, c}}, {{0, 0, c}}));
      groups.push_back(make_group("bottom",
                                  T::velocity,
                                  -big,
                                  bot_hi,
                                  {{0, 0, -z_first}},
                                  {{0, -Vy, nan}}));
      groups.back().switch_time = delay;
      groups.push_back(make_group(
        "bottom_load", T::force, -big, bot_hi, {{0, 0, 0}}, {{0, 0, F}}));
      groups.push_back(make_group(
        "bottom_damping", T::damping, -big, bot_hi, {{0, 0, c}}, {{0, 0, c}}));
      if (delay > 0)
        {
          groups.push_back(make_group("top_approach",
                                      T::velocity,
                                      top_lo,
                                      big,
                                      {{nan, nan, -Vz}},
                                      {{nan, nan, nan}}));
          groups.push_back(make_group("bottom_approach",
                                      T::velocity,
                                      -big,
                                      bot_hi,
                                      {{nan, nan, Vz}},
                                      {{nan, nan, nan}}));
        }
      check_parameter(
        groups.size() <= 32,
        "Boundary conditions/Groups",
        "at most 32 groups (the friction loading adds 6, or 8 with a "
        "Sliding delay).");
    }
  } // namespace mca
} // namespace tribodyn
