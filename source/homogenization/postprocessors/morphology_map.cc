// Postprocessor "morphology map" of 2D homogenization: with `Output/Write
// morphology`, the material map the cell problems solve on
// (morphology.vtu, one cell per element with its material id) and the
// morphology as a grid file (morphology.txt, readable by `Generator =
// grid file`), written once the mesh is made.
#include <memory>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/homogenization/postprocessor.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class MorphologyMap : public Postprocessor<2>
      {
      public:
        explicit MorphologyMap(const PostprocessorInputs<2> &in)
            : in(in)
        {
        }

        void
        started(std::ostream &) override
        {
          in.cell_problem.write_material_map(in.output_directory);
          if (in.root)
            in.morphology.write_grid_file(
              join_path(in.output_directory, "morphology.txt"));
        }

      private:
        const PostprocessorInputs<2> in;
      };

      const bool morphology_map_registered = PostprocessorRegistry<2>::add(
        {"morphology map",
         0,
         [](const PostprocessorInputs<2> &in)
           -> std::unique_ptr<Postprocessor<2>> {
           if (!in.parameters.output.write_morphology)
             return nullptr;
           return std::make_unique<MorphologyMap>(in);
         },
         "when Output/Write morphology = true"});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
