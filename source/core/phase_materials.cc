// Any number of named isotropic phases, pores included (issue #19 item 2).
#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/core/phase_materials.h>

namespace tribodyn
{
  void
  PhaseMaterials::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    prm.enter_subsection("Phases");
    {
      prm.declare_entry("Names",
                        "",
                        Anything(),
                        "Names of the phases, comma-separated: phase k is "
                        "material id k of the morphology (for an image: "
                        "the k-th class of its segmentation, darkest first, "
                        "or the k-th colour of its colour table). Empty: "
                        "the two phases 'Matrix' (id 0) and "
                        "'Heterogeneity' (id 1) are used instead; when "
                        "given, those two subsections are ignored.");
      prm.declare_entry("Young moduli",
                        "",
                        Anything(),
                        "Young's modulus of each phase (Pa), in the order of "
                        "'Names'; 0 makes the phase a pore.");
      prm.declare_entry("Poisson ratios",
                        "",
                        Anything(),
                        "Poisson's ratio of each phase, in (-1, 0.5) (not "
                        "used for a pore).");
      prm.declare_entry("Densities",
                        "",
                        Anything(),
                        "Density of each phase (kg/m^3); 0 is allowed for "
                        "a pore.");
      prm.declare_entry("Pore stiffness ratio",
                        "1e-6",
                        dealii::Patterns::Double(),
                        "Pores (Young modulus 0) get an ersatz stiffness so "
                        "that every cell problem stays well posed: E = this "
                        "ratio times the smallest Young modulus of the solid "
                        "phases, nu = 0. In (0, 1e-2]; the apparent moduli "
                        "change by about this ratio (relative) when no pore "
                        "touches a boundary loaded by SUBC.");
    }
    prm.leave_subsection();
  }


  void
  PhaseMaterials::parse_parameters(dealii::ParameterHandler &prm,
                                   const std::string        &section)
  {
    const std::string s = section + "/Phases/";
    prm.enter_subsection("Phases");
    names = dealii::Utilities::split_string_list(prm.get("Names"));
    const std::vector<double> E
      = parse_number_list(prm.get("Young moduli"), s + "Young moduli");
    const std::vector<double> nu
      = parse_number_list(prm.get("Poisson ratios"), s + "Poisson ratios");
    const std::vector<double> rho
      = parse_number_list(prm.get("Densities"), s + "Densities");
    pore_stiffness_ratio = prm.get_double("Pore stiffness ratio");
    prm.leave_subsection();
    materials.clear();
    pore.clear();
    if (names.empty())
      {
        check_parameter(E.empty() && nu.empty() && rho.empty(),
                        s + "Names",
                        "the properties of phases are given but not their "
                        "names: give one name per phase, comma-separated.");
        return;
      }
    check_parameter(names.size() >= 2,
                    s + "Names",
                    "give at least two phases (a single one is 'Generator = "
                    "homogeneous' with the two-phase 'Matrix').");
    for (unsigned int k = 0; k < names.size(); ++k)
      for (unsigned int q = 0; q < k; ++q)
        check_parameter(names[k] != names[q],
                        s + "Names",
                        "the name '" + names[k] + "' is given twice.");
    const auto check_size = [&](const std::vector<double> &v,
                                const std::string         &name) {
      check_parameter(v.size() == names.size(),
                      s + name,
                      "give one value per phase: " + std::to_string(v.size())
                        + " values for the " + std::to_string(names.size())
                        + " phases of '" + s + "Names'.");
    };
    check_size(E, "Young moduli");
    check_size(nu, "Poisson ratios");
    check_size(rho, "Densities");
    check_parameter_range(s + "Pore stiffness ratio",
                          pore_stiffness_ratio,
                          0,
                          1e-2,
                          true,
                          false,
                          "It is the ersatz Young modulus of pores relative "
                          "to the softest solid phase.");
    for (unsigned int k = 0; k < names.size(); ++k)
      {
        IsotropicElasticMaterial m;
        m.youngs_modulus   = E[k];
        m.poisson_ratio    = nu[k];
        m.density          = rho[k];
        const bool is_pore = E[k] == 0;
        if (is_pore)
          check_parameter_range(s + "Densities (" + names[k] + ")",
                                rho[k],
                                0,
                                max_density,
                                false,
                                false);
        else
          check_isotropic_elastic_constants(s + names[k]
                                              + ": Young moduli, "
                                                "Poisson ratios, Densities",
                                            E[k],
                                            nu[k],
                                            rho[k]);
        materials.push_back(m);
        pore.push_back(is_pore);
      }
    check_parameter(std::count(pore.begin(), pore.end(), false) >= 1,
                    s + "Young moduli",
                    "every phase is a pore (Young modulus 0): at least one "
                    "must be solid.");
  }


  bool
  PhaseMaterials::given() const
  {
    return !names.empty();
  }


  unsigned int
  PhaseMaterials::size() const
  {
    return names.size();
  }


  std::vector<IsotropicElasticMaterial>
  PhaseMaterials::phases() const
  {
    double smallest = std::numeric_limits<double>::max();
    for (unsigned int k = 0; k < materials.size(); ++k)
      if (!pore[k])
        smallest = std::min(smallest, materials[k].youngs_modulus);
    std::vector<IsotropicElasticMaterial> p = materials;
    for (unsigned int k = 0; k < p.size(); ++k)
      if (pore[k])
        {
          p[k].youngs_modulus = pore_stiffness_ratio * smallest;
          p[k].poisson_ratio  = 0;
        }
    return p;
  }
} // namespace tribodyn
