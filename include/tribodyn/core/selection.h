#ifndef tribodyn_core_selection_h
#define tribodyn_core_selection_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/errors.h>
#include <utility>

namespace tribodyn
{
  /**
   * A selection parameter's choices: the text of each choice in the
   * parameter file and the enum value it stands for. One table per
   * parameter, used both to declare the entry (its Patterns::Selection) and
   * to parse it, so that the two cannot drift apart.
   */
  template <typename Enum, std::size_t N>
  using SelectionTable = std::array<std::pair<const char *, Enum>, N>;

  /// The deal.II pattern "a|b|c" of the choices of @p table.
  template <typename Enum, std::size_t N>
  dealii::Patterns::Selection
  selection_pattern(const SelectionTable<Enum, N> &table)
  {
    std::string choices;
    for (const auto &[text, value] : table)
      choices += (choices.empty() ? "" : "|") + std::string(text);
    return dealii::Patterns::Selection(choices);
  }

  /// The enum value of the selection entry @p name of the current
  /// subsection (declared with selection_pattern(@p table)).
  template <typename Enum, std::size_t N>
  Enum
  get_selection(const dealii::ParameterHandler &prm,
                const std::string              &name,
                const SelectionTable<Enum, N>  &table)
  {
    const std::string given = prm.get(name);
    for (const auto &[text, value] : table)
      if (given == text)
        return value;
    // Unreachable when the entry was declared with selection_pattern():
    // the parameter handler has already refused other text.
    throw InputError("'" + name + "' = '" + given + "' is not one of "
                     + selection_pattern(table).description() + ".");
  }
} // namespace tribodyn

#endif
