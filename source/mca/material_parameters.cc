// The materials of the automata: their parameters (MaterialParameters) and
// the list of named materials (Materials/Names, one subsection per name).
#include "parameter_tools.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/mca/parameters.h>

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
      const SelectionTable<Hardening, 3> hardening_table{
        {{"elastic", Hardening::elastic},
         {"linear", Hardening::linear},
         {"bilinear", Hardening::bilinear}}};
    } // namespace


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


    ParameterBinding
    MaterialParameters::binding(const std::string &section)
    {
      ParameterBinding b(section);
      b.add("Density", density, "Mass density rho (kg/m^3), > 0.");
      b.add("Young modulus", youngs_modulus, "Young's modulus E (Pa), > 0.");
      b.add("Poisson ratio",
            poisson_ratio,
            "Poisson's ratio nu, in (-1, 0.5). The pair law reproduces "
            "Hooke's law with these E and nu.");
      b.add("Hardening",
            hardening,
            "Response beyond the elastic range: elastic (no plasticity), "
            "linear (sigma_y = Yield stress + Hardening modulus * eps_p) or "
            "bilinear (slope Second hardening modulus beyond Second hardening "
            "onset). Von Mises plasticity, Wilkins radial return.",
            hardening_table);
      b.add("Yield stress",
            yield_stress,
            "Initial yield stress sigma_y0 (Pa), > 0.",
            Double(),
            Interval{0, inf, true, true});
      b.add("Hardening modulus",
            hardening_modulus,
            "Plastic hardening modulus H1 = dsigma_y/deps_p (Pa), >= 0. The "
            "uniaxial tangent modulus is E H1 / (E + H1).",
            Double(),
            Interval{0, inf, false, true});
      b.add("Second hardening modulus",
            second_hardening_modulus,
            "Bilinear hardening: H2 = dsigma_y/deps_p beyond the onset (Pa), "
            ">= 0.",
            Double(),
            Interval{0, inf, false, true});
      b.add("Second hardening onset",
            second_hardening_onset,
            "Bilinear hardening: plastic strain where the second branch "
            "starts, > 0.",
            Double(),
            Interval{0, inf, true, true});
      b.add("Bond breaking stress",
            bond_breaking_stress,
            "A bonded pair breaks when the von Mises stress of its stress "
            "state reaches this value (Pa), > 0 (the smaller value of the two "
            "materials applies).",
            Double(),
            Interval{0, inf, true, true});
      b.add("Bond energy density",
            bond_energy_density,
            "Energy to break a bond per unit volume of the pair (J/m^3): the "
            "bond energy of pair ij is this times S_ij (d_i + d_j)/2. The "
            "default is sigma_b^2/(2E) with sigma_b the bond breaking stress.",
            Double(),
            Interval{0, inf, false, true});
      return b;
    }


    void
    MaterialParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &section)
    {
      binding(section).parse(prm);
      check_isotropic_elastic_constants(section,
                                        youngs_modulus,
                                        poisson_ratio,
                                        density);
    }


    namespace
    {
      /// The defaults of material @p name: carbon's for carbon, steel's for
      /// steel and for every other name.
      MaterialParameters
      material_defaults(const std::string &name)
      {
        MaterialParameters m = name == "carbon" ? MaterialParameters::carbon()
                                                : MaterialParameters::steel();
        m.name               = name;
        return m;
      }

      /// Materials/Names, written once: the list as its text.
      struct MaterialNames
      {
        std::string names = "steel, carbon";

        ParameterBinding
        binding()
        {
          ParameterBinding b("Materials");
          b.add(
            "Names",
            names,
            "The materials of the scene, by name (any number): each gets its "
            "subsection Materials/<Name>, the name with its first letter in "
            "upper case (steel: 'subsection Steel', oxide: 'subsection "
            "Oxide'), and bodies, regions and inclusions refer to it by name. "
            "A material named carbon starts from carbon's defaults, any other "
            "from steel's: set what differs. Example of a third material: "
            "'set Names = steel, carbon, oxide' and 'subsection Oxide / set "
            "Density = 5200 / set Young modulus = 150e9 ... end'.",
            dealii::Patterns::List(dealii::Patterns::Anything()));
          return b;
        }

        /// The names as the handler (at the top level) has them now.
        std::vector<std::string>
        read(ParameterHandler &prm)
        {
          binding().parse(prm);
          return dealii::Utilities::split_string_list(names);
        }
      };

      /// The names of Materials/Names, checked.
      std::vector<std::string>
      material_names(ParameterHandler &prm)
      {
        MaterialNames entry;
        entry.binding().parse(prm);
        return split_material_names(
          entry.names,
          entry.binding().path("Names"),
          {"steel, carbon", "void", "the voids of Geometry/Regions", 64});
      }
    } // namespace


    void
    Parameters::declare_material_names(ParameterHandler &prm)
    {
      MaterialNames().binding().declare(prm);
    }


    void
    Parameters::declare_material_sections(ParameterHandler &prm)
    {
      // each named material's subsection (declared again for a name that
      // already has one: same entries, same defaults)
      const auto names = MaterialNames().read(prm);
      for (const auto &name : names)
        if (!name.empty())
          material_defaults(name)
            .binding("Materials/" + material_subsection(name))
            .declare(prm);
    }


    std::vector<MaterialParameters>
    Parameters::parse_materials(ParameterHandler &prm)
    {
      std::vector<MaterialParameters> list;
      const std::vector<std::string>  names = material_names(prm);
      for (const auto &name : names)
        {
          list.push_back(material_defaults(name));
          list.back().parse_parameters(prm,
                                       "Materials/"
                                         + material_subsection(name));
        }
      return list;
    }
  } // namespace mca
} // namespace tribodyn
