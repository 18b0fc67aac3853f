// The one table of per-automaton arrays of the automata (issue #52 item 1),
// as PairFieldTable is for the pairs: each array is registered once, with
// what it is to the system, and that registration drives its storage
// (resize), its order along the curve, the migration record of an automaton
// that changes rank, the checkpoint and the memory accounting.
#ifndef tribodyn_mca_automaton_fields_h
#define tribodyn_mca_automaton_fields_h

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <tribodyn/core/archive_fwd.h>
#include <type_traits>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, typename Number>
  class Point;
} // namespace dealii

namespace tribodyn
{
  namespace mca
  {
    /**
     * What a per-automaton array is to the system. Its rows are the local
     * automata (owned first, then ghosts) unless its documentation says
     * otherwise.
     */
    enum class AutomatonFieldKind : unsigned char
    {
      /// The automaton's identity and place (id, position, cell): sized,
      /// ordered, moved and checkpointed with the automaton; a migrating
      /// automaton carries it in the record's head (particle id and
      /// location), written by the caller.
      identity,
      /// Its state that travels with it: in the migration record (pair-list
      /// rebuilds, repartitions, restarts on another number of ranks),
      /// sized, ordered, moved and checkpointed.
      carried,
      /// State that lives from one step to the next but is set anew by its
      /// owner at a rebuild (positions at the rebuild, many-body state,
      /// inverse fabric tensors): checkpointed only.
      step,
      /// A per-step buffer, rebuilt before use: memory accounting only.
      scratch
    };

    namespace internal
    {
      /// Rows a migration record can carry: numbers and arrays of numbers.
      template <typename T>
      struct RowDoubles
      {
        static constexpr unsigned int value = std::is_arithmetic_v<T> ? 1 : 0;
      };
      template <typename T, std::size_t N>
      struct RowDoubles<std::array<T, N>>
      {
        static constexpr unsigned int value = N;
      };
      template <int dim, typename Number>
      struct RowDoubles<dealii::Point<dim, Number>>
      {
        static constexpr unsigned int value = dim;
      };

      /// A checkpoint's rows as raw bytes (the row count, then the bytes).
      void
      save_rows(boost::archive::binary_oarchive &ar,
                const void                      *data,
                std::size_t                      n_rows,
                std::size_t                      row_bytes);
      /// Read rows saved by save_rows(): @p resize(n) sizes the array and
      /// returns its data.
      void
      load_rows(boost::archive::binary_iarchive          &ar,
                const std::function<void *(std::size_t)> &resize,
                std::size_t                               row_bytes);
    } // namespace internal

    /// One registered array, whatever its element type.
    class AutomatonFieldArray
    {
    public:
      virtual ~AutomatonFieldArray() = default;
      /// Doubles of a row in a migration record (carried fields).
      virtual unsigned int
      width() const = 0;
      /// Resize to @p n rows, new rows with all components @p value.
      virtual void
      resize(std::size_t n, double value)
        = 0;
      virtual void
      pack(unsigned int k, double *out) const = 0;
      virtual void
      unpack(unsigned int k, const double *in)
        = 0;
      virtual void
      move(unsigned int from, unsigned int to)
        = 0;
      /// Row k becomes the old row perm[k], for k < perm.size().
      virtual void
      permute(const std::vector<unsigned int> &perm)
        = 0;
      virtual std::size_t
      memory_consumption() const = 0;
      virtual void
      save(boost::archive::binary_oarchive &ar) const = 0;
      virtual void
      load(boost::archive::binary_iarchive &ar)
        = 0;
    };

    /// One per-automaton array: its name, its kind, the value of a new row
    /// and whether the scene uses it.
    struct AutomatonField
    {
      const char                          *name;
      AutomatonFieldKind                   kind;
      std::shared_ptr<AutomatonFieldArray> array;
      /// All components of a new row (identity and carried fields).
      double new_value = 0;
      /// Whether the scene allocates it (an unused array stays empty; a
      /// migration record then holds new_value); always when empty.
      std::function<bool()> in_use = {};
      /// Whether a ghost of the automaton on a neighbour rank holds it (in
      /// the ghost record of a rebuild; the kinematics of the ghosts are
      /// updated every step apart).
      bool to_ghosts = false;
    };

    /**
     * The per-automaton arrays of AutomatonSystem, each registered once
     * (AutomatonSystem::register_automaton_fields()) in checkpoint order. A
     * new per-automaton array is one add() there: nothing else lists them.
     */
    class AutomatonFieldTable
    {
    public:
      /// Register @p vec (its element type trivially copyable: checkpoints
      /// write it as raw bytes).
      template <typename T>
      AutomatonField &
      add(const char              *name,
          const AutomatonFieldKind kind,
          std::vector<T>          &vec,
          const double             new_value = 0,
          std::function<bool()>    in_use    = {});

