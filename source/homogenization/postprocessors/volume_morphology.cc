// Postprocessor "morphology" of 3D voxel volumes: with `Output/Write
// morphology`, the voxel volume the cell problems solve on as
// morphology.raw (one byte per voxel, its material id, x fastest) with its
// header morphology.hdr, readable by `Morphology/Generator = raw file`.
#include <memory>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <tribodyn/homogenization/volume_homogenization_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class VolumeMorphology : public Postprocessor<3>
      {
      public:
        explicit VolumeMorphology(const PostprocessorInputs<3> &in)
            : in(in)
        {
        }

        void
        started(std::ostream &) override
        {
          if (in.root)
            in.volume.write_raw(
              join_path(in.output_directory, "morphology.hdr"),
              join_path(in.output_directory, "morphology.raw"));
        }

      private:
        const PostprocessorInputs<3> in;
      };

      const bool volume_morphology_registered = PostprocessorRegistry<3>::add(
        {"morphology",
         0,
         [](const PostprocessorInputs<3> &in)
           -> std::unique_ptr<Postprocessor<3>> {
           if (!in.parameters.output.write_morphology)
             return nullptr;
           return std::make_unique<VolumeMorphology>(in);
         },
         "when Output/Write morphology = true"});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
