// Postprocessor "visualization": at the output times (`Output/Output
// interval`), the automata (`Output/Write particles`: particles.pvd) and a
// slab across the scene (`Output/Cross section`: cross_section.pvd, and the
// unbonded contacts in it, unbonded_pairs.pvd) as VTU files for ParaView,
// each indexed by its PVD file.
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      class Visualization : public Postprocessor
      {
      public:
        explicit Visualization(const PostprocessorInputs &in)
            : system(in.system)
            , prm(in.parameters)
            , directory(in.output_directory)
            , particles(join_path(directory, "particles.pvd"), in.root)
            , slab(join_path(directory, "cross_section.pvd"), in.root)
            , pairs(join_path(directory, "unbonded_pairs.pvd"), in.root)
        {
        }

        void
        write_output() override
        {
          const bool stress = prm.output.write_stress;
          if (prm.output.write_particles)
            particles.add(system.time(),
                          system.write_particles(
                            directory, "particles", output_number, stress));
          if (prm.output.cross_section)
            {
              const double th
                = prm.output.cross_section_thickness > 0
                    ? prm.output.cross_section_thickness
                    : 7 * prm.geometry.automaton_size / std::sqrt(2.);
              const double lo = prm.output.cross_section_position - th / 2,
                           hi = prm.output.cross_section_position + th / 2;
              const unsigned int axis = prm.output.cross_section_axis;
              slab.add(system.time(),
                       system.write_particles(directory,
                                              "cross_section",
                                              output_number,
                                              stress,
                                              true,
                                              axis,
                                              lo,
                                              hi));
              pairs.add(
                system.time(),
                system.write_unbonded_pairs(
                  directory, "unbonded_pairs", output_number, axis, lo, hi));
            }
          ++output_number;
        }

        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          ar << output_number;
          for (const PvdWriter *w : {&particles, &slab, &pairs})
            ar << w->entries();
        }

        void
        load(boost::archive::binary_iarchive &ar) override
        {
          ar >> output_number;
          for (PvdWriter *w : {&particles, &slab, &pairs})
            {
              std::vector<std::pair<double, std::string>> entries;
              ar >> entries;
              w->restore(entries);
            }
        }

        void
        resume_outputs() const override
        {
          for (const PvdWriter *w : {&particles, &slab, &pairs})
            w->write();
        }

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
        const std::string      directory;
        PvdWriter              particles, slab, pairs;
        /// the number of the next output (file names)
        unsigned int output_number = 0;
      };


      const bool visualization_registered = PostprocessorRegistry::add(
        {"visualization", 60, [](const PostprocessorInputs &in) {
           return std::make_unique<Visualization>(in);
         }});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
