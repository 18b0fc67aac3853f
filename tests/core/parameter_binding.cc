// Parameters declared once (core/parameter_binding.h, issue #52 item 3):
// a struct's binding declares its entries with the members' initial values
// as defaults, and parses a file into the members; a value out of range is
// refused with the entry's full path; a default spelled by hand
// (add_spelled) must read back to its member. exact_number(), which writes
// those defaults and the numbers of a checkpoint's parameter lines, reads back
// to the same double (an exact identity) for 2e5 random doubles over 600
// decades and for the hand-written defaults it replaces.
#include "../test_utilities.h"

#include <deal.II/base/mpi.h>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>

using namespace tribodyn;
using tribodyn_test::check;

namespace
{
  enum class Colour
  {
    red,
    green
  };
  constexpr SelectionTable<Colour, 2> colours{
    {{"red", Colour::red}, {"green", Colour::green}}};

  struct Toy
  {
    double       length  = 0.5e6;
    unsigned int count   = 7;
    bool         on      = true;
    std::string  name    = "pin";
    Colour       colour  = Colour::green;
    double       speed   = -2;
    double       initial = 0;
    double       modulus = 31.9e9;

    ParameterBinding
    binding()
    {
      ParameterBinding b("Outer/Inner");
      b.add("Length",
            length,
            "A length (m).",
            dealii::Patterns::Double(),
            Interval{0, 1e9, true, false});
      b.add("Count", count, "A count.", dealii::Patterns::Integer(1, 100));
      b.add("On", on, "A switch.");
      b.add("Name", name, "A name.");
      b.add("Colour", colour, "A colour.", colours);
      b.add("Speed", speed, "A speed (m/s).");
      b.add_spelled("Modulus", modulus, "31.9e9", "A modulus (Pa).");
      b.add("Pair",
            "1, 2",
            "Two numbers.",
            dealii::Patterns::Anything(),
            [this](const std::string &text) {
              initial = std::stod(text.substr(text.find(',') + 1));
            });
      return b;
    }
  };
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 1. declared from the members' initial values
  dealii::ParameterHandler prm;
  Toy().binding().declare(prm);
  prm.enter_subsection("Outer");
  prm.enter_subsection("Inner");
  check(prm.get("Length") == "5e5" && prm.get("Count") == "7"
          && prm.get("On") == "true" && prm.get("Name") == "pin"
          && prm.get("Colour") == "green" && prm.get("Speed") == "-2"
          && prm.get("Pair") == "1, 2" && prm.get("Modulus") == "31.9e9",
        "defaults are the members' initial values: Length = "
          + prm.get("Length") + ", Colour = " + prm.get("Colour"));
  prm.leave_subsection();
  prm.leave_subsection();

  // 2. a file parsed into the members; the others keep their defaults
  std::istringstream file("subsection Outer\n subsection Inner\n"
                          "  set Length = 2.5e-4\n  set Colour = red\n"
                          "  set Pair = 3, 4.5\n end\nend\n");
  prm.parse_input(file);
  Toy toy;
  toy.length = toy.speed = -1;
  toy.binding().parse(prm);
  check(toy.length == 2.5e-4 && toy.colour == Colour::red && toy.count == 7
          && toy.speed == -2 && toy.initial == 4.5,
        "parsed: Length 2.5e-4, Colour red, Pair 4.5; Count, Speed default");

  // 3. out of range: refused with the full path
  std::istringstream bad("subsection Outer\n subsection Inner\n"
                         "  set Length = 0\n end\nend\n");
  prm.parse_input(bad);
  std::string message;
  try
    {
      Toy().binding().parse(prm);
    }
  catch (const InputError &e)
    {
      message = e.what();
    }
  check(message.find("'Outer/Inner/Length'") != std::string::npos,
        "Length = 0 refused naming 'Outer/Inner/Length': " + message);

  // 4. a default given in another spelling than exact_number's must read
  // back to the member: one that drifted from it is refused on declaring
  Toy drifted;
  drifted.modulus = 32e9;
  std::string drift;
  try
    {
      dealii::ParameterHandler other;
      drifted.binding().declare(other);
    }
  catch (const std::logic_error &e)
    {
      drift = e.what();
    }
  check(drift.find("'Outer/Inner/Modulus'") != std::string::npos,
        "a spelled default that does not read back to its member (31.9e9 "
        "against 32e9) refused: "
          + drift);

  // 5. exact_number reads back exactly
  std::mt19937_64                        random(2026);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int>     power(-300, 300);
  unsigned int                           wrong = 0;
  for (unsigned int k = 0; k < 200000; ++k)
    {
      const double x = std::ldexp(mantissa(random), power(random) * 3);
      if (std::stod(exact_number(x)) != x)
        ++wrong;
    }
  check(wrong == 0,
        "exact_number reads back exactly for 2e5 random doubles ("
          + std::to_string(wrong) + " wrong)");
  const char *hand[][2]  = {{"0.5e6", "5e5"},
                            {"28e-3", "0.028"},
                            {"0.25e-3", "2.5e-4"},
                            {"10", "10"},
                            {"1.1e-9", "1.1e-9"},
                            {"-2", "-2"},
                            {"0.9", "0.9"},
                            {"300e6", "3e8"},
                            {"100e-6", "1e-4"},
                            {"0", "0"}};
  bool        as_written = true;
  for (const auto &h : hand)
    as_written = as_written && exact_number(std::stod(h[0])) == h[1];
  check(as_written,
        "hand-written defaults respelled with the fewest digits "
        "(0.5e6 -> 5e5, 28e-3 -> 0.028, 10 -> 10, ...)");

  return tribodyn_test::result();
}
