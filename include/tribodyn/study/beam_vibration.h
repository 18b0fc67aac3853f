#ifndef tribodyn_study_beam_vibration_h
#define tribodyn_study_beam_vibration_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/problem.h>
#include <vector>

namespace tribodyn
{
  namespace study
  {
    /**
     * Angular frequency (rad/s) of the first bending mode of a free-free
     * Timoshenko beam of length @p L with bending stiffness @p EI, shear
     * stiffness @p kGA (kappa G A), mass per length @p rhoA and rotary
     * inertia per length @p rhoI. Solved by shooting: the state (w, theta,
     * M, V) obeys w' = theta + V/kGA, theta' = M/EI, M' = -V - rhoI w^2
     * theta, V' = -rhoA w^2 w (RK4, 4000 steps); the two solutions starting
     * from a free end (M = V = 0) give a 2 x 2 determinant of (M, V) at
     * x = L that vanishes at the eigenfrequencies (bisection to 1e-12).
     * With kGA -> infinity and rhoI = 0 this is Euler-Bernoulli's
     * 4.7300408^2 sqrt(EI / (rhoA L^4)).
     */
    double
    timoshenko_free_free_omega(const double EI,
                               const double kGA,
                               const double rhoA,
                               const double rhoI,
                               const double L);

    /// Subsection "Beam" of `set Problem = beam`.
    struct BeamParameters
    {
      double length = 40e-3, height = 4e-3;
      double youngs_modulus = 30e9, poisson_ratio = 0.2, density = 1770;
      double mesh_size = 0.25e-3;
      /// Stiffness-proportional damping beta (s).
      double damping = 1.5e-7;
      /// Peak initial transverse velocity (m/s).
      double amplitude = 0.01;
      /// Simulated time in periods of the reference frequency.
      double periods = 8;
      /// Fraction of the critical time step.
      double safety_factor = 0.9;
      /// Shear coefficient kappa of the Timoshenko reference.
      double shear_coefficient = 5. / 6.;

      /// The entries of "Beam", bound to the members above (their initial
      /// values are the defaults).
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    struct BeamResult
    {
      double frequency_hz = 0, frequency_reference_hz = 0,
             frequency_euler_bernoulli_hz = 0;
      double decay_rate = 0, damping_ratio = 0, damping_ratio_reference = 0;
      double n_dofs = 0, n_steps = 0, dt = 0, n_periods_measured = 0;
      /// The measured signal: transverse velocity of point M against time.
      std::vector<double> times, transverse_velocities;
    };

    /**
     * Free vibration of a free-free plane-strain beam (the explicit contact
     * solver, far from the plane, no load): the initial velocity is the
     * first Euler-Bernoulli free-free mode; the frequency is measured from
     * the zero crossings of the transverse velocity of the bottom node at
     * mid-length, the decay rate from a least-squares fit of the logarithm
     * of its half-period peaks. References: Timoshenko frequency (plane
     * strain: E' = E/(1 - nu^2), kappa G A, rotary inertia), and the modal
     * decay rate beta omega^2 / 2 of C = beta K (damping ratio beta omega/2).
     * Writes nothing (BeamProblem writes beam.csv from the result).
     */
    BeamResult
    run_beam_vibration(const BeamParameters &parameters, const MPI_Comm comm);

    /// `set Problem = beam`: run_beam_vibration and summary.json.
    class BeamProblem : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      BeamProblem(dealii::ParameterHandler &prm, const RunContext &context);
      void
      run() override;

    private:
      RunContext     context;
      BeamParameters parameters;
    };
  } // namespace study
} // namespace tribodyn

#endif
