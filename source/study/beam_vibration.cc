// Verification: free vibration of a free-free beam with the explicit contact
// solver, against Timoshenko beam theory and the modal damping of C = beta K
// (doc/theory/verification.md).

#include <array>
#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/study/beam_vibration.h>

namespace tribodyn
{
  namespace study
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    namespace
    {
      /// det [[M1, M2], [V1, V2]] at x = L of the two shooting solutions.
      double
      free_end_determinant(const double omega,
                           const double EI,
                           const double kGA,
                           const double rhoA,
                           const double rhoI,
                           const double L)
      {
        using State        = std::array<double, 4>; // w, theta, M, V
        const double w2    = omega * omega;
        auto         deriv = [&](const State &y) {
          return State{{y[1] + y[3] / kGA,
                        y[2] / EI,
                        -y[3] - rhoI * w2 * y[1],
                        -rhoA * w2 * y[0]}};
        };
        const unsigned int n  = 4000;
        const double       dx = L / n;
        State              end[2];
        for (unsigned int k = 0; k < 2; ++k)
          {
            State y = {{k == 0 ? 1. : 0., k == 1 ? 1. / L : 0., 0., 0.}};
            for (unsigned int i = 0; i < n; ++i)
              {
                const State k1 = deriv(y);
                State       t;
                for (unsigned int j = 0; j < 4; ++j)
                  t[j] = y[j] + 0.5 * dx * k1[j];
                const State k2 = deriv(t);
                for (unsigned int j = 0; j < 4; ++j)
                  t[j] = y[j] + 0.5 * dx * k2[j];
                const State k3 = deriv(t);
                for (unsigned int j = 0; j < 4; ++j)
                  t[j] = y[j] + dx * k3[j];
                const State k4 = deriv(t);
                for (unsigned int j = 0; j < 4; ++j)
                  y[j] += dx / 6. * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
              }
            end[k] = y;
          }
        return end[0][2] * end[1][3] - end[1][2] * end[0][3];
      }
    } // namespace


    double
    timoshenko_free_free_omega(const double EI,
                               const double kGA,
                               const double rhoA,
                               const double rhoI,
                               const double L)
    {
      const double beta_L = 4.730040744862704;
      const double omega_eb
        = beta_L * beta_L * std::sqrt(EI / (rhoA * std::pow(L, 4)));
      // Shear and rotary inertia lower the frequency: bracket in
      // [0.5, 1.01] omega_EB by a scan, then bisect.
      double       a    = 0.5 * omega_eb;
      double       fa   = free_end_determinant(a, EI, kGA, rhoA, rhoI, L);
      const double step = 0.01 * omega_eb;
      double       b = a, fb = fa;
      while (b < 1.02 * omega_eb)
        {
          b += step;
          fb = free_end_determinant(b, EI, kGA, rhoA, rhoI, L);
          if ((fa < 0) != (fb < 0))
            break;
          a  = b;
          fa = fb;
        }
      if ((fa < 0) == (fb < 0))
        throw RunError("timoshenko_free_free_omega: no root bracketed.");
      for (unsigned int i = 0; i < 200 && (b - a) > 1e-13 * b; ++i)
        {
          const double m  = 0.5 * (a + b);
          const double fm = free_end_determinant(m, EI, kGA, rhoA, rhoI, L);
          if ((fm < 0) == (fa < 0))
            {
              a  = m;
              fa = fm;
            }
          else
            b = m;
        }
      return 0.5 * (a + b);
    }


