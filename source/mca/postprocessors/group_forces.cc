// Postprocessor "boundary groups": the force on each boundary group
// (`Boundary conditions`) and its mean displacement, six columns per group
// in series.csv ("<group>_fx", ..., "<group>_uz"), and the final forces in
// summary.json ("group_forces").
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      class GroupForces : public Postprocessor
      {
      public:
        GroupForces(const AutomatonSystem &system, const Parameters &p)
            : system(system)
            , prm(p)
        {
        }

        std::vector<std::string>
        series_columns() const override
        {
          std::vector<std::string> columns;
          for (const auto &g : prm.boundary.groups)
            for (const char *c : {"fx", "fy", "fz", "ux", "uy", "uz"})
              columns.push_back(g.name + "_" + c);
          return columns;
        }

        void
        record(const SeriesSample &s, std::vector<double> &row) override
        {
          for (unsigned int g = 0; g < s.group_forces.size(); ++g)
            {
              for (unsigned int c = 0; c < 3; ++c)
                row.push_back(s.group_forces[g][c]);
              for (unsigned int c = 0; c < 3; ++c)
                row.push_back(s.group_displacements[g][c]);
            }
        }

        void
        finish(JsonValue &summary, std::ostream &) const override
        {
          const auto forces = system.boundary_loads().reactions();
          JsonValue  groups = JsonValue::object();
          for (unsigned int g = 0; g < forces.size(); ++g)
            groups[prm.boundary.groups[g].name]
              = json_array({forces[g][0], forces[g][1], forces[g][2]});
          summary["group_forces"] = groups;
        }

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
      };


      const bool group_forces_registered = PostprocessorRegistry::add(
        {"boundary groups", 20, [](const PostprocessorInputs &in) {
           return std::make_unique<GroupForces>(in.system, in.parameters);
         }});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