      /// Doubles of an automaton's migration record beyond its id and
      /// position (fixed: a field not in use writes its new value).
      /// Numbers travel as doubles, 64-bit integers as their bits.
      unsigned int
      record_width() const;
      /// Doubles of a ghost record (the fields sent to ghosts).
      unsigned int
      ghost_width() const;
      /// The fields of automaton @p k its ghosts hold, to
      /// @p out[0 .. ghost_width()).
      void
      pack_ghost(unsigned int k, double *out) const;
      /// Ghost @p k from a record of pack_ghost().
      void
      unpack_ghost(unsigned int k, const double *in) const;
      /// Identity and carried fields in use to @p n rows.
      void
      resize(std::size_t n) const;
      /// The carried fields of automaton @p k to @p out[0 .. record_width()).
      void
      pack(unsigned int k, double *out) const;
      /// The carried fields of automaton @p k from a record of pack().
      void
      unpack(unsigned int k, const double *in) const;
      /// Row @p from of the identity and carried fields to row @p to.
      void
      move(unsigned int from, unsigned int to) const;
      /// Rows of the identity and carried fields in the order @p perm.
      void
      permute(const std::vector<unsigned int> &perm) const;
      /// Every field but the scratch ones, in registration order.
      void
      save(boost::archive::binary_oarchive &ar) const;
      void
      load(boost::archive::binary_iarchive &ar) const;
      /// Bytes held by the registered arrays (their capacity), field by
      /// field: (name, bytes) appended to @p parts (fields of one name,
      /// such as the scratch buffers, summed).
      void
      memory_by_field(
        std::vector<std::pair<std::string, std::size_t>> &parts) const;

    private:
      /// Does the scene use @p field (allocate it)?
      static bool
      in_use(const AutomatonField &field);
      /// Is @p field an identity or carried field the scene uses (sized,
      /// moved and ordered with the automata)?
      bool
      sized(const AutomatonField &field) const;

      std::vector<AutomatonField> fields;
    };


    namespace internal
    {
      template <typename T>
      class TypedAutomatonFieldArray : public AutomatonFieldArray
      {
      public:
        explicit TypedAutomatonFieldArray(std::vector<T> &vec)
            : vec(vec)
        {
        }
        unsigned int
        width() const override
        {
          return RowDoubles<T>::value;
        }
        void
        resize(const std::size_t n, const double value) override
        {
          vec.resize(n, filled(value));
        }
        void
        pack(const unsigned int k, double *out) const override
        {
          if constexpr (std::is_same_v<T, std::uint64_t>)
            std::memcpy(out, &vec[k], sizeof(double));
          else if constexpr (std::is_arithmetic_v<T>)
            out[0] = static_cast<double>(vec[k]);
          else if constexpr (RowDoubles<T>::value > 0)
            for (unsigned int c = 0; c < RowDoubles<T>::value; ++c)
              out[c] = static_cast<double>(vec[k][c]);
        }
        void
        unpack(const unsigned int k, const double *in) override
        {
          if constexpr (std::is_same_v<T, std::uint64_t>)
            std::memcpy(&vec[k], in, sizeof(double));
          else if constexpr (std::is_arithmetic_v<T>)
            vec[k] = static_cast<T>(in[0]);
          else if constexpr (RowDoubles<T>::value > 0)
            for (unsigned int c = 0; c < RowDoubles<T>::value; ++c)
              vec[k][c] = static_cast<std::decay_t<decltype(vec[k][c])>>(in[c]);
        }
        void
        move(const unsigned int from, const unsigned int to) override
        {
          vec[to] = vec[from];
        }
        void
        permute(const std::vector<unsigned int> &perm) override
        {
          const std::vector<T> copy = vec;
          for (unsigned int k = 0; k < perm.size(); ++k)
            vec[k] = copy[perm[k]];
        }
        std::size_t
        memory_consumption() const override
        {
          return vec.capacity() * sizeof(T);
        }
        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          save_rows(ar, vec.data(), vec.size(), sizeof(T));
        }
        void
        load(boost::archive::binary_iarchive &ar) override
        {
          load_rows(
            ar,
            [this](const std::size_t n) -> void * {
              vec.resize(n);
              return vec.data();
            },
            sizeof(T));
        }

      private:
        static T
        filled(const double value)
        {
          T row{};
          if constexpr (std::is_arithmetic_v<T>)
            row = static_cast<T>(value);
          else if constexpr (RowDoubles<T>::value > 0)
            for (unsigned int c = 0; c < RowDoubles<T>::value; ++c)
              row[c] = static_cast<std::decay_t<decltype(row[c])>>(value);
          return row;
        }
        std::vector<T> &vec;
      };
    } // namespace internal


    template <typename T>
    AutomatonField &
    AutomatonFieldTable::add(const char              *name,
                             const AutomatonFieldKind kind,
                             std::vector<T>          &vec,
                             const double             new_value,
                             std::function<bool()>    in_use)
    {
      static_assert(std::is_trivially_copyable_v<T>,
                    "checkpoints write a per-automaton array as raw bytes");
      if (kind == AutomatonFieldKind::carried
          && internal::RowDoubles<T>::value == 0)
        throw std::logic_error(std::string("per-automaton field '") + name
                               + "' cannot be carried in a migration record "
                                 "(numbers or arrays of numbers only)");
      fields.push_back(
        {name,
         kind,
         std::make_shared<internal::TypedAutomatonFieldArray<T>>(vec),
         new_value,
         std::move(in_use)});
      return fields.back();
    }
  } // namespace mca
} // namespace tribodyn

#endif
