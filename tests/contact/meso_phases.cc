// Meso pins of any number of phases from an image (issue #50 item 1), on
// the ranks the test is given (1 and 2):
// (a) One material in three phases: laminate3.png (40 x 10 pixels of
//     0.1 mm, three grey levels) segmented into three phases that all have
//     the matrix's constants gives the homogeneous pin of the same mesh:
//     every sample of a 20 us sliding run agrees to 1e-12 (relative to the
//     largest value of its column: the sums run over the same cells in the
//     same order, so they agree to the last bit in practice).
// (b) Static stiffness of an image laminate: laminate3_y.png holds layers
//     normal to y (from the top 3, 4 and 3 rows of 0.1 mm), segmented into
//     an isotropic phase (E = 30 GPa), a transversely isotropic one with
//     its axis along y (E_L = 230 GPa, E_T = 40 GPa) and an isotropic one
//     (E = 80 GPa), all Poisson ratios 0, two elements per pixel. Pressed
//     with P on the frictionless plane at rest, the exact static state is
//     sigma_yy = -P in every layer (no lateral strain with zero Poisson
//     ratios, which bilinear elements represent exactly), so the elastic
//     energy is U = P^2 W / 2 sum_k h_k / C_yy,k, i.e. the laminate's exact
//     series constant E_y = H / sum_k (h_k / C_yy,k), with C_yy = E_L for
//     the fibre phase. After a 10 us ramp and damped relaxation to 80 us
//     the pin's energy is within 1e-10 of it (measured 8e-15 on one rank:
//     the vibration has decayed to round-off; 1e-10 leaves room for the
//     order of the sums on other ranks); the axis taken along x instead
//     (C_yy = E_T) misses it by 53 %.
// (c) Pores are cut out: laminate3.png with its darkest phase a pore
//     (Young modulus 0) leaves four solid columns of 14 pixels; the mass
//     is rho times the solid area (1e-12), the contact face is the solid
//     part of the bottom (1e-12), and the static energy is that of the
//     columns under P on their own tops, P^2 (0.7 W) H / (2 E) (1e-10, as
//     in (b)).
// (e) A pin of one phase that is not material 0 (a grid file of
//     heterogeneity only) is the homogeneous pin of the heterogeneity's
//     constants (1e-12, as (a)); before issue #50 the one-material kernel
//     took material 0's stiffness for it. The homogeneous pin is chosen
//     by name ('Materials/Pin material = heterogeneity', issue #52 item 4).
// (d) Morphology::held_from_top(): a solid ring closed by pores around an
//     island keeps the ring and cuts the island; corner contacts do not
//     hold a pixel.

#include "../homogenization/image_test_tools.h"
#include "contact_test_tools.h"

#include <cmath>
#include <fstream>
#include <tribodyn/core/morphology.h>

namespace
{
  using namespace tribodyn_test;

  /// The largest |difference| of two sample series, relative to the
  /// largest |value| of each column, over every column of Sample.
  double
  largest_sample_difference(const std::vector<Sample> &a,
                            const std::vector<Sample> &b)
  {
    if (a.size() != b.size() || a.empty())
      return 1e300;
    double worst = 0;
    for (double Sample::*column : {&Sample::time,
                                   &Sample::normal_force,
                                   &Sample::tangential_force,
                                   &Sample::mu_global,
                                   &Sample::contact_tangential_force,
                                   &Sample::contact_normal_force,
                                   &Sample::mu_contact,
                                   &Sample::kinetic_energy,
                                   &Sample::elastic_energy,
                                   &Sample::external_work,
                                   &Sample::contact_work,
                                   &Sample::damping_dissipation,
                                   &Sample::friction_dissipation,
                                   &Sample::energy_balance_error,
                                   &Sample::momentum_x,
                                   &Sample::momentum_y,
                                   &Sample::M_ux,
                                   &Sample::M_vx,
                                   &Sample::M_uy,
                                   &Sample::M_vy,
                                   &Sample::stick_fraction,
                                   &Sample::slip_fraction,
                                   &Sample::separation_fraction})
      {
        double scale = 0, diff = 0;
        for (std::size_t k = 0; k < a.size(); ++k)
          {
            scale = std::max(scale, std::abs(a[k].*column));
            diff  = std::max(diff, std::abs(a[k].*column - b[k].*column));
          }
        if (scale > 0)
          worst = std::max(worst, diff / scale);
      }
    for (std::size_t k = 0; k < a.size(); ++k)
      if (a[k].M_status != b[k].M_status)
        return 1e300;
    return worst;
  }

