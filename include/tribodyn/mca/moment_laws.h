// The laws of the relative-rotation moment K_ij of a pair (seed eq. 1): one
// header each in moment_laws/, listed here once. The first law whose
// parameters choose it acts; the last, "none", is the default.
#ifndef tribodyn_mca_moment_laws_h
#define tribodyn_mca_moment_laws_h

#include <tribodyn/mca/moment_laws/elastic.h>
#include <tribodyn/mca/moment_laws/none.h>
#include <tribodyn/mca/switched_law_list.h>

namespace tribodyn
{
  namespace mca
  {
    using MomentLaws = SwitchedLawList<ElasticMoment, NoMoment>;
  } // namespace mca
} // namespace tribodyn

#endif
