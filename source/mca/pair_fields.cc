// The table of persistent pair fields: packing, remapping over a rebuild,
// memory accounting (issue #17 item 3).

#include <tribodyn/mca/pair_fields.h>

namespace tribodyn
{
  namespace mca
  {
    void
    PairFieldTable::add(PairField field)
    {
      if (!field.in_use)
        field.in_use = [] { return true; };
      fields.push_back(std::move(field));
    }


    unsigned int
    PairFieldTable::width() const
    {
      unsigned int w = 0;
      for (const PairField &field : fields)
        w += field.width();
      return w;
    }


    void
    PairFieldTable::pack(const unsigned int p,
                         const bool         swap,
                         const double       distance,
                         double            *out) const
    {
      for (const PairField &field : fields)
        {
          const unsigned int w = field.width();
          if (!field.in_use())
            {
              for (unsigned int c = 0; c < w; ++c)
                *out++ = field.new_value;
              continue;
            }
          if (field.flags != nullptr)
            {
              *out++ = (*field.flags)[p];
              continue;
            }
          const auto &a = field.arrays;
          switch (field.rule)
            {
              case Relabel::even:
                for (unsigned int c = 0; c < w; ++c)
                  *out++ = (*a[c])[p];
                break;
              case Relabel::odd:
                for (unsigned int c = 0; c < w; ++c)
                  *out++ = swap ? -(*a[c])[p] : (*a[c])[p];
                break;
              case Relabel::sides:
                *out++ = swap ? (*a[1])[p] : (*a[0])[p];
                *out++ = swap ? (*a[0])[p] : (*a[1])[p];
                break;
              case Relabel::complement:
                *out++ = swap ? distance - (*a[0])[p] : (*a[0])[p];
                break;
            }
        }
    }


    void
    PairFieldTable::remap(const std::vector<std::uint32_t>      &source,
                          const std::vector<unsigned char>      &swap,
                          const std::vector<double>             &records,
                          const std::function<double(unsigned)> &distance) const
    {
      const std::size_t   n_pairs = source.size();
      const unsigned int  stride  = width();
      unsigned int        offset  = 0; // of the field in a record
      std::vector<double> new_a, new_b;
      // The value of slot c of the field for the state o: an old pair's
      // array or a received record's slot (both as stored: in the old
      // pair's orientation, or in id order).
      auto old_value = [&](const std::vector<double> &array,
                           const std::uint32_t        o,
                           const unsigned int         c) {
        return (o & received) ? records[(o & ~received) * stride + offset + c]
                              : array[o];
      };
      for (const PairField &field : fields)
        {
          const unsigned int w = field.width();
          if (!field.in_use())
            {
              offset += w;
              continue;
            }
          if (field.flags != nullptr)
            {
              std::vector<unsigned char> f(n_pairs);
              for (std::size_t p = 0; p < n_pairs; ++p)
                {
                  const std::uint32_t o = source[p];
                  f[p]                  = o == none ? field.new_value != 0
                                          : (o & received)
                                            ? records[(o & ~received) * stride + offset] != 0
                                            : (*field.flags)[o];
                }
              field.flags->swap(f);
              offset += w;
              continue;
            }
          const auto &a = field.arrays;
          switch (field.rule)
            {
              case Relabel::even:
              case Relabel::odd:
                {
                  const double sign = field.rule == Relabel::odd ? -1 : 1;
                  for (unsigned int c = 0; c < w; ++c)
                    {
                      new_a.assign(n_pairs, field.new_value);
                      if (field.new_value_of)
                        for (std::size_t p = 0; p < n_pairs; ++p)
                          if (source[p] == none)
                            new_a[p] = field.new_value_of(p);
                      for (std::size_t p = 0; p < n_pairs; ++p)
                        if (source[p] != none)
                          {
                            const double v = old_value(*a[c], source[p], c);
                            new_a[p]       = swap[p] ? sign * v : v;
                          }
                      a[c]->swap(new_a);
                    }
                  break;
                }
              case Relabel::sides:
                new_a.assign(n_pairs, field.new_value);
                new_b.assign(n_pairs, field.new_value);
                for (std::size_t p = 0; p < n_pairs; ++p)
                  if (source[p] != none)
                    {
                      const double vi = old_value(*a[0], source[p], 0);
                      const double vj = old_value(*a[1], source[p], 1);
                      new_a[p]        = swap[p] ? vj : vi;
                      new_b[p]        = swap[p] ? vi : vj;
                    }
                a[0]->swap(new_a);
                a[1]->swap(new_b);
                break;
              case Relabel::complement:
                new_a.resize(n_pairs);
                for (std::size_t p = 0; p < n_pairs; ++p)
                  {
                    const double r = distance(p);
                    if (source[p] == none)
                      new_a[p] = field.new_value * r;
                    else
                      {
                        const double v = old_value(*a[0], source[p], 0);
                        new_a[p]       = swap[p] ? r - v : v;
                      }
                  }
                a[0]->swap(new_a);
                break;
            }
          offset += w;
        }
    }


    void
    PairFieldTable::compact(const std::vector<unsigned char> &keep) const
    {
      const auto squeeze = [&](auto &array) {
        if (array.size() != keep.size())
          return; // not allocated in this scene
        std::size_t q = 0;
        for (std::size_t p = 0; p < keep.size(); ++p)
          if (keep[p])
            array[q++] = array[p];
        array.resize(q);
      };
      for (const PairField &field : fields)
        if (field.in_use())
          {
            if (field.flags != nullptr)
              squeeze(*field.flags);
            else
              for (std::vector<double> *a : field.arrays)
                squeeze(*a);
          }
    }


    void
    PairFieldTable::memory_by_field(
      std::vector<std::pair<std::string, std::size_t>> &parts) const
    {
      for (const PairField &field : fields)
        {
          std::size_t bytes = 0;
          if (field.flags != nullptr)
            bytes = field.flags->capacity();
          else
            for (const std::vector<double> *a : field.arrays)
              bytes += a->capacity() * sizeof(double);
          parts.emplace_back(std::string("pair ") + field.name, bytes);
        }
    }


    std::size_t
    PairFieldTable::bytes_per_pair() const
    {
      std::size_t bytes = 0;
      for (const PairField &field : fields)
        if (field.in_use())
          bytes += field.flags != nullptr ? 1 : field.width() * sizeof(double);
      return bytes;
    }
  } // namespace mca
} // namespace tribodyn
