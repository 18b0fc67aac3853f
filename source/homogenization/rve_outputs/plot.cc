// Output 'plot' of the RVE study: rve.png, drawn from rve.csv by the
// script 'RVE study/Plot script' (scripts/plot_rve; skipped when python3
// or matplotlib is missing).
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/rve_output.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class Plot : public RveOutput
      {
      public:
        void
        write(const RveResults &r, std::ostream &) const override
        {
          run_plot_script(r.parameters.plot_script,
                          "plot_rve",
                          "RVE study/Plot script",
                          r.output_directory);
        }

        std::string
        files() const override
        {
          return "rve.png";
        }
      };

      const bool rve_plot_registered = RveOutputRegistry::add(
        {"plot",
         2,
         [](const RveStudyParameters &p) -> std::unique_ptr<RveOutput> {
           if (p.plot_script == "none")
             return nullptr;
           return std::make_unique<Plot>();
         },
         "when 'RVE study/Plot script' is not none"});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
