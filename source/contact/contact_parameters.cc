#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      constexpr SelectionTable<ContactAlgorithm, 2> algorithm_choices{
        {{"node-wise", ContactAlgorithm::node_wise},
         {"projected Gauss-Seidel", ContactAlgorithm::projected_gauss_seidel}}};
      constexpr SelectionTable<RegularizationRate, 2> rate_choices{
        {{"plane speed", RegularizationRate::plane_speed},
         {"local slip rate", RegularizationRate::local_slip_rate}}};
      constexpr SelectionTable<RecontactState, 3> recontact_choices{
        {{"reset to zero", RecontactState::reset_to_zero},
         {"keep", RecontactState::keep},
         {"reset to mu sigma", RecontactState::reset_to_mu_sigma}}};
    } // namespace

    using dealii::ParameterHandler;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::List;
    using dealii::Patterns::Selection;

    namespace internal
    {
      std::vector<double>
      parse_numbers(const std::string &text,
                    const unsigned int n,
                    const std::string &name)
      {
        std::vector<double> values;
        try
          {
            values = parse_number_list(text, name);
          }
        catch (const InputError &)
          {
            values.clear();
          }
        if (values.size() != n)
          throw InputError("Parameter '" + name + "' must be a list of "
                           + std::to_string(n)
                           + " comma-separated numbers; got '" + text + "'.");
        for (const double v : values)
          if (!std::isfinite(v))
            throw InputError("Parameter '" + name
                             + "' contains a non-finite number: '" + text
                             + "'.");
        return values;
      }
    } // namespace internal


    ParameterBinding
    GeometryParameters::binding()
    {
      ParameterBinding b("Geometry");
      b.add("Width",
            width,
            "Extent of the pin along x, the sliding direction (m). Ignored "
            "for 'Materials/Type = morphology', whose pin is the "
            "morphology's rectangle.",
            Double(),
            Interval{0, 10, true, false});
      b.add("Height",
            height,
            "Extent of the pin along y (m). Ignored for 'Materials/Type = "
            "morphology'.",
            Double(),
            Interval{0, 10, true, false});
      b.add("Mesh size",
            mesh_size,
            "Target size h of the square Q1 elements (m); the mesh has "
            "round(Width/h) x round(Height/h) elements. The seed uses "
            "0.25e-3 (coarse) and 0.1e-3 (fine). Ignored for 'Materials/Type "
            "= morphology'.");
      b.add("Subdivisions per pixel",
            subdivisions_per_pixel,
            "Meso pin ('Materials/Type = morphology'): elements per "
            "morphology pixel along each axis, so that the phase boundaries "
            "lie on element edges.",
            Integer(1, 64));
      return b;
    }


    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      GeometryParameters().binding().declare(prm);
    }


    void
    GeometryParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      check_parameter_range(b.path("Mesh size"),
                            mesh_size,
                            0,
                            std::min(width, height),
                            true,
                            false,
                            "The mesh needs at least one element across the "
                            "pin ('"
                              + b.path("Width") + "' = " + format_number(width)
                              + " m, '" + b.path("Height")
                              + "' = " + format_number(height) + " m).");
      const double n_cells
        = std::round(width / mesh_size) * std::round(height / mesh_size);
      check_parameter(n_cells <= 2e8,
                      b.path("Mesh size"),
                      "a mesh of at most 2e8 elements (this one has "
                        + format_number(n_cells) + ")");
    }


    ParameterBinding
    LoadingParameters::binding()
    {
      ParameterBinding b("Loading");
      b.add("Pressure",
            pressure,
            "Pressure P on the top face (Pa), reached at the end of the "
            "ramp. The seed uses 0.5e6, 2.5e6 and 5e6.",
            Double(),
            Interval{0,
                     1e11,
                     false,
                     false,
                     "The pressure pushes the pin on the plane; it must not "
                     "be negative."});
      b.add("Ramp time",
            ramp_time,
            "Duration t_r of the smooth ramp P(t) = P (1 - cos(pi t/t_r))/2 "
            "(s); 0 applies P at once.",
            Double(0));
      b.add("Sliding velocity",
            plane_velocity,
            "Velocity V of the rigid plane along x (m/s).",
            Double(),
            Interval{-1e4, 1e4});
      b.add("Top face held in x",
            top_held_in_x,
            "Hold the top face in x; its reaction is the friction force. "
            "'false' leaves it free (a block dragged by the plane).");
      b.add("Initial velocity",
            "0, 0",
            "Initial velocity of the whole pin (m/s), x then y (e.g. '0, -1' "
            "for an impact on the plane).",
            List(Double(), 2, 2, ","),
            [this, path = b.path("Initial velocity")](const std::string &text) {
              const auto v        = internal::parse_numbers(text, 2, path);
              initial_velocity[0] = v[0];
              initial_velocity[1] = v[1];
            });
      b.add("Initial gap",
            initial_gap,
            "Initial distance between the bottom face and the plane (m).",
            Double(0));
      b.add("Sliding start time",
            plane_start_time,
            "The plane is at rest until this time (the pressure preloads the "
            "pin), then its velocity ramps to 'Sliding velocity' (s). 0: it "
            "moves from the start.",
            Double(0));
      b.add("Sliding velocity ramp time",
            plane_velocity_ramp_time,
            "Duration of the smooth ramp V(t) = V (1 - cos(pi (t - "
            "t_start)/t_v))/2 of the plane velocity (s); 0 starts the plane "
            "at V at once.",
            Double(0));
      b.add("Sliding velocity step time",
            plane_velocity_step_time,
            "At this time the plane's velocity steps at once to 'Sliding "
            "velocity after step' (s), e.g. to see the transient of "
            "rate-and-state friction. 0: no step.",
            Double(0));
      b.add("Sliding velocity after step",
            plane_velocity_after_step,
            "The plane's velocity after that step (m/s): nonzero, in the "
            "direction of 'Sliding velocity'.");
      b.add("Surface imperfection amplitude",
            imperfection_amplitude,
            "Absolute amplitude A of a waviness of the plane (m): its "
            "surface is y = -gap - A (1 - cos(2 pi xi / lambda))/2 with xi "
            "the coordinate along the moving plane. Does not scale with P, "
            "so it breaks the P/|V| invariance of the model. 0: flat plane.",
            Double(0));
      b.add("Surface imperfection wavelength",
            imperfection_wavelength,
            "Wavelength lambda of that waviness (m).",
            Double(0),
            Interval{0, 1e3, true, false});
      b.add("Initial velocity perturbation",
            velocity_perturbation,
            "Amplitude a of a uniform random initial velocity in [-a, a] "
            "added to every free dof (m/s); repeats of a study use it to "
            "sample the chaotic dynamics.",
            Double(0));
      b.add("Perturbation seed",
            perturbation_seed,
            "Seed of that random perturbation (the same seed gives the same "
            "perturbation on any number of ranks).",
            Integer(0));
      return b;
    }


    void
    LoadingParameters::declare_parameters(ParameterHandler &prm)
    {
      LoadingParameters().binding().declare(prm);
    }


    void
    LoadingParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      check_parameter_range(b.path("Surface imperfection amplitude"),
                            imperfection_amplitude,
                            0,
                            0.1 * imperfection_wavelength,
                            false,
                            false,
                            "The contact normal is taken along y: the "
                            "waviness must be shallow (amplitude at most a "
                            "tenth of the wavelength).");
      if (plane_velocity_step_time > 0)
        {
          check_parameter(plane_velocity_step_time
                            > plane_start_time + plane_velocity_ramp_time,
                          b.path("Sliding velocity step time"),
                          "a time after the plane's start and velocity ramp ("
                            + format_number(plane_start_time
                                            + plane_velocity_ramp_time)
                            + " s)");
          check_parameter(plane_velocity_after_step * plane_velocity > 0
                            && std::abs(plane_velocity_after_step) <= 1e4,
                          b.path("Sliding velocity after step"),
                          "a velocity in the direction of '"
                            + b.path("Sliding velocity")
                            + "' (friction is measured against that "
                              "direction), at most 1e4 m/s in magnitude");
        }
    }


    double
    LoadingParameters::plane_speed_maximum() const
    {
      return std::max(std::abs(plane_velocity),
                      plane_velocity_step_time > 0
                        ? std::abs(plane_velocity_after_step)
                        : 0.);
    }


    double
    LoadingParameters::plane_velocity_at(const double t) const
    {
      if (plane_velocity_step_time > 0 && t >= plane_velocity_step_time)
        return plane_velocity_after_step;
      if (t >= plane_start_time + plane_velocity_ramp_time)
        return plane_velocity;
      if (t <= plane_start_time)
        return 0.;
      return 0.5 * plane_velocity
             * (1.
                - std::cos(M_PI * (t - plane_start_time)
                           / plane_velocity_ramp_time));
    }


    double
    LoadingParameters::plane_position_at(const double t) const
    {
      if (t <= plane_start_time)
        return 0.;
      const double tv = plane_velocity_ramp_time;
      const double s  = std::min(t - plane_start_time, tv);
      double       x  = 0.5 * plane_velocity * s;
      if (tv > 0)
        x -= 0.5 * plane_velocity * tv / M_PI * std::sin(M_PI * s / tv);
      if (t > plane_start_time + tv)
        x += plane_velocity * (t - plane_start_time - tv);
      if (plane_velocity_step_time > 0 && t > plane_velocity_step_time)
        x += (plane_velocity_after_step - plane_velocity)
             * (t - plane_velocity_step_time);
      return x;
    }


    double
    LoadingParameters::pressure_at(const double t) const
    {
      if (t >= ramp_time)
        return pressure;
      if (t <= 0)
        return 0.;
      return 0.5 * pressure * (1. - std::cos(M_PI * t / ramp_time));
    }


    ParameterBinding
    TimeParameters::binding()
    {
      ParameterBinding b("Time");
      b.add("Time step",
            time_step,
            "Time step dt (s). A dt above the critical time step of the mesh "
            "is refused unless 'Automatic time step = true'.",
            Double(),
            Interval{0, 1, true, false});
      b.add("End time",
            end_time,
            "Simulated time (s).",
            Double(),
            Interval{0, 1e3, true, false});
      b.add("Beta2",
            beta2,
            "Parameter beta2 of the explicit beta2 (Newmark beta = 0, gamma "
            "= beta2) scheme, in [0.5, 1]; 0.5 is central differences, "
            "larger values add numerical dissipation.",
            Double(),
            Interval{0.5,
                     1,
                     false,
                     false,
                     "The beta2 scheme is stable and at least first order "
                     "accurate only for beta2 in [0.5, 1]."});
      b.add("Damping coefficient",
            damping,
            "beta of the stiffness-proportional damping C = beta K (s); 0 "
            "switches damping off.",
            Double(),
            Interval{0, 1});
      b.add("Automatic time step",
            automatic_time_step,
            "If true, use dt = min(Time step, safety factor x critical dt) "
            "instead of refusing an unstable dt.");
      b.add("Safety factor",
            safety_factor,
            "Fraction of the critical time step used by the automatic time "
            "step, in (0, 1].",
            Double(),
            Interval{0, 1, true, false});
      return b;
    }


    void
    TimeParameters::declare_parameters(ParameterHandler &prm)
    {
      TimeParameters().binding().declare(prm);
    }


    void
    TimeParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      const double n_steps = end_time / time_step;
      check_parameter(n_steps < 4e9,
                      b.path("End time"),
                      "fewer than 4e9 time steps (End time / Time step = "
                        + format_number(n_steps) + ")");
    }


    ParameterBinding
    ContactLawParameters::binding()
    {
      ParameterBinding b("Contact");
      b.add("Algorithm",
            algorithm,
            "How the forward-increment Lagrange multipliers are found: "
            "'node-wise' closed form (rigid plane, lumped mass: the "
            "constraints decouple), or the general projected Gauss-Seidel "
            "iteration over constraint rows (for coupled constraints; gives "
            "the same result here).",
            algorithm_choices);
      b.add("Friction coefficient",
            friction_coefficient,
            "Friction coefficient mu.",
            Double(),
            Interval{0, 10});
      b.add("Regularization time",
            regularization_time,
            "L*/|V| of the regularized law (s). The seed uses 300 time "
            "steps, 1.5e-6 s at dt = 5 ns; keep it fixed when refining dt to "
            "study convergence.",
            Double(),
            Interval{0, 1, true, false});
      b.add("Gauss-Seidel tolerance",
            pgs_tolerance,
            "Projected Gauss-Seidel: stop when the largest change of a "
            "multiplier, relative to the largest multiplier, is below this.",
            Double(),
            Interval{0, 1, true, true});
      b.add("Gauss-Seidel max iterations",
            pgs_max_iterations,
            "Projected Gauss-Seidel: iteration limit per step.",
            Integer(1, 100000));
      b.add("Regularization rate",
            regularization_rate,
            "Time constant t* of the regularized law during slip: 'plane "
            "speed': t* = L*/|V(t)| (seed eq. (4)); 'local slip rate': t* = "
            "L*/|[u']| with the node's slip rate of the previous step "
            "(Prakash-Clifton), L* = 'Regularization time' x |Sliding "
            "velocity|.",
            rate_choices);
      b.add("State on re-contact",
            recontact_state,
            "Friction state tau of the regularized law when a separated node "
            "touches the plane again: 'reset to zero' (tau starts from 0), "
            "'keep' (tau of the last contact step), 'reset to mu sigma' (tau "
            "starts at alpha mu |sigma|, Coulomb on the first step).",
            recontact_choices);
      return b;
    }


    void
    ContactLawParameters::declare_parameters(ParameterHandler &prm)
    {
      ContactLawParameters().binding().declare(prm);
      prm.enter_subsection("Contact");
      FrictionLaws::declare_parameters(prm);
      prm.leave_subsection();
    }


    void
    ContactLawParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
      prm.enter_subsection("Contact");
      friction.parse_parameters(prm, FrictionLaws::entry);
      prm.leave_subsection();
    }


    ParameterBinding
    ContactOutputParameters::binding()
    {
      ParameterBinding b("Output");
      b.add("Sample interval",
            sample_interval,
            "Record friction.csv, point_M.csv and contact_status.csv every "
            "this many time steps; the time averages and the spectrum use "
            "these samples.",
            Integer(1));
      b.add("Field interval",
            field_interval,
            "Write the VTU fields every this much simulated time (s); 0 "
            "writes none.",
            Double(0));
      b.add("Averaging start time",
            average_start,
            "Start of the window of the time averages (mu_global_mean, "
            "status fractions) and of the spectrum (s), after the transient.",
            Double(0));
      b.add("Averaging end time",
            average_end,
            "End of that window (s); negative: the end of the run.");
      b.add("Regime threshold",
            regime_threshold,
            "A status (stick, slip, separation) counts in the name of the "
            "regime when its time fraction over the window is above this "
            "(for point M, and for all the contact node-samples of the "
            "face).",
            Double(0, 1));
      b.add("Contact face interval",
            contact_face_interval,
            "Write the space-time series of the contact face "
            "(contact_face_lambda_n.csv, contact_face_lambda_t.csv, "
            "contact_face_status.csv: one row per time, one column per "
            "contact node) every this many samples; 0 writes none.",
            Integer(0));
      PostprocessorRegistry::add_selection(b,
                                           "Postprocessors",
                                           postprocessors,
                                           "outputs (files, summary keys)");
      return b;
    }


    void
    ContactOutputParameters::declare_parameters(ParameterHandler &prm)
    {
      ContactOutputParameters().binding().declare(prm);
    }


    void
    ContactOutputParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      if (average_end >= 0)
        check_parameter(average_end > average_start,
                        b.path("Averaging end time"),
                        "a time after 'Averaging start time' (or a negative "
                        "value for the end of the run)");
    }


    void
    ContactParameters::declare_parameters(ParameterHandler &prm)
    {
      GeometryParameters::declare_parameters(prm);
      ContactMaterialParameters::declare_parameters(prm);
      MorphologyParameters::declare_parameters(prm);
      LoadingParameters::declare_parameters(prm);
      TimeParameters::declare_parameters(prm);
      ContactLawParameters::declare_parameters(prm);
      ContactOutputParameters::declare_parameters(prm);
    }


    void
    ContactParameters::parse_parameters(ParameterHandler &prm,
                                        const bool        one_pin)
    {
      using Type = ContactMaterialParameters::Type;
      geometry.parse_parameters(prm);
      material.parse_parameters(prm);
      morphology.parse_parameters(prm);
      if (one_pin && material.type == Type::morphology)
        material.composite.check(morphology);
      if (one_pin && material.type == Type::isotropic)
        material.check_isotropic_pin(material.pin_index,
                                     "Materials/Pin material");
      loading.parse_parameters(prm);
      time.parse_parameters(prm);
      contact.parse_parameters(prm);
      output.parse_parameters(prm);
      if (contact.regularization_rate == RegularizationRate::local_slip_rate)
        check_parameter(
          loading.plane_velocity != 0,
          "Contact/Regularization rate",
          "'plane speed' when 'Loading/Sliding velocity' is 0 (L* "
          "= Regularization time x |V| would vanish)");
    }


    void
    ContactParameters::check_averaging_window(const bool checkpointed) const
    {
      check_parameter(checkpointed || output.average_start < time.end_time,
                      "Output/Averaging start time",
                      "a time before 'Time/End time' ("
                        + format_number(time.end_time)
                        + " s), or checkpoints (Checkpoint/Interval > 0) "
                          "when this run is the first leg of a longer one");
    }
  } // namespace contact
} // namespace tribodyn
