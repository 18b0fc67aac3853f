// The one table of persistent pair fields of the automata (issue #17 item
// 3): what a pair carries from one pair list to the next.
#ifndef tribodyn_mca_pair_fields_h
#define tribodyn_mca_pair_fields_h

#include <cstdint>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * How a persistent pair field changes when its pair is relabelled: the
     * i of a pair is the automaton of smaller order key, which changes when
     * automata change cells, so the sides of a pair can exchange at a
     * rebuild (doc/theory/mca.md §3).
     */
    enum class Relabel : unsigned char
    {
      /// unchanged (bond and contact flags, plastic heat)
      even,
      /// negated: vectors that follow x_j - x_i (shear stress, the
      /// relative-rotation moment on i)
      odd,
      /// the two arrays of the field hold side i and side j: they exchange
      /// (normal stresses, shear factors)
      sides,
      /// a value of side i becomes r - value (q_i, the distance of i to the
      /// contact point, q_j = r - q_i)
      complement
    };

    /// One persistent pair field: its arrays, its relabelling rule and the
    /// value a new pair starts with.
    struct PairField
    {
      const char *name;
      Relabel     rule;
      /// Value of a new pair (complement fields: a fraction of the pair
      /// distance instead, e.g. 1/2 for q_i).
      double new_value;
      /// Arrays of doubles: the components (odd and even vector fields),
      /// or side i then side j (sides), or one array.
      std::vector<std::vector<double> *> arrays;
      /// Or one array of 0/1 flags (even).
      std::vector<unsigned char> *flags = nullptr;
      /// Whether the field is allocated in this scene (an unused field's
      /// arrays stay empty and are not carried); always when empty.
      std::function<bool()> in_use;
      /// Value of new pair p when set (even fields whose start depends on
      /// the pair, e.g. the contact area of a pair of graded automata);
      /// otherwise new_value.
      std::function<double(unsigned int)> new_value_of;

      /// Doubles of a pair state record.
      unsigned int
      width() const
      {
        return flags != nullptr ? 1 : arrays.size();
      }
    };

    /**
     * The persistent pair fields of AutomatonSystem, each registered once
     * with its rule. Everything that carries pair states goes through it:
     * the states of migrating pairs (pack()), the pair states over a
     * rebuild (remap()), checkpoints (for_each_array()) and the memory
     * accounting. A new pair field is one add() in
     * AutomatonSystem::register_pair_fields().
     */
    class PairFieldTable
    {
    public:
      /// Source of a new pair's state in remap(): an old pair of this rank
      /// (its index), a received state (received | index), or none.
      static constexpr std::uint32_t none     = 0xffffffffu;
      static constexpr std::uint32_t received = 0x80000000u;

      void
      add(PairField field);

      /// Doubles of a pair state record (the key not included).
      unsigned int
      width() const;

      /**
       * Write the state of pair @p p in id order (as if its i were the
       * automaton of smaller id; @p swap: its i has the larger id) to
       * @p out[0 .. width()). @p distance: the pair distance.
       */
      void
      pack(const unsigned int p,
           const bool         swap,
           const double       distance,
           double            *out) const;

      /**
       * Replace every field in use by its values on the new pair list: new
       * pair p takes the state @p source[p] (an old index into the current
       * arrays, received | index of a record in @p records (stride
       * width()), or none: the field's new value), with the sides
       * exchanged where @p swap[p]. @p distance(p): the new pair distance.
       * At most two scratch arrays live at a time.
       */
      void
      remap(const std::vector<std::uint32_t>      &source,
            const std::vector<unsigned char>      &swap,
            const std::vector<double>             &records,
            const std::function<double(unsigned)> &distance) const;

      /// Keep the pairs p with @p keep[p] (in order) in every field in use.
      void
      compact(const std::vector<unsigned char> &keep) const;

      /// Call @p f on every array of every field, in registration order
      /// (also those not in use: they are empty), flag arrays through
      /// @p g.
      template <typename F, typename G>
      void
      for_each_array(const F &f, const G &g) const
      {
        for (const PairField &field : fields)
          if (field.flags != nullptr)
            g(*field.flags);
          else
            for (std::vector<double> *a : field.arrays)
              f(*a);
      }

      /// Bytes held by the fields' arrays, field by field: ("pair " +
      /// name, bytes) appended to @p parts.
      void
      memory_by_field(
        std::vector<std::pair<std::string, std::size_t>> &parts) const;

      /// Bytes per pair of the fields in use.
      std::size_t
      bytes_per_pair() const;

    private:
      std::vector<PairField> fields;
    };

    namespace internal
    {
      template <class Tuple, std::size_t... I>
      void
      register_law_pair_fields(PairFieldTable     &table,
                               Tuple              &laws,
                               const unsigned int &selected,
                               std::index_sequence<I...>)
      {
        (std::get<I>(laws).register_pair_fields(
           table, [&selected] { return selected == I; }),
         ...);
      }
    } // namespace internal

    /// Register the persistent pair fields of every law of a list (the
    /// tuple @p laws), each in use only while it is the @p selected one:
    /// the checkpoint layout is the same for every choice.
    template <class... Laws>
    void
    register_law_pair_fields(PairFieldTable      &table,
                             std::tuple<Laws...> &laws,
                             const unsigned int  &selected)
    {
      internal::register_law_pair_fields(table,
                                         laws,
                                         selected,
                                         std::index_sequence_for<Laws...>());
    }
  } // namespace mca
} // namespace tribodyn

#endif
