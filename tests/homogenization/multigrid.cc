// Geometric multigrid for the cell problems (issue #19 item 4).
//
// (a) Same answer: on a random morphology of the seed's generator (56 x 16
//     pixels, 3 multigrid levels below the pixel grid) and on the example
//     micrograph (pores with the ersatz stiffness 1e-6, a 230/30 GPa
//     contrast), KUBC, SUBC and periodic apparent stiffnesses (periodic:
//     the multigrid of multilinear elements carries the periodicity through
//     its levels) with multigrid and with AMG agree to 1e-9 relative (largest
//     entry difference over largest entry) at a CG tolerance of 1e-12: two
//     solvers of the same linear system, so their difference is of the
//     order of the CG tolerance (measured: 1.1e-14 .. 2.1e-12 with the
//     single-precision V-cycle; 1.6e-14 .. 5.9e-13 in double).
//     The same for elements of degree 2 and 3 (the general matrix-free
//     kernel; degree 1 has a fast path of its own; periodic problems of
//     other degrees use AMG). (a) runs with the default single-precision
//     V-cycle.
// (b) Iterations independent of h: on the random morphology refined from
//     1 to 8 elements per pixel (1 894 to 115 362 DoFs), the multigrid CG
//     iteration count of every boundary condition and load case stays
//     within 3 of its count on the coarsest mesh, with a double-precision
//     V-cycle at the tolerance 1e-12 (measured: 9-10 for KUBC, 11-12 for
//     SUBC, 9-11 for periodic) and with the default single-precision
//     one at the default tolerance 1e-10 (8-9, 9-10, 8-9). Single
//     precision at 1e-12 is printed, not bounded (measured: KUBC 9-10, SUBC
//     11-12). AMG's counts are printed next to them. (SUBC solves the
//     floating problem, the rigid motions projected out and the pins on the
//     coarsest level only; with the pins on every level it took 16-17,
//     14-15 and 16 -> 18-20. Periodic: the translations projected out, one
//     pin on the coarsest level; without the periodic transfer's expansion
//     of the coarse images (the coarse correction left at zero there) CG
//     did not converge in 2000 iterations: shown failing.)

#include "image_test_tools.h"

namespace
{
  using namespace tribodyn_test;

  CellProblemResult
  solve_with(const Morphology                &morphology,
             const std::vector<ElasticPhase> &phases,
             const BoundaryCondition          bc,
             const CellPreconditioner         preconditioner,
             const unsigned int               subdivisions,
             unsigned int                    &levels,
             const unsigned int               degree    = 1,
             const double                     tolerance = 1e-12,
             const MultigridPrecision precision = MultigridPrecision::single)
  {
    CellProblemParameters parameters;
    parameters.subdivisions_per_pixel = subdivisions;
    parameters.solver_tolerance       = tolerance;
    parameters.preconditioner         = preconditioner;
    parameters.fe_degree              = degree;
    parameters.multigrid_precision    = precision;
    return solve_cell(morphology, phases, bc, parameters, &levels);
  }

