// Any number of named phases, isotropic or transversely isotropic, pores
// included (issue #19 item 2).
#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/phase_materials.h>

namespace tribodyn
{
  namespace
  {
    const std::string axis_names[3] = {"x", "y", "z"};
  }


  namespace
  {
    /// The entries of "Phases" and of "Phases/Transversely isotropic",
    /// each written once (core/parameter_binding.h): the lists as their
    /// text, which PhaseMaterials::parse_parameters() splits and checks
    /// against each other.
    struct PhaseEntries
    {
      std::string names, young_moduli, poisson_ratios, densities;
      double      pore_stiffness_ratio = PhaseMaterials().pore_stiffness_ratio;
      std::string transverse_phases, axes, axial_young_moduli,
        axial_poisson_ratios, axial_shear_moduli;

      /// @p outer: the path of the subsection that holds "Phases".
      ParameterBinding
      phases(const std::string &outer)
      {
        ParameterBinding b("Phases", outer);
        b.add("Names",
              names,
              "Names of the phases, comma-separated: phase k is "
              "material id k of the morphology (for an image: "
              "the k-th class of its segmentation, darkest first, "
              "or the k-th colour of its colour table). Empty: "
              "the two phases 'Matrix' (id 0) and "
              "'Heterogeneity' (id 1) are used instead; when "
              "given, those two subsections are ignored.");
        b.add("Young moduli",
              young_moduli,
              "Young's modulus of each phase (Pa), in the order of "
              "'Names'; 0 makes the phase a pore.");
        b.add("Poisson ratios",
              poisson_ratios,
              "Poisson's ratio of each phase, in (-1, 0.5) (not "
              "used for a pore).");
        b.add("Densities",
              densities,
              "Density of each phase (kg/m^3); 0 is allowed for "
              "a pore.");
        b.add("Pore stiffness ratio",
              pore_stiffness_ratio,
              "Pores (Young modulus 0) get an ersatz stiffness so "
              "that every cell problem stays well posed: E = this "
              "ratio times the smallest Young modulus of the solid "
              "phases, nu = 0. In (0, 1e-2]; the apparent moduli "
              "change by about this ratio (relative) when no pore "
              "touches a boundary loaded by SUBC.",
              dealii::Patterns::Double(),
              Interval{0,
                       1e-2,
                       true,
                       false,
                       "It is the ersatz Young modulus of pores relative "
                       "to the softest solid phase."});
        return b;
      }

      ParameterBinding
      transversely_isotropic(const std::string &outer)
      {
        ParameterBinding b("Phases/Transversely isotropic", outer);
        b.add("Phases",
              transverse_phases,
              "Names (from 'Names') of the phases that are transversely "
              "isotropic, comma-separated; empty: every phase is isotropic. "
              "For these phases the entries of 'Young moduli' and 'Poisson "
              "ratios' are E_T and nu_TT of their plane of isotropy, and the "
              "lists below give, in the order of this list, the axis and the "
              "axial constants.");
        b.add("Axes",
              axes,
              "Direction of the axis L of each phase of "
              "'Phases': x or y (in the plane of the problem) or "
              "z (normal to it: the fibres of a cross-section).");
        b.add("Axial Young moduli",
              axial_young_moduli,
              "E_L of each phase of 'Phases' (Pa).");
        b.add("Axial Poisson ratios",
              axial_poisson_ratios,
              "nu_LT of each phase of 'Phases': -eps_T / eps_L "
              "under a uniaxial stress along L.");
        b.add("Axial shear moduli",
              axial_shear_moduli,
              "G_LT of each phase of 'Phases' (Pa): the shear "
              "modulus of planes that contain L.");
        return b;
      }
    };
  } // namespace


  void
  PhaseMaterials::declare_parameters(dealii::ParameterHandler &prm)
  {
    PhaseEntries e;
    e.phases("").declare(prm);
    e.transversely_isotropic("").declare(prm);
  }


