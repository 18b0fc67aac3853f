// No relative-rotation moment (Interaction/Relative rotation stiffness =
// 0, the default): the pair kernel compiles the moment's calls away.
#ifndef tribodyn_mca_moment_laws_none_h
#define tribodyn_mca_moment_laws_none_h

#include <functional>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/series_springs.h>
#include <tribodyn/mca/switched_law_list.h>
#include <tribodyn/mca/vector_algebra.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    class NoMoment
    {
    public:
      static constexpr const char *name            = "none";
      static constexpr bool        active          = false;
      static constexpr bool        needs_rotations = false;
      using Parameters                             = AlwaysChosen;

      explicit NoMoment(const Parameters &)
      {
      }
      void
      set_up(const std::vector<SeriesSprings> &, const double)
      {
      }
      void
      register_pair_fields(PairFieldTable &, const std::function<bool()> &)
      {
      }
      static Vec3
      moment(const unsigned int)
      {
        return {{0, 0, 0}};
      }
      static std::pair<double, double>
      stiffnesses(const unsigned int)
      {
        return {0., 0.};
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
