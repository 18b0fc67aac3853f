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

  /// The text of @p value in @p table (the default of a selection entry).
  template <typename Enum, std::size_t N>
  std::string
  selection_text(const SelectionTable<Enum, N> &table, const Enum value)
  {
    for (const auto &[text, v] : table)
      if (v == value)
        return text;
    return table[0].first;
  }

  /// The value of the choice @p text of @p table (a word inside a list
  /// entry), or nullptr when @p text is none of them.
  template <typename Enum, std::size_t N>
  const Enum *
  find_selection(const SelectionTable<Enum, N> &table, const std::string &text)
  {
    for (const auto &entry : table)
      if (text == entry.first)
        return &entry.second;
    return nullptr;
  }

  /// "a, b or c": the choices of @p table for a message.
  template <typename Enum, std::size_t N>
  std::string
  selection_choices(const SelectionTable<Enum, N> &table)
  {
    std::string out;
    for (std::size_t i = 0; i < N; ++i)
      out += (i == 0 ? "" : (i + 1 == N ? " or " : ", "))
             + std::string(table[i].first);
    return out;
  }
} // namespace tribodyn

#endif
