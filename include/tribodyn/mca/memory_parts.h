// The memory accounting of the automata engine by part (name, bytes):
// AutomatonSystem::memory_by_part() and the parts that count their own
// arrays (PairList).
#ifndef tribodyn_mca_memory_parts_h
#define tribodyn_mca_memory_parts_h

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /// Parts of the memory and their bytes, in the order they are counted.
    using MemoryParts = std::vector<std::pair<std::string, std::size_t>>;

    /// Append the part @p name: the bytes the vectors @p vecs hold
    /// (capacity, not size: what the process keeps).
    template <class... Vectors>
    void
    add_memory_part(MemoryParts &parts,
                    const char  *name,
                    const Vectors &...vecs)
    {
      parts.emplace_back(name, ((vecs.capacity() * sizeof(vecs[0])) + ...));
    }
  } // namespace mca
} // namespace tribodyn

#endif
