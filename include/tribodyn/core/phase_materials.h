#ifndef tribodyn_core_phase_materials_h
#define tribodyn_core_phase_materials_h

#include <deal.II/base/parameter_handler.h>
#include <optional>
#include <string>
#include <tribodyn/core/elastic_phase.h>
#include <tribodyn/core/material.h>
#include <tribodyn/core/morphology.h>
#include <vector>

namespace tribodyn
{
  /**
   * Any number of named phases, isotropic or transversely isotropic (issue #19
   * item 2): the subsection "Phases" of the current subsection, ASPECT-style
   * lists with one entry per phase, phase k being material id k of the
   * morphology:
   *
   *   subsection Phases
   *     set Names            = pores, matrix, fibres
   *     set Young moduli     = 0, 30e9, 80e9
   *     set Poisson ratios   = 0, 0.2, 0.2
   *     set Densities        = 0, 1770, 1770
   *   end
   *
   * A phase may be transversely isotropic: named in the subsection
   * "Transversely isotropic", with its axis and its axial constants there,
   * its entries in the lists above being those of its plane of isotropy
   * (E_T, nu_TT):
   *
   *   subsection Phases
   *     ...
   *     subsection Transversely isotropic
   *       set Phases               = fibres
   *       set Axes                 = z
   *       set Axial Young moduli   = 230e9
   *       set Axial Poisson ratios = 0.2
   *       set Axial shear moduli   = 27e9
   *     end
   *   end
   *
   * A Young modulus of 0 makes the phase a pore. The cell problems stay
   * well posed by giving pores an ersatz stiffness: E = 'Pore stiffness
   * ratio' times the smallest solid E, nu = 0 (theory:
   * doc/theory/homogenization.md, "Any number of phases, pores", with the error
   * this causes). An empty 'Names' list (the default) leaves the two phases
   * "Matrix" and "Heterogeneity" in charge, as before.
   */
  struct PhaseMaterials
  {
    std::vector<std::string>              names;
    std::vector<IsotropicElasticMaterial> materials; ///< as given (E = 0: pore)
    std::vector<bool>                     pore;
    /// The axial constants of each phase that is transversely isotropic
    /// (E_T and nu_TT from 'materials').
    std::vector<std::optional<TransverselyIsotropicConstants>> axial;
    double pore_stiffness_ratio = 1e-6;

    /// Declare "Phases" in the current subsection.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse it; @p section (e.g. "Materials") prefixes the names in error
    /// messages.
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &section);

    /// True when the list is in use (Names not empty).
    bool
    given() const;
    /// Number of phases.
    unsigned int
    size() const;
    /// The phases the cell problems use, indexed by material id: pores
    /// replaced by their ersatz material.
    std::vector<ElasticPhase>
    phases() const;

  private:
    /// The lists of the subsection "Transversely isotropic", as given.
    struct TransverseLists
    {
      std::vector<std::string> which, axes;
      std::vector<double>      E_L, nu_LT, G_LT;
    };
    /// Check them against the phases and fill 'axial'.
    void
    set_transversely_isotropic(const TransverseLists &lists,
                               const std::string     &section);
  };

  /**
   * The phases of a morphology as every engine reads them (the subsection
   * "Materials" of the homogenization and of the meso contact pin): the
   * named list "Phases" when it is given, else the two phases "Matrix"
   * (material id 0) and "Heterogeneity" (id 1).
   */
  struct MorphologyMaterials : TwoPhaseMaterials
  {
    PhaseMaterials named;

    /// Declare "Materials/Matrix", "Materials/Heterogeneity" and
    /// "Materials/Phases" (@p prm at the top level).
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse them (@p prm at the top level).
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The phases, indexed by material id (pores with their ersatz
    /// stiffness: engines that cut pores out of the mesh ignore it).
    std::vector<ElasticPhase>
    phases() const;
    /// The phases as given (a pore with its zero Young modulus).
    std::vector<IsotropicElasticMaterial>
    given() const;
    /// Name of each phase ("matrix", "heterogeneity" for two).
    std::vector<std::string>
    names() const;
    /// Whether each phase is a pore.
    std::vector<bool>
    pores() const;

    /**
     * Refuse (InputError naming 'Materials/Phases/Names') a morphology
     * with more phases than are given; an image's segmentation must give
     * exactly as many phases as are named (@p image: the morphology is a
     * segmented image).
     */
    void
    check(const Morphology &morphology, const bool image) const;
    /// The same at parse time for the morphology @p parameters describe,
    /// when it is a map read from a file (a generator's map has the two
    /// ids the two phases name): the map is read to count its phases.
    void
    check(const MorphologyParameters &parameters) const;
  };
} // namespace tribodyn

#endif
