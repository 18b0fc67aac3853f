#ifndef tribodyn_mca_parameters_h
#define tribodyn_mca_parameters_h

#include <array>
#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <memory>
#include <string>
#include <tribodyn/core/material_names.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/mca/bond_laws.h>
#include <tribodyn/mca/friction_laws.h>
#include <tribodyn/mca/moment_laws.h>
#include <vector>

namespace tribodyn
{
  /**
   * The 3D movable cellular automaton (MCA) method of seed 000 (see
   * doc/theory/mca.md for the equations as implemented).
   */
  namespace mca
  {
    using Point3 = dealii::Point<3>;

    /// Response function of a material beyond the elastic range.
    enum class Hardening
    {
      elastic, ///< no plasticity
      linear,  ///< sigma_y = sigma_y0 + H1 eps_p
      bilinear ///< slope H1 up to eps_p = onset, H2 beyond
    };

    /**
     * One MCA material (subsections "Materials/Steel", "Materials/Carbon").
     * Defaults: seed 000 Tables 1 and 2.
     */
    struct MaterialParameters
    {
      std::string name;
      double      density        = 7800;
      double      youngs_modulus = 206e9;
      double      poisson_ratio  = 0.28;
      Hardening   hardening      = Hardening::linear;
      double      yield_stress   = 800e6;
      /// dsigma_y / deps_p of the first (or only) hardening branch.
      double hardening_modulus = 2e9;
      /// dsigma_y / deps_p beyond the onset (bilinear only).
      double second_hardening_modulus = 0;
      /// Plastic strain where the second branch starts (bilinear only).
      double second_hardening_onset = 0.05;
      /// Von Mises stress of a bonded pair at which the bond breaks.
      double bond_breaking_stress = 1.2e9;
      /// Energy per unit volume of a pair (S_ij r_ij) to break a bond.
      double bond_energy_density = 3.5e6;

      /// The entries of subsection @p section ("Materials/Steel"), bound to
      /// these members (their values the defaults: steel's, carbon's).
      ParameterBinding
      binding(const std::string &section);
      /// Parse subsection @p section (from the top level) into these.
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &section);

      double
      shear_modulus() const
      {
        return youngs_modulus / (2 * (1 + poisson_ratio));
      }
      double
      bulk_modulus() const
      {
        return youngs_modulus / (3 * (1 - 2 * poisson_ratio));
      }
      /// Many-body coefficient D = 1 - 2G/(3K) = lambda/K of the pair law.
      double
      many_body_coefficient() const
      {
        return 1 - 2 * shear_modulus() / (3 * bulk_modulus());
      }
      /// Longitudinal wave speed sqrt((K + 4G/3)/rho).
      double
      p_wave_speed() const;
      /// Current yield stress after accumulated plastic strain @p eps_p.
      double
      yield_stress_at(const double eps_p) const;
      bool
      is_plastic() const
      {
        return hardening != Hardening::elastic;
      }

      static MaterialParameters
      steel();
      static MaterialParameters
      carbon();
    };


    /// A region of the packing: a shape that sets the material or removes
    /// automata ("void").
    struct Region
    {
      enum class Shape
      {
        box,
        sphere,
        cylinder
      };
      Shape shape = Shape::box;
      /// box: two corners; sphere: centre in a; cylinder: axis from a to b.
      Point3 a, b;
      double radius = 0;
      /// Index into the material list, or -1 for a void.
      int material = -1;

      bool
      contains(const Point3 &p) const;
    };


    /// A body: FCC automata filling a box, with a material.
    struct Body
    {
      Point3 lower, upper;
      int    material = 0;
    };


    struct InclusionLayout;

    /**
     * Subsection "Geometry/Inclusions": carbon cylinders and voids placed by
     * the generator of inclusions.h in the contacting part of each body of
     * a rough interface (seed 000 Sec. 2.2: cylinders of radius 10 nm and
     * length 70 nm, about 2 % of each contacting part; Fig. 2b: voids).
     * The contacting part of the lower body is z in [Height - Contacting
     * part thickness, Height], of the upper body [Height, Height +
     * thickness] (before the interface gap); a shape converts only the
     * automata of its own body.
     */
    struct InclusionPackingParameters
    {
      bool          enabled         = false;
      int           material        = 1;
      double        part_thickness  = 0;
      double        cylinder_radius = 10e-9;
      double        cylinder_length = 70e-9;
      std::string   orientation     = "isotropic";
      double        volume_fraction = 0.02;
      double        void_radius     = 20e-9;
      double        void_fraction   = 0;
      double        gap             = 0;
      std::uint64_t seed            = 1;

