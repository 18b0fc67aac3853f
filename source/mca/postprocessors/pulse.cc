// Postprocessor "pulse" (`Analysis/Type = pulse`): the arrival of a pulse
// at two probe planes (the peak of the mean axial velocity of the automata
// of each plane, located by a parabola through the largest sample and its
// neighbours) and the wave speed between them, against c_p.
#include <cmath>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Arrival of a pulse at two probe planes (peak of the mean axial
      /// velocity of the automata of each plane).
      class PulseAnalysis : public Postprocessor
      {
      public:
        explicit PulseAnalysis(const PostprocessorInputs &in)
            : system(in.system)
            , prm(in.parameters)
            , comm(in.comm)
        {
        }

        bool
        reads_every_step() const override
        {
          return true;
        }

        /// The mean axial velocity of each probe layer, every step.
        void
        after_step() override
        {
          const double       t = system.time();
          const auto        &x = system.positions();
          const auto        &u = system.displacements();
          const auto        &v = system.velocities();
          const unsigned int a = prm.analysis.axis;
          const double half = prm.geometry.automaton_size * std::sqrt(2.) / 8;
          double       s[4] = {0, 0, 0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double y = x[k][a] - u[k][a];
              if (std::abs(y - prm.analysis.probe_1) < half)
                {
                  s[0] += v[k][a];
                  s[1] += 1;
                }
              if (std::abs(y - prm.analysis.probe_2) < half)
                {
                  s[2] += v[k][a];
                  s[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, s, 4, MPI_DOUBLE, MPI_SUM, comm);
          if (s[1] == 0 || s[3] == 0)
            throw InputError("Parameters 'Analysis/Probe 1' and 'Probe 2' "
                             "must lie on layers of automata (none found "
                             "within a/8 of them).");
          times.push_back(t);
          v1.push_back(s[0] / s[1]);
          v2.push_back(s[2] / s[3]);
        }

        static double
        peak_time(const std::vector<double> &t, const std::vector<double> &v)
        {
          std::size_t best = 0;
          for (std::size_t k = 0; k < v.size(); ++k)
            if (std::abs(v[k]) > std::abs(v[best]))
              best = k;
          if (best == 0 || best + 1 >= v.size())
            return t[best];
          // parabola through three points
          const double y0 = v[best - 1], y1 = v[best], y2 = v[best + 1];
          const double h   = t[best + 1] - t[best];
          const double den = y0 - 2 * y1 + y2;
          return den == 0 ? t[best] : t[best] + 0.5 * h * (y0 - y2) / den;
        }

        void
        finish(JsonValue &summary, std::ostream &out) const override
        {
          const double t1 = peak_time(times, v1), t2 = peak_time(times, v2);
          const double c
            = std::abs(prm.analysis.probe_2 - prm.analysis.probe_1) / (t2 - t1);
          summary["arrival_time_1"] = t1;
          summary["arrival_time_2"] = t2;
          summary["wave_speed"]     = c;
          const double cp
            = prm.materials[prm.geometry.bodies[0].material].p_wave_speed();
          summary["p_wave_speed_reference"] = cp;
          out << "Pulse: arrival at the probes " << t1 << " s and " << t2
              << " s, wave speed " << c
              << " m/s (c_p = sqrt((K + 4G/3)/rho) = " << cp << " m/s)"
              << std::endl;
        }

        std::vector<std::vector<double> *>
        saved_series() override
        {
          return {&times, &v1, &v2};
        }

        /// Columns of series.csv: the mean velocity along the axis of the
        /// automata of each probe layer (m/s), whose peaks time the pulse
        /// (the automata start at rest).
        std::vector<std::string>
        series_columns() const override
        {
          return {"probe_1_velocity", "probe_2_velocity"};
        }

        void
        record(const SeriesSample &, std::vector<double> &row) override
        {
          if (times.empty())
            row.insert(row.end(), {0., 0.});
          else
            row.insert(row.end(), {v1.back(), v2.back()});
        }

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
        MPI_Comm               comm;
        std::vector<double>    times, v1, v2;
      };


      const bool pulse_registered = PostprocessorRegistry::add(
        {"pulse",
         50,
         [](const PostprocessorInputs &in) -> std::unique_ptr<Postprocessor> {
           if (in.parameters.analysis.type != AnalysisParameters::Type::pulse)
             return nullptr;
           return std::make_unique<PulseAnalysis>(in);
         },
         "when Analysis/Type = pulse"});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
