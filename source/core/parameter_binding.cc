// Entries of a subsection written once: declared, read and range-checked
// from one list (parameter_binding.h).

#include <deal.II/base/utilities.h>
#include <stdexcept>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>

namespace tribodyn
{


  ParameterBinding::ParameterBinding(const std::string &subsection,
                                     const std::string &outer)
      : outer(outer)
  {
    std::string part;
    for (const char c : subsection + "/")
      if (c == '/')
        {
          if (!part.empty())
            subsections.push_back(part);
          part.clear();
        }
      else
        part += c;
  }


  ParameterBinding &
  ParameterBinding::add_entry(
    const std::string                              &name,
    const std::string                              &default_value,
    const std::string                              &documentation,
    const dealii::Patterns::PatternBase            &pattern,
    std::function<void(dealii::ParameterHandler &)> read,
    std::function<void()>                           check)
  {
    entries.push_back({name,
                       default_value,
                       documentation,
                       std::shared_ptr<dealii::Patterns::PatternBase>(
                         pattern.clone().release()),
                       std::move(read),
                       std::move(check)});
    return *this;
  }


  ParameterBinding &
  ParameterBinding::add(const std::string                   &name,
                        double                              &value,
                        const std::string                   &documentation,
                        const dealii::Patterns::PatternBase &pattern,
                        const std::optional<Interval>       &range)
  {
    std::function<void()> check;
    if (range)
      check = [&value, range, where = path(name)]() {
        check_parameter_range(where,
                              value,
                              range->lower,
                              range->upper,
                              range->lower_open,
                              range->upper_open,
                              range->hint);
      };
    return add_entry(
      name,
      exact_number(value),
      documentation,
      pattern,
      [&value, name](dealii::ParameterHandler &prm) {
        value = prm.get_double(name);
      },
      check);
  }


  ParameterBinding &
  ParameterBinding::add_spelled(const std::string &name,
                                double            &value,
                                const std::string &spelling,
                                const std::string &documentation,
                                const dealii::Patterns::PatternBase &pattern,
                                const std::optional<Interval>       &range)
  {
    add(name, value, documentation, pattern, range);
    Entry &e        = entries.back();
    e.default_value = spelling;
    e.on_declare    = [&value, spelling, where = path(name)]() {
      if (dealii::Utilities::string_to_double(spelling) != value)
        throw std::logic_error("The default of '" + where + "' is spelled '"
                               + spelling + "' but its member holds "
                               + exact_number(value) + ": make the two equal.");
    };
    return *this;
  }


  namespace
  {
    /// The reader of a whole number of type @p Integer.
    template <typename Integer>
    std::function<void(dealii::ParameterHandler &)>
    integer_reader(Integer &value, const std::string &name)
    {
      return [&value, name](dealii::ParameterHandler &prm) {
        value = prm.get_integer(name);
      };
    }
  } // namespace


  ParameterBinding &
  ParameterBinding::add(const std::string                   &name,
                        unsigned int                        &value,
                        const std::string                   &documentation,
                        const dealii::Patterns::PatternBase &pattern)
  {
    return add_entry(name,
                     std::to_string(value),
                     documentation,
                     pattern,
                     integer_reader(value, name),
                     {});
  }


  ParameterBinding &
  ParameterBinding::add(const std::string                   &name,
                        std::uint64_t                       &value,
                        const std::string                   &documentation,
                        const dealii::Patterns::PatternBase &pattern)
  {
    return add_entry(name,
                     std::to_string(value),
                     documentation,
                     pattern,
                     integer_reader(value, name),
                     {});
  }


  ParameterBinding &
  ParameterBinding::add(const std::string &name,
                        bool              &value,
                        const std::string &documentation)
  {
    return add_entry(name,
                     value ? "true" : "false",
                     documentation,
                     dealii::Patterns::Bool(),
                     [&value, name](dealii::ParameterHandler &prm) {
                       value = prm.get_bool(name);
                     },
                     {});
  }


  ParameterBinding &
  ParameterBinding::add(const std::string                   &name,
                        std::string                         &value,
                        const std::string                   &documentation,
                        const dealii::Patterns::PatternBase &pattern)
  {
    return add_entry(name,
                     value,
                     documentation,
                     pattern,
                     [&value, name](dealii::ParameterHandler &prm) {
                       value = prm.get(name);
                     },
                     {});
  }


  ParameterBinding &
  ParameterBinding::add(const std::string                   &name,
                        const std::string                   &default_value,
                        const std::string                   &documentation,
                        const dealii::Patterns::PatternBase &pattern,
                        const std::function<void(const std::string &)> &read)
  {
    return add_entry(name,
                     default_value,
                     documentation,
                     pattern,
                     [read, name](dealii::ParameterHandler &prm) {
                       read(prm.get(name));
                     },
                     {});
  }


  template <typename Action>
  void
  ParameterBinding::inside(dealii::ParameterHandler &prm,
                           const Action             &action) const
  {
    for (const std::string &s : subsections)
      prm.enter_subsection(s);
    try
      {
        action();
      }
    catch (...)
      {
        for (std::size_t k = 0; k < subsections.size(); ++k)
          prm.leave_subsection();
        throw;
      }
    for (std::size_t k = 0; k < subsections.size(); ++k)
      prm.leave_subsection();
  }


  ParameterBinding &
  ParameterBinding::mark_last(const char *tag, const char *mark)
  {
    if (entries.empty())
      throw std::logic_error("ParameterBinding::" + std::string(mark)
                             + "() before any entry was added.");
    entries.back().documentation += tag;
    return *this;
  }


  ParameterBinding &
  ParameterBinding::analysis_only()
  {
    return mark_last(analysis_only_tag, "analysis_only");
  }


  ParameterBinding &
  ParameterBinding::layout_only()
  {
    return mark_last(layout_only_tag, "layout_only");
  }


  void
  ParameterBinding::declare(dealii::ParameterHandler &prm) const
  {
    inside(prm, [&]() {
      for (const Entry &e : entries)
        {
          if (e.on_declare)
            e.on_declare();
          prm.declare_entry(e.name,
                            e.default_value,
                            *e.pattern,
                            e.documentation);
        }
    });
  }


  void
  ParameterBinding::parse(dealii::ParameterHandler &prm) const
  {
    inside(prm, [&]() {
      for (const Entry &e : entries)
        e.read(prm);
    });
    for (const Entry &e : entries)
      if (e.check)
        e.check();
  }


  std::string
  ParameterBinding::path(const std::string &name) const
  {
    std::string p = outer.empty() ? "" : outer + "/";
    for (const std::string &s : subsections)
      p += s + "/";
    return p + name;
  }
} // namespace tribodyn
