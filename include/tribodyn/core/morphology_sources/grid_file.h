#ifndef tribodyn_core_morphology_sources_grid_file_h
#define tribodyn_core_morphology_sources_grid_file_h

#include <string>
#include <tribodyn/core/morphology_source.h>

namespace tribodyn
{
  /**
   * The morphology source 'grid file': material ids read from a plain-text
   * grid (Morphology::read_grid_file()), stretched over the rectangle.
   */
  class GridFileMorphology : public MorphologySource
  {
  public:
    /// Path of the plain-text grid of material ids.
    std::string file;

    void
    bind(ParameterBinding &b) override;
    void
    parse(dealii::ParameterHandler &prm,
          const ParameterBinding   &b,
          MorphologyParameters     &common) override;
    Morphology
    create(const MorphologyParameters &common) const override;
    bool
    is_map() const override;
  };
} // namespace tribodyn

#endif
