// Subsection "Materials" of the contact problem and the stiffnesses it
// builds: transversely isotropic constants, homogenization summaries.
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/selection.h>

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

    void
    ContactMaterialParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      prm.declare_entry(
        "Type",
        "isotropic",
        selection_pattern(type_choices),
        "Constitutive model of the pin. 'isotropic': subsection Isotropic. "
        "'anisotropic': the plane-strain stiffness of subsection "
        "Anisotropic. 'engineering constants': transversely isotropic with "
        "axis L = x (subsection Engineering constants, defaults = seed "
        "Table 1 homogenized values). 'homogenization summary': the apparent "
        "stiffness C of a homogenization run's summary.json. 'morphology': a "
        "heterogeneous (meso) pin from subsection Morphology with the phases "
        "of subsections Matrix and Heterogeneity.");
      prm.declare_entry("Kinematics",
                        "small strain",
                        selection_pattern(kinematics_choices),
                        "'small strain': linear elasticity. 'large "
                        "deformation': total Lagrangian, St Venant-Kirchhoff "
                        "(S = C:E with the Green-Lagrange strain E).");
      prm.declare_entry("Density",
                        "1770",
                        Double(),
                        "Density (kg/m^3) of the homogeneous anisotropic "
                        "materials (types anisotropic, engineering constants, "
                        "homogenization summary).");
      prm.enter_subsection("Isotropic");
      IsotropicElasticMaterial::declare_parameters(prm, 30e9, 0.2, 1770.);
      prm.leave_subsection();
      prm.enter_subsection("Anisotropic");
      prm.declare_entry("Stiffness",
                        "33.33e9, 8.33e9, 0, 8.33e9, 33.33e9, 0, 0, 0, 12.5e9",
                        List(Double(), 9, 9, ","),
                        "Plane-strain stiffness C (Pa), 9 numbers row by row, "
                        "Voigt order (xx, yy, xy) with the engineering shear "
                        "strain: sigma = C (eps_xx, eps_yy, gamma_xy).");
      prm.declare_entry("Out-of-plane stiffness",
                        "8.33e9, 8.33e9, 0",
                        List(Double(), 3, 3, ","),
                        "Row c_z with sigma_zz = c_z . (eps_xx, eps_yy, "
                        "gamma_xy) (Pa); used only for the von Mises output.");
      prm.leave_subsection();
      prm.enter_subsection("Engineering constants");
      prm.declare_entry("E_L",
                        "31.9e9",
                        Double(),
                        "Young modulus along x (Pa).");
      prm.declare_entry("E_T",
                        "34e9",
                        Double(),
                        "Young modulus along y, z (Pa).");
      prm.declare_entry("nu_LT", "0.2", Double(), "Poisson ratio nu_LT.");
      prm.declare_entry("nu_TT", "0.2", Double(), "Poisson ratio nu_TT'.");
      prm.declare_entry("G_LT", "13.3e9", Double(), "Shear modulus G_LT (Pa).");
      prm.leave_subsection();
      prm.enter_subsection("Homogenization summary");
      prm.declare_entry("File",
                        "",
                        dealii::Patterns::Anything(),
                        "summary.json written by a 'set Problem = "
                        "homogenization' run.");
      prm.declare_entry("Boundary condition",
                        "KUBC",
                        Selection("KUBC|SUBC|periodic"),
                        "Which apparent stiffness of the file to use.");
      prm.leave_subsection();
      TwoPhaseMaterials::declare_parameters(prm);
      prm.leave_subsection();
    }


    void
    ContactMaterialParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      type       = get_selection(prm, "Type", type_choices);
      kinematics = get_selection(prm, "Kinematics", kinematics_choices);
      density    = prm.get_double("Density");
      check_parameter_range("Materials/Density", density, 0, 1e6, true, false);
      prm.enter_subsection("Isotropic");
      isotropic.parse_parameters(prm, "Materials/Isotropic");
      prm.leave_subsection();
      prm.enter_subsection("Anisotropic");
      {
        const auto c
          = internal::parse_numbers(prm.get("Stiffness"),
                                    9,
                                    "Materials/Anisotropic/Stiffness");
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            anisotropic_stiffness[i][j] = c[3 * i + j];
        const auto z
          = internal::parse_numbers(prm.get("Out-of-plane stiffness"),
                                    3,
                                    "Materials/Anisotropic/Out-of-plane "
                                    "stiffness");
        for (unsigned int i = 0; i < 3; ++i)
          anisotropic_c_z[i] = z[i];
      }
      prm.leave_subsection();
      prm.enter_subsection("Engineering constants");
      E_L   = prm.get_double("E_L");
      E_T   = prm.get_double("E_T");
      nu_LT = prm.get_double("nu_LT");
      nu_TT = prm.get_double("nu_TT");
      G_LT  = prm.get_double("G_LT");
      prm.leave_subsection();
      prm.enter_subsection("Homogenization summary");
      summary_file = prm.get("File");
      summary_key  = prm.get("Boundary condition");
      prm.leave_subsection();
      composite.parse_parameters(prm, "Materials");
      prm.leave_subsection();

      if (type == Type::engineering_constants)
        {
          const std::string s = "Materials/Engineering constants/";
          check_parameter_range(s + "E_L", E_L, 0, 1e15, true, false);
          check_parameter_range(s + "E_T", E_T, 0, 1e15, true, false);
          check_parameter_range(s + "G_LT", G_LT, 0, 1e15, true, false);
          check_parameter_range(s + "nu_TT", nu_TT, -1, 1, true, true);
          check_parameter_range(s + "nu_LT", nu_LT, -1, 1, true, true);
        }
      if (type == Type::homogenization_summary)
        check_parameter(!summary_file.empty(),
                        "Materials/Homogenization summary/File",
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
