// The states of a run's plugins (its postprocessors) kept by their
// registered names, as a checkpoint carries them (issue #52 item 2): a
// plugin finds its own state wherever it stands in the list, in every
// engine the same way.
#ifndef tribodyn_core_plugin_states_h
#define tribodyn_core_plugin_states_h

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cstddef>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tribodyn
{
  /// (name, the plugin's save() as bytes), in the run's order.
  using PluginStates = std::vector<std::pair<std::string, std::string>>;

  /// The states of @p plugins, named by @p names (PluginRegistry::
  /// create_all()).
  template <class Plugin>
  PluginStates
  save_plugin_states(const std::vector<std::unique_ptr<Plugin>> &plugins,
                     const std::vector<std::string>             &names)
  {
    PluginStates states;
    for (std::size_t k = 0; k < plugins.size(); ++k)
      {
        std::ostringstream bytes(std::ios::binary);
        {
          boost::archive::binary_oarchive ar(bytes);
          plugins[k]->save(ar);
        }
        states.emplace_back(names[k], bytes.str());
      }
    return states;
  }

  /// Give each of @p plugins its state from @p states, found by its name;
  /// a plugin without one (not in the checkpointed run) keeps its fresh
  /// state, a state without a plugin is not used.
  template <class Plugin>
  void
  load_plugin_states(const PluginStates                         &states,
                     const std::vector<std::unique_ptr<Plugin>> &plugins,
                     const std::vector<std::string>             &names)
  {
    for (std::size_t k = 0; k < plugins.size(); ++k)
      for (const auto &[name, bytes] : states)
        if (name == names[k])
          {
            std::istringstream              in(bytes);
            boost::archive::binary_iarchive ar(in);
            plugins[k]->load(ar);
          }
  }
} // namespace tribodyn

#endif
