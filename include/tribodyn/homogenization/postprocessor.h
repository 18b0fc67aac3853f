// The outputs of a 2D homogenization run as postprocessors (issue #52
// item 2; core/postprocessor.h): each registers itself from its own file
// in source/homogenization/postprocessors/ and owns its files, its rows of
// the screen table and its summary.json keys. HomogenizationProblem::run()
// solves the cell problems and calls the list: started() once the mesh is
// made, solved() after each boundary condition, finish() at the end, in
// the list's order (the order keys of their registrations). A new output
// is one file.
#ifndef tribodyn_homogenization_postprocessor_h
#define tribodyn_homogenization_postprocessor_h

#include <mpi.h>
#include <ostream>
#include <string>
#include <tribodyn/core/json.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/postprocessor.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    struct HomogenizationParameters;

    /// What a postprocessor is made from (it keeps the references: they
    /// live for the run).
    struct PostprocessorInputs
    {
      const HomogenizationParameters  &parameters;
      const Morphology                &morphology;
      const CellProblem<2>            &cell_problem;
      const std::vector<ElasticPhase> &phases;
      /// Area fraction of each phase (material id) on the mesh.
      const std::vector<double> &fractions;
      /// The run's output directory.
      const std::string &output_directory;
      MPI_Comm           comm;
      /// Whether this rank writes the files of rank 0.
      bool root;
    };

    class Postprocessor : public PostprocessorBase
    {
    public:
      /// The mesh is made and the output directory claimed: write what
      /// the morphology alone gives, and the heading of @p table (the
      /// screen's table of results).
      virtual void
      started(std::ostream &table)
      {
        (void)table;
      }

      /// Boundary condition @p result.boundary_condition was solved (in
      /// the order of `Cell problem/Boundary conditions`): its keys in
      /// @p summary, its row in @p table.
      virtual void
      solved(const CellProblemResult &result,
             JsonValue               &summary,
             std::ostream            &table)
      {
        (void)result;
        (void)summary;
        (void)table;
      }
    };

    using PostprocessorRegistry
      = PluginRegistry<Postprocessor, PostprocessorInputs>;
  } // namespace homogenization
} // namespace tribodyn

#endif
