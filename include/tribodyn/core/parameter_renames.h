#ifndef tribodyn_core_parameter_renames_h
#define tribodyn_core_parameter_renames_h

#include <string>
#include <vector>

namespace tribodyn
{
  /**
   * The parameters, subsections and choices renamed so that one concept
   * has one name in every engine (issue #52 item 3): `Time integration`
   * (contact) is `Time` as in the automata, `Material` (contact, study)
   * is `Materials` as in homogenization and the automata, `Plane
   * velocity` is `Sliding velocity`, `Random seed` is `Seed`, and the
   * automata's friction laws `Amontons-Coulomb` and `Dieterich` are
   * `Coulomb` and `rate and state` (with the subsection `Rate and state
   * friction`) as in the contact engine. The table is in
   * parameter_renames.cc, written once; it serves two readers:
   *
   * - a parameter file with an old name is refused, and the message gives
   *   the new one (renamed_hint(), renamed_choice_hint(), used by
   *   describe_parameter_error() and set_parameter_by_path());
   * - a run written before the rename stays a run of the same parameters:
   *   a checkpoint's or a finished study scene's parameter lines are read
   *   with the current names (with_current_names()), so it resumes or is
   *   reused.
   *
   * Two subsections were replaced by a new layout rather than renamed
   * (issue #52 item 4, the materials' one scheme): 'Materials/Phases'
   * (parallel lists) and the contact pin's 'Materials/Isotropic'. A file
   * with them is refused with the new layout; a run written with them is
   * not mapped (its parameters are not the same lines).
   */

  /// For the subsection or entry @p name inside the subsection path
  /// @p parent ("" at the top level, "A/B" deeper): " ('NAME' is now called
  /// 'NEW': ...)" when it was renamed, " ('NAME' was replaced: ...)" when
  /// a new layout replaced it, "" otherwise.
  std::string
  renamed_hint(const std::string &parent, const std::string &name);

  /// For the value @p value of the entry at @p path ("Interaction/Friction
  /// law"): the same kind of hint when that choice was renamed.
  std::string
  renamed_choice_hint(const std::string &path, const std::string &value);

  /// Parameter lines "Section/Name = value" (resumable_parameter_lines())
  /// with every renamed path component and choice in its current name,
  /// sorted (deal.II prints a subsection's entries in alphabetical order,
  /// which a rename changes).
  std::vector<std::string>
  with_current_names(const std::vector<std::string> &lines);
} // namespace tribodyn

#endif
