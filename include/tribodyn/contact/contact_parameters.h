#ifndef tribodyn_contact_contact_parameters_h
#define tribodyn_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <string>
#include <tribodyn/contact/friction_laws.h>
#include <tribodyn/core/material.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/phase_materials.h>
#include <tribodyn/core/plugin_registry.h>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    /// A 3x3 plane-strain stiffness in Voigt order (xx, yy, xy), engineering
    /// shear strain gamma_xy = 2 eps_xy, in Pa.
    using VoigtStiffness = dealii::Tensor<2, 3>;

    /// Subsection "Geometry": the rectangular pin and its structured mesh.
    struct GeometryParameters
    {
      /// Extent along x (sliding direction) and y (m).
      double width  = 28e-3;
      double height = 8e-3;
      /// Target element size h (m): n_x = round(width/h), n_y =
      /// round(height/h).
      double mesh_size = 0.25e-3;
      /// Meso pins only: elements per morphology pixel along each axis.
      unsigned int subdivisions_per_pixel = 1;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Subsection "Materials": the constitutive model of the pin.
    struct ContactMaterialParameters
    {
      enum class Type
      {
        isotropic,
        anisotropic,
        engineering_constants,
        homogenization_summary,
        morphology
      };
      enum class Kinematics
      {
        small_strain,
        large_deformation
      };

      Type       type       = Type::isotropic;
      Kinematics kinematics = Kinematics::small_strain;
      /// Density of the homogeneous anisotropic materials (kg/m^3).
      double density = 1770.;

      /// Type = isotropic: the name of the pin's material in
      /// Materials/Names ("": the first), and its constants (parsed from
      /// its subsection).
      std::string              pin_material;
      IsotropicElasticMaterial isotropic{30e9, 0.2, 1770.};
      /// Index of the pin's material in Materials/Names.
      unsigned int pin_index = 0;

      /// Type = anisotropic: the 2D stiffness and the out-of-plane row
      /// (sigma_zz = c_z . eps, used only for the von Mises output).
      VoigtStiffness anisotropic_stiffness{
        {{33.33e9, 8.33e9, 0}, {8.33e9, 33.33e9, 0}, {0, 0, 12.5e9}}};
      dealii::Tensor<1, 3> anisotropic_c_z{{8.33e9, 8.33e9, 0}};

      /// Type = engineering constants: transversely isotropic, axis L = x.
      double E_L = 31.9e9, E_T = 34e9, nu_LT = 0.2, nu_TT = 0.2, G_LT = 13.3e9;

      /// Type = homogenization summary: file and key (KUBC, SUBC, periodic).
      std::string summary_file;
      std::string summary_key = "KUBC";

      /// The named materials (Materials/Names): the phases of the
      /// morphology by material id (Type = morphology), the pin's material
      /// (Type = isotropic).
      MorphologyMaterials composite;

      /// The entries of "Materials" (Type, Kinematics, Density), bound to
      /// the members above (their initial values are the defaults).
      ParameterBinding
      binding();
      /// Those of its subsections "Anisotropic", "Engineering constants"
      /// and "Homogenization summary", in this order (the named
      /// materials' are MorphologyMaterials').
      std::vector<ParameterBinding>
      subsection_bindings();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Refuse (InputError naming @p parameter) material @p k of the list
      /// as the material of an isotropic pin (@p pin, for the message): a
      /// pore, or transversely isotropic.
      void
      check_isotropic_pin(const unsigned int k,
                          const std::string &parameter,
                          const std::string &pin = "the pin") const;
    };

    /// Subsection "Loading".
    struct LoadingParameters
    {
      /// Pressure on the top face (Pa), reached after the ramp.
      double pressure = 0.5e6;
      /// Duration of the smooth ramp P(t) = P (1 - cos(pi t / t_r)) / 2 (s).
      double ramp_time = 10e-6;
      /// Tangential velocity V of the rigid plane along x (m/s).
      double plane_velocity = -2.;
      /// Hold the top face in x (its reaction is the friction force).
      bool top_held_in_x = true;
      /// Initial velocity of the whole pin (m/s).
      dealii::Tensor<1, 2> initial_velocity;
      /// Initial distance between the pin's bottom face and the plane (m).
      double initial_gap = 0.;
      /// The plane is at rest until this time, then its velocity ramps
      /// smoothly to V over the velocity ramp time (s).
      double plane_start_time         = 0.;
      double plane_velocity_ramp_time = 0.;
      /// At this time (0: never) the plane's velocity steps to the velocity
      /// after the step (m/s): the velocity-step test of rate and state.
      double plane_velocity_step_time  = 0.;
      double plane_velocity_after_step = -2.;
      /// Waviness of the plane (absolute, m): its surface is
      /// y = -gap - A (1 - cos(2 pi xi / lambda)) / 2, xi the coordinate
      /// along the plane (it moves with the plane).
      double imperfection_amplitude  = 0.;
      double imperfection_wavelength = 2e-3;
      /// Uniform random initial velocity in [-a, a] per dof (m/s), seeded by
      /// the perturbation seed and the global dof index (rank independent).
      double       velocity_perturbation = 0.;
      unsigned int perturbation_seed     = 1;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// The pressure at time t (smooth ramp).
      double
      pressure_at(const double t) const;
      /// Velocity of the plane at time t (m/s).
      double
      plane_velocity_at(const double t) const;
      /// The largest |plane velocity| of the run (m/s).
      double
      plane_speed_maximum() const;
      /// Displacement of the plane along x from 0 to t (m).
      double
      plane_position_at(const double t) const;
      /// True when the plane moves at the constant V from t = 0 on.
      bool
      constant_plane_velocity() const
      {
        return plane_start_time == 0 && plane_velocity_ramp_time == 0
               && plane_velocity_step_time == 0;
      }
    };

    /// Subsection "Time": the beta2 scheme.
    struct TimeParameters
    {
      double time_step = 5e-9;
      double end_time  = 100e-6;
      double beta2     = 0.5;
      /// Stiffness-proportional damping C = beta K (s).
      double damping = 1.1e-9;
      /// Take dt = min(Time step, safety factor * critical dt) instead of
      /// refusing a time step above the critical one.
      bool   automatic_time_step = false;
      double safety_factor       = 0.9;
      /// Refuse a time step above the critical one (InputError). Not a
      /// parameter of the file: the stability tests turn it off to check
      /// that the blow-up detection stops an unstable run.
      bool refuse_unstable_time_step = true;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    enum class ContactAlgorithm
    {
      node_wise, ///< closed form per node (rigid plane, lumped mass)
      projected_gauss_seidel ///< general path for coupled constraints
    };

    /// Subsection "Contact".
    struct ContactLawParameters
    {
      ContactAlgorithm algorithm = ContactAlgorithm::node_wise;
      /// Contact/Friction law and the laws' own parameters
      FrictionLaws::Parameters friction = FrictionLaws::choosing<Regularized>();
      double                   friction_coefficient = 0.25;
      /// L*/|V| of the regularized law (s); 1.5e-6 = 300 x 5 ns.
      double             regularization_time = 1.5e-6;
      RegularizationRate regularization_rate = RegularizationRate::plane_speed;
      RecontactState     recontact_state     = RecontactState::reset_to_zero;
      double             pgs_tolerance       = 1e-12;
      unsigned int       pgs_max_iterations  = 50;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Subsection "Output".
    struct ContactOutputParameters
    {
      /// Record the time series every this many steps.
      unsigned int sample_interval = 20;
      /// Write VTU fields every this much simulated time (0: never).
      double field_interval = 10e-6;
      /// Window [start, end] of the time averages (end < 0: end of run).
      double average_start = 40e-6;
      double average_end   = -1;
      /// Fraction of time above which a status counts in the regime name.
      double regime_threshold = 0.01;
      /// Space-time series of the contact face (lambda_N, lambda_T, status
      /// per contact node) every this many samples (0: none).
      unsigned int contact_face_interval = 0;
      /// Output/Postprocessors: the outputs the user chose
      /// (source/contact/postprocessors/).
      PluginSelection postprocessors;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Every parameter of `set Problem = contact`.
    struct ContactParameters
    {
      GeometryParameters        geometry;
      ContactMaterialParameters material;
      MorphologyParameters      morphology;
      LoadingParameters         loading;
      TimeParameters            time;
      ContactLawParameters      contact;
      ContactOutputParameters   output;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// @p one_pin: the pin of a run (its material checked for its
      /// Type); false for the base of a study, whose models choose the pin
      /// and check what they take from it.
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const bool                one_pin = true);
      /// The averaging window must start before the run ends, unless the
      /// run is a leg of a longer one (@p checkpointed: it writes
      /// checkpoints, and a resumed leg reaches the window; its summary
      /// says the window is empty). InputError naming the parameter.
      void
      check_averaging_window(const bool checkpointed) const;
    };

    namespace internal
    {
      /// The @p n comma-separated numbers of @p text; InputError naming the
      /// parameter @p name otherwise.
      std::vector<double>
      parse_numbers(const std::string &text,
                    const unsigned int n,
                    const std::string &name);
    } // namespace internal

    /**
     * Read the apparent stiffness C (and c_z when present) stored under
     * @p key (KUBC, SUBC or periodic) of a homogenization summary.json.
     * Throws InputError naming the file and key when it cannot.
     */
    VoigtStiffness
    read_homogenization_stiffness(const std::string    &file,
                                  const std::string    &key,
                                  dealii::Tensor<1, 3> &c_z);
  } // namespace contact
} // namespace tribodyn

#endif
