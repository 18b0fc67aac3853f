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
        selection_text(hardening_table, d.hardening),
        selection_pattern(hardening_table),
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
      density           = prm.get_double("Density");
      youngs_modulus    = prm.get_double("Young modulus");
      poisson_ratio     = prm.get_double("Poisson ratio");
      hardening         = get_selection(prm, "Hardening", hardening_table);
      yield_stress      = prm.get_double("Yield stress");
      hardening_modulus = prm.get_double("Hardening modulus");
      second_hardening_modulus = prm.get_double("Second hardening modulus");
      second_hardening_onset   = prm.get_double("Second hardening onset");
      bond_breaking_stress     = prm.get_double("Bond breaking stress");
      bond_energy_density      = prm.get_double("Bond energy density");

      check_isotropic_elastic_constants(section,
                                        youngs_modulus,
                                        poisson_ratio,
                                        density);
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


    namespace
    {
      /// Subsection of material @p name: the name with its first letter
      /// in upper case (steel: Materials/Steel).
      std::string
      material_subsection(const std::string &name)
      {
        std::string s = name;
        if (!s.empty())
          s[0]
            = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
        return s;
      }

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

      /// The names of Materials/Names, checked.
      std::vector<std::string>
      material_names(ParameterHandler &prm)
      {
        prm.enter_subsection("Materials");
        const auto names
          = dealii::Utilities::split_string_list(prm.get("Names"));
        prm.leave_subsection();
        check_parameter(!names.empty(),
                        "Materials/Names",
                        "must name at least one material (e.g. 'steel, "
                        "carbon').");
        check_parameter(names.size() <= 64,
                        "Materials/Names",
                        "names " + std::to_string(names.size())
                          + " materials; at most 64 are supported.");
        std::vector<std::string> seen;
        for (const auto &n : names)
          {
            std::string lower = n;
            for (char &c : lower)
              c = static_cast<char>(
                std::tolower(static_cast<unsigned char>(c)));
            check_parameter(
              !n.empty() && n.find_first_of(" \t/") == std::string::npos
                && lower != "void",
              "Materials/Names",
              "'" + n
                + "' is not a material name: use letters, digits and "
                  "'_' (no spaces or '/'; 'void' is reserved for the voids of "
                  "Geometry/Regions).");
            check_parameter(std::find(seen.begin(), seen.end(), lower)
                              == seen.end(),
                            "Materials/Names",
                            "names '" + n
                              + "' twice (names differing only in case "
                                "count as the same: their subsections "
                                "would coincide).");
            seen.push_back(lower);
          }
        return names;
      }
    } // namespace


    void
    Parameters::declare_material_sections(ParameterHandler &prm)
    {
      // each named material's subsection (declared again for a name that
      // already has one: same entries, same defaults)
      prm.enter_subsection("Materials");
      for (const auto &name :
           dealii::Utilities::split_string_list(prm.get("Names")))
        if (!name.empty())
          {
            prm.enter_subsection(material_subsection(name));
            MaterialParameters::declare_parameters(prm,
                                                   material_defaults(name));
            prm.leave_subsection();
          }
      prm.leave_subsection();
    }


    std::vector<MaterialParameters>
    Parameters::parse_materials(ParameterHandler &prm)
    {
      std::vector<MaterialParameters> list;
      const std::vector<std::string>  names = material_names(prm);
      prm.enter_subsection("Materials");
      for (const auto &name : names)
        {
          const std::string section = material_subsection(name);
          prm.enter_subsection(section);
          list.push_back(material_defaults(name));
          list.back().parse_parameters(prm, "Materials/" + section);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      return list;
    }
  } // namespace mca
} // namespace tribodyn
