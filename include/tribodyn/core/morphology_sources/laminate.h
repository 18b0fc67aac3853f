#ifndef tribodyn_core_morphology_sources_laminate_h
#define tribodyn_core_morphology_sources_laminate_h

#include <tribodyn/core/morphology_source.h>

namespace tribodyn
{
  /**
   * The morphology source 'laminate': layers through the whole rectangle,
   * a heterogeneity layer of `Morphology/Volume fraction` in the middle of
   * each period.
   */
  class LaminateMorphology : public MorphologySource
  {
  public:
    enum class Normal
    {
      x, ///< vertical layers, stacked along x
      y  ///< horizontal layers, stacked along y
    };

    /// Stacking direction and number of (matrix, heterogeneity) periods.
    Normal       normal    = Normal::x;
    unsigned int n_periods = 4;

    void
    bind(ParameterBinding &b) override;
    void
    parse(dealii::ParameterHandler &prm,
          const ParameterBinding   &b,
          MorphologyParameters     &common) override;
    Morphology
    create(const MorphologyParameters &common) const override;
  };
} // namespace tribodyn

#endif
