// Any number of named phases, isotropic or transversely isotropic, pores
// included (issue #19 item 2).
#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material_names.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/phase_materials.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace
  {
    enum class Symmetry
    {
      isotropic,
      transversely_isotropic
    };
    constexpr SelectionTable<Symmetry, 2> symmetry_choices{
      {{"isotropic", Symmetry::isotropic},
       {"transversely isotropic", Symmetry::transversely_isotropic}}};

    /// Materials/Names and Materials/Pore stiffness ratio, each written
    /// once (core/parameter_binding.h).
    struct ListEntries
    {
      std::string names                = "matrix, heterogeneity";
      double      pore_stiffness_ratio = PhaseMaterials().pore_stiffness_ratio;

      ParameterBinding
      binding()
      {
        ParameterBinding b("Materials");
        b.add("Names",
              names,
              "The materials of the morphology, by name, comma-separated: "
              "material id k of the morphology is the k-th name (for an "
              "image: the k-th class of its segmentation, darkest first, or "
              "the k-th colour of its colour table; for the generators: "
              "matrix 0, heterogeneity 1). Each gets its subsection "
              "Materials/<Name>, the name with its first letter in upper "
              "case (fibres: 'subsection Fibres'), as the automata's "
              "materials do. A material named heterogeneity starts from its "
              "defaults (E = 80 GPa), any other from the matrix's (30 GPa): "
              "set what differs.");
        b.add("Pore stiffness ratio",
              pore_stiffness_ratio,
              "Pores (Young modulus 0) get an ersatz stiffness so that every "
              "cell problem stays well posed: E = this ratio times the "
              "smallest Young modulus of the solid phases, nu = 0. In (0, "
              "1e-2]; the apparent moduli change by about this ratio "
              "(relative) when no pore touches a boundary loaded by SUBC.",
              dealii::Patterns::Double(),
              Interval{0,
                       1e-2,
                       true,
                       false,
                       "It is the ersatz Young modulus of pores relative to "
                       "the softest solid phase."});
        return b;
      }

      /// The names, checked (@p prm at the top level).
      std::vector<std::string>
      read(dealii::ParameterHandler &prm)
      {
        ParameterBinding b = binding();
        b.parse(prm);
        return split_material_names(names,
                                    b.path("Names"),
                                    {"matrix, fibres", "", "", 0});
      }
    };

    /// The entries of one material's subsection, each written once; their
    /// ranges depend on each other (a pore, a transversely isotropic
    /// phase) and are checked by MorphologyMaterials::parse_parameters().
    struct MaterialEntries
    {
      IsotropicElasticMaterial elastic;
      Symmetry                 symmetry = Symmetry::isotropic;
      std::string              axis     = "z";
      double                   E_L = 0, nu_LT = 0, G_LT = 0;

      /// The defaults of material @p name: the heterogeneity's of the
      /// generated morphologies for heterogeneity, the matrix's for every
      /// other name.
      explicit MaterialEntries(const std::string &name)
          : elastic(name == "heterogeneity"
                      ? IsotropicElasticMaterial{80e9, 0.2, 1770.}
                      : IsotropicElasticMaterial{30e9, 0.2, 1770.})
      {
      }

      ParameterBinding
      binding(const std::string &section)
      {
        ParameterBinding b(section);
        b.add("Young modulus",
              elastic.youngs_modulus,
              "Young's modulus E (Pa), > 0; 0 makes the material a pore (the "
              "pixels of a meso pin's pores are cut out of the pin). A "
              "transversely isotropic material: E_T, of its plane of "
              "isotropy.");
        b.add("Poisson ratio",
              elastic.poisson_ratio,
              "Poisson's ratio nu, in (-1, 0.5) (not used for a pore). A "
              "transversely isotropic material: nu_TT, of its plane of "
              "isotropy (may exceed 0.5: its whole stiffness must be "
              "positive definite).");
        b.add("Density",
              elastic.density,
              "Mass density rho (kg/m^3), > 0; 0 is allowed for a pore.");
        b.add("Symmetry",
              symmetry,
              "isotropic, or transversely isotropic with the axis and the "
              "axial constants below.",
              symmetry_choices);
        b.add("Axis",
              axis,
              "Transversely isotropic: the direction of the axis L: x or y "
              "(in the plane of a 2D problem) or z (normal to it: the fibres "
              "of a cross-section).",
              dealii::Patterns::Selection("x|y|z"));
        b.add("Axial Young modulus",
              E_L,
              "Transversely isotropic: E_L (Pa), > 0.");
        b.add("Axial Poisson ratio",
              nu_LT,
              "Transversely isotropic: nu_LT = -eps_T / eps_L under a "
              "uniaxial stress along L.");
        b.add("Axial shear modulus",
              G_LT,
              "Transversely isotropic: G_LT (Pa), > 0, the shear modulus of "
              "planes that contain L.");
        return b;
      }
    };
  } // namespace


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
    ListEntries().binding().declare(prm);
    declare_material_sections(prm);
  }


  void
  MorphologyMaterials::declare_material_sections(dealii::ParameterHandler &prm)
  {
    // (declared again for a name that already has one: same entries, same
    // defaults)
    ListEntries entries;
    entries.binding().parse(prm);
    for (const auto &name : dealii::Utilities::split_string_list(entries.names))
      if (!name.empty())
        MaterialEntries(name)
          .binding("Materials/" + material_subsection(name))
          .declare(prm);
  }


  void
  MorphologyMaterials::parse_parameters(dealii::ParameterHandler &prm)
  {
    ListEntries entries;
    list                      = PhaseMaterials();
    list.names                = entries.read(prm);
    list.pore_stiffness_ratio = entries.pore_stiffness_ratio;
    for (const std::string &name : list.names)
      {
        const std::string section = "Materials/" + material_subsection(name);
        MaterialEntries   e(name);
        e.binding(section).parse(prm);
        const IsotropicElasticMaterial &m       = e.elastic;
        const bool                      is_pore = m.youngs_modulus == 0;
        std::optional<TransverselyIsotropicConstants> axial;
        if (is_pore)
          {
            check_parameter_range(
              section + "/Density", m.density, 0, max_density, false, false);
            check_parameter(e.symmetry == Symmetry::isotropic,
                            section + "/Symmetry",
                            "'" + name
                              + "' is a pore (Young modulus 0): a pore has "
                                "no elastic constants; set 'Symmetry = "
                                "isotropic' or give its Young modulus.");
          }
        else if (e.symmetry == Symmetry::transversely_isotropic)
          {
            // E_T and nu_TT: nu_TT may exceed 0.5 (the positive
            // definiteness of the whole stiffness is checked below)
            check_parameter_range(section + "/Young modulus",
                                  m.youngs_modulus,
                                  0,
                                  max_youngs_modulus,
                                  true,
                                  false);
            check_parameter_range(
              section + "/Density", m.density, 0, max_density, true, false);
            check_parameter_range(section + "/Axial Young modulus",
                                  e.E_L,
                                  0,
                                  max_youngs_modulus,
                                  true,
                                  false);
            check_parameter_range(section + "/Axial shear modulus",
                                  e.G_LT,
                                  0,
                                  max_youngs_modulus,
                                  true,
                                  false);
            TransverselyIsotropicConstants c;
            c.E_L   = e.E_L;
            c.E_T   = m.youngs_modulus;
            c.nu_LT = e.nu_LT;
            c.nu_TT = m.poisson_ratio;
            c.G_LT  = e.G_LT;
            c.axis  = e.axis == "x" ? 0 : e.axis == "y" ? 1 : 2;
            // the positive definiteness of the stiffness
            ElasticPhase(c, m.density, section);
            axial = c;
          }
        else
          check_isotropic_elastic_constants(section,
                                            m.youngs_modulus,
                                            m.poisson_ratio,
                                            m.density);
        list.materials.push_back(m);
        list.pore.push_back(is_pore);
        list.axial.push_back(axial);
      }
    check_parameter(std::count(list.pore.begin(), list.pore.end(), false) >= 1,
                    "Materials/Names",
                    "every material is a pore (Young modulus 0): at least "
                    "one must be solid.");
  }


  std::vector<ElasticPhase>
  MorphologyMaterials::phases() const
  {
    return list.phases();
  }


  std::vector<IsotropicElasticMaterial>
  MorphologyMaterials::given() const
  {
    return list.materials;
  }


  std::vector<std::string>
  MorphologyMaterials::names() const
  {
    return list.names;
  }


  std::vector<bool>
  MorphologyMaterials::pores() const
  {
    return list.pore;
  }


  void
  MorphologyMaterials::check(const Morphology  &morphology,
                             const std::string &phases_set_by) const
  {
    const unsigned int n_given = names().size();
    const std::string  named
      = " ('Materials/Names': " + material_list_message(names()) + ")";
    if (!phases_set_by.empty())
      check_parameter(morphology.n_phases() == n_given,
                      "Materials/Names",
                      "the image is segmented into "
                        + std::to_string(morphology.n_phases()) + " phases by '"
                        + phases_set_by + "', but " + std::to_string(n_given)
                        + " materials are named" + named
                        + ". Give as many names (and "
                          "constants) as the segmentation has phases, or "
                          "change the segmentation.");
    else
      check_parameter(morphology.n_phases() <= n_given,
                      "Materials/Names",
                      "the morphology has material ids up to "
                        + std::to_string(morphology.n_phases() - 1)
                        + " but only " + std::to_string(n_given)
                        + " materials are named" + named
                        + ". Name one material per phase, in the order of "
                          "the material ids.");
  }


  void
  MorphologyMaterials::check(const MorphologyParameters &parameters) const
  {
    if (parameters.is_map())
      check(Morphology::create(parameters), parameters.source->phases_set_by());
  }
} // namespace tribodyn
