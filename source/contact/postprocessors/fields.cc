// Postprocessor "fields": displacement, velocity, stresses and the contact
// status as binary VTU every `Output/Field interval` of simulated time
// (fields_NNNNN.vtu, indexed by fields.pvd for ParaView).
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/utilities.h>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/output.h>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      class Fields : public Postprocessor
      {
      public:
        Fields(const PostprocessorInputs &in)
            : solver(in.solver)
            , directory(in.directory)
            , every(in.prm.output.field_interval)
            , pvd(join_path(in.directory, "fields.pvd"), in.root)
        {
        }

        void
        open(const bool) override
        {
          pvd.restore(entries);
          pvd.write();
        }

        void
        after_step(const double time) override
        {
          if (every <= 0 || time + 0.5 * solver.time_step() < next)
            return;
          const std::string name
            = "fields_" + dealii::Utilities::int_to_string(count, 5) + ".vtu";
          solver.write_fields_of_step(directory, time, name);
          pvd.add(time, name);
          ++count;
          next += every;
        }

        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          ar << count << next << pvd.entries();
        }

        void
        load(boost::archive::binary_iarchive &ar) override
        {
          ar >> count >> next >> entries;
        }

      private:
        ContactSolver &solver;
        std::string    directory;
        double         every;
        PvdWriter      pvd;
        unsigned int   count = 0;
        double         next  = 0;
        /// The checkpointed run's entries of fields.pvd.
        std::vector<std::pair<double, std::string>> entries;
      };

      const bool fields_registered = PostprocessorRegistry::add(
        {"fields", 50, [](const PostprocessorInputs &in) {
           return std::make_unique<Fields>(in);
         }});
    } // namespace
  }   // namespace contact
} // namespace tribodyn
