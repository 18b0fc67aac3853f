#ifndef tribodyn_core_parameter_binding_h
#define tribodyn_core_parameter_binding_h

#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <tribodyn/core/selection.h>
#include <vector>

namespace tribodyn
{
  /// The interval a numeric parameter must lie in, checked after parsing
  /// (check_parameter_range()): the ends open or closed, and a hint for
  /// the message.
  struct Interval
  {
    double      lower      = -std::numeric_limits<double>::max();
    double      upper      = std::numeric_limits<double>::max();
    bool        lower_open = false;
    bool        upper_open = false;
    std::string hint       = "";
  };

  /**
   * The entries of one subsection, each written once: its name, default,
   * pattern, documentation and range beside the member that holds its
   * value (issue #52 item 3, in the spirit of deal.II's
   * ParameterAcceptor::add_parameter, but bound to a parameter struct that
   * is declared on one object and parsed into another). A parameter struct
   * lists its entries in one function,
   *
   *   ParameterBinding LoadingParameters::binding()
   *   {
   *     ParameterBinding b("Loading");
   *     b.add("Pressure", pressure, "Pressure P ... (Pa).", Double(),
   *           Interval{0, 1e11});
   *     ...
   *     return b;
   *   }
   *
   * and uses it twice: `LoadingParameters().binding().declare(prm)` to
   * declare, with the members' initial values as the defaults (the struct's
   * initializers are the one place of a default: a struct built in code
   * and a file that leaves the entry out agree), `binding().parse(prm)` to
   * read every entry into its member and check the ranges, whose messages
   * name the full path ("Loading/Pressure") without it being typed again.
   * Checks that relate two parameters stay in the struct's
   * parse_parameters(), after the binding's parse, with path() for their
   * messages.
   *
   * A binding refers to the members of the object it was made from: it
   * must not outlive that object.
   */
  class ParameterBinding
  {
  public:
    /// The entries of @p subsection ("A/B" for a nested one, "" for the
    /// top level), entered from the subsection the handler is in when
    /// declare() and parse() are called, whose path is @p outer: "" (the
    /// top level) unless the caller is itself inside a subsection, as a
    /// law's parameters are, declared and read inside their engine's
    /// ("Interaction", "Contact").
    explicit ParameterBinding(const std::string &subsection,
                              const std::string &outer = "");

    /// A number; its default is @p value's current value, written with
    /// the fewest digits that read back to it.
    ParameterBinding &
    add(const std::string                   &name,
        double                              &value,
        const std::string                   &documentation,
        const dealii::Patterns::PatternBase &pattern
        = dealii::Patterns::Double(),
        const std::optional<Interval> &range = std::nullopt);

    /// A number whose default the reference spells as @p spelling (e.g.
    /// "40e-3", where exact_number() would write 0.04). Declaring refuses
    /// (std::logic_error) a spelling that does not read back to @p value's
    /// current value: the default written twice cannot drift.
    ParameterBinding &
    add_spelled(const std::string                   &name,
                double                              &value,
                const std::string                   &spelling,
                const std::string                   &documentation,
                const dealii::Patterns::PatternBase &pattern
                = dealii::Patterns::Double(),
                const std::optional<Interval> &range = std::nullopt);

    /// A whole number (@p pattern an Integer pattern with its bounds).
    ParameterBinding &
    add(const std::string                   &name,
        unsigned int                        &value,
        const std::string                   &documentation,
        const dealii::Patterns::PatternBase &pattern);

    /// A whole number of 64 bits (a seed).
    ParameterBinding &
    add(const std::string                   &name,
        std::uint64_t                       &value,
        const std::string                   &documentation,
        const dealii::Patterns::PatternBase &pattern);

    /// true or false.
    ParameterBinding &
    add(const std::string &name, bool &value, const std::string &documentation);

    /// Text (a file name, a list to be parsed by its owner).
    ParameterBinding &
    add(const std::string                   &name,
        std::string                         &value,
        const std::string                   &documentation,
        const dealii::Patterns::PatternBase &pattern
        = dealii::Patterns::Anything());

