// A choice among laws given as a list of types (the friction laws of the
// automata and of the contact pin): the `SelectionTable` of their names,
// every law's own parameter struct, and the call of a function with the
// chosen one, so that the caller's hot loop is compiled per law (no
// run-time dispatch per item).
//
// A law type has `static constexpr const char *name` and a `struct
// Parameters` with `static void declare_parameters(prm)` and `void
// parse_parameters(prm)` (called in the subsection of the choice; a law
// with constants of its own declares a subsection for them), which
// BoundLawParameters derives from the struct's binding(): its entries
// written once.
#ifndef tribodyn_core_law_selection_h
#define tribodyn_core_law_selection_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>
#include <tuple>
#include <type_traits>
#include <utility>

namespace tribodyn
{
  /// The parameters of a law that has none of its own (or whose entries
  /// are shared, declared by the caller).
  struct NoLawParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &)
    {
    }
    void
    parse_parameters(dealii::ParameterHandler &)
    {
    }
  };

  /// The declare_parameters() and parse_parameters() of a law's
  /// parameters @p Derived from its `ParameterBinding binding()`, where
  /// each entry is written once (core/parameter_binding.h; the binding's
  /// outer subsection is the one its law list declares it in).
  template <class Derived>
  struct BoundLawParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      Derived().binding().declare(prm);
    }
    void
    parse_parameters(dealii::ParameterHandler &prm)
    {
      static_cast<Derived &>(*this).binding().parse(prm);
    }
  };

  template <class... Laws>
  struct LawSelection
  {
    static constexpr std::size_t n_laws = sizeof...(Laws);

    /// The laws' names, by index.
    static SelectionTable<unsigned int, n_laws>
    table()
    {
      return table_of(std::index_sequence_for<Laws...>());
    }

    /// The name of law @p index.
    static const char *
    name(const unsigned int index)
    {
      return table()[index].first;
    }

    /// The position of @p Law in Laws.
    template <class Law>
    static constexpr std::size_t
    index_of()
    {
      std::size_t index = 0, k = 0;
      ((std::is_same_v<Law, Laws> ? (void)(index = k) : (void)0, ++k), ...);
      return index;
    }

    /// The choice and every law's own parameters.
    struct Parameters
    {
      /// Index of the chosen law in Laws.
      unsigned int                             selected = 0;
      std::tuple<typename Laws::Parameters...> laws;

      /// Declare the entry @p entry (a selection of the laws' names,
      /// default @p default_law, documented by @p documentation followed
      /// by the list of names) and every law's parameters.
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &entry,
                         const std::string        &default_law,
                         const std::string        &documentation)
      {
        prm.declare_entry(entry,
                          default_law,
                          selection_pattern(table()),
                          documentation
                            + " Choices: " + selection_choices(table()) + ".");
        (Laws::Parameters::declare_parameters(prm), ...);
      }

      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &entry)
      {
        selected = get_selection(prm, entry, table());
        std::apply([&](auto &...p) { (p.parse_parameters(prm), ...); }, laws);
      }

      template <class Law>
      typename Law::Parameters &
      get()
      {
        return std::get<index_of<Law>()>(laws);
      }
      template <class Law>
      const typename Law::Parameters &
      get() const
      {
        return std::get<index_of<Law>()>(laws);
      }

      /// Choose @p Law (programs and tests; a parameter file chooses by
      /// name).
      template <class Law>
      void
      select()
      {
        selected = *find_selection(table(), Law::name);
      }

      template <class Law>
      bool
      is() const
      {
        return std::string(name(selected)) == Law::name;
      }

      /// The chosen law's name.
      const char *
      selected_name() const
      {
        return name(selected);
      }
    };

    /// Call @p f(std::get<I>(tuple)) for the chosen index I of a tuple
    /// with one element per law (objects or type tags).
    template <class Tuple, class F>
    static void
    with_selected(const unsigned int selected, Tuple &tuple, const F &f)
    {
      with_index(selected, tuple, f, std::index_sequence_for<Laws...>());
    }

  private:
    template <std::size_t... I>
    static SelectionTable<unsigned int, n_laws>
    table_of(std::index_sequence<I...>)
    {
      return {{{Laws::name, static_cast<unsigned int>(I)}...}};
    }

    template <class Tuple, class F, std::size_t... I>
    static void
    with_index(const unsigned int selected,
               Tuple             &tuple,
               const F           &f,
               std::index_sequence<I...>)
    {
      ((selected == I ? f(std::get<I>(tuple)) : void()), ...);
    }
  };
} // namespace tribodyn

#endif
