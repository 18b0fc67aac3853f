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
   * The phases of a morphology, indexed by material id, as every engine of
   * the finite elements uses them: named, isotropic or transversely
   * isotropic, pores among them (issue #19 item 2; doc/theory/
   * homogenization.md, "Any number of phases, pores").
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

    /// The phases the cell problems use, indexed by material id: pores
    /// replaced by their ersatz material (E = 'Pore stiffness ratio' times
    /// the smallest solid E, nu = 0).
    std::vector<ElasticPhase>
    phases() const;
  };

  /**
   * The subsection "Materials" of the homogenization, of the meso contact
   * pin and of their studies, in the materials' one scheme
   * (core/material_names.h): the materials by name, material id k of the
   * morphology being the k-th name, each with its subsection:
   *
   *   subsection Materials
   *     set Names = pores, matrix, fibres
   *     subsection Pores
   *       set Young modulus = 0          # a pore
   *     end
   *     subsection Matrix
   *       set Young modulus = 30e9
   *       set Poisson ratio = 0.35
   *       set Density       = 1200
   *     end
   *     subsection Fibres
   *       set Young modulus       = 230e9   # E_T, of the plane of isotropy
   *       set Poisson ratio       = 0.2     # nu_TT
   *       set Density             = 1800
   *       set Symmetry            = transversely isotropic
   *       set Axis                = z
   *       set Axial Young modulus = 230e9   # E_L
   *       set Axial Poisson ratio = 0.2     # nu_LT
   *       set Axial shear modulus = 27e9    # G_LT
   *     end
   *   end
   *
   * The default list is the two phases of the generated morphologies,
   * "matrix" (id 0) and "heterogeneity" (id 1). A Young modulus of 0 makes
   * a phase a pore; the cell problems give pores an ersatz stiffness
   * ('Materials/Pore stiffness ratio').
   */
  struct MorphologyMaterials
  {
    PhaseMaterials list;

    /// Declare "Materials/Names", "Materials/Pore stiffness ratio" and the
    /// subsections of the names the handler has now (its defaults: what
    /// --print-parameters shows); @p prm at the top level.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Declare the subsections of the names the handler has now (after a
    /// lenient first reading of the file: the file's names;
    /// ProblemDescription::declare_dependent_parameters).
    static void
    declare_material_sections(dealii::ParameterHandler &prm);
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
    /// Name of each phase.
    std::vector<std::string>
    names() const;
    /// Whether each phase is a pore.
    std::vector<bool>
    pores() const;

    /**
     * Refuse (InputError naming 'Materials/Names') a morphology with more
     * phases than are named; where an entry fixes the number of phases
     * (@p phases_set_by, e.g. an image's segmentation:
     * MorphologySource::phases_set_by()), exactly as many must be named.
     */
    void
    check(const Morphology &morphology, const std::string &phases_set_by) const;
    /// The same at parse time for the morphology @p parameters describe,
    /// when it is a map read from a file (a generator's map has the two
    /// ids the two phases name): the map is read to count its phases.
    void
    check(const MorphologyParameters &parameters) const;
  };
} // namespace tribodyn

#endif
