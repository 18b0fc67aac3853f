#include "parameter_tools.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Double;
    namespace Patterns = dealii::Patterns;

    using namespace parameter_tools;

    namespace
    {
      const SelectionTable<AnalysisParameters::Type, 4> analysis_table{
        {{"none", AnalysisParameters::Type::none},
         {"uniaxial", AnalysisParameters::Type::uniaxial},
         {"pulse", AnalysisParameters::Type::pulse},
         {"friction", AnalysisParameters::Type::friction}}};
      /// Coordinate axes by index.
      const SelectionTable<unsigned int, 3> axis_table{
        {{"x", 0u}, {"y", 1u}, {"z", 2u}}};
    } // namespace

    void
    apply_friction_loading(Parameters &p); // friction_loading.cc


    // ------------------------------------------------------------------
    ParameterBinding
    InteractionParameters::binding()
    {
      ParameterBinding b("Interaction");
      b.add("Rotations",
            rotations,
            "Integrate the rotation of automata (Euler's equation). Without "
            "rotations the tangential increments use translations only.");
      b.add("Plasticity",
            plasticity,
            "Von Mises plasticity (Wilkins radial return adapted to MCA) for "
            "materials whose Hardening is not 'elastic'. Skipped when every "
            "material is elastic.");
      b.add("Skin",
            skin,
            "Pair-list skin as a fraction of the automaton size: the list "
            "holds pairs closer than (d_i + d_j)/2 + skin d and is rebuilt "
            "when an automaton has moved more than skin d / 2. In (0, 1].",
            Double(),
            Interval{0, 1, true, false});
      b.add("Elastic regions",
            "",
            "Boxes 'x0 y0 z0 x1 y1 z1' (m), separated by ';', whose automata "
            "(by their initial positions, with periodic images) are declared "
            "elastic: they skip the plastic return, and their pairs with "
            "other elastic automata skip the bond breaking and formation "
            "checks. For the parts of a scene far from the friction zone "
            "(the seed's bases), where nothing yields or breaks: they then "
            "cost what an elastic block costs. Empty: none.",
            Patterns::Anything(),
            [this, where = b.path("Elastic regions")](const std::string &text) {
              elastic_regions.clear();
              for (const std::string &entry : split(text, ';'))
                {
                  const auto t = tokens(entry);
                  if (t.size() != 6)
                    throw InputError(
                      "Parameter '" + where + "': the entry '" + entry
                      + "' must read 'x0 y0 z0 x1 y1 z1' (a box, "
                        "m).");
                  Region r;
                  r.shape = Region::Shape::box;
                  r.a     = read_point(t, 0, where, entry);
                  r.b     = read_point(t, 3, where, entry);
                  elastic_regions.push_back(r);
                }
            });
      return b;
    }


    void
    InteractionParameters::declare_parameters(ParameterHandler &prm)
    {
      InteractionParameters().binding().declare(prm);
      // the pair-law policies' own entries (pair_law.h)
      prm.enter_subsection("Interaction");
      FrictionLaws::Parameters::declare_parameters(prm);
      MomentLaws::Parameters::declare_parameters(prm);
      BondBreakingLaws::Parameters::declare_parameters(prm);
      BondFormationLaws::Parameters::declare_parameters(prm);
      prm.leave_subsection();
    }


    void
    InteractionParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
      prm.enter_subsection("Interaction");
      friction.parse_parameters(prm);
      moment.parse_parameters(prm);
      bond_breaking.parse_parameters(prm);
      bond_formation.parse_parameters(prm);
      prm.leave_subsection();
    }


    // ------------------------------------------------------------------
    // ------------------------------------------------------------------
    // ------------------------------------------------------------------
    ParameterBinding
    McaOutputParameters::binding()
    {
      ParameterBinding b("Output");
      b.add("Output interval",
            output_interval,
            "Simulated time between particle outputs (s); 0 writes the "
            "first and last state only.",
            Double(),
            Interval{0, inf, false, true});
      b.add("Series interval",
            series_interval,
            "Simulated time between rows of series.csv (s); 0 means every "
            "100 steps.",
            Double(),
            Interval{0, inf, false, true});
      b.add("Write particles",
            write_particles,
            "Write the automata as particles (VTU/PVTU, particles.pvd).");
      b.add("Write stress",
            write_stress,
            "Include the stress tensor, pressure and von Mises stress in the "
            "particle output (costs a stress recovery at output steps).");
      b.add("Cross section",
            cross_section,
            "Also write the automata of a slab (cross_section.pvd), as in "
            "seed Fig. 3 and 4.");
      b.add("Cross section axis",
            cross_section_axis,
            "Normal of the cross-section slab.",
            axis_table);
      b.add("Cross section position",
            cross_section_position,
            "Centre of the slab along its normal (m).");
      b.add("Cross section thickness",
            cross_section_thickness,
            "Thickness of the slab (m); 0 means 7 automaton layers as in the "
            "seed.",
            Double(),
            Interval{0, inf, false, true});
      PostprocessorRegistry::add_selection(b,
                                           "Postprocessors",
                                           postprocessors,
                                           "outputs (series.csv columns, "
                                           "files, summary.json keys)");
      return b;
    }


    void
    McaOutputParameters::declare_parameters(ParameterHandler &prm)
    {
      McaOutputParameters().binding().declare(prm);
    }


    void
    McaOutputParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    // ------------------------------------------------------------------
    ParameterBinding
    AnalysisParameters::binding()
    {
      ParameterBinding b("Analysis");
      b.add("Type",
            type,
            "Headline figures: uniaxial (E, nu, sigma_y and hardening slope "
            "from the reaction of the loaded group and the lateral "
            "contraction), pulse (wave speed from the arrival times at two "
            "probe planes), friction (mu = tangential / normal force on the "
            "loaded group).",
            analysis_table);
      b.add("Axis",
            axis,
            "Loading axis (uniaxial), propagation axis (pulse), normal axis "
            "(friction).",
            axis_table);
      b.add("Loaded group", loaded_group, "Name of the loaded boundary group.");
      b.add("Support group",
            support_group,
            "Name of the supporting boundary group.");
      b.add("Elastic fit fraction",
            elastic_fit_fraction,
            "uniaxial: E and nu are fitted on stresses below this fraction of "
            "the first yield, in (0, 1).",
            Double(),
            Interval{0, 1, true, true});
      b.add("Probe 1",
            probe_1,
            "pulse: coordinate of the first probe plane (m).");
      b.add("Probe 2",
            probe_2,
            "pulse: coordinate of the second probe plane (m).");
      b.add("Averaging start",
            averaging_start,
            "friction: the mean mu is taken from this time on (s).")
        .analysis_only();
      b.add("Smoothing window",
            smoothing_window,
            "friction: width of the centred moving average of mu giving "
            "mu_smoothed (s); 0 = a tenth of the End time.",
            Double(0))
        .analysis_only();
      b.add("Steady band",
            steady_band,
            "friction: the quasi-steady regime starts when the smoothed mu "
            "stays within this fraction of its later mean for the rest of the "
            "run (and for at least a fifth of it); its mu is block-averaged "
            "from there, with a standard error.",
            Double(0, 1))
        .analysis_only();
      b.add("Layer bin width",
            layer_bin_width,
            "friction: bin width along the normal axis of the quasi-fluid "
            "layer profile (unbonded contacts per automaton and plastic "
            "strain against z, written to layer.csv at every series sample) "
            "(m); 0 = the automaton size.",
            Double(0));
      b.add("Layer threshold",
            layer_threshold,
            "friction: the quasi-fluid layer is the z-range around the peak "
            "of the profile where it exceeds this fraction of the peak (0.5: "
            "full width at half maximum).",
            Double(0, 1),
            Interval{0, 1, true, false});
      return b;
    }


    void
    AnalysisParameters::declare_parameters(ParameterHandler &prm)
    {
      AnalysisParameters().binding().declare(prm);
    }


    void
    AnalysisParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    // ------------------------------------------------------------------
    Parameters::Parameters()
    {
      materials = {MaterialParameters::steel(), MaterialParameters::carbon()};
    }


    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      declare_material_names(prm);
      declare_material_sections(prm);
      GeometryParameters::declare_parameters(prm);
      InteractionParameters::declare_parameters(prm);
      BoundaryParameters::declare_parameters(prm);
      TimeParameters::declare_parameters(prm);
      PartitionParameters::declare_parameters(prm);
      McaOutputParameters::declare_parameters(prm);
      AnalysisParameters::declare_parameters(prm);
      FrictionLoadingParameters::declare_parameters(prm);
    }


    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      materials = parse_materials(prm);
      std::vector<std::string> names;
      for (const auto &m : materials)
        names.push_back(m.name);
      geometry.parse_parameters(prm, names);
      interaction.parse_parameters(prm);
      boundary.parse_parameters(prm);
      time.parse_parameters(prm);
      partition.parse_parameters(prm);
      output.parse_parameters(prm);
      analysis.parse_parameters(prm);
      loading.parse_parameters(prm);
      apply_friction_loading(*this);

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
    Parameters::displacements_needed() const
    {
      return output.write_particles || output.cross_section
             || analysis.type == AnalysisParameters::Type::uniaxial
             || analysis.type == AnalysisParameters::Type::pulse;
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
