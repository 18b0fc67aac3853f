// Tabulated friction mu(p, v) (`Friction law = tabulated`,
// include/tribodyn/contact/friction_table.h, friction_laws/tabulated.h).
// (a) The table: exact at its grid points (==), bilinear between them: a
//     bilinear function f = a + b p + c v + d p v on an uneven 3 x 4 grid
//     is reproduced at 200 points inside to 1e-14 (round-off); along a
//     grid line it is linear in the other variable; outside, p and v are
//     clamped to the edges and every such evaluation is counted.
// (b) The CSV reader: rows in any order, an extra column and comments give
//     the same table; a missing file, a missing column, an incomplete grid,
//     mu < 0 are refused (InputError naming the file and the cause).
// (c) A table that holds mu = 0.25 everywhere gives the held block of
//     block_drag.cc bit for bit as Coulomb's law with mu = 0.25 (the
//     plumbing changes nothing).
// (d) Pressure: on the held block sliding under P = 5 MPa, a table mu(p) =
//     0.2 + 0.02 p/MPa: at the end every slipping node carries |lambda_T| =
//     mu(p) lambda_N with its own contact pressure p = lambda_N / (its
//     tributary length: a cell, half a cell at the corners) to round-off
//     (1e-12); the pressures average to P (the nodes' lambda_N sum to P W
//     within 1 %, as block_drag.cc's reaction). The load-dependent map
//     (Pressure exponent m = 1/2, Reference pressure p_ref = 2 MPa,
//     Pressure scale 3) reads the same table at 3 p_ref (p / p_ref)^m: the
//     same check with that pressure (1e-12).
// (e) Speed: with `Speed = plane speed` and mu(v) = 0.1 + 0.05 v/(m/s), the
//     block sliding at |V| = 2 m/s has |sum lambda_T| = 0.2 sum lambda_N to
//     round-off (1e-12) once every node slips.
// (f) The clamped share (summary.json), once per node-step in contact and
//     by cause: a table of pressures 0-5 MPa on the held block (pressures
//     about 5 MPa) clamps a share above (0 < share < 1) and nothing below
//     or in speed, and the projected Gauss-Seidel path, which evaluates the
//     law in each of its sweeps, reports the same node-steps and shares as
//     the node-wise one (exact); a table of 1-2 GPa clamps every node-step
//     below, one of 10-100 m/s at the plane speed 2 m/s every node-step in
//     speed (exact: 1); a warning is printed above 1 % and not for the
//     constant table of (c), which clamps nothing.

#include "contact_test_tools.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <tribodyn/contact/friction_table.h>
#include <tribodyn/core/errors.h>

namespace
{
  double
  bilinear(const double p, const double v)
  {
    return 0.3 + 0.01 * p - 0.02 * v + 0.004 * p * v;
  }

