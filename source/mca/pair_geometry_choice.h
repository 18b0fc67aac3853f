// The pair geometry of a scene as a choice for with_chosen()
// (include/tribodyn/mca/pair_law.h): UniformPairs, or GradedPairs where the
// automata have several sizes. Shared by the kernels' dispatches
// (pair_kernel.cc, pair_kernel_bulk.cc).

#ifndef tribodyn_mca_pair_geometry_choice_h
#define tribodyn_mca_pair_geometry_choice_h

#include "pair_geometry.h"

#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/pair_law.h>

namespace tribodyn
{
  namespace mca
  {
    inline auto
    AutomatonSystem::pair_geometry_choice() const
    {
      return choice_of([this](const auto &f) {
        if (graded)
          {
            const GradedPairs g{pair_area.data(),
                                pair_half_rest.data(),
                                r0,
                                &face_offset,
                                1. / S};
            f(g);
          }
        else
          {
            const UniformPairs u{S, r0, 1. / r0, d};
            f(u);
          }
      });
    }
  } // namespace mca
} // namespace tribodyn

#endif
