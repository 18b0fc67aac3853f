// Carbon cylinders and voids of the composite scene (issue #8, seed 000
// section 2.2: R = 10 nm, L = 70 nm, ~2 % of the contacting part).
//
// Checks and tolerances:
// - the achieved cylinder fraction is the 2 % target to within half a
//   cylinder, 0.5 pi R^2 L / V (the count is round(target V / pi R^2 L):
//   here 0.5 / n < 1 % of the target; measured 0.73 %), and it is reported
//   exactly: n pi R^2 L / V to round-off (1e-12), and a
//   Monte Carlo estimate over the box through the index (images included)
//   agrees within 4 binomial standard deviations sqrt(f (1 - f) / N);
// - no two cylinders, over all pairs of primaries and all periodic shifts,
//   have axes closer than 2R + gap (exact geometric test, 1e-12 relative);
// - every primary whose bounding box crosses a periodic face has its images
//   (exact shifted copies) in the list;
// - aligned orientation: b - a = L e_z to round-off (1e-12 relative);
// - same seed: bitwise identical; different seed: different;
// - an unreachable fraction is refused with an InputError naming the
//   parameter; voids do not overlap cylinders.

#include "../test_utilities.h"

#include <tribodyn/core/errors.h>
#include <tribodyn/mca/inclusions.h>

using namespace tribodyn_test;
using namespace tribodyn::mca;
using Point3 = dealii::Point<3>;

namespace
{
  InclusionParameters
  seed_like_parameters()
  {
    // A contacting part of 0.6 x 0.6 x 0.2 um, periodic in x and y.
    InclusionParameters p;
    p.lower                    = Point3(0, 0, 0);
    p.upper                    = Point3(0.6e-6, 0.6e-6, 0.2e-6);
    p.periodic                 = {{true, true, false}};
    p.cylinder_radius          = 10e-9;
    p.cylinder_length          = 70e-9;
    p.cylinder_volume_fraction = 0.02;
    p.void_radius              = 15e-9;
    p.void_volume_fraction     = 0.005;
    p.gap                      = 7.5e-9; // one automaton size
    p.seed                     = 42;
    return p;
  }

  std::vector<dealii::Tensor<1, 3>>
  shifts(const InclusionParameters &p)
  {
    std::vector<dealii::Tensor<1, 3>> result;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k)
          {
            const int            m[3] = {i, j, k};
            dealii::Tensor<1, 3> s;
            bool                 ok = true;
            for (unsigned int d = 0; d < 3; ++d)
              {
                ok   = ok && (p.periodic[d] || m[d] == 0);
                s[d] = m[d] * (p.upper[d] - p.lower[d]);
              }
            if (ok)
              result.push_back(s);
          }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const InclusionParameters                p   = seed_like_parameters();
  const InclusionSet                       set = generate_inclusions(p);
  const double                             R   = p.cylinder_radius;
  const double                             L   = p.cylinder_length;
  const double                             V
    = (p.upper - p.lower)[0] * (p.upper - p.lower)[1] * (p.upper - p.lower)[2];
  std::cout << set.n_cylinders << " cylinders, " << set.n_voids << " voids, "
            << set.shapes.size() << " shapes with images" << std::endl;

  const double one_cylinder = M_PI * R * R * L / V;
  check_relative(set.cylinder_volume_fraction,
                 0.02,
                 (0.5 * one_cylinder / 0.02) * (1 + 1e-12),
                 "achieved cylinder fraction vs the 2 % target (within half "
                 "a cylinder)");
  check_relative(set.cylinder_volume_fraction,
                 set.n_cylinders * one_cylinder,
                 1e-12,
                 "reported fraction = n pi R^2 L / V");
  const InclusionIndex index(set.shapes, p.lower, p.upper, p.periodic);
  const unsigned int   N  = 400000;
  const double         mc = index.monte_carlo_volume_fraction(N, 7);
  const double f = set.cylinder_volume_fraction + set.void_volume_fraction;
  check_relative(mc,
                 f,
                 4 * std::sqrt(f * (1 - f) / N) / f,
                 "Monte Carlo fraction of the box (4 sigma) = exact");

  // Non-overlap over all pairs and periodic shifts (brute force).
  const auto all_shifts = shifts(p);
  double     closest    = 1e300; // min axis distance between cylinders
  double     closest_sv = 1e300; // min sphere-centre to cylinder-axis
  for (unsigned int i = 0; i < set.n_cylinders + set.n_voids; ++i)
    for (unsigned int j = 0; j < set.n_cylinders + set.n_voids; ++j)
      for (const auto &s : all_shifts)
        {
          if (i == j && s.norm() == 0)
            continue;
          const Inclusion &a = set.shapes[i];
          const Inclusion &b = set.shapes[j];
          if (i < set.n_cylinders && j < set.n_cylinders)
            closest
              = std::min(closest,
                         segment_segment_distance(a.a, a.b, b.a + s, b.b + s));
          if (i < set.n_cylinders && j >= set.n_cylinders)
            closest_sv
              = std::min(closest_sv,
                         segment_segment_distance(a.a, a.b, b.a + s, b.a + s));
        }
  check(closest >= (2 * R + p.gap) * (1 - 1e-12),
        "cylinder axes (incl. periodic images) >= 2R + gap apart: closest "
          + std::to_string(closest / R) + " R");
  check(closest_sv >= (R + p.void_radius + p.gap) * (1 - 1e-12),
        "void centres >= R_void + R + gap from cylinder axes");

