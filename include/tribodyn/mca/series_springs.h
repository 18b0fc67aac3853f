// The normal springs of a pair of materials, shared by the pair kernel
// and the pair-law policies that scale with them (the relative-rotation
// moment, include/tribodyn/mca/moment_laws/elastic.h).
#ifndef tribodyn_mca_series_springs_h
#define tribodyn_mca_series_springs_h

namespace tribodyn
{
  namespace mca
  {
    /// Normal stiffnesses k = 2G / r0 of the two halves of a pair of
    /// materials (i, j), 1 / (k_i + k_j) and the halves' compliances 1 / k
    /// (the energy of a side, doc/theory/mca.md §8.4); tables of them are
    /// indexed by mat_i * n_materials + mat_j.
    struct SeriesSprings
    {
      double ki, kj, inv_sum, inv_ki, inv_kj;
    };
  } // namespace mca
} // namespace tribodyn

#endif