  void
  PhaseMaterials::set_transversely_isotropic(const TransverseLists &l,
                                             const std::string     &section)
  {
    const std::string s     = section + "Transversely isotropic/";
    const auto       &which = l.which, &axes = l.axes;
    const auto       &E_L = l.E_L, &nu_LT = l.nu_LT, &G_LT = l.G_LT;
    axial.assign(names.size(), std::nullopt);
    const auto check_size = [&](const std::size_t n, const std::string &name) {
      check_parameter(n == which.size(),
                      s + name,
                      "give one entry per phase of '" + s
                        + "Phases': " + std::to_string(n) + " for "
                        + std::to_string(which.size()) + " phases.");
    };
    check_size(axes.size(), "Axes");
    check_size(E_L.size(), "Axial Young moduli");
    check_size(nu_LT.size(), "Axial Poisson ratios");
    check_size(G_LT.size(), "Axial shear moduli");
    for (unsigned int t = 0; t < which.size(); ++t)
      {
        const auto k = static_cast<unsigned int>(
          std::find(names.begin(), names.end(), which[t]) - names.begin());
        std::string known;
        for (const auto &n : names)
          known += (known.empty() ? "" : ", ") + n;
        check_parameter(k < names.size(),
                        s + "Phases",
                        "'" + which[t] + "' is not a phase of '" + section
                          + "Names' (" + known + ").");
        check_parameter(!axial[k],
                        s + "Phases",
                        "'" + which[t] + "' is given twice.");
        check_parameter(!pore[k],
                        s + "Phases",
                        "'" + which[t]
                          + "' is a pore (Young modulus 0): a pore has no "
                            "elastic constants.");
        const auto axis
          = std::find(std::begin(axis_names), std::end(axis_names), axes[t])
            - std::begin(axis_names);
        check_parameter(axis < 3,
                        s + "Axes",
                        "'" + axes[t] + "' (phase '" + which[t]
                          + "') is not an axis: give x, y or z.");
        TransverselyIsotropicConstants c;
        c.E_L   = E_L[t];
        c.E_T   = materials[k].youngs_modulus;
        c.nu_LT = nu_LT[t];
        c.nu_TT = materials[k].poisson_ratio;
        c.G_LT  = G_LT[t];
        c.axis  = static_cast<unsigned int>(axis);
        check_parameter_range(s + "Axial Young moduli (" + which[t] + ")",
                              c.E_L,
                              0,
                              max_youngs_modulus,
                              true,
                              false);
        check_parameter_range(s + "Axial shear moduli (" + which[t] + ")",
                              c.G_LT,
                              0,
                              max_youngs_modulus,
                              true,
                              false);
        // the positive definiteness of the stiffness
        ElasticPhase(c,
                     materials[k].density,
                     section + "Transversely isotropic (phase '" + which[t]
                       + "', with its entries of '" + section
                       + "Young moduli' and '" + section + "Poisson ratios')");
        axial[k] = c;
      }
  }