  // Images of cylinders crossing periodic faces.
  unsigned int crossing = 0, missing = 0, all_in_z = 0;
  for (unsigned int i = 0; i < set.n_cylinders; ++i)
    {
      const auto bb = set.shapes[i].bounding_box();
      all_in_z += (bb.first[2] >= p.lower[2] - 1e-18
                   && bb.second[2] <= p.upper[2] + 1e-18);
      for (unsigned int d = 0; d < 2; ++d)
        for (const int side : {-1, 1})
          {
            const bool out
              = side < 0 ? bb.first[d] < p.lower[d] : bb.second[d] > p.upper[d];
            if (!out)
              continue;
            ++crossing;
            dealii::Tensor<1, 3> s;
            s[d]       = -side * (p.upper[d] - p.lower[d]);
            bool found = false;
            for (unsigned int k = 0; k < set.shapes.size(); ++k)
              found = found
                      || (set.primary[k] == i
                          && set.shapes[k].a.distance(set.shapes[i].a + s)
                               < 1e-12 * L);
            missing += !found;
          }
    }
  check(crossing > 0 && missing == 0,
        std::to_string(crossing) + " face crossings, each with its image ("
          + std::to_string(missing) + " missing)");
  check(all_in_z == set.n_cylinders,
        "cylinders stay inside the box in the non-periodic direction z");

  // Determinism.
  const InclusionSet again = generate_inclusions(p);
  bool               same  = again.shapes.size() == set.shapes.size();
  for (unsigned int k = 0; same && k < set.shapes.size(); ++k)
    same = set.shapes[k].a == again.shapes[k].a
           && set.shapes[k].b == again.shapes[k].b;
  check(same, "same seed: identical inclusions");
  InclusionParameters other = p;
  other.seed                = 43;
  check(generate_inclusions(other).shapes[0].a != set.shapes[0].a,
        "different seed: different inclusions");

  // Aligned orientation.
  InclusionParameters aligned = p;
  aligned.orientation         = InclusionOrientation::z;
  const InclusionSet z        = generate_inclusions(aligned);
  double             off      = 0;
  for (unsigned int k = 0; k < z.n_cylinders; ++k)
    {
      const auto axis = z.shapes[k].b - z.shapes[k].a;
      off             = std::max(
        {off, std::abs(axis[0]), std::abs(axis[1]), std::abs(axis[2] - L)});
    }
  check(off <= 1e-12 * L, "aligned with z: b - a = L e_z");

  // Membership through the index equals brute force on a grid of points
  // (including points outside the box in periodic directions).
  unsigned int disagreements = 0, inside = 0;
  for (unsigned int i = 0; i < 40; ++i)
    for (unsigned int j = 0; j < 40; ++j)
      for (unsigned int k = 0; k < 20; ++k)
        {
          const Point3 x(-0.3e-6 + i * 0.03e-6, j * 0.0151e-6, k * 0.01e-6);
          Point3       w = x; // wrapped into the box in x
          while (w[0] < 0)
            w[0] += 0.6e-6;
          while (w[0] >= 0.6e-6)
            w[0] -= 0.6e-6;
          bool brute = false;
          for (const auto &s : set.shapes)
            brute = brute || s.contains(w);
          const bool indexed = index.find(x) >= 0;
          disagreements += (brute != indexed);
          inside += indexed;
        }
  check(disagreements == 0 && inside > 0,
        "index membership = brute force on 32000 points ("
          + std::to_string(inside) + " inside)");

  bool refused = false;
  try
    {
      parse_inclusion_orientation("diagonal", "Inclusions/Orientation");
    }
  catch (const tribodyn::InputError &)
    {
      refused = true;
    }
  check(refused
          && parse_inclusion_orientation("y", "") == InclusionOrientation::y,
        "orientation names parsed, unknown one refused");

  // Unreachable target.
  InclusionParameters dense      = p;
  dense.cylinder_volume_fraction = 0.6;
  dense.void_volume_fraction     = 0;
  dense.max_attempts             = 2000;
  std::string message;
  try
    {
      generate_inclusions(dense);
    }
  catch (const tribodyn::InputError &e)
    {
      message = e.what();
    }
  check(message.find("Cylinder volume fraction") != std::string::npos,
        "60 % of cylinders refused naming the parameter: " + message);

  return result();
}
