// The contact run's outputs as postprocessors (issue #20 item 1; ASPECT's
// postprocess interface, as the automata's mca/postprocessor.h): each owns
// its files, their columns, when they are flushed, and the state a resumed
// run needs to continue them (save()/load(), carried by the checkpoint by
// name). Each registers itself from its own file in
// source/contact/postprocessors/ (PluginRegistry: sorted by an order key;
// a factory returns nullptr when the run does not need it), and
// ContactSolver::run() calls the list from the common time loop
// (core/time_loop.h): a new output is one file.
//
// The samples themselves (Sample, ContactSolver::samples()) and the
// averages of the summary (ContactSolver::summarize()) are the run's
// results, read by the study and the tests: they stay with the solver.
#ifndef tribodyn_contact_postprocessor_h
#define tribodyn_contact_postprocessor_h

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <mpi.h>
#include <string>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/postprocessor.h>

namespace tribodyn
{
  namespace contact
  {
    class ContactSolver;
    struct ContactParameters;
    struct Sample;

    /// What a postprocessor's factory is given.
    struct PostprocessorInputs
    {
      ContactSolver           &solver;
      const ContactParameters &prm;
      /// The run's output directory (postprocessors are made only for runs
      /// that write one).
      std::string directory;
      MPI_Comm    comm;
      /// Whether this rank writes the files of rank 0.
      bool root;
    };

    class Postprocessor : public PostprocessorBase
    {
    public:
      /// Open the files: anew, or (@p resumed, after load()) continuing
      /// those of the checkpointed run.
      virtual void
      open(const bool resumed)
        = 0;

      /// A sample was taken (the solver's latest, complete: its
      /// mu_global and top reaction included). A sample of step n comes
      /// after after_step() of step n (core/time_loop.h).
      virtual void
      sample(const Sample &)
      {
      }

      /// Step n is done (@p time = t_n; the solver's state is that of
      /// t_{n+1}, its previous one t_n).
      virtual void
      after_step(const double /*time*/)
      {
      }

      /// Write what is buffered: @p complete at checkpoints, interruptions
      /// and the end (the files as a reader expects them), otherwise as the
      /// writer's own pace allows.
      virtual void
      flush(const bool /*complete*/)
      {
      }

      /// The end of the run (after the last flush).
      virtual void
      close()
      {
      }

      /// (PostprocessorBase: save() and load(), the state a resumed run
      /// needs to continue the files, rows written, entries of a PVD, ...;
      /// finish(), the summary.json keys, called after close() and after
      /// the run's own keys.)
    };

    using PostprocessorRegistry
      = PluginRegistry<Postprocessor, PostprocessorInputs>;
  } // namespace contact
} // namespace tribodyn

#endif
