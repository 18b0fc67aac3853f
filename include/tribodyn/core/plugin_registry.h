#ifndef tribodyn_core_plugin_registry_h
#define tribodyn_core_plugin_registry_h

#include <algorithm>
#include <deal.II/base/utilities.h>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>
#include <vector>

namespace tribodyn
{
  /// The user's choice among the plugins of a list
  /// (PluginRegistry::add_selection()): every one that applies, or the
  /// listed ones.
  struct PluginSelection
  {
    bool                     all = true;
    std::vector<std::string> names;
    /// "Subsection/Name" of the entry it was read from (messages).
    std::string path;
  };

  /**
   * Add @p entry to the list @p entries of a registry whose entries have a
   * `name` and an `order` key, keeping the list sorted by the keys and, for
   * equal keys, by the names (static initialization runs in an unspecified
   * order across files: the list is the same whatever it is). A name
   * registered twice is a programming error (std::logic_error naming
   * @p what the list holds).
   */
  template <typename Entry>
  void
  add_registered(std::vector<Entry> &entries,
                 Entry               entry,
                 const std::string  &what)
  {
    for (const Entry &e : entries)
      if (e.name == entry.name)
        throw std::logic_error("two " + what + " are registered as '"
                               + entry.name + "'");
    entries.push_back(std::move(entry));
    std::stable_sort(entries.begin(),
                     entries.end(),
                     [](const Entry &a, const Entry &b) {
                       return a.order < b.order
                              || (a.order == b.order && a.name < b.name);
                     });
  }

  /**
   * A list of plugins that register themselves from their own source files
   * (ASPECT's way): each file holds
   *
   *   static const bool name_registered = PluginRegistry<Base, Inputs>::add(
   *     {"name", order, [](const Inputs &in) { return ...; }});
   *
   * (the flag named after the file: the library is compiled in unity
   * batches, where names at file scope must differ between files)
   *
   * and create_all() makes, in the order of the `order` keys (static
   * initialization runs in an unspecified order across files, so the list
   * is sorted), every plugin whose factory returns one: a factory returns
   * nullptr when the run does not need its plugin. A new plugin touches no
   * shared file.
   *
   * The user chooses among them with one entry of the engine's parameters,
   * bound by add_selection() ("Output/Postprocessors": 'all', or a list
   * of names), and create_all() makes the chosen ones; a listed plugin
   * whose factory declines is refused with its `applies` text.
   */
  template <typename Base, typename Inputs>
  class PluginRegistry
  {
  public:
    struct Entry
    {
      std::string name;
      /// Position in the run's list (for the plugin's outputs, e.g. the
      /// order of the series columns).
      double                                               order = 0;
      std::function<std::unique_ptr<Base>(const Inputs &)> create;
      /// When the factory makes one (for the documentation and the
      /// refusal of a listed plugin that does not apply), e.g. "when
      /// Analysis/Type = friction"; empty: always.
      std::string applies = "";
    };

    using Selection = PluginSelection;

    /// Bind @p selection to the entry @p name of @p binding: 'all' or a
    /// comma-separated list of the registered names of this list (the
    /// documentation names them, with when each applies; an unknown name
    /// is refused naming the entry and the known ones). @p what says what
    /// the plugins are ("outputs").
    static void
    add_selection(ParameterBinding  &binding,
                  const std::string &name,
                  Selection         &selection,
                  const std::string &what)
    {
      std::string known;
      for (const Entry &e : entries())
        known += (known.empty() ? "" : ", ") + e.name
                 + (e.applies.empty() ? "" : " (" + e.applies + ")");
      selection.path = binding.path(name);
      binding.add(
        name,
        "all",
        "The " + what
          + " of the run: 'all' (each one that applies to it) or a "
            "comma-separated list of: "
          + known + ". A listed one that does not apply is refused.",
        dealii::Patterns::Anything(),
        [&selection, what, known](const std::string &text) {
          selection.names.clear();
          selection.all = text == "all";
          if (selection.all)
            return;
          for (const std::string &n :
               dealii::Utilities::split_string_list(text, ','))
            {
              if (std::none_of(entries().begin(),
                               entries().end(),
                               [&n](const Entry &e) { return e.name == n; }))
                throw InputError("Parameter '" + selection.path + "' lists '"
                                 + n + "', which is not one of the " + what
                                 + " of this engine. Use 'all' or names "
                                   "among: "
                                 + known + ".");
              selection.names.push_back(n);
            }
        });
    }

    /// Add @p entry; returns true (for a static initializer). A name
    /// registered twice is a programming error (std::logic_error).
    static bool
    add(Entry entry)
    {
      add_registered(entries(), std::move(entry), "plugins");
      return true;
    }

    /// The registered plugins, in order.
    static const std::vector<Entry> &
    list()
    {
      return entries();
    }

    /// The plugins this run needs, in order (of @p selection, those it
    /// lists); their registered names in @p names (for states saved by
    /// name: core/plugin_states.h). A listed plugin that does not apply
    /// to the run is refused (InputError naming the selection's entry).
    static std::vector<std::unique_ptr<Base>>
    create_all(const Inputs             &inputs,
               std::vector<std::string> &names,
               const Selection          &selection = Selection())
    {
      std::vector<std::unique_ptr<Base>> made;
      names.clear();
      for (const Entry &e : entries())
        {
          if (!selection.all
              && std::find(selection.names.begin(),
                           selection.names.end(),
                           e.name)
                   == selection.names.end())
            continue;
          if (auto plugin = e.create(inputs))
            {
              made.push_back(std::move(plugin));
              names.push_back(e.name);
            }
          else if (!selection.all)
            throw InputError("Parameter '" + selection.path + "' lists '"
                             + e.name + "', which does not apply to this run"
                             + (e.applies.empty() ? std::string()
                                                  : ": it applies " + e.applies)
                             + ". Remove it from the list, or use 'all'.");
        }
      return made;
    }

  private:
    static std::vector<Entry> &
    entries()
    {
      static std::vector<Entry> all;
      return all;
    }
  };
} // namespace tribodyn

#endif
