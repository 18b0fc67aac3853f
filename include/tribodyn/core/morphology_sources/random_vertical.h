#ifndef tribodyn_core_morphology_sources_random_vertical_h
#define tribodyn_core_morphology_sources_random_vertical_h

#include <tribodyn/core/morphology_source.h>

namespace tribodyn
{
  /**
   * The morphology source 'random vertical' (seed 001, Fig. 1): random
   * non-overlapping vertical heterogeneities, each a rectangle of a fixed
   * width and a random height, placed up to `Morphology/Volume fraction`
   * with `Morphology/Seed`.
   */
  class RandomVerticalMorphology : public MorphologySource
  {
  public:
    /// Width (m) of each heterogeneity and the range of their heights (m).
    double inclusion_width      = 0.1e-3;
    double inclusion_min_height = 1.2e-3;
    double inclusion_max_height = 3.6e-3;

    void
    bind(ParameterBinding &b) override;
    void
    parse(dealii::ParameterHandler &prm,
          const ParameterBinding   &b,
          MorphologyParameters     &common) override;
    Morphology
    create(const MorphologyParameters &common) const override;
    bool
    uses_seed() const override;
  };
} // namespace tribodyn

#endif
