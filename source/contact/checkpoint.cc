// Checkpoints of the contact solver: the state of the time loop as a Boost
// binary archive (one per rank; restored on the same number of ranks, whose
// p4est partition of the pin is the same), so that a resumed run continues
// bit for bit (doc/user_guide.md, "Checkpoints").
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/binary_object.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/errors.h>
#include <type_traits>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      constexpr unsigned int state_version = 1;

      static_assert(std::is_trivially_copyable<Sample>::value,
                    "Sample is saved as raw bytes");

      /// The owned entries of @p v.
      template <typename VectorType>
      std::vector<double>
      owned_values(const VectorType &v, const unsigned int n_owned)
      {
        return std::vector<double>(v.begin(), v.begin() + n_owned);
      }
    } // namespace


    std::string
    ContactSolver::save_state(const LoopState &loop) const
    {
      const unsigned int n_owned = mass.size();
      std::ostringstream out(std::ios::binary);
      {
        boost::archive::binary_oarchive ar(out);
        ar << state_version << n_owned << dt << step_count;
        // Solver state: the vectors the next step reads (u_n, u_{n-1},
        // p_n, w = u_n + beta p_n, a_{n-1} for the samples).
        for (const VectorType *v : {&u, &u_prev, &p, &w, &a})
          {
            const std::vector<double> values = owned_values(*v, n_owned);
            ar << values;
          }
        // Contact nodes: multipliers, friction state, status, slip rate.
        std::vector<double> nodes;
        for (const ContactNode &node : contact_nodes)
          nodes.insert(nodes.end(),
                       {node.lambda_n,
                        node.lambda_t,
                        node.tau,
                        double(node.status),
                        node.slip_rate});
        ar << nodes;
        ar << pgs_iterations_max << work_external << work_internal
           << work_contact << dissipation_friction << energy_initial
           << scale_energy;
        // The samples so far (the summary's averages and spectra).
        const std::size_t n_samples = history.size();
        ar << n_samples;
        if (n_samples > 0)
          ar << boost::serialization::make_binary_object(
            const_cast<Sample *>(history.data()), n_samples * sizeof(Sample));
        // Loop counters and outputs already written.
        ar << loop.sample_count << loop.field_count << loop.next_field
           << loop.csv_rows << loop.face_rows << loop.pvd;
      }
      return out.str();
    }


    void
    ContactSolver::load_state(const std::string &blob, LoopState &loop)
    {
      const unsigned int n_owned = mass.size();
      std::istringstream in(blob, std::ios::binary);
      try
        {
          boost::archive::binary_iarchive ar(in);
          unsigned int                    version = 0, n_saved = 0;
          double                          saved_dt = 0;
          ar >> version >> n_saved >> saved_dt >> step_count;
          if (version != state_version || n_saved != n_owned || saved_dt != dt)
            throw InputError(
              "The checkpoint does not fit this run: it holds "
              + std::to_string(n_saved) + " degrees of freedom on this rank "
              + "and a time step of " + format_number(saved_dt)
              + " s, this run has " + std::to_string(n_owned) + " and "
              + format_number(dt)
              + " s. Resume with the parameters and number of MPI ranks of "
                "the checkpointed run.");
          for (VectorType *v : {&u, &u_prev, &p, &w, &a})
            {
              std::vector<double> values;
              ar >> values;
              AssertDimension(values.size(), n_owned);
              std::copy(values.begin(), values.end(), v->begin());
            }
          std::vector<double> nodes;
          ar >> nodes;
          AssertDimension(nodes.size(), 5 * contact_nodes.size());
          for (std::size_t k = 0; k < contact_nodes.size(); ++k)
            {
              ContactNode &node = contact_nodes[k];
              node.lambda_n     = nodes[5 * k];
              node.lambda_t     = nodes[5 * k + 1];
              node.tau          = nodes[5 * k + 2];
              node.status = static_cast<ContactStatus>(int(nodes[5 * k + 3]));
              node.slip_rate = nodes[5 * k + 4];
            }
          ar >> pgs_iterations_max >> work_external >> work_internal
            >> work_contact >> dissipation_friction >> energy_initial
            >> scale_energy;
          std::size_t n_samples = 0;
          ar >> n_samples;
          history.resize(n_samples);
          if (n_samples > 0)
            ar >> boost::serialization::make_binary_object(history.data(),
                                                           n_samples
                                                             * sizeof(Sample));
          ar >> loop.sample_count >> loop.field_count >> loop.next_field
            >> loop.csv_rows >> loop.face_rows >> loop.pvd;
        }
      catch (const boost::archive::archive_exception &e)
        {
          throw InputError(std::string("The checkpoint cannot be read (")
                           + e.what()
                           + "): it is damaged or from another version of "
                             "tribodyn. Start afresh with 'Checkpoint/Resume "
                             "= false'.");
        }
      r = 0;
    }
  } // namespace contact
} // namespace tribodyn