    ParameterBinding
    BeamParameters::binding()
    {
      // (three defaults spelled as the reference writes them: 40e-3, not
      // the 0.04 of exact_number())
      ParameterBinding b("Beam");
      b.add_spelled(
        "Length", length, "40e-3", "Length L (m).", Patterns::Double(0));
      b.add("Height", height, "Height H (m).", Patterns::Double(0));
      b.add_spelled("Young modulus",
                    youngs_modulus,
                    "30e9",
                    "E (Pa).",
                    Patterns::Double(0));
      b.add("Poisson ratio",
            poisson_ratio,
            "nu (plane strain).",
            Patterns::Double(-1, 0.5));
      b.add("Density", density, "rho (kg/m^3).", Patterns::Double(0));
      b.add_spelled("Mesh size",
                    mesh_size,
                    "0.25e-3",
                    "Element size h (m); L/h and H/h are rounded.",
                    Patterns::Double(0));
      b.add("Damping coefficient",
            damping,
            "beta of C = beta K (s); the first mode's damping ratio is beta "
            "omega / 2.",
            Patterns::Double(0));
      b.add("Amplitude",
            amplitude,
            "Peak initial transverse velocity (m/s).",
            Patterns::Double(0));
      b.add("Periods",
            periods,
            "Simulated time in periods of the reference frequency.",
            Patterns::Double(1));
      b.add("Safety factor",
            safety_factor,
            "Time step as a fraction of the critical one.",
            Patterns::Double(0, 1));
      b.add("Shear coefficient",
            shear_coefficient,
            "kappa of the Timoshenko reference (5/6 for a rectangular "
            "section).",
            Patterns::Double(0, 1));
      return b;
    }


    void
    BeamParameters::declare_parameters(ParameterHandler &prm)
    {
      BeamParameters().binding().declare(prm);
    }