    /// One of the names of @p table.
    template <typename Enum, std::size_t N>
    ParameterBinding &
    add(const std::string             &name,
        Enum                          &value,
        const std::string             &documentation,
        const SelectionTable<Enum, N> &table)
    {
      return add_entry(name,
                       selection_text(table, value),
                       documentation,
                       selection_pattern(table),
                       [&value, &table, name](dealii::ParameterHandler &prm) {
                         value = get_selection(prm, name, table);
                       },
                       {});
    }

    /// An entry of another type: its default as text, and @p read, which
    /// receives the value's text (and throws InputError naming path(name)
    /// when it does not fit).
    ParameterBinding &
    add(const std::string                              &name,
        const std::string                              &default_value,
        const std::string                              &documentation,
        const dealii::Patterns::PatternBase            &pattern,
        const std::function<void(const std::string &)> &read);

    /**
     * Mark the entry added last as one that only analyses the run's record
     * after the fact (a smoothing window, a band test): changing it changes
     * no step of the run. A run resumed from a checkpoint may change it,
     * and a study re-analyses a finished scene instead of running it again
     * (resumable_parameters(), core/resumable_parameters.h). The mark is
     * analysis_only_tag at the end of the entry's documentation, so the
     * declared tree carries it and the parameter reference shows it.
     */
    ParameterBinding &
    analysis_only();

    /// What analysis_only() appends to an entry's documentation.
    static constexpr const char *analysis_only_tag
      = " [Analysis only: a resumed run may change it; a study re-analyses "
        "its finished scenes with the new value instead of running them "
        "again.]";

    /**
     * Mark the entry added last as one of how the work is laid out (the
     * order of the automata, the chunks of the pair kernel's pipeline):
     * like the number of MPI ranks, it changes a run's results at most
     * at round-off. A run resumed from a checkpoint may change it, and a
     * study reuses a finished scene run with another value as it is
     * (resumable_parameters(), core/resumable_parameters.h). The mark is
     * layout_only_tag at the end of the entry's documentation.
     */
    ParameterBinding &
    layout_only();

    /// What layout_only() appends to an entry's documentation.
    static constexpr const char *layout_only_tag
      = " [Layout only: results change at most at round-off, as on another "
        "number of MPI ranks; a resumed run may change it, and a study "
        "reuses its finished scenes run with another value.]";

    /// Declare the entries in @p prm (which is at the subsection `outer`).
    void
    declare(dealii::ParameterHandler &prm) const;

    /// Read the entries of @p prm (at the subsection `outer`) into their
    /// members, then check their ranges in the order they were added.
    void
    parse(dealii::ParameterHandler &prm) const;

    /// "Subsection/Name" of the entry @p name, for messages.
    std::string
    path(const std::string &name) const;

  private:
    /// Append @p tag to the documentation of the entry added last (the
    /// marks above; @p mark names the one asked for in the error).
    ParameterBinding &
    mark_last(const char *tag, const char *mark);

    struct Entry
    {
      std::string                                     name;
      std::string                                     default_value;
      std::string                                     documentation;
      std::shared_ptr<dealii::Patterns::PatternBase>  pattern;
      std::function<void(dealii::ParameterHandler &)> read;
      std::function<void()>                           check;
      /// Run when the entry is declared (add_spelled(): the spelling
      /// against the member).
      std::function<void()> on_declare = {};
    };

    ParameterBinding &
    add_entry(const std::string                              &name,
              const std::string                              &default_value,
              const std::string                              &documentation,
              const dealii::Patterns::PatternBase            &pattern,
              std::function<void(dealii::ParameterHandler &)> read,
              std::function<void()>                           check);

    template <typename Action>
    void
    inside(dealii::ParameterHandler &prm, const Action &action) const;

    /// The path of the subsection the handler is in (messages only).
    std::string              outer;
    std::vector<std::string> subsections;
    std::vector<Entry>       entries;
  };
} // namespace tribodyn

#endif
