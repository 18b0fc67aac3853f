#ifndef tribodyn_tests_contact_tools_h
#define tribodyn_tests_contact_tools_h

#include "../test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <string>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/errors.h>

namespace tribodyn_test
{
  using namespace tribodyn;
  using namespace tribodyn::contact;

  /// Contact parameters: the defaults overridden by @p prm_text (a piece of
  /// parameter file), parsed exactly as tribodyn parses a .prm.
  inline ContactParameters
  contact_parameters(const std::string &prm_text)
  {
    dealii::ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    // (the subsections of the named materials depend on the text's names:
    // a lenient reading, their declaration, then the strict one)
    prm.parse_input_from_string(prm_text, "", true);
    MorphologyMaterials::declare_material_sections(prm);
    prm.parse_input_from_string(prm_text);
    ContactParameters p;
    p.parse_parameters(prm);
    return p;
  }

  /// A set-up solver with its parameters and a silent timer.
  struct ContactRun
  {
    ContactParameters                    parameters;
    std::unique_ptr<dealii::TimerOutput> timer;
    std::unique_ptr<ContactSolver>       solver;

    ContactRun(const std::string &prm_text,
               const MPI_Comm     comm = MPI_COMM_WORLD)
        : parameters(contact_parameters(prm_text))
        , timer(std::make_unique<dealii::TimerOutput>(
            comm,
            std::cout,
            dealii::TimerOutput::never,
            dealii::TimerOutput::wall_times))
        , solver(std::make_unique<ContactSolver>(comm, parameters, *timer))
    {
      solver->setup();
    }

    /// Integrate without files or progress lines.
    const std::vector<Sample> &
    run()
    {
      solver->run("", -1);
      return solver->samples();
    }
  };

  /// The held block of block_drag.cc: 4 x 2 mm (h = 0.25 mm) pressed with
  /// 5 MPa (ramp 5 us) on the plane moving at -@p V, top face held in x,
  /// automatic time step (at most 5 ns), damping @p damping, to
  /// @p end_time, a sample every @p sample_interval steps.
  inline std::string
  held_block_prm(const double       V,
                 const double       end_time,
                 const double       damping         = 2e-8,
                 const unsigned int sample_interval = 5)
  {
    return R"(
      subsection Geometry
        set Width = 4e-3
        set Height = 2e-3
        set Mesh size = 0.25e-3
      end
      subsection Loading
        set Pressure = 5e6
        set Sliding velocity = )"
           + format_number(-V) + R"(
        set Ramp time = 5e-6
      end
      subsection Time
        set Damping coefficient = )"
           + format_number(damping) + R"(
        set Automatic time step = true
        set Time step = 5e-9
        set End time = )"
           + format_number(end_time) + R"(
      end
      subsection Output
        set Sample interval = )"
           + std::to_string(sample_interval) + R"(
        set Averaging start time = 0
      end
    )";
  }

  /// Parameters of a 1 x 8 mm column dropped at 1 m/s on the rigid plane at
  /// rest (frictionless, undamped, no pressure, mesh 0.1 mm): the 1D impact
  /// of the tests contact_bar_impact and contact_anisotropic_impact.
  /// @p material: the lines inside 'subsection Material'.
  inline std::string
  column_impact_prm(const std::string &material,
                    const double       time_step,
                    const double       end_time)
  {
    return R"(
      subsection Geometry
        set Width = 1e-3
        set Height = 8e-3
        set Mesh size = 0.1e-3
      end
      subsection Materials
)" + material
           + R"(
      end
      subsection Loading
        set Pressure = 0
        set Top face held in x = false
        set Sliding velocity = 0
        set Initial velocity = 0, -1
      end
      subsection Time
        set Time step = )"
           + format_number(time_step) + R"(
        set End time = )"
           + format_number(end_time) + R"(
        set Damping coefficient = 0
      end
      subsection Contact
        set Friction law = frictionless
      end
      subsection Output
        set Sample interval = 1
        set Averaging start time = 0
      end)";
  }

  /// Contact duration (end of the last sample with a contact force) and
  /// the mean contact force over 0.2 ... 0.8 of @p window (s; the measured
  /// duration when @p window is not positive) of an impact.
  struct ImpactFigures
  {
    double duration = 0, plateau_force = 0;
  };
  inline ImpactFigures
  impact_figures(const std::vector<Sample> &samples,
                 const double               time_step,
                 double                     window = -1)
  {
    ImpactFigures r;
    for (const auto &s : samples)
      if (s.contact_normal_force > 0)
        r.duration = s.time + time_step;
    if (window <= 0)
      window = r.duration;
    double n = 0;
    for (const auto &s : samples)
      if (s.time > 0.2 * window && s.time < 0.8 * window)
        {
          r.plateau_force += s.contact_normal_force;
          n += 1;
        }
    r.plateau_force /= n;
    return r;
  }
} // namespace tribodyn_test

#endif
