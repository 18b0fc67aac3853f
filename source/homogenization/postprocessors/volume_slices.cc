// Postprocessor "slices" of 3D voxel volumes: with `Output/Write slices`,
// the mid-plane slices (normal to z, x and y) of the material ids and of
// the von Mises stress and sigma_xx of the first load case of KUBC (of the
// first condition when KUBC is not solved), gathered from all ranks into
// slices.json, and drawn at the end by `Output/Plot script`
// (scripts/plot_volume: slice_*.png, volume_slices.png).
#include <algorithm>
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
      class VolumeSlices : public Postprocessor<3>
      {
      public:
        explicit VolumeSlices(const PostprocessorInputs<3> &in)
            : in(in)
        {
          const auto &conditions
            = in.parameters.cell_problem.boundary_conditions;
          sliced = std::find(conditions.begin(),
                             conditions.end(),
                             BoundaryCondition::kubc)
                       != conditions.end()
                     ? BoundaryCondition::kubc
                     : conditions.front();
        }

        std::vector<SlicePlane>
        slice_planes(const BoundaryCondition bc) const override
        {
          std::vector<SlicePlane> planes;
          if (bc == sliced)
            for (const unsigned int axis : {2u, 0u, 1u})
              planes.push_back({axis, in.volume.n_voxels(axis) / 2});
          return planes;
        }

        void
        solved(const CellResult<3> &r, JsonValue &, std::ostream &) override
        {
          if (r.boundary_condition != sliced || !in.root)
            return;
          const char *const axis_names[3] = {"x", "y", "z"};
          JsonValue         j             = in.geometry;
          JsonValue         names         = JsonValue::array();
          for (const std::string &name : in.parameters.materials.names())
            names.push_back(name);
          j["phases"]             = names;
          j["boundary_condition"] = to_string(r.boundary_condition);
          j["load_case"]          = "xx";
          JsonValue list          = JsonValue::array();
          for (const FieldSlice &s : r.slices)
            {
              JsonValue o = JsonValue::object();
              o["axis"]   = axis_names[s.plane.axis];
              o["index"]  = s.plane.index;
              o["axes"]   = JsonValue::array();
              o["axes"].push_back(axis_names[s.axes[0]]);
              o["axes"].push_back(axis_names[s.axes[1]]);
              o["n"] = json_array({double(s.n[0]), double(s.n[1])});
              // values[a + n0 b], a along axes[0], b along axes[1]
              for (const std::string field :
                   {"material_id", "von_mises", "stress_xx"})
                {
                  const auto f
                    = std::find(s.names.begin(), s.names.end(), field)
                      - s.names.begin();
                  o[field] = json_array(s.values[f]);
                }
              list.push_back(o);
            }
          j["slices"] = list;
          write_file_atomically(join_path(in.output_directory, "slices.json"),
                                j.dump() + "\n");
        }

        void
        closed() override
        {
          if (in.root)
            run_plot_script(in.parameters.output.plot_script,
                            "plot_volume",
                            "Output/Plot script",
                            in.output_directory);
        }

      private:
        const PostprocessorInputs<3> in;
        BoundaryCondition            sliced;
      };

      const bool volume_slices_registered = PostprocessorRegistry<3>::add(
        {"slices",
         40,
         [](const PostprocessorInputs<3> &in)
           -> std::unique_ptr<Postprocessor<3>> {
           if (!in.parameters.output.write_slices)
             return nullptr;
           return std::make_unique<VolumeSlices>(in);
         },
         "when Output/Write slices = true"});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
