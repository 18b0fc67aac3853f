// The one scheme of materials of every engine (issue #52 item 4): the
// subsection "Materials" lists the materials by name in its entry "Names",
// each material has its subsection "Materials/<Name>" (the name with its
// first letter in upper case), and whatever refers to a material (a body,
// an inclusion, a phase of a morphology, the pin) does so by its name. The
// automata's materials carry plasticity and bonds (mca/parameters.h), the
// finite elements' elastic constants (core/phase_materials.h); the names,
// their subsections and their checks are these, written once.
#ifndef tribodyn_core_material_names_h
#define tribodyn_core_material_names_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace tribodyn
{
  /// The subsection of material @p name: the name with its first letter in
  /// upper case (steel: "Steel", matrix: "Matrix").
  std::string
  material_subsection(const std::string &name);

  /// "a, b, c": the names for a message.
  std::string
  material_list_message(const std::vector<std::string> &names);

  /// What an engine's list of names allows beyond the common rules.
  struct MaterialNameRules
  {
    /// A list for the message of an empty one, e.g. "steel, carbon".
    std::string example;
    /// A name no material may have (lower case; "" for none), and why.
    std::string reserved, reserved_use;
    /// The most materials an engine supports (0: no limit).
    unsigned int max_materials = 0;
  };

  /**
   * The names of the text @p text of the entry @p path ("Materials/Names"),
   * checked: at least one; none twice (names differing only in case count
   * as the same, their subsections would coincide); none empty or with
   * spaces or '/'; not the reserved name of @p rules. InputError naming
   * @p path otherwise.
   */
  std::vector<std::string>
  split_material_names(const std::string       &text,
                       const std::string       &path,
                       const MaterialNameRules &rules);

  /// The index of material @p name in @p names, or InputError naming the
  /// parameter @p parameter that refers to it and the materials there are.
  unsigned int
  material_index(const std::vector<std::string> &names,
                 const std::string              &name,
                 const std::string              &parameter);
} // namespace tribodyn

#endif
