// The table of per-automaton arrays (include/tribodyn/mca/automaton_fields.h,
// issue #52 item 1): what one registration drives, checked exactly on a
// few arrays of each kind and type.
//
//  - a migration record and a ghost record carry their fields bit for bit
//    (64-bit order keys as their bits: a key above 2^53 would be rounded
//    as a double), and only theirs (record widths 3 + 1 + 1, 1 + 1 + 3);
//  - a field not in use stays empty, its slot in the record holds its new
//    value, and its unpack leaves it empty;
//  - resize fills new rows with each field's new value; move and permute
//    reorder the identity and carried fields only;
//  - a checkpoint (save, then load into cleared arrays) restores every
//    non-scratch field byte for byte, scratch ones untouched;
//  - memory_by_field() counts every registered array.
#include "../test_utilities.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <sstream>
#include <tribodyn/mca/automaton_fields.h>
#include <tribodyn/mca/parameters.h>

using namespace tribodyn_test;
using namespace tribodyn::mca;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::vector<std::uint32_t> id    = {7, 8, 9};
  std::vector<std::uint64_t> order = {(1ull << 60) + 1, 2, 3};
  std::vector<Point3>        x
    = {Point3(0.1, 0.2, 0.3), Point3(1, 2, 3), Point3(-1, -2, -3)};
  std::vector<std::array<double, 3>> v
    = {{{1, 2, 3}}, {{4, 5, 6}}, {{7, 8, 9}}};
  std::vector<unsigned char> mat    = {0, 1, 2};
  std::vector<double>        volume = {1.5, 2.5, 3.5};
  std::vector<double>        yield; // not in use
  std::vector<float>         step    = {0.25f, 0.5f, 0.75f};
  std::vector<double>        buffer  = {42, 43, 44};
  bool                       plastic = false;

  using Kind = AutomatonFieldKind;
  AutomatonFieldTable t;
  t.add("id", Kind::identity, id).to_ghosts      = true;
  t.add("order", Kind::step, order).to_ghosts    = true;
  t.add("position", Kind::identity, x).to_ghosts = true;
  t.add("velocity", Kind::carried, v);
  t.add("material", Kind::carried, mat).to_ghosts = true;
  t.add("volume", Kind::carried, volume, 9.75);
  t.add("yield", Kind::carried, yield, -1, [&] { return plastic; });
  t.add("step", Kind::step, step);
  t.add("buffer", Kind::scratch, buffer);

  check(t.record_width() == 3 + 1 + 1 + 1,
        "record width: velocity 3, material, volume, yield (not in use)");
  check(t.ghost_width() == 1 + 1 + 3 + 1,
        "ghost width: id, order, position 3, material");

  // migration record of automaton 1, unpacked into row 0
  std::vector<double> record(t.record_width());
  t.pack(1, record.data());
  check(record == std::vector<double>({4, 5, 6, 1, 2.5, -1}),
        "migration record: the carried fields, the unused one's new value");
  t.unpack(0, record.data());
  check(v[0] == v[1] && mat[0] == 1 && volume[0] == 2.5 && yield.empty()
          && id[0] == 7 && x[0] == Point3(0.1, 0.2, 0.3),
        "unpack: carried fields only, the unused field stays empty");

  // ghost record of automaton 0 (key above 2^53) into a new row 3
  std::vector<double> ghost(t.ghost_width());
  t.pack_ghost(0, ghost.data());
  t.resize(4);
  order.resize(4);
  t.unpack_ghost(3, ghost.data());
  check(id[3] == 7 && order[3] == order[0] && x[3] == x[0] && mat[3] == 1,
        "ghost record: id, 64-bit key bit for bit, position, material");
  check(volume[3] == 9.75 && v[3] == (std::array<double, 3>{{0, 0, 0}})
          && yield.empty() && step.size() == 3 && buffer.size() == 3,
        "resize: new value in new rows, unused, step and scratch untouched");

  // move and permute
  t.move(2, 1);
  check(id[1] == 9 && v[1] == v[2] && step[1] == 0.5f,
        "move: identity and carried fields, step fields untouched");
  t.permute({3, 0, 1});
  check(id[0] == 7 && id[1] == 7 && id[2] == 9 && volume[0] == 9.75
          && step[0] == 0.25f,
        "permute: rows in the new order, step fields untouched");

  // a field taken into use, then a checkpoint round trip
  plastic = true;
  t.resize(4);
  check(yield.size() == 4 && yield[2] == -1,
        "a field in use is sized with its new value");
  const auto        saved_id = id;
  const auto        saved_x  = x;
  const auto        saved_o  = order;
  const auto        saved_s  = step;
  const auto        saved_y  = yield;
  std::stringstream buf;
  {
    boost::archive::binary_oarchive ar(buf);
    t.save(ar);
  }
  id.assign(id.size(), 0);
  x.assign(2, Point3());
  order.clear();
  step.clear();
  yield.clear();
  buffer.assign(1, -7);
  {
    boost::archive::binary_iarchive ar(buf);
    t.load(ar);
  }
  check(id == saved_id && x == saved_x && order == saved_o && step == saved_s
          && yield == saved_y,
        "checkpoint: every non-scratch field restored");
  check(buffer == std::vector<double>(1, -7),
        "checkpoint: scratch fields neither saved nor loaded");

  const std::size_t expected
    = id.capacity() * 4 + order.capacity() * 8 + x.capacity() * 24
      + v.capacity() * 24 + mat.capacity() + volume.capacity() * 8
      + yield.capacity() * 8 + step.capacity() * 4 + buffer.capacity() * 8;
  std::vector<std::pair<std::string, std::size_t>> parts;
  t.memory_by_field(parts);
  std::size_t counted = 0;
  for (const auto &part : parts)
    counted += part.second;
  check(counted == expected, "memory: the capacity of every registered array");
  return result();
}
