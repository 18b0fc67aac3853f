#ifndef tribodyn_mca_record_bits_h
#define tribodyn_mca_record_bits_h

// Raw 64-bit keys carried in the double records that automata and pair
// states travel in between ranks (rebuild.cc, automaton_partition.cc).

#include <cstdint>
#include <cstring>

namespace tribodyn
{
  namespace mca
  {
    namespace records
    {
      inline double
      bits_to_double(const std::uint64_t k)
      {
        double v;
        std::memcpy(&v, &k, sizeof(v));
        return v;
      }

      inline std::uint64_t
      double_to_bits(const double v)
      {
        std::uint64_t k;
        std::memcpy(&k, &v, sizeof(k));
        return k;
      }

      /// Key of the pair of automata @p a and @p b: the smaller id in the
      /// upper 32 bits (the same on both sides).
      inline std::uint64_t
      pair_key(const std::uint32_t a, const std::uint32_t b)
      {
        return a < b ? (std::uint64_t(a) << 32 | b)
                     : (std::uint64_t(b) << 32 | a);
      }
    } // namespace records
  }   // namespace mca
} // namespace tribodyn

#endif