  std::string
  iterations(const CellProblemResult &r)
  {
    return std::to_string(r.load_cases[0].cg_iterations) + "/"
           + std::to_string(r.load_cases[1].cg_iterations) + "/"
           + std::to_string(r.load_cases[2].cg_iterations);
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const Morphology random     = seed_generator_map(56, 16, 0.3e-3, 0.9e-3);
  const Morphology micrograph = Morphology::create(
    image_parameters(repository_path("prm/homogenization/micrograph.png"), 3));
  const auto pores = named_phases({{0, 0}, {30e9, 0.35}, {230e9, 0.2}}, 1e-6);

  const BoundaryCondition all[] = {BoundaryCondition::kubc,
                                   BoundaryCondition::subc,
                                   BoundaryCondition::periodic};
  // elements of higher degree: periodic problems use AMG
  // (CellProblem::uses_multigrid)
  const BoundaryCondition not_periodic[]
    = {BoundaryCondition::kubc, BoundaryCondition::subc};

  // (a) multigrid and AMG solve the same systems.
  for (const auto &[name, morphology, phases] :
       {std::make_tuple("random 56 x 16", &random, seed_phases()),
        std::make_tuple("micrograph with pores", &micrograph, pores)})
    for (const auto bc : all)
      {
        unsigned int levels_mg = 0, levels_amg = 0;
        const auto   mg = solve_with(
          *morphology, phases, bc, CellPreconditioner::multigrid, 1, levels_mg);
        const auto amg = solve_with(
          *morphology, phases, bc, CellPreconditioner::amg, 1, levels_amg);
        std::cout << name << ", " << to_string(bc) << ": " << levels_mg
                  << " multigrid levels, CG iterations multigrid "
                  << iterations(mg) << ", AMG " << iterations(amg) << std::endl;
        check(levels_mg >= 2 && levels_amg == 0,
              std::string(name) + ": multigrid has a hierarchy");
        check_relative(matrix_relative_difference(mg.properties.C,
                                                  amg.properties.C),
                       0,
                       1e-9,
                       std::string(name) + ", " + to_string(bc)
                         + ": C multigrid vs AMG",
                       1.);
      }

  // (c) the general matrix-free kernel (degrees 2 and 3; degree 1 takes
  // the bilinear fast path) solves the same systems as AMG.
  for (const unsigned int degree : {2u, 3u})
    for (const auto bc : not_periodic)
      {
        unsigned int levels = 0, unused = 0;
        const auto   mg  = solve_with(random,
                                   seed_phases(),
                                   bc,
                                   CellPreconditioner::multigrid,
                                   1,
                                   levels,
                                   degree);
        const auto   amg = solve_with(random,
                                    seed_phases(),
                                    bc,
                                    CellPreconditioner::amg,
                                    1,
                                    unused,
                                    degree);
        std::cout << "degree " << degree << ", " << to_string(bc) << ": "
                  << levels << " levels, CG iterations multigrid "
                  << iterations(mg) << ", AMG " << iterations(amg) << std::endl;
        check_relative(matrix_relative_difference(mg.properties.C,
                                                  amg.properties.C),
                       0,
                       1e-9,
                       "Q" + std::to_string(degree) + ", " + to_string(bc)
                         + ": C multigrid vs AMG",
                       1.);
      }

  // (b) iteration counts independent of the element size: a double
  // precision V-cycle at the tolerance 1e-12, a single precision one (the
  // default) at the default tolerance 1e-10; single precision at 1e-12 is
  // printed (not bounded: it adds a few SUBC iterations on fine meshes).
  const std::tuple<MultigridPrecision, double, bool> variants[]
    = {{MultigridPrecision::double_, 1e-12, true},
       {MultigridPrecision::single, 1e-10, true},
       {MultigridPrecision::single, 1e-12, false}};
  for (const auto &[precision, tolerance, bounded] : variants)
    {
      const std::string variant
        = std::string(precision == MultigridPrecision::single ? "single"
                                                              : "double")
          + " precision, tolerance " + (tolerance < 1e-11 ? "1e-12" : "1e-10");
      std::array<std::array<unsigned int, 3>, 3> first{};
      for (const unsigned int s : {1u, 2u, 4u, 8u})
        for (unsigned int b = 0; b < 3; ++b)
          {
            unsigned int levels = 0, unused = 0;
            const auto   mg  = solve_with(random,
                                       seed_phases(),
                                       all[b],
                                       CellPreconditioner::multigrid,
                                       s,
                                       levels,
                                       1,
                                       tolerance,
                                       precision);
            const auto   amg = solve_with(random,
                                        seed_phases(),
                                        all[b],
                                        CellPreconditioner::amg,
                                        s,
                                        unused,
                                        1,
                                        tolerance);
            std::cout << variant << ", h = pixel/" << s << ", "
                      << to_string(all[b]) << ": " << levels
                      << " levels, CG iterations multigrid " << iterations(mg)
                      << ", AMG " << iterations(amg) << std::endl;
            for (unsigned int k = 0; k < 3; ++k)
              {
                const unsigned int n = mg.load_cases[k].cg_iterations;
                if (s == 1)
                  first[b][k] = n;
                else if (bounded)
                  check(n <= first[b][k] + 3,
                        variant + ", h = pixel/" + std::to_string(s) + ", "
                          + to_string(all[b]) + ", load case "
                          + std::to_string(k) + ": " + std::to_string(n)
                          + " multigrid iterations <= coarsest mesh's + 3 ("
                          + std::to_string(first[b][k]) + " + 3)");
              }
          }
    }
  return result();
}