  void
  PhaseMaterials::parse_parameters(dealii::ParameterHandler &prm,
                                   const std::string        &section)
  {
    const std::string s = section + "/Phases/";
    PhaseEntries      e;
    e.phases(section).parse(prm);
    e.transversely_isotropic(section).parse(prm);
    names = dealii::Utilities::split_string_list(e.names);
    const std::vector<double> E
      = parse_number_list(e.young_moduli, s + "Young moduli");
    const std::vector<double> nu
      = parse_number_list(e.poisson_ratios, s + "Poisson ratios");
    const std::vector<double> rho
      = parse_number_list(e.densities, s + "Densities");
    pore_stiffness_ratio = e.pore_stiffness_ratio;
    const std::string t  = s + "Transversely isotropic/";
    TransverseLists   transverse;
    transverse.which
      = dealii::Utilities::split_string_list(e.transverse_phases);
    transverse.axes = dealii::Utilities::split_string_list(e.axes);
    transverse.E_L
      = parse_number_list(e.axial_young_moduli, t + "Axial Young moduli");
    transverse.nu_LT
      = parse_number_list(e.axial_poisson_ratios, t + "Axial Poisson ratios");
    transverse.G_LT
      = parse_number_list(e.axial_shear_moduli, t + "Axial shear moduli");
    materials.clear();
    pore.clear();
    axial.clear();
    if (names.empty())
      {
        check_parameter(transverse.which.empty(),
                        s + "Transversely isotropic/Phases",
                        "transversely isotropic phases need named phases: "
                        "give '"
                          + s + "Names' and their constants.");
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
        else if (std::find(transverse.which.begin(),
                           transverse.which.end(),
                           names[k])
                 != transverse.which.end())
          {
            // E_T and nu_TT: nu_TT may exceed 0.5 (the positive
            // definiteness of the whole stiffness is checked below)
            const std::string t = s + names[k] + ": ";
            check_parameter_range(
              t + "Young moduli", E[k], 0, max_youngs_modulus, true, false);
            check_parameter_range(
              t + "Densities", rho[k], 0, max_density, true, false);
          }
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
    set_transversely_isotropic(transverse, s);
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


  std::vector<ElasticPhase>
  PhaseMaterials::phases() const
  {
    // (axial may be empty: every phase isotropic)
    const auto transverse = [&](const unsigned int k) {
      return k < axial.size() ? axial[k] : std::nullopt;
    };
    double smallest = std::numeric_limits<double>::max();
    for (unsigned int k = 0; k < materials.size(); ++k)
      if (!pore[k])
        smallest = std::min({smallest,
                             materials[k].youngs_modulus,
                             transverse(k) ? transverse(k)->E_L : smallest});
    std::vector<ElasticPhase> p;
    for (unsigned int k = 0; k < materials.size(); ++k)
      if (pore[k])
        {
          IsotropicElasticMaterial ersatz = materials[k];
          ersatz.youngs_modulus           = pore_stiffness_ratio * smallest;
          ersatz.poisson_ratio            = 0;
          p.emplace_back(ersatz);
        }
      else if (transverse(k))
        p.emplace_back(*transverse(k), materials[k].density, names[k]);
      else
        p.emplace_back(materials[k]);
    return p;
  }


  void
  MorphologyMaterials::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    TwoPhaseMaterials::declare_parameters(prm);
    PhaseMaterials::declare_parameters(prm);
    prm.leave_subsection();
  }


  void
  MorphologyMaterials::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    TwoPhaseMaterials::parse_parameters(prm, "Materials");
    named.parse_parameters(prm, "Materials");
    prm.leave_subsection();
  }


  std::vector<ElasticPhase>
  MorphologyMaterials::phases() const
  {
    if (named.given())
      return named.phases();
    const auto two = TwoPhaseMaterials::phases();
    return {two.begin(), two.end()};
  }


  std::vector<IsotropicElasticMaterial>
  MorphologyMaterials::given() const
  {
    return named.given() ? named.materials : TwoPhaseMaterials::phases();
  }


  std::vector<std::string>
  MorphologyMaterials::names() const
  {
    return named.given() ? named.names
                         : std::vector<std::string>{"matrix", "heterogeneity"};
  }


  std::vector<bool>
  MorphologyMaterials::pores() const
  {
    return named.given() ? named.pore : std::vector<bool>(2, false);
  }


  void
  MorphologyMaterials::check(const Morphology &morphology,
                             const bool        image) const
  {
    const unsigned int n_given = names().size();
    if (!named.given())
      check_parameter(morphology.n_phases() <= 2,
                      "Materials/Phases/Names",
                      "the morphology has "
                        + std::to_string(morphology.n_phases())
                        + " phases (material ids 0 to "
                        + std::to_string(morphology.n_phases() - 1)
                        + ") but only two are given ('Materials/Matrix' and "
                          "'Materials/Heterogeneity'). Name every phase in "
                          "'Materials/Phases' (Names, Young moduli, Poisson "
                          "ratios, Densities), in the order of the "
                          "segmentation.");
    else if (image)
      check_parameter(morphology.n_phases() == n_given,
                      "Materials/Phases/Names",
                      "the image is segmented into "
                        + std::to_string(morphology.n_phases())
                        + " phases by 'Morphology/Image/Segmentation', but "
                        + std::to_string(n_given)
                        + " phases are named. Give as many names (and "
                          "constants) as the segmentation has phases, or "
                          "change the segmentation.");
    else
      check_parameter(morphology.n_phases() <= n_given,
                      "Materials/Phases/Names",
                      "the morphology has material ids up to "
                        + std::to_string(morphology.n_phases() - 1)
                        + " but only " + std::to_string(n_given)
                        + " phases are named.");
  }


  void
  MorphologyMaterials::check(const MorphologyParameters &parameters) const
  {
    if (parameters.is_map())
      check(Morphology::create(parameters),
            parameters.generator == MorphologyParameters::Generator::image);
  }
} // namespace tribodyn
