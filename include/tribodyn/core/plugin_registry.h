#ifndef tribodyn_core_plugin_registry_h
#define tribodyn_core_plugin_registry_h

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tribodyn
{
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
    };

    /// Add @p entry; returns true (for a static initializer).
    static bool
    add(Entry entry)
    {
      entries().push_back(std::move(entry));
      std::stable_sort(entries().begin(),
                       entries().end(),
                       [](const Entry &a, const Entry &b) {
                         return a.order < b.order
                                || (a.order == b.order && a.name < b.name);
                       });
      return true;
    }

    /// The registered plugins, in order.
    static const std::vector<Entry> &
    list()
    {
      return entries();
    }

    /// The plugins this run needs, in order; their registered names in
    /// @p names (for states saved by name: core/plugin_states.h).
    static std::vector<std::unique_ptr<Base>>
    create_all(const Inputs &inputs, std::vector<std::string> &names)
    {
      std::vector<std::unique_ptr<Base>> made;
      names.clear();
      for (const Entry &e : entries())
        if (auto plugin = e.create(inputs))
          {
            made.push_back(std::move(plugin));
            names.push_back(e.name);
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
