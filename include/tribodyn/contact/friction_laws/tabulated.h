// Contact friction law "tabulated": Coulomb's law with a coefficient
// mu(p, v) read from a CSV table of contact pressure and slip speed
// (subsection `Contact/Tabulated friction`; FrictionTable: bilinear,
// clamped outside the table with a warning). The table may come from the
// automata (`scripts/mca_friction_table`): the bridge between the
// scales (doc/user_guide/contact.md).
#ifndef tribodyn_contact_friction_laws_tabulated_h
#define tribodyn_contact_friction_laws_tabulated_h

#include <deal.II/base/mpi.h>
#include <iostream>
#include <sstream>
#include <tribodyn/contact/friction_law.h>
#include <tribodyn/contact/friction_table.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace contact
  {
    struct Tabulated : FrictionLawBase
    {
      static constexpr const char *name = "tabulated";

      /// The speed mu is read at.
      enum class Speed
      {
        slip_rate,  ///< the node's slip rate of the previous step
        plane_speed ///< the plane's speed (the pin's nominal sliding speed)
      };
      static constexpr SelectionTable<Speed, 2> speed_choices{
        {{"local slip rate", Speed::slip_rate},
         {"plane speed", Speed::plane_speed}}};

      /// Subsection `Tabulated friction` of Contact.
      struct Parameters
      {
        std::string file;
        Speed       speed          = Speed::slip_rate;
        double      pressure_scale = 1, speed_scale = 1;

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.enter_subsection("Tabulated friction");
          prm.declare_entry(
            "File",
            "",
            dealii::Patterns::Anything(),
            "CSV table of mu for 'Friction law = tabulated': a header line "
            "naming the columns pressure (Pa), speed (m/s) and mu (others "
            "ignored), one row per point of a full grid (at least 2 x 2). "
            "mu is bilinear between the points and clamped, with a warning, "
            "outside. Relative paths: from the working directory.");
          prm.declare_entry("Speed",
                            "local slip rate",
                            selection_pattern(speed_choices),
                            "The speed v of mu(p, v): 'local slip rate' "
                            "(the node's slip rate of the previous step), "
                            "or 'plane speed' (the plane's speed).");
          prm.declare_entry(
            "Pressure scale",
            "1",
            dealii::Patterns::Double(),
            "The table is read at p = Pressure scale x (the node's "
            "contact pressure lambda_n / tributary length): the map from "
            "the pin's pressure to the table's (e.g. the automata scene's).");
          prm.declare_entry("Speed scale",
                            "1",
                            dealii::Patterns::Double(),
                            "The table is read at v = Speed scale x the "
                            "speed above.");
          prm.leave_subsection();
        }

        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          prm.enter_subsection("Tabulated friction");
          file           = prm.get("File");
          speed          = get_selection(prm, "Speed", speed_choices);
          pressure_scale = prm.get_double("Pressure scale");
          speed_scale    = prm.get_double("Speed scale");
          prm.leave_subsection();
          check_parameter_range("Contact/Tabulated friction/Pressure scale",
                                pressure_scale,
                                0,
                                1e300,
                                true,
                                false);
          check_parameter_range("Contact/Tabulated friction/Speed scale",
                                speed_scale,
                                0,
                                1e300,
                                true,
                                false);
        }
      };

      template <class ContactLawParameters>
      Tabulated(const ContactLawParameters &, const Parameters &p, const double)
          : table(p.file.empty()
                    ? throw InputError(
                      "Parameter 'Contact/Tabulated friction/File' is "
                      "empty: 'Friction law = tabulated' needs the path "
                      "of a CSV table of mu(pressure, speed).")
                    : FrictionTable(p.file, "Contact/Tabulated friction/File"))
          , speed(p.speed)
          , pressure_scale(p.pressure_scale)
          , speed_scale(p.speed_scale)
      {
      }

      void
      begin_step(const PlaneStep &s)
      {
        plane_speed = s.dt > 0 ? std::abs(s.slide) / s.dt : s.speed;
      }

      /// Coulomb's law with mu of the table at the node's pressure (of
      /// this step) and speed.
      double
      tangential(const ContactNode &before,
                 const double       trial,
                 const double       lambda_n,
                 ContactStatus     &status) const
      {
        const double v
          = speed == Speed::slip_rate ? before.slip_rate : plane_speed;
        const double mu
          = table(pressure_scale * lambda_n / before.length, speed_scale * v);
        if (!warned && clamped.earlier == 0 && table.clamped() > 0)
          warn_clamped(pressure_scale * lambda_n / before.length,
                       speed_scale * v);
        return coulomb_tangential(trial, mu * lambda_n, status);
      }

      void
      report(JsonValue     &summary,
             std::ostream  &figures,
             const MPI_Comm comm) const
      {
        clamped.leg                           = table.clamped();
        const unsigned long long n            = clamped.total(comm);
        summary["tabulated_friction_clamped"] = n;
        figures << "Tabulated friction: " << n
                << " evaluation(s) outside the table (clamped to its edges)"
                << std::endl;
      }

      /// f("tabulated_friction_clamped", count of evaluations outside the
      /// table).
      template <class F>
      void
      for_each_counter(const F &f) const
      {
        clamped.leg = table.clamped();
        f("tabulated_friction_clamped", clamped);
      }

      FrictionTable table;

    private:
      void
      warn_clamped(const double p, const double v) const
      {
        warned = true;
        // one write of the whole line, so that the ranks' warnings do not
        // interleave
        std::ostringstream m;
        m << "Warning (rank " << rank
          << "): 'Contact/Tabulated friction/File': mu read outside the "
             "table (pressure "
          << p << " Pa, speed " << v << " m/s; the table covers "
          << table.pressure_axis().front() << " to "
          << table.pressure_axis().back() << " Pa and "
          << table.speed_axis().front() << " to " << table.speed_axis().back()
          << " m/s): clamped to its edges (this warning once per rank and "
             "run; the count is in summary.json).\n";
        std::cerr << m.str() << std::flush;
      }

      Speed        speed;
      double       pressure_scale, speed_scale, plane_speed = 0;
      unsigned int rank
        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      mutable bool       warned = false;
      mutable RunCounter clamped;
    };
  } // namespace contact
} // namespace tribodyn

#endif