    void
    BeamParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      // The ranges of Amplitude, Damping coefficient and Periods are checked
      // here, after the checks relating the sizes, not by the binding: the
      // refusals keep their order.
      check_parameter(length > 4 * height,
                      b.path("Length"),
                      "a beam: at least 4 times 'Beam/Height'");
      check_parameter(height >= 2 * mesh_size,
                      b.path("Mesh size"),
                      "at most half of 'Beam/Height'");
      // (the fuzzer's 1e-300 gave a mesh of no cells: an internal error)
      check_parameter(mesh_size >= height / 1000,
                      b.path("Mesh size"),
                      "at least 'Beam/Height' / 1000 (a finer mesh of a "
                      "beam is beyond this verification)");
      check_parameter_range(
        b.path("Amplitude"), amplitude, 0, 1e3, true, false);
      // Found by the parameter fuzzer (doc/stability.md): an absurd damping
      // made the critical step vanish and the run blow up at step 0; an
      // absurd number of periods ran into a wrong "too few zero crossings".
      check_parameter_range(b.path("Damping coefficient"),
                            damping,
                            0,
                            1e-3,
                            false,
                            false,
                            "It is the stiffness-proportional damping beta "
                            "(s); the critical time step shrinks as "
                            "1 / (beta omega_max^2).");
      check_parameter_range(b.path("Periods"), periods, 1, 1e4, false, false);
    }


    BeamResult
    run_beam_vibration(const BeamParameters &bp, const MPI_Comm comm)
    {
      const double L = bp.length, H = bp.height, nu = bp.poisson_ratio;
      const double E_plane = bp.youngs_modulus / (1 - nu * nu);
      const double G       = bp.youngs_modulus / (2 * (1 + nu));
      BeamResult   result;
      const double omega_ref
        = timoshenko_free_free_omega(E_plane * H * H * H / 12.,
                                     bp.shear_coefficient * G * H,
                                     bp.density * H,
                                     bp.density * H * H * H / 12.,
                                     L);
      const double beta_L           = 4.730040744862704;
      result.frequency_reference_hz = omega_ref / (2 * M_PI);
      result.frequency_euler_bernoulli_hz
        = beta_L * beta_L * std::sqrt(E_plane * H * H / 12. / bp.density)
          / (L * L) / (2 * M_PI);
      result.damping_ratio_reference = bp.damping * omega_ref / 2.;

      // The pin of the contact solver as a free beam far above the plane.
      contact::ContactParameters p;
      p.geometry.width     = L;
      p.geometry.height    = H;
      p.geometry.mesh_size = bp.mesh_size;
      p.material.type = contact::ContactMaterialParameters::Type::isotropic;
      p.material.isotropic.youngs_modulus = bp.youngs_modulus;
      p.material.isotropic.poisson_ratio  = nu;
      p.material.isotropic.density        = bp.density;
      p.loading.pressure                  = 0;
      p.loading.ramp_time                 = 0;
      p.loading.plane_velocity            = 0;
      p.loading.top_held_in_x             = false;
      p.loading.initial_gap               = 10 * H;
      p.contact.friction.select<contact::Frictionless>();
      p.time.time_step           = 1.;
      p.time.automatic_time_step = true;
      p.time.safety_factor       = bp.safety_factor;
      p.time.damping             = bp.damping;
      p.time.end_time            = bp.periods / result.frequency_reference_hz;
      p.output.average_start     = 0;
      p.output.field_interval    = 0;

      // A timer that is never printed, on MPI_COMM_SELF: its destructor
      // then needs no exchange (and prints no warning) when a stop or an
      // interruption unwinds through here.
      dealii::TimerOutput    timer(MPI_COMM_SELF,
                                std::cout,
                                dealii::TimerOutput::never,
                                dealii::TimerOutput::wall_times);
      contact::ContactSolver solver(comm, p, timer);
      solver.setup();
      // About 400 samples per period.
      p.output.sample_interval = std::max<unsigned int>(
        1,
        std::lround(
          1. / (400. * result.frequency_reference_hz * solver.time_step())));
      // First free-free Euler-Bernoulli mode as initial velocity, plane
      // sections for the axial part.
      const double k     = beta_L / L;
      const double sigma = (std::cosh(beta_L) - std::cos(beta_L))
                           / (std::sinh(beta_L) - std::sin(beta_L));
      const double A = bp.amplitude / 2.;
      solver.set_initial_velocity_field([&](const dealii::Point<2> &x) {
        const double s = k * x[0];
        const double phi
          = std::cosh(s) + std::cos(s) - sigma * (std::sinh(s) + std::sin(s));
        const double dphi = k
                            * (std::sinh(s) - std::sin(s)
                               - sigma * (std::cosh(s) + std::cos(s)));
        dealii::Tensor<1, 2> v;
        v[1] = A * phi;
        v[0] = -(x[1] - 0.5 * H) * A * dphi;
        return v;
      });
      // progress lines every 5 s: a long beam run (many periods, a fine
      // mesh) shows that it advances, with what the beam measures
      solver.set_progress_report("beam", [](const contact::Sample &s) {
        std::ostringstream key;
        key << std::scientific << std::setprecision(3) << "v_M = " << s.M_vy
            << " m/s  kinetic energy = " << s.kinetic_energy << " J";
        return key.str();
      });
      solver.run("", 5.);
      result.n_dofs  = solver.n_dofs();
      result.n_steps = solver.n_steps_done();
      result.dt      = solver.time_step();

      // Transverse velocity of the bottom node at mid-length (point M).
      const auto         &samples = solver.samples();
      std::vector<double> t, v;
      for (const auto &s : samples)
        {
          t.push_back(s.time);
          v.push_back(s.M_vy);
        }
      double mean = 0;
      for (const double x : v)
        mean += x / v.size();
      std::vector<double> crossings;
      for (std::size_t i = 1; i < v.size(); ++i)
        {
          const double a = v[i - 1] - mean, b = v[i] - mean;
          if ((a < 0) != (b < 0) && a != b)
            crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * a / (a - b));
        }
      if (crossings.size() < 6)
        throw RunError("beam vibration: fewer than 6 zero crossings; "
                       "increase 'Beam/Periods'.");
      const double half_periods = crossings.size() - 1;
      result.frequency_hz
        = half_periods / (2. * (crossings.back() - crossings.front()));
      result.n_periods_measured = half_periods / 2.;
      // Peaks between crossings; least-squares line through log|peak|,
      // skipping the first period (the higher modes that the
      // Euler-Bernoulli shape excites a little die out faster, at
      // beta omega_k^2 / 2).
      double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
      for (std::size_t c = 2; c + 1 < crossings.size(); ++c)
        {
          double best = 0, best_t = 0;
          for (std::size_t i = 0; i < v.size(); ++i)
            if (t[i] > crossings[c] && t[i] < crossings[c + 1]
                && std::abs(v[i] - mean) > best)
              {
                best   = std::abs(v[i] - mean);
                best_t = t[i];
              }
          if (best > 0)
            {
              const double y = std::log(best);
              sx += best_t;
              sy += y;
              sxx += best_t * best_t;
              sxy += best_t * y;
              n += 1;
            }
        }
      const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
      result.decay_rate  = -slope;
      result.damping_ratio
        = result.decay_rate / (2 * M_PI * result.frequency_hz);

      result.times                 = t;
      result.transverse_velocities = v;
      return result;
    }


    void
    BeamProblem::declare_parameters(ParameterHandler &prm)
    {
      BeamParameters::declare_parameters(prm);
    }


    BeamProblem::BeamProblem(ParameterHandler &prm, const RunContext &context)
        : context(context)
    {
      parameters.parse_parameters(prm);
    }


    void
    BeamProblem::run()
    {
      const auto       start = std::chrono::steady_clock::now();
      const BeamResult r
        = run_beam_vibration(parameters, context.mpi_communicator);
      // The run is done: only now is the output directory touched.
      context.claim_output();
      const bool root
        = dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator)
          == 0;
      if (root)
        {
          std::ostringstream out;
          out << "time,transverse_velocity_M\n" << std::setprecision(10);
          for (std::size_t i = 0; i < r.times.size(); ++i)
            out << r.times[i] << "," << r.transverse_velocities[i] << "\n";
          write_file_atomically(join_path(context.output_directory, "beam.csv"),
                                out.str());
        }
      const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count();
      JsonValue s       = summary_header("beam", context.mpi_communicator);
      s["frequency_hz"] = r.frequency_hz;
      s["frequency_reference_hz"]       = r.frequency_reference_hz;
      s["frequency_euler_bernoulli_hz"] = r.frequency_euler_bernoulli_hz;
      s["frequency_relative_error"]
        = r.frequency_hz / r.frequency_reference_hz - 1.;
      s["decay_rate"]              = r.decay_rate;
      s["damping_ratio"]           = r.damping_ratio;
      s["damping_ratio_reference"] = r.damping_ratio_reference;
      s["damping_ratio_relative_error"]
        = r.damping_ratio / r.damping_ratio_reference - 1.;
      s["periods_measured"] = r.n_periods_measured;
      s["n_dofs"]           = r.n_dofs;
      s["n_steps"]          = r.n_steps;
      s["dt"]               = r.dt;
      s["wall_time_s"]      = wall;
      dealii::ConditionalOStream pcout(std::cout, root);
      if (root)
        write_file_atomically(join_path(context.output_directory,
                                        "summary.json"),
                              s.dump() + "\n");
      pcout << std::setprecision(6) << "First bending frequency "
            << r.frequency_hz << " Hz (Timoshenko " << r.frequency_reference_hz
            << " Hz, Euler-Bernoulli " << r.frequency_euler_bernoulli_hz
            << " Hz); damping ratio " << r.damping_ratio
            << " (beta omega/2 = " << r.damping_ratio_reference
            << ")\nResults written to " << context.output_directory
            << "/ (summary.json, beam.csv)" << std::endl;
    }


    namespace
    {
      const bool beam_vibration_registered = register_problem(
        {"beam",
         "verification: free vibration of a free-free plane-strain beam with "
         "the explicit contact solver, against Timoshenko beam theory and the "
         "modal damping of C = beta K",
         &BeamProblem::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(new BeamProblem(prm, context));
         }});
    } // namespace
  }   // namespace study
} // namespace tribodyn
