// Subsection "Materials" of the contact problem and the stiffnesses it
// builds: transversely isotropic constants, homogenization summaries.
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <string>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material_names.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      using Type = ContactMaterialParameters::Type;
      constexpr SelectionTable<Type, 5> type_choices{
        {{"isotropic", Type::isotropic},
         {"anisotropic", Type::anisotropic},
         {"engineering constants", Type::engineering_constants},
         {"homogenization summary", Type::homogenization_summary},
         {"morphology", Type::morphology}}};
      using Kinematics = ContactMaterialParameters::Kinematics;
      constexpr SelectionTable<Kinematics, 2> kinematics_choices{
        {{"small strain", Kinematics::small_strain},
         {"large deformation", Kinematics::large_deformation}}};
    } // namespace

    using dealii::ParameterHandler;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::List;
    using dealii::Patterns::Selection;

    ParameterBinding
    ContactMaterialParameters::binding()
    {
      ParameterBinding b("Materials");
      b.add("Type",
            type,
            "Constitutive model of the pin. 'isotropic': homogeneous, of "
            "the material 'Pin material'. 'anisotropic': the plane-strain "
            "stiffness of "
            "subsection Anisotropic. 'engineering constants': transversely "
            "isotropic with axis L = x (subsection Engineering constants, "
            "defaults = seed Table 1 homogenized values). 'homogenization "
            "summary': the apparent stiffness C of a homogenization run's "
            "summary.json. 'morphology': a heterogeneous (meso) pin from "
            "subsection Morphology, material id k being the k-th material of "
            "'Names' (any number, transversely isotropic ones and pores: a "
            "pore's pixels are cut out of the pin, and so is a fragment they "
            "detach from the top face).",
            type_choices);
      b.add("Pin material",
            pin_material,
            "Type = isotropic: the material of the pin, by its name in "
            "'Names' (its Young modulus, Poisson ratio and Density in its "
            "subsection); empty: the first of 'Names'.");
      b.add("Kinematics",
            kinematics,
            "'small strain': linear elasticity. 'large deformation': total "
            "Lagrangian, St Venant-Kirchhoff (S = C:E with the Green-Lagrange "
            "strain E).",
            kinematics_choices);
      b.add("Density",
            density,
            "Density (kg/m^3) of the homogeneous anisotropic materials (types "
            "anisotropic, engineering constants, homogenization summary).",
            Double(),
            Interval{0, 1e6, true, false});
      return b;
    }


    std::vector<ParameterBinding>
    ContactMaterialParameters::subsection_bindings()
    {
      // (three defaults spelled as the reference writes them: 31.9e9, not
      // the 3.19e10 of exact_number())
      ParameterBinding anisotropic("Materials/Anisotropic");
      anisotropic.add(
        "Stiffness",
        "33.33e9, 8.33e9, 0, 8.33e9, 33.33e9, 0, 0, 0, 12.5e9",
        "Plane-strain stiffness C (Pa), 9 numbers row by row, Voigt order "
        "(xx, yy, xy) with the engineering shear strain: sigma = C (eps_xx, "
        "eps_yy, gamma_xy).",
        List(Double(), 9, 9, ","),
        [this, path = anisotropic.path("Stiffness")](const std::string &text) {
          const auto c = internal::parse_numbers(text, 9, path);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              anisotropic_stiffness[i][j] = c[3 * i + j];
        });
      anisotropic.add(
        "Out-of-plane stiffness",
        "8.33e9, 8.33e9, 0",
        "Row c_z with sigma_zz = c_z . (eps_xx, eps_yy, gamma_xy) (Pa); used "
        "only for the von Mises output.",
        List(Double(), 3, 3, ","),
        [this, path = anisotropic.path("Out-of-plane stiffness")](
          const std::string &text) {
          const auto z = internal::parse_numbers(text, 3, path);
          for (unsigned int i = 0; i < 3; ++i)
            anisotropic_c_z[i] = z[i];
        });

      ParameterBinding constants("Materials/Engineering constants");
      constants.add_spelled("E_L",
                            E_L,
                            "31.9e9",
                            "Young modulus along x (Pa).");
      constants.add_spelled("E_T",
                            E_T,
                            "34e9",
                            "Young modulus along y, z (Pa).");
      constants.add("nu_LT", nu_LT, "Poisson ratio nu_LT.");
      constants.add("nu_TT", nu_TT, "Poisson ratio nu_TT'.");
      constants.add_spelled("G_LT", G_LT, "13.3e9", "Shear modulus G_LT (Pa).");

      ParameterBinding summary("Materials/Homogenization summary");
      summary.add("File",
                  summary_file,
                  "summary.json written by a 'set Problem = homogenization' "
                  "run.");
      summary.add("Boundary condition",
                  summary_key,
                  "Which apparent stiffness of the file to use.",
                  Selection("KUBC|SUBC|periodic"));

      return {anisotropic, constants, summary};
    }


    void
    ContactMaterialParameters::declare_parameters(ParameterHandler &prm)
    {
      ContactMaterialParameters p;
      p.binding().declare(prm);
      for (const ParameterBinding &b : p.subsection_bindings())
        b.declare(prm);
      MorphologyMaterials::declare_parameters(prm);
    }


    void
    ContactMaterialParameters::check_isotropic_pin(const unsigned int k,
                                                   const std::string &parameter,
                                                   const std::string &pin) const
    {
      const std::string name = composite.names()[k];
      check_parameter(!composite.pores()[k],
                      parameter,
                      "'" + name + "' is a pore (Young modulus 0): " + pin
                        + " must be solid. Name a solid material.");
      check_parameter(!composite.list.axial[k],
                      parameter,
                      "'" + name + "' is transversely isotropic: " + pin
                        + " is isotropic. Name an isotropic material (a "
                          "transversely isotropic pin is 'Type = "
                          "engineering constants').");
    }


    void
    ContactMaterialParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      const std::vector<ParameterBinding> subsections = subsection_bindings();
      for (const ParameterBinding &s : subsections)
        s.parse(prm);
      composite.parse_parameters(prm);
      // the pin's material, by name (Type = isotropic; a study's
      // homogeneous pin), checked by ContactParameters::parse_parameters()
      const std::vector<std::string> names = composite.names();
      const std::string              path  = b.path("Pin material");
      pin_index
        = pin_material.empty() ? 0 : material_index(names, pin_material, path);
      isotropic = composite.given()[pin_index];

      const ParameterBinding &constants = subsections[1];
      const ParameterBinding &summary   = subsections[2];
      if (type == Type::engineering_constants)
        {
          check_parameter_range(
            constants.path("E_L"), E_L, 0, 1e15, true, false);
          check_parameter_range(
            constants.path("E_T"), E_T, 0, 1e15, true, false);
          check_parameter_range(
            constants.path("G_LT"), G_LT, 0, 1e15, true, false);
          check_parameter_range(
            constants.path("nu_TT"), nu_TT, -1, 1, true, true);
          check_parameter_range(
            constants.path("nu_LT"), nu_LT, -1, 1, true, true);
        }
      if (type == Type::homogenization_summary)
        check_parameter(!summary_file.empty(),
                        summary.path("File"),
                        "the path of a homogenization summary.json when "
                        "'Materials/Type = homogenization summary'");
    }


    VoigtStiffness
    read_homogenization_stiffness(const std::string    &file,
                                  const std::string    &key,
                                  dealii::Tensor<1, 3> &c_z)
    {
      namespace pt = boost::property_tree;
      pt::ptree tree;
      {
        std::ifstream in(file);
        if (!in)
          throw InputError("Cannot read the homogenization summary '" + file
                           + "' ('Materials/Homogenization summary/File'): it "
                             "does not exist or is not readable. Run 'set "
                             "Problem = homogenization' first; it writes "
                             "OUTPUT_DIRECTORY/summary.json.");
        try
          {
            pt::read_json(in, tree);
          }
        catch (const std::exception &e)
          {
            throw InputError("The homogenization summary '" + file
                             + "' is not valid JSON: " + e.what());
          }
      }
      const auto entry = tree.get_child_optional(key);
      if (!entry || !entry->get_child_optional("C"))
        throw InputError("The homogenization summary '" + file
                         + "' has no stiffness '" + key
                         + ".C'; was it computed with that boundary "
                           "condition? Choose another 'Materials/"
                           "Homogenization summary/Boundary condition'.");
      VoigtStiffness C;
      unsigned int   i = 0;
      for (const auto &row : entry->get_child("C"))
        {
          unsigned int j = 0;
          for (const auto &value : row.second)
            {
              if (i < 3 && j < 3)
                C[i][j] = value.second.get_value<double>();
              ++j;
            }
          if (j != 3)
            i = 99;
          ++i;
        }
      if (i != 3)
        throw InputError("The stiffness '" + key + ".C' of '" + file
                         + "' is not a 3x3 array.");
      c_z = dealii::Tensor<1, 3>();
      if (const auto z = entry->get_child_optional("c_z"))
        {
          unsigned int k = 0;
          for (const auto &value : *z)
            if (k < 3)
              c_z[k++] = value.second.get_value<double>();
        }
      if (!(C[0][0] > 0 && C[1][1] > 0 && C[2][2] > 0))
        throw InputError("The stiffness '" + key + ".C' of '" + file
                         + "' is not positive definite.");
      return C;
    }
  } // namespace contact
} // namespace tribodyn
