// The names of the materials and their subsections (material_names.h).
#include <algorithm>
#include <cctype>
#include <deal.II/base/utilities.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material_names.h>

namespace tribodyn
{
  std::string
  material_subsection(const std::string &name)
  {
    std::string s = name;
    if (!s.empty())
      s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
    return s;
  }


  std::string
  material_list_message(const std::vector<std::string> &names)
  {
    std::string s;
    for (const auto &n : names)
      s += (s.empty() ? "" : ", ") + n;
    return s;
  }


  std::vector<std::string>
  split_material_names(const std::string       &text,
                       const std::string       &path,
                       const MaterialNameRules &rules)
  {
    const auto names = dealii::Utilities::split_string_list(text);
    check_parameter(!names.empty(),
                    path,
                    "must name at least one material (e.g. '" + rules.example
                      + "').");
    check_parameter(
      rules.max_materials == 0 || names.size() <= rules.max_materials,
      path,
      "names " + std::to_string(names.size()) + " materials; at most "
        + std::to_string(rules.max_materials) + " are supported.");
    std::vector<std::string> seen;
    for (const auto &n : names)
      {
        std::string lower = n;
        for (char &c : lower)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        check_parameter(
          !n.empty() && n.find_first_of(" \t/") == std::string::npos
            && (rules.reserved.empty() || lower != rules.reserved),
          path,
          "'" + n
            + "' is not a material name: use letters, digits and '_' (no "
              "spaces or '/'"
            + (rules.reserved.empty()
                 ? std::string(")")
                 : "; '" + rules.reserved + "' is reserved for "
                     + rules.reserved_use + ")")
            + ".");
        check_parameter(std::find(seen.begin(), seen.end(), lower)
                          == seen.end(),
                        path,
                        "names '" + n
                          + "' twice (names differing only in case count as "
                            "the same: their subsections would coincide).");
        seen.push_back(lower);
      }
    return names;
  }


  unsigned int
  material_index(const std::vector<std::string> &names,
                 const std::string              &name,
                 const std::string              &parameter)
  {
    for (unsigned int i = 0; i < names.size(); ++i)
      if (names[i] == name)
        return i;
    throw InputError("Parameter '" + parameter + "': unknown material '" + name
                     + "'. The materials are: " + material_list_message(names)
                     + ".");
  }
} // namespace tribodyn
