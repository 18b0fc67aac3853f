#ifndef tribodyn_mca_mca_problem_h
#define tribodyn_mca_mca_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    /**
     * `set Problem = mca`: pack the automata, integrate the MCA equations
     * (velocity Verlet) to the end time, write series.csv, particle VTU and
     * summary.json, and the headline figures of the chosen analysis
     * (uniaxial: E, nu, sigma_y; pulse: c_p; friction: mu).
     */
    class McaProblem : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// tribodyn --partition-report N FILE.prm
      static void
      print_partition_report(dealii::ParameterHandler &prm,
                             const unsigned int        n_ranks,
                             std::ostream             &out);

      McaProblem(dealii::ParameterHandler &prm, const RunContext &context);

      void
      run() override;

    private:
      void
      run_with_timer(dealii::TimerOutput &timer);

      RunContext           context;
      Parameters           parameters;
      CheckpointParameters checkpoint;
      ResumableParameters  checkpoint_lines;
    };
  } // namespace mca
} // namespace tribodyn

#endif
