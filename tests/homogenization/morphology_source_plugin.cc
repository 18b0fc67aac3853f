// A new morphology source is one file (issue #52 item 6): this test adds a
// source the way a contributor would (a class and a registration line in
// this file, nothing else in tribodyn): 'checkerboard', squares of
// `Morphology/Checker size` pixels, the heterogeneity on the odd ones. It
// checks that
//
// - `tribodyn --print-parameters homogenization` lists it among the
//   choices of `Morphology/Generator`, with its text, and declares its
//   entry with its documentation;
// - a run with `Generator = checkerboard` reads the entry and uses the map
//   the source makes: an 8 x 8 pixel map with squares of 2 has a
//   heterogeneity fraction of 1/2 (the cells' areas summed: to 1e-12) and
//   8 heterogeneities (squares
//   touching at corners are not connected), and since the map is its own
//   transpose on a square mesh, C11 = C22 for KUBC, SUBC and periodic
//   conditions (measured: equal to the last bit; allowed 1e-7 relative,
//   the solver's tolerance);
// - the source's own check refuses a size that does not divide the pixels,
//   naming its entry (exit code 2).
#include "../run_parameter_text.h"
#include "../test_utilities.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/core/output.h>

namespace
{
  class CheckerboardMorphology : public tribodyn::MorphologySource
  {
  public:
    unsigned int size = 1;

    void
    bind(tribodyn::ParameterBinding &b) override
    {
      b.add("Checker size",
            size,
            "Side of a checkerboard square, in pixels (test plugin).",
            dealii::Patterns::Integer(1));
    }

    void
    parse(dealii::ParameterHandler &,
          const tribodyn::ParameterBinding &b,
          tribodyn::MorphologyParameters   &common) override
    {
      tribodyn::check_parameter(common.n_pixels_x % size == 0
                                  && common.n_pixels_y % size == 0,
                                b.path("Checker size"),
                                "the squares must tile the pixels.");
    }

    tribodyn::Morphology
    create(const tribodyn::MorphologyParameters &p) const override
    {
      std::vector<unsigned int> ids(std::size_t(p.n_pixels_x) * p.n_pixels_y);
      for (unsigned int j = 0; j < p.n_pixels_y; ++j)
        for (unsigned int i = 0; i < p.n_pixels_x; ++i)
          ids[std::size_t(j) * p.n_pixels_x + i] = (i / size + j / size) % 2;
      return tribodyn::Morphology(p.width,
                                  p.height,
                                  p.n_pixels_x,
                                  p.n_pixels_y,
                                  ids,
                                  "checkerboard",
                                  tribodyn::Morphology::connected_groups);
    }
  };

  const bool registered = tribodyn::MorphologySources::add(
    {"checkerboard", 10, "squares of 'Checker size' pixels", [] {
       return std::make_unique<CheckerboardMorphology>();
     }});

  std::string
  prm(const unsigned int size)
  {
    return R"(
set Problem          = homogenization
set Output directory = output-morphology-source-plugin
subsection Morphology
  set Generator    = checkerboard
  set Checker size = )"
           + std::to_string(size) + R"(
  set Width        = 0.0008
  set Height       = 0.0008
  set Pixels in x  = 8
  set Pixels in y  = 8
end
subsection Cell problem
  set Boundary conditions = KUBC, SUBC, periodic
end
subsection Output
  set Write fields     = false
  set Write morphology = false
end
)";
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribodyn_test::check;
  (void)registered;

  // The parameter reference.
  {
    int               code = 0;
    const std::string text
      = tribodyn_test::printed_parameters("homogenization", code);
    check(code == 0
            && text.find("see the subsection 'Image'), 'checkerboard' "
                         "(squares of 'Checker size' pixels).")
                 != std::string::npos,
          "the reference lists 'checkerboard' among the generators, with its "
          "text, after 'image' (order 10)");
    check(text.find("Side of a checkerboard square, in pixels (test "
                    "plugin).")
              != std::string::npos
            && text.find("set Checker size") != std::string::npos,
          "the reference declares 'Checker size' with its documentation");
  }

  // A run on the plugin's map.
  check(tribodyn_test::run_parameter_text("morphology_source_plugin.prm",
                                          prm(2))
          == 0,
        "the run with 'Generator = checkerboard' succeeds");
  std::ifstream        in("output-morphology-source-plugin/summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  check(std::abs(summary.at("volume_fraction").get<double>() - 0.5) < 1e-12
          && summary.at("n_heterogeneities").get<unsigned int>() == 8,
        "the map is the source's: fraction 1/2 and 8 squares ("
          + summary.at("volume_fraction").dump() + ", "
          + summary.at("n_heterogeneities").dump() + ")");
  for (const std::string bc : {"KUBC", "SUBC", "periodic"})
    {
      const auto  &C   = summary.at(bc).at("C");
      const double c11 = C[0][0].get<double>(), c22 = C[1][1].get<double>();
      const double c12 = C[0][1].get<double>();
      check(std::abs(c11 - c22) <= 1e-7 * c11 && c12 > 0 && c11 > c12,
            bc + ": C11 = C22 on the transpose-symmetric map ("
              + tribodyn::format_number(c11) + ", "
              + tribodyn::format_number(c22) + ")");
    }

  // The source's own refusal.
  std::string errors;
  const int   code
    = tribodyn_test::run_parameter_text("morphology_source_plugin_bad.prm",
                                        prm(3),
                                        errors);
  check(code == 2
          && errors.find("'Morphology/Checker size'") != std::string::npos
          && errors.find("the squares must tile the pixels")
               != std::string::npos,
        "a size of 3 on 8 pixels is refused naming 'Morphology/Checker "
        "size' (exit code "
          + std::to_string(code) + ")");

  // A second source under a registered name is a programming error
  // (add_registered(), shared with the plugin lists), and the list keeps
  // its first one.
  bool refused = false;
  try
    {
      tribodyn::MorphologySources::add(
        {"checkerboard", 11, "again", [] {
           return std::make_unique<CheckerboardMorphology>();
         }});
    }
  catch (const std::logic_error &e)
    {
      refused
        = std::string(e.what()).find("'checkerboard'") != std::string::npos;
    }
  unsigned int n_checkerboards = 0;
  for (const auto &e : tribodyn::MorphologySources::list())
    n_checkerboards += e.name == "checkerboard";
  check(refused && n_checkerboards == 1,
        "a second 'checkerboard' is refused (std::logic_error naming it) "
        "and the list keeps one");
  return tribodyn_test::result();
}
