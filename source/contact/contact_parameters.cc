#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/number_list.h>
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


    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Width",
                        "28e-3",
                        Double(),
                        "Extent of the pin along x, the sliding direction (m). "
                        "Ignored for 'Materials/Type = morphology', whose pin "
                        "is the morphology's rectangle.");
      prm.declare_entry("Height",
                        "8e-3",
                        Double(),
                        "Extent of the pin along y (m). Ignored for "
                        "'Materials/Type = morphology'.");
      prm.declare_entry("Mesh size",
                        "0.25e-3",
                        Double(),
                        "Target size h of the square Q1 elements (m); the mesh "
                        "has round(Width/h) x round(Height/h) elements. The "
                        "seed uses 0.25e-3 (coarse) and 0.1e-3 (fine). "
                        "Ignored for 'Materials/Type = morphology'.");
      prm.declare_entry(
        "Subdivisions per pixel",
        "1",
        Integer(1, 64),
        "Meso pin ('Materials/Type = morphology'): elements per "
        "morphology pixel along each axis, so that the phase "
        "boundaries lie on element edges.");
      prm.leave_subsection();
    }


    void
    GeometryParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      width                  = prm.get_double("Width");
      height                 = prm.get_double("Height");
      mesh_size              = prm.get_double("Mesh size");
      subdivisions_per_pixel = prm.get_integer("Subdivisions per pixel");
      prm.leave_subsection();
      check_parameter_range("Geometry/Width", width, 0, 10, true, false);
      check_parameter_range("Geometry/Height", height, 0, 10, true, false);
      check_parameter_range("Geometry/Mesh size",
                            mesh_size,
                            0,
                            std::min(width, height),
                            true,
                            false,
                            "The mesh needs at least one element across the "
                            "pin ('Geometry/Width' = "
                              + format_number(width)
                              + " m, 'Geometry/Height' = "
                              + format_number(height) + " m).");
      const double n_cells
        = std::round(width / mesh_size) * std::round(height / mesh_size);
      check_parameter(n_cells <= 2e8,
                      "Geometry/Mesh size",
                      "a mesh of at most 2e8 elements (this one has "
                        + format_number(n_cells) + ")");
    }


    void
    LoadingParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      prm.declare_entry("Pressure",
                        "0.5e6",
                        Double(),
                        "Pressure P on the top face (Pa), reached at the end "
                        "of the ramp. The seed uses 0.5e6, 2.5e6 and 5e6.");
      prm.declare_entry("Ramp time",
                        "10e-6",
                        Double(0),
                        "Duration t_r of the smooth ramp P(t) = P (1 - "
                        "cos(pi t/t_r))/2 (s); 0 applies P at once.");
      prm.declare_entry("Sliding velocity",
                        "-2",
                        Double(),
                        "Velocity V of the rigid plane along x (m/s).");
      prm.declare_entry("Top face held in x",
                        "true",
                        Bool(),
                        "Hold the top face in x; its reaction is the "
                        "friction force. 'false' leaves it free (a block "
                        "dragged by the plane).");
      prm.declare_entry("Initial velocity",
                        "0, 0",
                        List(Double(), 2, 2, ","),
                        "Initial velocity of the whole pin (m/s), x then y "
                        "(e.g. '0, -1' for an impact on the plane).");
      prm.declare_entry("Initial gap",
                        "0",
                        Double(0),
                        "Initial distance between the bottom face and the "
                        "plane (m).");
      prm.declare_entry("Sliding start time",
                        "0",
                        Double(0),
                        "The plane is at rest until this time (the pressure "
                        "preloads the pin), then its velocity ramps to "
                        "'Sliding velocity' (s). 0: it moves from the start.");
      prm.declare_entry("Sliding velocity ramp time",
                        "0",
                        Double(0),
                        "Duration of the smooth ramp V(t) = V (1 - cos(pi "
                        "(t - t_start)/t_v))/2 of the plane velocity (s); 0 "
                        "starts the plane at V at once.");
      prm.declare_entry("Sliding velocity step time",
                        "0",
                        Double(0),
                        "At this time the plane's velocity steps at once to "
                        "'Sliding velocity after step' (s), e.g. to see the "
                        "transient of rate-and-state friction. 0: no step.");
      prm.declare_entry("Sliding velocity after step",
                        "-2",
                        Double(),
                        "The plane's velocity after that step (m/s): "
                        "nonzero, in the direction of 'Sliding velocity'.");
      prm.declare_entry("Surface imperfection amplitude",
                        "0",
                        Double(0),
                        "Absolute amplitude A of a waviness of the plane (m): "
                        "its surface is y = -gap - A (1 - cos(2 pi xi / "
                        "lambda))/2 with xi the coordinate along the moving "
                        "plane. Does not scale with P, so it breaks the P/|V| "
                        "invariance of the model. 0: flat plane.");
      prm.declare_entry("Surface imperfection wavelength",
                        "2e-3",
                        Double(0),
                        "Wavelength lambda of that waviness (m).");
      prm.declare_entry("Initial velocity perturbation",
                        "0",
                        Double(0),
                        "Amplitude a of a uniform random initial velocity in "
                        "[-a, a] added to every free dof (m/s); repeats of a "
                        "study use it to sample the chaotic dynamics.");
      prm.declare_entry("Perturbation seed",
                        "1",
                        Integer(0),
                        "Seed of that random perturbation (the same seed "
                        "gives the same perturbation on any number of "
                        "ranks).");
      prm.leave_subsection();
    }


    void
    LoadingParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      pressure            = prm.get_double("Pressure");
      ramp_time           = prm.get_double("Ramp time");
      plane_velocity      = prm.get_double("Sliding velocity");
      top_held_in_x       = prm.get_bool("Top face held in x");
      const auto v        = internal::parse_numbers(prm.get("Initial velocity"),
                                             2,
                                             "Loading/Initial velocity");
      initial_velocity[0] = v[0];
      initial_velocity[1] = v[1];
      initial_gap         = prm.get_double("Initial gap");
      plane_start_time    = prm.get_double("Sliding start time");
      plane_velocity_ramp_time  = prm.get_double("Sliding velocity ramp time");
      plane_velocity_step_time  = prm.get_double("Sliding velocity step time");
      plane_velocity_after_step = prm.get_double("Sliding velocity after step");
      imperfection_amplitude = prm.get_double("Surface imperfection amplitude");
      imperfection_wavelength
        = prm.get_double("Surface imperfection wavelength");
      velocity_perturbation = prm.get_double("Initial velocity perturbation");
      perturbation_seed     = prm.get_integer("Perturbation seed");
      prm.leave_subsection();
      check_parameter_range("Loading/Surface imperfection wavelength",
                            imperfection_wavelength,
                            0,
                            1e3,
                            true,
                            false);
      check_parameter_range("Loading/Surface imperfection amplitude",
                            imperfection_amplitude,
                            0,
                            0.1 * imperfection_wavelength,
                            false,
                            false,
                            "The contact normal is taken along y: the "
                            "waviness must be shallow (amplitude at most a "
                            "tenth of the wavelength).");
      check_parameter_range("Loading/Pressure",
                            pressure,
                            0,
                            1e11,
                            false,
                            false,
                            "The pressure pushes the pin on the plane; it "
                            "must not be negative.");
      check_parameter_range(
        "Loading/Sliding velocity", plane_velocity, -1e4, 1e4, false, false);
      if (plane_velocity_step_time > 0)
        {
          check_parameter(plane_velocity_step_time
                            > plane_start_time + plane_velocity_ramp_time,
                          "Loading/Sliding velocity step time",
                          "a time after the plane's start and velocity ramp ("
                            + format_number(plane_start_time
                                            + plane_velocity_ramp_time)
                            + " s)");
          check_parameter(plane_velocity_after_step * plane_velocity > 0
                            && std::abs(plane_velocity_after_step) <= 1e4,
                          "Loading/Sliding velocity after step",
                          "a velocity in the direction of 'Loading/Sliding "
                          "velocity' (friction is measured against that "
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


    void
    TimeParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      prm.declare_entry("Time step",
                        "5e-9",
                        Double(),
                        "Time step dt (s). A dt above the critical time step "
                        "of the mesh is refused unless 'Automatic time step = "
                        "true'.");
      prm.declare_entry("End time", "100e-6", Double(), "Simulated time (s).");
      prm.declare_entry("Beta2",
                        "0.5",
                        Double(),
                        "Parameter beta2 of the explicit beta2 (Newmark beta "
                        "= 0, gamma = beta2) scheme, in [0.5, 1]; 0.5 is "
                        "central differences, larger values add numerical "
                        "dissipation.");
      prm.declare_entry("Damping coefficient",
                        "1.1e-9",
                        Double(),
                        "beta of the stiffness-proportional damping C = beta "
                        "K (s); 0 switches damping off.");
      prm.declare_entry("Automatic time step",
                        "false",
                        Bool(),
                        "If true, use dt = min(Time step, safety factor x "
                        "critical dt) instead of refusing an unstable dt.");
      prm.declare_entry("Safety factor",
                        "0.9",
                        Double(),
                        "Fraction of the critical time step used by the "
                        "automatic time step, in (0, 1].");
      prm.leave_subsection();
    }


    void
    TimeParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      time_step           = prm.get_double("Time step");
      end_time            = prm.get_double("End time");
      beta2               = prm.get_double("Beta2");
      damping             = prm.get_double("Damping coefficient");
      automatic_time_step = prm.get_bool("Automatic time step");
      safety_factor       = prm.get_double("Safety factor");
      prm.leave_subsection();
      check_parameter_range("Time/Time step", time_step, 0, 1, true, false);
      check_parameter_range("Time/End time", end_time, 0, 1e3, true, false);
      check_parameter_range("Time/Beta2",
                            beta2,
                            0.5,
                            1,
                            false,
                            false,
                            "The beta2 scheme is stable and at least first "
                            "order accurate only for beta2 in [0.5, 1].");
      check_parameter_range(
        "Time/Damping coefficient", damping, 0, 1, false, false);
      check_parameter_range(
        "Time/Safety factor", safety_factor, 0, 1, true, false);
      const double n_steps = end_time / time_step;
      check_parameter(n_steps < 4e9,
                      "Time/End time",
                      "fewer than 4e9 time steps (End time / Time step = "
                        + format_number(n_steps) + ")");
    }


    void
    ContactLawParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry("Algorithm",
                        "node-wise",
                        selection_pattern(algorithm_choices),
                        "How the forward-increment Lagrange multipliers are "
                        "found: 'node-wise' closed form (rigid plane, lumped "
                        "mass: the constraints decouple), or the general "
                        "projected Gauss-Seidel iteration over constraint "
                        "rows (for coupled constraints; gives the same result "
                        "here).");
      FrictionLaws::declare_parameters(prm);
      prm.declare_entry("Friction coefficient",
                        "0.25",
                        Double(),
                        "Friction coefficient mu.");
      prm.declare_entry("Regularization time",
                        "1.5e-6",
                        Double(),
                        "L*/|V| of the regularized law (s). The seed uses 300 "
                        "time steps, 1.5e-6 s at dt = 5 ns; keep it fixed "
                        "when refining dt to study convergence.");
      prm.declare_entry("Gauss-Seidel tolerance",
                        "1e-12",
                        Double(),
                        "Projected Gauss-Seidel: stop when the largest change "
                        "of a multiplier, relative to the largest multiplier, "
                        "is below this.");
      prm.declare_entry("Gauss-Seidel max iterations",
                        "50",
                        Integer(1, 100000),
                        "Projected Gauss-Seidel: iteration limit per step.");
      prm.declare_entry("Regularization rate",
                        "plane speed",
                        selection_pattern(rate_choices),
                        "Time constant t* of the regularized law during slip: "
                        "'plane speed': t* = L*/|V(t)| (seed eq. (4)); 'local "
                        "slip rate': t* = L*/|[u']| with the node's slip rate "
                        "of the previous step (Prakash-Clifton), L* = "
                        "'Regularization time' x |Sliding velocity|.");
      prm.declare_entry("State on re-contact",
                        "reset to zero",
                        selection_pattern(recontact_choices),
                        "Friction state tau of the regularized law when a "
                        "separated node touches the plane again: 'reset to "
                        "zero' (tau starts from 0), 'keep' (tau of the last "
                        "contact step), 'reset to mu sigma' (tau starts at "
                        "alpha mu |sigma|, Coulomb on the first step).");
      prm.leave_subsection();
    }


    void
    ContactLawParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      algorithm = get_selection(prm, "Algorithm", algorithm_choices);
      friction.parse_parameters(prm, "Friction law");
      friction_coefficient = prm.get_double("Friction coefficient");
      regularization_time  = prm.get_double("Regularization time");
      pgs_tolerance        = prm.get_double("Gauss-Seidel tolerance");
      pgs_max_iterations   = prm.get_integer("Gauss-Seidel max iterations");
      regularization_rate
        = get_selection(prm, "Regularization rate", rate_choices);
      recontact_state
        = get_selection(prm, "State on re-contact", recontact_choices);
      prm.leave_subsection();
      check_parameter_range("Contact/Friction coefficient",
                            friction_coefficient,
                            0,
                            10,
                            false,
                            false);
      check_parameter_range(
        "Contact/Regularization time", regularization_time, 0, 1, true, false);
      check_parameter_range(
        "Contact/Gauss-Seidel tolerance", pgs_tolerance, 0, 1, true, true);
    }


    void
    ContactOutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Sample interval",
                        "20",
                        Integer(1),
                        "Record friction.csv, point_M.csv and "
                        "contact_status.csv every this many time steps; the "
                        "time averages and the spectrum use these samples.");
      prm.declare_entry("Field interval",
                        "10e-6",
                        Double(0),
                        "Write the VTU fields every this much simulated time "
                        "(s); 0 writes none.");
      prm.declare_entry("Averaging start time",
                        "40e-6",
                        Double(0),
                        "Start of the window of the time averages "
                        "(mu_global_mean, status fractions) and of the "
                        "spectrum (s), after the transient.");
      prm.declare_entry("Averaging end time",
                        "-1",
                        Double(),
                        "End of that window (s); negative: the end of the "
                        "run.");
      prm.declare_entry("Regime threshold",
                        "0.01",
                        Double(0, 1),
                        "A status (stick, slip, separation) counts in the "
                        "name of the regime when its time fraction over the "
                        "window is above this (for point M, and for all the "
                        "contact node-samples of the face).");
      prm.declare_entry(
        "Contact face interval",
        "0",
        Integer(0),
        "Write the space-time series of the contact face "
        "(contact_face_lambda_n.csv, contact_face_lambda_t.csv, "
        "contact_face_status.csv: one row per time, one "
        "column per contact node) every this many samples; 0 "
        "writes none.");
      prm.leave_subsection();
    }


    void
    ContactOutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      sample_interval       = prm.get_integer("Sample interval");
      field_interval        = prm.get_double("Field interval");
      average_start         = prm.get_double("Averaging start time");
      average_end           = prm.get_double("Averaging end time");
      regime_threshold      = prm.get_double("Regime threshold");
      contact_face_interval = prm.get_integer("Contact face interval");
      prm.leave_subsection();
      if (average_end >= 0)
        check_parameter(average_end > average_start,
                        "Output/Averaging end time",
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
    ContactParameters::parse_parameters(ParameterHandler &prm)
    {
      geometry.parse_parameters(prm);
      material.parse_parameters(prm);
      morphology.parse_parameters(prm);
      if (material.type == ContactMaterialParameters::Type::morphology
          && (morphology.generator == MorphologyParameters::Generator::image
              || morphology.generator
                   == MorphologyParameters::Generator::grid_file))
        {
          // The meso pin has the two phases of Materials/Matrix and
          // Materials/Heterogeneity: refuse a map of more.
          const bool image
            = morphology.generator == MorphologyParameters::Generator::image;
          const unsigned int n = Morphology::create(morphology).n_phases();
          check_parameter(
            n <= 2,
            image ? "Morphology/Image/Segmentation" : "Morphology/Grid file",
            "the meso pin ('Materials/Type = morphology') has two phases "
            "(material id 0: 'Materials/Matrix', 1: "
            "'Materials/Heterogeneity'), but the "
              + (image
                   ? "image '" + morphology.image.file + "' is segmented into "
                   : "grid file '" + morphology.grid_file + "' holds ")
              + std::to_string(n) + " phases. "
              + (image ? "Segment it into two (one threshold, 'Otsu phases "
                         "= 2' or two colours), or homogenize"
                       : "Use ids 0 and 1 only, or homogenize")
              + " the map with 'set Problem = homogenization' and use its "
                "constants with 'Materials/Type = homogenization summary'.");
        }
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
