// The table of per-automaton arrays (include/tribodyn/mca/automaton_fields.h).
#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/binary_object.hpp>
#include <tribodyn/mca/automaton_fields.h>

namespace tribodyn
{
  namespace mca
  {
    namespace internal
    {
      void
      save_rows(boost::archive::binary_oarchive &ar,
                const void                      *data,
                const std::size_t                n_rows,
                const std::size_t                row_bytes)
      {
        ar << n_rows;
        if (n_rows > 0)
          ar << boost::serialization::make_binary_object(
            const_cast<void *>(data), n_rows * row_bytes);
      }


      void
      load_rows(boost::archive::binary_iarchive          &ar,
                const std::function<void *(std::size_t)> &resize,
                const std::size_t                         row_bytes)
      {
        std::size_t n_rows = 0;
        ar >> n_rows;
        void *data = resize(n_rows);
        if (n_rows > 0)
          ar >> boost::serialization::make_binary_object(data,
                                                         n_rows * row_bytes);
      }
    } // namespace internal


    bool
    AutomatonFieldTable::in_use(const AutomatonField &field)
    {
      return !field.in_use || field.in_use();
    }


    bool
    AutomatonFieldTable::sized(const AutomatonField &field) const
    {
      return (field.kind == AutomatonFieldKind::identity
              || field.kind == AutomatonFieldKind::carried)
             && in_use(field);
    }


    unsigned int
    AutomatonFieldTable::record_width() const
    {
      unsigned int width = 0;
      for (const AutomatonField &field : fields)
        if (field.kind == AutomatonFieldKind::carried)
          width += field.array->width();
      return width;
    }


    unsigned int
    AutomatonFieldTable::ghost_width() const
    {
      unsigned int width = 0;
      for (const AutomatonField &field : fields)
        if (field.to_ghosts)
          width += field.array->width();
      return width;
    }


    void
    AutomatonFieldTable::pack_ghost(const unsigned int k, double *out) const
    {
      for (const AutomatonField &field : fields)
        if (field.to_ghosts)
          {
            const unsigned int w = field.array->width();
            if (in_use(field))
              field.array->pack(k, out);
            else
              std::fill(out, out + w, field.new_value);
            out += w;
          }
    }


    void
    AutomatonFieldTable::unpack_ghost(const unsigned int k,
                                      const double      *in) const
    {
      for (const AutomatonField &field : fields)
        if (field.to_ghosts)
          {
            if (in_use(field))
              field.array->unpack(k, in);
            in += field.array->width();
          }
    }


    void
    AutomatonFieldTable::resize(const std::size_t n) const
    {
      for (const AutomatonField &field : fields)
        if (sized(field))
          field.array->resize(n, field.new_value);
    }


    void
    AutomatonFieldTable::pack(const unsigned int k, double *out) const
    {
      for (const AutomatonField &field : fields)
        if (field.kind == AutomatonFieldKind::carried)
          {
            const unsigned int w = field.array->width();
            if (sized(field))
              field.array->pack(k, out);
            else
              std::fill(out, out + w, field.new_value);
            out += w;
          }
    }


    void
    AutomatonFieldTable::unpack(const unsigned int k, const double *in) const
    {
      for (const AutomatonField &field : fields)
        if (field.kind == AutomatonFieldKind::carried)
          {
            if (sized(field))
              field.array->unpack(k, in);
            in += field.array->width();
          }
    }


    void
    AutomatonFieldTable::move(const unsigned int from,
                              const unsigned int to) const
    {
      for (const AutomatonField &field : fields)
        if (sized(field))
          field.array->move(from, to);
    }


    void
    AutomatonFieldTable::permute(const std::vector<unsigned int> &perm) const
    {
      for (const AutomatonField &field : fields)
        if (sized(field))
          field.array->permute(perm);
    }


    void
    AutomatonFieldTable::save(boost::archive::binary_oarchive &ar) const
    {
      for (const AutomatonField &field : fields)
        if (field.kind != AutomatonFieldKind::scratch)
          field.array->save(ar);
    }


    void
    AutomatonFieldTable::load(boost::archive::binary_iarchive &ar) const
    {
      for (const AutomatonField &field : fields)
        if (field.kind != AutomatonFieldKind::scratch)
          field.array->load(ar);
    }


    void
    AutomatonFieldTable::memory_by_field(
      std::vector<std::pair<std::string, std::size_t>> &parts) const
    {
      for (const AutomatonField &field : fields)
        {
          const std::size_t bytes = field.array->memory_consumption();
          auto              same
            = std::find_if(parts.begin(), parts.end(), [&](const auto &part) {
                return part.first == field.name;
              });
          if (same != parts.end())
            same->second += bytes;
          else
            parts.emplace_back(field.name, bytes);
        }
    }
  } // namespace mca
} // namespace tribodyn
