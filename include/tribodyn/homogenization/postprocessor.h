// The outputs of a homogenization run as postprocessors (issue #52 item 2;
// core/postprocessor.h): each registers itself from its own file in
// source/homogenization/postprocessors/ and owns its files, its rows of the
// screen table and its summary.json keys. The 2D problem
// (HomogenizationProblem, dim = 2) and the 3D voxel volumes
// (VolumeHomogenizationProblem, dim = 3) solve their cell problems and call
// their lists: started() once the mesh is made and the output directory
// claimed, slice_planes() and solved() for each boundary condition,
// finish() at the end, closed() once summary.json is written, in the
// list's order (the order keys of the registrations). A new output is one
// file.
#ifndef tribodyn_homogenization_postprocessor_h
#define tribodyn_homogenization_postprocessor_h

#include <memory>
#include <mpi.h>
#include <ostream>
#include <string>
#include <tribodyn/core/json.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/postprocessor.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <tribodyn/homogenization/voxel_volume.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    struct HomogenizationParameters;
    struct VolumeHomogenizationParameters;

    /// What a postprocessor is made from (it keeps the references: they
    /// live for the run).
    template <int dim>
    struct PostprocessorInputs;

    /// 2D: a morphology (pixels) in plane strain.
    template <>
    struct PostprocessorInputs<2>
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

    /// 3D: a voxel volume.
    template <>
    struct PostprocessorInputs<3>
    {
      const VolumeHomogenizationParameters &parameters;
      const VoxelVolume                    &volume;
      /// The mesh's cell problems; null where the voxel grid solves them
      /// (`Cell problem/Grid`: no VTU fields then).
      const CellProblem<3> *cell_problem;
      /// The unknowns of the (non-periodic) problem.
      dealii::types::global_dof_index  n_dofs;
      const std::vector<ElasticPhase> &phases;
      /// The phases' 6 x 6 stiffnesses, by material id.
      const std::vector<VoigtMatrix6> &stiffness;
      /// Volume fraction of each phase on the mesh.
      const std::vector<double> &fractions;
      /// The keys n_voxels and voxel_size of the volume (summary.json).
      const JsonValue   &geometry;
      const std::string &output_directory;
      MPI_Comm           comm;
      bool               root;
    };

    template <int dim>
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

      /// The planes whose cell fields (of the first load case) solve()
      /// should gather for this postprocessor, for boundary condition
      /// @p bc (CellResult::slices; the lists of all postprocessors are
      /// joined).
      virtual std::vector<SlicePlane>
      slice_planes(const BoundaryCondition bc) const
      {
        (void)bc;
        return {};
      }

      /// Whether load_case_solved() is to be called: the cell problem
      /// computes every load case's cell fields only for outputs that want
      /// them.
      virtual bool
      wants_load_cases() const
      {
        return false;
      }

      /// A load case of a boundary condition was solved: its solution and
      /// cell fields (CellProblem::solve()'s observer), before solved().
      virtual void
      load_case_solved(const LoadCaseFields<dim> &fields)
      {
        (void)fields;
      }

      /// Boundary condition @p result.boundary_condition was solved (in
      /// the order of `Cell problem/Boundary conditions`): its keys in
      /// @p summary, its row in @p table.
      virtual void
      solved(const CellResult<dim> &result,
             JsonValue             &summary,
             std::ostream          &table)
      {
        (void)result;
        (void)summary;
        (void)table;
      }

      /// After summary.json is written (and the screen table shown): draw
      /// the figures from the files.
      virtual void
      closed()
      {
      }
    };

    /// The observer of CellProblem::solve() that hands each load case to
    /// the @p outputs that want it (empty when none does: no cell fields
    /// are computed).
    template <int dim>
    typename CellProblem<dim>::LoadCaseObserver
    load_case_observer(
      const std::vector<std::unique_ptr<Postprocessor<dim>>> &outputs)
    {
      std::vector<Postprocessor<dim> *> wanting;
      for (const auto &o : outputs)
        if (o->wants_load_cases())
          wanting.push_back(o.get());
      if (wanting.empty())
        return {};
      return [wanting](const LoadCaseFields<dim> &fields) {
        for (Postprocessor<dim> *o : wanting)
          o->load_case_solved(fields);
      };
    }

    template <int dim>
    using PostprocessorRegistry
      = PluginRegistry<Postprocessor<dim>, PostprocessorInputs<dim>>;
  } // namespace homogenization
} // namespace tribodyn

#endif
