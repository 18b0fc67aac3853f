// Postprocessor "spectrum": the amplitude spectra of the friction
// coefficient mu_global (spectrum.csv) and of the contact normal force, the
// sum of lambda_N (spectrum_normal_force.csv), over the averaging window,
// written at the end of the run (doc/theory/contact.md Sec. 5; the series:
// ContactSolver::spectrum_series()). Their peaks are the run's own figures
// (summary.json's dominant_frequency_hz, ContactSolver::summarize()).
#include <iomanip>
#include <memory>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/contact/spectrum.h>
#include <tribodyn/core/output.h>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      class Spectrum : public Postprocessor
      {
      public:
        explicit Spectrum(const PostprocessorInputs &in)
            : solver(in.solver)
            , directory(in.directory)
            , root(in.root)
        {
        }

        void
        open(const bool) override
        {
        }

        /// The spectra of all the run's samples (a resumed run's included:
        /// the solver keeps them over checkpoints), rewritten whole.
        void
        close() override
        {
          if (!root)
            return;
          const auto series = solver.spectrum_series();
          write("spectrum.csv", series.mu, series.spacing);
          write("spectrum_normal_force.csv", series.normal, series.spacing);
        }

      private:
        void
        write(const char                *file,
              const std::vector<double> &values,
              const double               spacing) const
        {
          std::ostringstream text;
          text << "frequency_hz,amplitude\n" << std::setprecision(10);
          for (const auto &f : amplitude_spectrum(values, spacing))
            text << f.first << "," << f.second << "\n";
          write_file_atomically(join_path(directory, file), text.str());
        }

        const ContactSolver &solver;
        std::string          directory;
        bool                 root;
      };

      const bool spectrum = PostprocessorRegistry::add(
        {"spectrum", 60, [](const PostprocessorInputs &in) {
           return std::make_unique<Spectrum>(in);
         }});
    } // namespace
  }   // namespace contact
} // namespace tribodyn
