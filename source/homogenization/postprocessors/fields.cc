// Postprocessor "fields" of 2D and 3D homogenization: with `Output/Write
// fields`, each load case's displacement and cell fields (stresses, strains,
// von Mises, material) as VTU, indexed by fields_<BC>.pvd with the load cases
// as pseudo-times (CellProblem::write_fields(); doc/user_guide/
// homogenization.md), written as the cell problem solves them.
#include <memory>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <tribodyn/homogenization/volume_homogenization_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      /// The mesh's cell problems (3D: the voxel grid writes no fields,
      /// and 'Cell problem/Grid = auto' takes the mesh when they are asked
      /// for).
      const CellProblem<2> &
      mesh_of(const CellProblem<2> &problem)
      {
        return problem;
      }
      const CellProblem<3> &
      mesh_of(const CellProblem<3> *problem)
      {
        AssertThrow(problem != nullptr, dealii::ExcInternalError());
        return *problem;
      }

      template <int dim>
      class Fields : public Postprocessor<dim>
      {
      public:
        explicit Fields(const PostprocessorInputs<dim> &in)
            : cell_problem(mesh_of(in.cell_problem))
            , directory(in.output_directory)
        {
        }

        bool
        wants_load_cases() const override
        {
          return true;
        }

        void
        load_case_solved(const LoadCaseFields<dim> &fields) override
        {
          cell_problem.write_fields(fields, directory);
        }

      private:
        const CellProblem<dim> &cell_problem;
        std::string             directory;
      };

      template <int dim>
      bool
      register_fields()
      {
        return PostprocessorRegistry<dim>::add(
          {"fields",
           5,
           [](const PostprocessorInputs<dim> &in)
             -> std::unique_ptr<Postprocessor<dim>> {
             if (!in.parameters.output.write_fields)
               return nullptr;
             return std::make_unique<Fields<dim>>(in);
           },
           "when Output/Write fields = true"});
      }

      const bool fields_2d_registered = register_fields<2>();
      const bool fields_3d_registered = register_fields<3>();
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
