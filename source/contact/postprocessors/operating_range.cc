// Postprocessor "operating range": where the pin's contact works, for the
// bridge from the automata (issue #50 item 3). Every step, each contact
// node in contact adds its contact pressure p = lambda_n / (tributary
// length) and its slip rate v to a histogram of 20 logarithmic bins per
// decade (p from 1 Pa to 1e13 Pa, v from 1e-9 to 1e4 m/s, each with a bin
// below and one above); at the end operating_range.csv gives, over all the
// node-steps in contact of the run, the percentiles a friction table must
// cover (0.25 and 99.75 %: a table from the one to the other on both axes
// leaves at most 1 % of the evaluations outside) and the median, each to
// the bin's resolution (a factor 10^(1/20) = 1.12, interpolated
// geometrically within the bin), and operating_range_histogram.csv the
// histograms. Theory: doc/theory/contact.md ("Operating range").
#include <algorithm>
#include <array>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <memory>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/output.h>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      /// A histogram on logarithmic bins from 10^lowest to 10^highest, with
      /// a bin below (zero included) and a bin above.
      struct LogHistogram
      {
        static constexpr unsigned int   per_decade = 20;
        int                             lowest, highest;
        std::vector<unsigned long long> counts;

        LogHistogram(const int lowest, const int highest)
            : lowest(lowest)
            , highest(highest)
            , counts((highest - lowest) * per_decade + 2, 0)
        {
        }

        void
        add(const double x)
        {
          const double b = x > 0 ? (std::log10(x) - lowest) * per_decade : -1;
          const std::size_t k
            = b < 0 ? 0 : std::min<std::size_t>(counts.size() - 1, 1 + b);
          ++counts[k];
        }

        /// Lower edge of bin k (0 for the bin below).
        double
        edge(const std::size_t k) const
        {
          return k == 0 ? 0. : std::pow(10., lowest + (k - 1.) / per_decade);
        }

        /// The value below which a fraction @p q of the counts lie.
        double
        percentile(const double q) const
        {
          unsigned long long n = 0;
          for (const auto c : counts)
            n += c;
          const double target = q * n;
          double       below  = 0;
          for (std::size_t k = 0; k < counts.size(); ++k)
            {
              if (counts[k] > 0 && below + counts[k] >= target)
                {
                  if (k == 0)
                    return 0.;
                  if (k + 1 == counts.size())
                    return std::pow(10., highest);
                  const double t = (target - below) / counts[k];
                  return edge(k) * std::pow(10., t / per_decade);
                }
              below += counts[k];
            }
          return 0.;
        }
      };

      class OperatingRange : public Postprocessor
      {
      public:
        OperatingRange(const PostprocessorInputs &in)
            : solver(in.solver)
            , directory(in.directory)
            , comm(in.comm)
            , root(in.root)
        {
        }

        void
        open(const bool) override
        {
        }

        void
        after_step(const double) override
        {
          for (const ContactNode &node : solver.contact_node_states())
            if (node.status != separated)
              {
                pressure.add(node.lambda_n / node.length);
                slip_rate.add(node.slip_rate);
              }
        }

        /// The run's histograms (collective), on rank 0 of the resumed run.
        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          ar << total(pressure.counts) << total(slip_rate.counts);
        }
        void
        load(boost::archive::binary_iarchive &ar) override
        {
          ar >> pressure.counts >> slip_rate.counts;
          if (!root)
            {
              std::fill(pressure.counts.begin(), pressure.counts.end(), 0);
              std::fill(slip_rate.counts.begin(), slip_rate.counts.end(), 0);
            }
        }

        void
        close() override
        {
          pressure.counts  = total(pressure.counts);
          slip_rate.counts = total(slip_rate.counts);
          if (!root)
            return;
          unsigned long long n = 0;
          for (const auto c : pressure.counts)
            n += c;
          const std::array<double, 3> q = {{0.0025, 0.5, 0.9975}};
          std::ostringstream          csv;
          csv << "quantity,node_steps_in_contact,p0.25,p50,p99.75\n"
              << std::setprecision(4);
          const std::array<std::pair<const char *, const LogHistogram *>, 2>
            quantities{{{"contact_pressure_Pa", &pressure},
                        {"slip_rate_m_per_s", &slip_rate}}};
          for (const auto &[name, h] : quantities)
            {
              csv << name << "," << n;
              for (const double f : q)
                csv << "," << h->percentile(f);
              csv << "\n";
            }
          write_file_atomically(join_path(directory, "operating_range.csv"),
                                csv.str());
          std::ostringstream bins;
          bins << "quantity,bin_low,bin_high,count\n" << std::setprecision(6);
          for (const auto &[name, h] : quantities)
            for (std::size_t k = 0; k < h->counts.size(); ++k)
              if (h->counts[k] > 0)
                bins << name << "," << h->edge(k) << ","
                     << (k + 1 < h->counts.size() ? h->edge(k + 1) : INFINITY)
                     << "," << h->counts[k] << "\n";
          write_file_atomically(join_path(directory,
                                          "operating_range_histogram.csv"),
                                bins.str());
        }

      private:
        std::vector<unsigned long long>
        total(const std::vector<unsigned long long> &local) const
        {
          std::vector<unsigned long long> sum(local.size());
          MPI_Allreduce(local.data(),
                        sum.data(),
                        local.size(),
                        MPI_UNSIGNED_LONG_LONG,
                        MPI_SUM,
                        comm);
          return sum;
        }

        const ContactSolver &solver;
        std::string          directory;
        MPI_Comm             comm;
        bool                 root;
        LogHistogram         pressure{0, 13}, slip_rate{-9, 4};
      };

      const bool operating_range_registered = PostprocessorRegistry::add(
        {"operating range", 50, [](const PostprocessorInputs &in) {
           return std::make_unique<OperatingRange>(in);
         }});
    } // namespace
  }   // namespace contact
} // namespace tribodyn
