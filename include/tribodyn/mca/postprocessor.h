#ifndef tribodyn_mca_postprocessor_h
#define tribodyn_mca_postprocessor_h

#include <mpi.h>
#include <ostream>
#include <string>
#include <tribodyn/core/archive_fwd.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/postprocessor.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/parameters.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /// What a postprocessor is made from (it keeps the references).
    struct PostprocessorInputs
    {
      const AutomatonSystem &system;
      const Parameters      &parameters;
      MPI_Comm               comm;
      /// The run's output directory.
      const std::string &output_directory;
      /// Whether this is the rank that writes the files (rank 0).
      bool root;
    };

    /// The figures of the whole system at a series sample, computed once
    /// (collectively) for all postprocessors.
    struct SeriesSample
    {
      double                   time;
      const SystemEnergies    &energies;
      const std::vector<Vec3> &group_forces;
      const std::vector<Vec3> &group_displacements;
    };

    /// Save or restore (with Boost's serialization of vectors) a list of
    /// recorded series: the state of most postprocessors.
    void
    save_series(boost::archive::binary_oarchive          &ar,
                const std::vector<std::vector<double> *> &series);
    void
    load_series(boost::archive::binary_iarchive          &ar,
                const std::vector<std::vector<double> *> &series);

    /**
     * One output of an mca run (ASPECT's postprocess interface): it owns its
     * series.csv columns, its files, its summary.json keys and the state it
     * needs to continue after a checkpoint. The run loop (McaProblem) calls
     * the list of those the run needs, in their registration order; a new
     * output is one new source file that registers itself:
     *
     *   static const bool name_registered = PostprocessorRegistry::add(
     *     {"name", order, [](const PostprocessorInputs &in)
     *        -> std::unique_ptr<Postprocessor> { ... or nullptr }});
     *
     * (the flag named after the file: the library is compiled in unity
     * batches, where names at file scope must differ between files).
     *
     * Every member but the destructor has a default that does nothing. The
     * collective ones (record(), write_output(), after_step(), finish())
     * are called on every rank.
     */
    class Postprocessor : public PostprocessorBase
    {
    public:
      /// The columns of series.csv this postprocessor owns.
      virtual std::vector<std::string>
      series_columns() const
      {
        return {};
      }

      /// After every time step (e.g. the pulse's probes, which need every
      /// step to time a peak).
      virtual void
      after_step()
      {
      }
      /// Whether after_step() reads the automata (their positions,
      /// velocities): each step then ends with its second half kick
      /// (AutomatonSystem::step()) rather than leave it to the next.
      virtual bool
      reads_every_step() const
      {
        return false;
      }

      /// At each series sample: append one value per column to @p row.
      virtual void
      record(const SeriesSample &sample, std::vector<double> &row)
      {
        (void)sample;
        (void)row;
      }

      /// At the output times: write the visual outputs (VTU/PVD).
      virtual void
      write_output()
      {
      }

      /// The figure the progress line shows (e.g. "mu = 0.41"), empty for
      /// none; the value of the last record().
      virtual std::string
      key_figure() const
      {
        return {};
      }

      /// The recorded series a resumed run needs, in a fixed order: what
      /// the default save() and load() carry (most postprocessors' state).
      virtual std::vector<std::vector<double> *>
      saved_series()
      {
        return {};
      }

      /// Save and restore the state a resumed run needs (the same on every
      /// rank; the checkpoint of writer 0 is read on another rank count).
      /// Default: saved_series().
      void
      save(boost::archive::binary_oarchive &ar) const override
      {
        save_series(ar, const_cast<Postprocessor *>(this)->saved_series());
      }
      void
      load(boost::archive::binary_iarchive &ar) override
      {
        load_series(ar, saved_series());
      }

      /// A resumed run has claimed its output directory: rewrite the index
      /// files of what was written before the checkpoint.
      virtual void
      resume_outputs() const
      {
      }

      /// The run stops early (instability, signal): write what the samples
      /// so far give.
      virtual void
      write_partial_results() const
      {
      }

      /// At the end (PostprocessorBase::finish()): the files of the whole
      /// run, the summary.json keys and a line of headline figures for the
      /// screen.
    };

    using PostprocessorRegistry
      = PluginRegistry<Postprocessor, PostprocessorInputs>;

  } // namespace mca
} // namespace tribodyn

#endif