      /// The entries of "Geometry/Inclusions" (@p names: the materials,
      /// for 'Material'; none are needed to declare).
      ParameterBinding
      binding(const std::vector<std::string> &names = {});
      /// Parse them (from the top level).
      void
      parse_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &names);
    };


    /**
     * Subsection "Geometry": automaton size, periodicity, bodies, regions,
     * optional rough interface between two bodies.
     */
    struct GeometryParameters
    {
      /// Automaton size d (distance between neighbours in the FCC packing).
      double automaton_size = 1e-3;
      /// The simulation box; in periodic directions it is the period.
      Point3              domain_lower, domain_upper = Point3(0.01, 0.01, 0.01);
      std::array<bool, 3> periodic = {{false, false, false}};
      std::vector<Body>   bodies;
      std::vector<Region> regions;
      /// The lists Geometry/Bodies, Size bands and Regions as written
      /// (parse_parameters() reads them into bodies, size_bands and
      /// regions: they need the material names, and the bands the bodies
      /// and the rough interface).
      std::string bodies_text = "0, 0, 0, 0.01, 0.01, 0.01, steel";
      std::string size_bands_text, regions_text;
      /// Rough interface: sites of all bodies are assigned to body 0 below
      /// the surface z = height + amplitude * f(x, y) and to body 1 above.
      bool         rough_interface      = false;
      double       interface_height     = 0;
      double       roughness_amplitude  = 0;
      double       roughness_wavelength = 1e-3;
      unsigned int roughness_seed       = 1;
      /// Initial gap added between the two bodies of a rough interface
      /// (body 1 is shifted up by it).
      double interface_gap = 0;
      /// Shift of body 1 of a rough interface along y (wrapped into the
      /// periodic box): the staged friction loading moves the bodies by
      /// half the width so that asperities meet asperities.
      double interface_shift_y = 0;

      /// Graded packing (issue #18): automata whose site lies in the band
      /// z_lower <= z < z_upper (in the frame of the Bodies, before the
      /// upper body of a rough interface is lifted) have size 2^level d,
      /// on the FCC lattice of that size with the common origin (its sites
      /// are sites of the finer lattices), but for the skin at free lateral
      /// faces (fine_free_faces). Elsewhere: size d.
      struct SizeBand
      {
        double       z_lower = 0, z_upper = 0;
        unsigned int level = 0;
      };
      std::vector<SizeBand> size_bands;
      /// Geometry/Size bands = 'interface N [M [O]]': the graded layout of the
      /// friction scenes written as bands 'z0 z1 k; ...' (fine within N
      /// cells a = d sqrt 2 of the rough interface's mean height and in
      /// the bodies' outer 4 cells, which hold the loading layers; 2d in
      /// the next M cells (4 if not given) and in 4-cell transitions next
      /// to the outer cells; 4d elsewhere; with O > 0 the outer cells are
      /// of 2^O d and have no transitions). Any other text is returned as
      /// it is. Needs the bodies and the rough interface parsed.
      std::string
      bands_around_interface(const std::string &text) const;
      /// Refuse size bands whose changes of size lie so near the rough
      /// interface that the automata near them (which take their contact
      /// areas from the set-up) could meet the other body.
      void
      check_size_changes_clear_of_interface() const;
      /// The size level of a site at height @p z (0 outside every band).
      unsigned int
      size_level(const double z) const;
      /// The FCC basis in units of the cubic lattice constant a = d sqrt 2:
      /// the sites are Domain lower + a/4 + a (n + b).
      static constexpr std::array<std::array<double, 3>, 4> fcc_basis
        = {{{{0, 0, 0}}, {{0.5, 0.5, 0}}, {{0.5, 0, 0.5}}, {{0, 0.5, 0.5}}}};
      /// Index of the body whose box holds @p p, or -1.
      int
      body_containing(const Point3 &p) const;
      /// The heights spanned by the bodies, the upper end just inside: the
      /// bands at the bodies' top and bottom go on beyond them (clamp a
      /// height into this range).
      std::array<double, 2>
      bodies_z_range() const;
      /// Geometry/Size at free faces = fine: at a free lateral face of its
      /// body (a face in x or y, not periodic) a band keeps the fine
      /// lattice's surface. The automata of size 2^L d fill the FCC cells
      /// of their lattice whose centres lie at least skin_depth(L) inside
      /// the body; the rest of the band is packed one size finer (nested
      /// skins: d, then 2d, then the band's size).
      bool fine_free_faces = true;
      /// The size level of a site at @p p: size_level(p[2]), or less in
      /// the skin of a free lateral face (fine_free_faces).
      unsigned int
      size_level(const Point3 &p) const;
      /// Depth of the skin below 2^L d at a free lateral face: a and 4a for
      /// L = 1 and 2 (a = d sqrt(2); the 4d cells, 2a in radius, then lie
      /// beyond the 2d cells of the skin of 2d, a in radius).
      double
      skin_depth(const unsigned int level) const
      {
        return (level == 1 ? 1. : 4.) * automaton_size * std::sqrt(2.);
      }
      /// Largest pair-list distance of two automata at rest: d, or with
      /// size bands up to level L that of the pairs near a change of size
      /// that share a Voronoi face, transition_face_factor() 2^L d
      /// (doc/theory/mca.md §9). The pair-list range and the cell size are
      /// this times 1 + Interaction/Skin.
      double
      largest_pair_distance() const;
      /// Pairs near a change of size that share a Voronoi face are at most
      /// this times 2^max(L_i, L_j) d apart at rest: their pair-list range,
      /// with the skin (measured √5/2 = 1.118 across d|2d and 2d|4d
      /// transitions, test mca_hooke_graded; checked for every face at
      /// set-up). Only those pairs interact, so
      /// the cells of the decomposition need not reach the candidates.
      /// Where a skin of fine automata meets a plane between bands at a
      /// free face (fine_free_faces) the cells reach across the corner of
      /// the coarse cells: √3 (measured, test mca_graded_free_faces).
      double
      transition_face_factor() const
      {
        return has_skins() ? 1.74 : 1.12;
      }
      /// Size bands that reach a free lateral face with fine_free_faces.
      bool
      has_skins() const
      {
        return fine_free_faces && !size_bands.empty()
               && !(periodic[0] && periodic[1]);
      }
      /// Is a site at @p p (frame of size_level()) within 3 2^max(L_a, L_b) d
      /// of a plane where the size changes from L_a to L_b, or of the inner
      /// face of a skin at a free face? Such automata have Voronoi cells of
      /// their own (volumes, areas).
      bool
      near_size_change(const Point3 &p) const;

      InclusionPackingParameters inclusions;
      /// The generated inclusions (set by parse_parameters or
      /// generate_inclusion_layout(); shared by copies, never modified).
      std::shared_ptr<const InclusionLayout> inclusion_layout;
      /// Run the generator for the current `inclusions` settings (the same
      /// shapes on every rank: the generator is deterministic).
      void
      generate_inclusion_layout();

      /// The entries of Geometry and of Geometry/Rough interface, each
      /// written once (core/parameter_binding.h).
      ParameterBinding
      binding();
      ParameterBinding
      rough_interface_binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &material_names);
      /// Refuse (InputError) a box that, filled, needs more memory per rank
      /// on @p n_ranks ranks than this machine has (checked when a run
      /// starts).
      void
      check_memory_per_rank(const unsigned int n_ranks) const;
    };


    /// Subsection "Interaction": what the pair law includes.
    struct InteractionParameters
    {
      bool rotations  = true;
      bool plasticity = true;
      /// The pair-law policies' choices and constants (pair_law.h): the
      /// friction law of unbonded pairs, the relative-rotation moment
      /// K_ij of seed eq. (1), bond breaking and bond formation.
      FrictionLaws::Parameters      friction;
      MomentLaws::Parameters        moment;
      BondBreakingLaws::Parameters  bond_breaking;
      BondFormationLaws::Parameters bond_formation;
      /// The moments K_ij are on (a moment law is chosen; parsing refuses
      /// one without Rotations).
      bool
      relative_rotation_on() const
      {
        return rotations && moment.active();
      }
      /// Bonds break or form in this scene.
      bool
      bond_switching_on() const
      {
        return bond_breaking.active() || bond_formation.active();
      }
      /// Pair-list skin as a fraction of the automaton size.
      double skin = 0.2;
      /// Boxes whose automata are declared elastic (no plastic return, no
      /// bond switching between two of them).
      std::vector<Region> elastic_regions;

      /// Its own entries (those of the pair laws are the laws').
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };


    /// A group of automata selected by a box, with a boundary condition.
    struct BoundaryGroup
    {
      enum class Type
      {
        fixed,
        velocity,
        force,
        damping
      };
      std::string name;
      Type        type = Type::fixed;
      Point3      lower, upper;
      /// velocity: prescribed components (NaN = free); force: total force
      /// on the group; damping: coefficient per component (1/s).
      std::array<double, 3> value = {{0, 0, 0}};
      /// Time at which a second value starts to ramp in (velocity/force),
      /// to chain e.g. approach then sliding; negative = none. With
      /// switch_on_contact: the delay from the first contact (>= 0).
      double                switch_time  = -1;
      std::array<double, 3> second_value = {{0, 0, 0}};
      /// The switch happens when the two bodies first touch ('then
      /// contact'), not at switch_time. Components free ('*') after the
      /// switch are released at the switch.
      bool switch_on_contact = false;
    };


    /**
     * Subsection "Friction loading": the staged loading of seed 000
     * Sec. 2.2 for a rough interface between body 0 (below) and body 1
     * (above). (1) The bodies are packed in full contact along the rough
     * surface; (2) body 1 is separated along z by `Separation` and (3)
     * shifted along y by `Shift` times the width (both rigid moves of a
     * body not yet touching the other: done at the packing); (4) the top
     * and bottom loading layers approach at -+`Approach velocity` along z
     * until the bodies touch; (5) then the layers carry the normal force
     * `Pressure` x area (rigid loading plates) and slide at +-`Sliding
     * velocity` along y, both ramped smoothly over Boundary conditions/Ramp
     * time from the moment of contact; x velocity of the layers is held at
     * zero; viscous damping along z in both layers. Generated boundary
     * groups: top, top_load, top_damping, bottom, bottom_load,
     * bottom_damping.
     */
    struct FrictionLoadingParameters
    {
      bool enabled = false;
      /// Gap along z before the approach (m); 0 = the largest rise of the
      /// lower surface over the shifted upper one + 1.25 d.
      double separation = 0;
      /// Shift of body 1 along y as a fraction of the box width.
      double shift_fraction = 0.5;
      /// Loading layer thickness in automaton layers (spacing a/2).
      unsigned int layer_layers      = 2;
      double       approach_velocity = 5;
      double       pressure          = 300e6;
      double       sliding_velocity  = 10;
      /// Time from the contact to the start of the sliding (s); 0 = the
      /// sliding ramps in with the pressure (the seed).
      double sliding_delay = 0;
      /// Damping along z in the loading layers (1/s); 0 = seed criterion.
      double damping = 0;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };


    /// Subsection "Boundary conditions".
    struct BoundaryParameters
    {
      std::vector<BoundaryGroup> groups;
      /// Duration of the smooth (C1) ramp of velocities and forces.
      double ramp_time = 0;
      /// Viscous damping of every automaton, F = -c m v (1/s).
      double global_damping = 0;

      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

    private:
      /// Read 'Groups' (@p text; @p p its path, for messages).
      void
      parse_groups(const std::string &text, const std::string &p);
    };


    /// Subsection "Time".
    struct TimeParameters
    {
      double end_time = 1e-6;
      /// 0: dt = courant * d_min / c_p,max.
      double time_step = 0;
      double courant   = 0.2;
      /// Largest accepted dt / (d_min / c_p,max).
      static constexpr double max_courant = 0.5;

      /// The entries of the subsection, each bound to its member
      /// (core/parameter_binding.h).
      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };


    /// Subsection "Partition": the work of the ranks kept even as the
    /// automata move (source/mca/automaton_partition.cc).
    struct PartitionParameters
    {
      /// Repartition at a pair-list rebuild when the work imbalance (the
      /// largest rank's automata over the mean) exceeds this; 0 = never.
      double rebalance_threshold = 1.1;
      /// Deal.II cells a rank keeps at least where the mesh holds 2 x 2 x 2
      /// search cells per cell (Decomposition::cell_split()); 0 = never.
      unsigned int mesh_cells_per_rank = 1000;
      /// The order in which each rank stores its automata and their pairs
      /// (AutomatonPartition::order_owned_automata()): along a Morton curve
      /// of the search cells, or in slabs across the longest direction
      /// without periodic faces (Decomposition::curve_index()).
      enum class AutomatonOrder
      {
        curve,
        slabs
      };
      AutomatonOrder automaton_order = AutomatonOrder::slabs;
      /// Pairs a chunk of the pair kernel's pipeline holds (about;
      /// PairList::chunk_for_pipeline()).
      unsigned int pairs_per_chunk = 2048;

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
    struct McaOutputParameters
    {
      double       output_interval         = 0; ///< 0 = only at the end
      double       series_interval         = 0; ///< 0 = every 100 steps
      bool         write_particles         = true;
      bool         write_stress            = true;
      bool         cross_section           = false;
      unsigned int cross_section_axis      = 0;
      double       cross_section_position  = 0;
      double       cross_section_thickness = 0;
      /// Output/Postprocessors: the outputs the user chose
      /// (source/mca/postprocessors/).
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


    /// Subsection "Analysis": headline figures of standard scenes.
    struct AnalysisParameters
    {
      enum class Type
      {
        none,
        uniaxial,
        pulse,
        friction
      };
      Type type = Type::none;
      /// uniaxial: loading axis; pulse: propagation axis; friction: normal.
      unsigned int axis = 2;
      /// uniaxial: groups whose reaction and displacement define stress and
      /// strain (the loaded group and the fixed one).
      std::string loaded_group  = "top";
      std::string support_group = "bottom";
      /// uniaxial: fit E over this fraction of the yield strain (upper).
      double elastic_fit_fraction = 0.5;
      /// pulse: positions of the two probe planes along the axis.
      double probe_1 = 0, probe_2 = 0;
      /// friction: time from which the mean mu is taken.
      double averaging_start = 0;
      /// friction: moving-average width of mu (s); 0 = End time / 10.
      double smoothing_window = 0;
      /// friction: relative band of the quasi-steady regime.
      double steady_band = 0.05;
      /// friction: bin width of the quasi-fluid layer z-profile (m);
      /// 0 = the automaton size.
      double layer_bin_width = 0;
      /// friction: the layer is where the profile exceeds this fraction of
      /// its peak (0.5: full width at half maximum).
      double layer_threshold = 0.5;

      ParameterBinding
      binding();
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };


    /// Every parameter of `set Problem = mca`.
    struct Parameters
    {
      std::vector<MaterialParameters> materials; ///< steel, carbon
      GeometryParameters              geometry;
      InteractionParameters           interaction;
      BoundaryParameters              boundary;
      TimeParameters                  time;
      PartitionParameters             partition;
      McaOutputParameters             output;
      AnalysisParameters              analysis;
      FrictionLoadingParameters       loading;
      /// Derived by the friction loading: damping coefficient used and the
      /// z-range of the two loading layers (for reports).
      double loading_damping = 0;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Materials/Names (source/mca/material_parameters.cc, where it is
      /// read).
      static void
      declare_material_names(dealii::ParameterHandler &prm);
      /// The subsections of the materials named in Materials/Names (its
      /// value now): called by declare_parameters() for the default list,
      /// and again once the parameter file's list is known (the problem's
      /// declare_dependent_parameters, source/core/application.cc).
      static void
      declare_material_sections(dealii::ParameterHandler &prm);
      /// The materials of Materials/Names with their parameters, in the
      /// list's order (source/mca/material_parameters.cc).
      static std::vector<MaterialParameters>
      parse_materials(dealii::ParameterHandler &prm);

      /// Defaults for programmatic use (tests): steel and carbon.
      Parameters();

      bool
      any_plastic() const;
      /// Whether an output reads each automaton's displacement since the
      /// start: the particles and the cross sections (their `displacement`
      /// field, source/mca/postprocessors/visualization.cc) and the
      /// uniaxial and pulse analyses (the automata's places at the start,
      /// x - u). Elsewhere no automaton stores one
      /// (AutomatonArrays::u_stored); the groups' mean displacements are
      /// summed as they move (BoundaryLoads::book_displacement()).
      bool
      displacements_needed() const;
    };

    /// (material_index(): core/material_names.h)
    using tribodyn::material_index;
  } // namespace mca
} // namespace tribodyn

#endif