  /// The message of the InputError @p f throws ("" if none).
  template <class F>
  std::string
  refusal(const F &f)
  {
    try
      {
        f();
      }
    catch (const tribodyn::InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  const std::string held_block = tribodyn_test::held_block_prm(2, 30e-6);
} // namespace


int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // (a)
  const std::vector<double> ps = {0., 1., 4.}, vs = {0.5, 1., 2., 10.};
  std::vector<double>       values;
  for (const double p : ps)
    for (const double v : vs)
      values.push_back(bilinear(p, v));
  const FrictionTable table(ps, vs, values);
  bool                exact = true;
  for (const double p : ps)
    for (const double v : vs)
      exact = exact && table(p, v) == bilinear(p, v);
  check(exact, "table: exact at the 12 grid points");
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> up(0., 4.), uv(0.5, 10.);
  double                                 worst = 0;
  for (unsigned int k = 0; k < 200; ++k)
    {
      const double p = up(random), v = uv(random);
      worst = std::max(worst,
                       std::abs(table(p, v) - bilinear(p, v)) / bilinear(p, v));
    }
  check(worst < 1e-14,
        "table: bilinear between the points (worst relative error "
          + std::to_string(worst) + ")");
  check(std::abs(table(1., 1.5) - 0.5 * (table(1., 1.) + table(1., 2.)))
          < 1e-15,
        "table: linear in v along p = 1");
  check(table.clamped() == 0, "table: nothing clamped inside");
  const bool edges = table(-1., 20.) == bilinear(0., 10.)
                     && table(9., 0.1) == bilinear(4., 0.5);
  check(edges && table.clamped() == 2,
        "table: clamped to the edges outside, each evaluation counted ("
          + std::to_string(table.clamped()) + ")");

  // (b)
  {
    std::ofstream csv("table.csv");
    csv << "# a comment\nspeed, mu ,pressure,mu_stderr\n"
        << std::setprecision(17);
    for (unsigned int k = ps.size(); k-- > 0;)
      for (const double v : vs)
        csv << v << "," << bilinear(ps[k], v) << "," << ps[k] << ",0.01\n";
  }
  const FrictionTable read("table.csv", "File");
  bool                same = true;
  for (const double p : {0., 0.3, 1., 2.5, 4.})
    for (const double v : {0.5, 0.7, 2., 9.})
      same = same && read(p, v) == table(p, v);
  check(same, "CSV: rows reordered, extra column, comment: the same table");
  write("no_mu.csv", "pressure,speed\n0,1\n");
  write("holes.csv", "pressure,speed,mu\n0,1,0.2\n0,2,0.2\n1,1,0.2\n");
  write("negative.csv",
        "pressure,speed,mu\n0,1,0.2\n0,2,0.2\n1,1,-0.2\n1,2,0.2\n");
  const std::string missing = refusal([] { FrictionTable("absent.csv", "F"); }),
                    no_mu   = refusal([] { FrictionTable("no_mu.csv", "F"); }),
                    holes   = refusal([] { FrictionTable("holes.csv", "F"); }),
                    negative
                    = refusal([] { FrictionTable("negative.csv", "F"); });
  check(missing.find("absent.csv") != std::string::npos
          && missing.find("cannot be read") != std::string::npos,
        "refused: missing file: " + missing);
  check(no_mu.find("no column 'mu'") != std::string::npos,
        "refused: no mu column: " + no_mu);
  check(holes.find("not a full grid") != std::string::npos,
        "refused: incomplete grid: " + holes);
  check(negative.find("< 0") != std::string::npos,
        "refused: negative mu: " + negative);

  // (c)
  write("constant.csv",
        "pressure,speed,mu\n0,0,0.25\n0,100,0.25\n1e9,0,0.25\n"
        "1e9,100,0.25\n");
  ContactRun  coulomb(held_block + R"(
    subsection Contact
      set Friction law = Coulomb
      set Friction coefficient = 0.25
    end)");
  ContactRun  tabulated(held_block + R"(
    subsection Contact
      set Friction law = tabulated
      subsection Tabulated friction
        set File = constant.csv
      end
    end)");
  const auto &a = coulomb.run(), &b = tabulated.run();
  bool        identical = a.size() == b.size();
  for (std::size_t k = 0; identical && k < a.size(); ++k)
    identical
      = a[k].mu_global == b[k].mu_global
        && a[k].contact_tangential_force == b[k].contact_tangential_force
        && a[k].M_ux == b[k].M_ux && a[k].M_status == b[k].M_status;
  check(identical,
        "constant table = Coulomb, bit for bit (" + std::to_string(a.size())
          + " samples)");

  // (d)
  write("pressure.csv",
        "pressure,speed,mu\n0,0,0.2\n0,100,0.2\n1e8,0,2.2\n"
        "1e8,100,2.2\n");
  for (const bool mapped : {false, true})
    {
      ContactRun run(held_block + R"(
      subsection Contact
        set Friction law = tabulated
        subsection Tabulated friction
          set File = pressure.csv
)"
                     + std::string(mapped ? R"(          set Pressure scale = 3
          set Pressure exponent = 0.5
          set Reference pressure = 2e6
)"
                                          : "")
                     + R"(        end
      end)");
      run.run();
      // the pressure the table is read at
      const auto table_pressure = [mapped](const double p) {
        return mapped ? 3 * 2e6 * std::sqrt(p / 2e6) : p;
      };
      const double h     = 0.25e-3;
      double       worst = 0, force = 0, p_min = 1e300, p_max = 0;
      unsigned int n_slip = 0;
      for (const ContactNode &node : run.solver->contact_node_states())
        {
          const bool   corner = node.x < 0.5 * h || node.x > 4e-3 - 0.5 * h;
          const double p      = node.lambda_n / (corner ? 0.5 * h : h);
          force += node.lambda_n;
          if (node.status != slip)
            continue;
          ++n_slip;
          p_min = std::min(p_min, p);
          p_max = std::max(p_max, p);
          worst = std::max(worst,
                           std::abs(std::abs(node.lambda_t)
                                    - (0.2 + 0.02 * table_pressure(p) / 1e6)
                                        * node.lambda_n)
                             / node.lambda_n);
        }
      check(n_slip > 10 && worst < 1e-12,
            std::string(mapped ? "mu(3 p_ref (p / p_ref)^(1/2)), p = lambda_N "
                                 "/ length"
                               : "mu(p)")
              + ": |lambda_T| = mu lambda_N at each of the "
              + std::to_string(n_slip) + " slipping nodes (worst "
              + std::to_string(worst) + "; p from "
              + std::to_string(p_min / 1e6) + " to "
              + std::to_string(p_max / 1e6) + " MPa)");
      // (the held block's reaction, with the unmapped table)
      if (!mapped)
        check_relative(force,
                       5e6 * 4e-3,
                       0.01,
                       "sum lambda_N = P W at the end");
    }

  // (e)
  write("speed.csv",
        "pressure,speed,mu\n0,0,0.1\n0,4,0.3\n1e9,0,0.1\n"
        "1e9,4,0.3\n");
  {
    ContactRun  run(held_block + R"(
      subsection Contact
        set Friction law = tabulated
        subsection Tabulated friction
          set File = speed.csv
          set Speed = plane speed
        end
      end)");
    const auto &samples = run.run();
    double      worst   = 0;
    for (const auto &s : samples)
      if (s.time >= 15e-6)
        worst = std::max(worst,
                         std::abs(std::abs(s.contact_tangential_force)
                                  - 0.2 * s.contact_normal_force)
                           / s.contact_normal_force);
    check(worst < 1e-12,
          "mu(v) at the plane speed 2 m/s: |sum lambda_T| = 0.2 sum "
          "lambda_N ("
            + std::to_string(worst) + ")");
  }
  // (f)
  {
    const auto clamped = [&](const std::string &file,
                             const std::string &algorithm,
                             std::string       *figures = nullptr) {
      ContactRun run(held_block + R"(
        subsection Contact
          set Algorithm = )"
                     + algorithm + R"(
          set Friction law = tabulated
          subsection Tabulated friction
            set File = )"
                     + file + R"(
            set Speed = plane speed
          end
        end)");
      run.run();
      JsonValue          summary = JsonValue::object();
      std::ostringstream text;
      run.solver->report_friction_law(summary, text);
      if (figures)
        *figures = text.str();
      return nlohmann::json::parse(summary.dump());
    };
    write("narrow.csv",
          "pressure,speed,mu\n0,0,0.25\n0,100,0.25\n5e6,0,0.25\n"
          "5e6,100,0.25\n");
    write("high.csv",
          "pressure,speed,mu\n1e9,0,0.25\n1e9,100,0.25\n2e9,0,0.25\n"
          "2e9,100,0.25\n");
    write("slow.csv",
          "pressure,speed,mu\n0,10,0.25\n0,100,0.25\n1e9,10,0.25\n"
          "1e9,100,0.25\n");
    std::string warning, none;
    const auto  wise   = clamped("narrow.csv", "node-wise", &warning),
               gs      = clamped("narrow.csv", "projected Gauss-Seidel");
    const double above = wise["tabulated_clamped_pressure_above_fraction"];
    check(above > 0.01 && above < 1
            && wise["tabulated_clamped_pressure_below_fraction"] == 0.
            && wise["tabulated_clamped_speed_fraction"] == 0.
            && wise["tabulated_clamped_fraction"] == above,
          "0-5 MPa table: a share " + std::to_string(above)
            + " of the node-steps clamped above, none below or in speed");
    check(gs == wise,
          "Gauss-Seidel reports what node-wise does, once per node-step ("
            + std::to_string(static_cast<unsigned long long>(
              gs["tabulated_contact_node_steps"]))
            + " node-steps)");
    const auto high = clamped("high.csv", "node-wise"),
               slow = clamped("slow.csv", "projected Gauss-Seidel");
    check(high["tabulated_clamped_pressure_below_fraction"] == 1.
            && high["tabulated_clamped_fraction"] == 1.
            && high["tabulated_clamped_speed_fraction"] == 0.,
          "1-2 GPa table: every node-step clamped below");
    check(slow["tabulated_clamped_speed_fraction"] == 1.
            && slow["tabulated_clamped_fraction"] == 1.
            && slow["tabulated_clamped_pressure_below_fraction"] == 0.
            && slow["tabulated_clamped_pressure_above_fraction"] == 0.,
          "10-100 m/s table at 2 m/s: every node-step clamped in speed");
    clamped("constant.csv", "node-wise", &none);
    check(warning.find("Warning") != std::string::npos
            && none.find("Warning") == std::string::npos,
          "a warning above 1 % only: " + warning);
  }
  return result();
}
