// What an output of every engine is (issue #52 item 2; ASPECT's
// postprocess interface): one file that registers itself
// (core/plugin_registry.h) and owns its files, its columns, its
// summary.json keys and the state a resumed run needs, kept by its
// registered name (core/plugin_states.h). Each engine's interface adds the
// moments it calls its outputs at: the automata's at series samples and
// visual outputs (mca/postprocessor.h), the pin's at samples and flushes
// (contact/postprocessor.h), homogenization's after each boundary
// condition is solved (homogenization/postprocessor.h).
#ifndef tribodyn_core_postprocessor_h
#define tribodyn_core_postprocessor_h

#include <ostream>
#include <tribodyn/core/archive_fwd.h>
#include <tribodyn/core/json.h>

namespace tribodyn
{
  class PostprocessorBase
  {
  public:
    virtual ~PostprocessorBase() = default;

    /// At the end of the run: its summary.json keys (added to @p summary
    /// in the list's order) and what it shows on the screen (@p figures).
    virtual void
    finish(JsonValue &summary, std::ostream &figures) const
    {
      (void)summary;
      (void)figures;
    }

    /// The state a resumed run needs to continue (the same on every rank;
    /// the checkpoint keeps it under the registered name). None by
    /// default; a run without checkpoints never calls them.
    virtual void
    save(boost::archive::binary_oarchive &) const
    {
    }
    virtual void
    load(boost::archive::binary_iarchive &)
    {
    }
  };
} // namespace tribodyn

#endif