  /// The frictionless static press of (b) and (c): P on the plane at rest,
  /// ramped over 10 us, relaxed to 80 us.
  const std::string static_press = R"(
      subsection Loading
        set Pressure = 5e6
        set Ramp time = 10e-6
        set Sliding velocity = 0
      end
      subsection Contact
        set Friction law = frictionless
      end
      subsection Time
        set Automatic time step = true
        set Time step = 5e-9
        set End time = 80e-6
        set Damping coefficient = 2e-8
      end
      subsection Output
        set Sample interval = 100
        set Averaging start time = 0
      end
  )";

  /// Sliding at -2 m/s under 5 MPa (ramp 5 us) to @p end_time, a sample
  /// every 20 steps: the runs of (a) and (e).
  std::string
  sliding(const std::string &end_time)
  {
    return R"(
      subsection Loading
        set Pressure = 5e6
        set Ramp time = 5e-6
        set Sliding velocity = -2
      end
      subsection Time
        set End time = )"
           + end_time + R"(
      end
      subsection Output
        set Sample interval = 20
        set Averaging start time = 0
      end
    )";
  }

  std::string
  image_pin(const std::string &file,
            const std::string &phases,
            const unsigned int subdivisions = 1)
  {
    return R"(
      subsection Materials
        set Type = morphology
)" + phases + R"(
      end
      subsection Morphology
        set Generator = image
        subsection Image
          set File = )"
           + image_path(file) + R"(
          set Pixel size = 1e-4
          set Segmentation = Otsu
          set Otsu phases = 3
        end
      end
      subsection Geometry
        set Subdivisions per pixel = )"
           + std::to_string(subdivisions) + R"(
      end
    )";
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;
  const double P = 5e6;

  // (a) one material in three phases = the homogeneous pin
  {
    const std::string run_to = sliding("20e-6");
    ContactRun        meso(run_to + image_pin("laminate3.png", R"(
        set Names = a, b, c
        subsection A
          set Young modulus = 30e9
          set Poisson ratio = 0.2
          set Density       = 1770
        end
        subsection B
          set Young modulus = 30e9
          set Poisson ratio = 0.2
          set Density       = 1770
        end
        subsection C
          set Young modulus = 30e9
          set Poisson ratio = 0.2
          set Density       = 1770
        end)"));
    ContactRun        homogeneous(run_to + R"(
      subsection Geometry
        set Width = 4e-3
        set Height = 1e-3
        set Mesh size = 1e-4
      end)");
    check(meso.solver->n_dofs() == homogeneous.solver->n_dofs(),
          "same mesh: " + std::to_string(meso.solver->n_dofs()) + " dofs");
    const double difference
      = largest_sample_difference(meso.run(), homogeneous.run());
    check(difference <= 1e-12,
          "one material in three phases = homogeneous pin (largest relative "
          "difference "
            + format_number(difference) + ")");
  }

  // (b) static stiffness of the image laminate with layers normal to y
  const auto laminate = [&](const std::string &axis) {
    ContactRun run(static_press
                   + image_pin("laminate3_y.png",
                               R"(
        set Names = soft, fibres, stiff
        subsection Soft
          set Young modulus = 30e9
          set Poisson ratio = 0
        end
        subsection Fibres
          set Young modulus       = 40e9
          set Poisson ratio       = 0
          set Symmetry            = transversely isotropic
          set Axis                = )"
                                 + axis + R"(
          set Axial Young modulus = 230e9
          set Axial Poisson ratio = 0
          set Axial shear modulus = 27e9
        end
        subsection Stiff
          set Young modulus = 80e9
          set Poisson ratio = 0
        end)",
                               2));
    return run.run().back().elastic_energy;
  };
  {
    // Otsu's phases are darkest first: grey 0 (the top 3 rows) is phase 0.
    const double W = 2e-3, h_soft = 3e-4, h_fibres = 4e-4, h_stiff = 3e-4;
    const double compliance = h_soft / 30e9 + h_fibres / 230e9 + h_stiff / 80e9;
    const double exact      = 0.5 * P * P * W * compliance;
    const double U          = laminate("y");
    const double error      = std::abs(U / exact - 1);
    check(error < 1e-10,
          "image laminate: elastic energy " + format_number(U) + " J/m, exact "
            + format_number(exact)
            + " (E_y = " + format_number(1e-3 / compliance / 1e9)
            + " GPa), relative error " + format_number(error));
    const double U_x = laminate("x");
    check(std::abs(U_x / exact - 1) > 0.1,
          "the fibres' axis matters: along x the energy is "
            + format_number(U_x) + " J/m");
  }

  // (c) pores cut out: four solid columns of 14 pixels
  {
    ContactRun   run(static_press + image_pin("laminate3.png", R"(
        set Names = pore, b, c
        subsection Pore
          set Young modulus = 0
          set Poisson ratio = 0
          set Density       = 0
        end
        subsection B
          set Young modulus = 30e9
          set Poisson ratio = 0
          set Density       = 1770
        end
        subsection C
          set Young modulus = 30e9
          set Poisson ratio = 0
          set Density       = 1770
        end)"));
    const double W = 4e-3, H = 1e-3, solid = 0.7;
    check_relative(run.solver->total_mass(),
                   1770 * solid * W * H,
                   1e-12,
                   "mass of the pin with pores = rho x solid area");
    check_relative(run.solver->contact_face_length(),
                   solid * W,
                   1e-12,
                   "contact face = solid part of the bottom");
    const double U     = run.run().back().elastic_energy;
    const double exact = 0.5 * P * P * solid * W * H / 30e9;
    check_relative(U, exact, 1e-10, "static energy of the solid columns");
  }

  // (e) one phase that is not material 0
  {
    const std::string grid = "meso_phases_heterogeneity_only.txt";
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream out(grid);
        for (unsigned int j = 0; j < 10; ++j)
          {
            for (unsigned int i = 0; i < 40; ++i)
              out << "1 ";
            out << "\n";
          }
      }
    MPI_Barrier(MPI_COMM_WORLD);
    const std::string run_to = sliding("10e-6");
    ContactRun        meso(run_to + R"(
      subsection Materials
        set Type = morphology
      end
      subsection Morphology
        set Generator = grid file
        set Grid file = )"
                    + grid + R"(
        set Width = 4e-3
        set Height = 1e-3
      end)");
    // (the homogeneous pin of the material named 'heterogeneity', with
    // its default constants: the pin's material chosen by name)
    ContactRun   homogeneous(run_to + R"(
      subsection Materials
        set Pin material = heterogeneity
      end
      subsection Geometry
        set Width = 4e-3
        set Height = 1e-3
        set Mesh size = 1e-4
      end)");
    const double difference
      = largest_sample_difference(meso.run(), homogeneous.run());
    check(difference <= 1e-12,
          "a pin of heterogeneity only = homogeneous pin of its constants "
          "(largest relative difference "
            + format_number(difference) + ")");
  }

  // (d) pixels held from the top face
  {
    // 5 x 5 pixels, 0 solid, 1 pore; the map with its top row first:
    //   row 4:  0 1 1 1 0
    //   row 3:  0 1 1 1 0
    //   row 2:  0 1 0 1 0    (2, 2): an island closed in by pores
    //   row 1:  0 1 1 0 1    (3, 1): touches (4, 0) and (4, 2) at corners
    //   row 0:  0 0 0 1 0    (4, 0): touches (3, 1) at a corner
    const std::vector<unsigned int> ids = {0, 0, 0, 1, 0, // row 0
                                           0, 1, 1, 0, 1, // row 1
                                           0, 1, 0, 1, 0, // row 2
                                           0, 1, 1, 1, 0, // row 3
                                           0, 1, 1, 1, 0};
    const Morphology                m(5, 5, 5, 5, ids);
    const std::vector<bool>         held = m.held_from_top({false, true});
    const auto                      at   = [&](unsigned int i, unsigned int j) {
      return static_cast<bool>(held[5 * j + i]);
    };
    check(at(0, 0) && at(1, 0) && at(2, 0) && at(0, 4) && at(4, 4) && at(4, 2),
          "solid pixels tied to the top through shared edges are held");
    check(!at(2, 2), "the island closed in by pores is cut");
    check(!at(3, 1) && !at(4, 0),
          "pixels touching held ones at corners only are cut");
    check(!at(3, 0) && !at(1, 1) && !at(4, 1), "pores are never held");
  }
  return result();
}
