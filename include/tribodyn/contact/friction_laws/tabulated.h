// Contact friction law "tabulated": Coulomb's law with a coefficient
// mu(p, v) read from a CSV table of contact pressure and slip speed
// (subsection `Contact/Tabulated friction`; FrictionTable: bilinear,
// clamped outside the table; the share of the node-steps in contact read
// outside, by cause, in summary.json, with a warning above 1 %). The table may
// come from the automata (`scripts/mca_friction_table`): the bridge between the
// scales (doc/user_guide/contact.md).
#ifndef tribodyn_contact_friction_laws_tabulated_h
#define tribodyn_contact_friction_laws_tabulated_h

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <iostream>
#include <string>
#include <tribodyn/contact/friction_law.h>
#include <tribodyn/contact/friction_table.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/core/parameter_binding.h>
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
      struct Parameters : BoundLawParameters<Parameters>
      {
        std::string file;
        Speed       speed          = Speed::slip_rate;
        double      pressure_scale = 1, speed_scale = 1;
        double      pressure_exponent = 1, reference_pressure = 1e6;

        /// The entries, each written once (the handler is in Contact).
        ParameterBinding
        binding()
        {
          ParameterBinding e("Tabulated friction", "Contact");
          e.add("File",
                file,
                "CSV table of mu for 'Friction law = tabulated': a header line "
                "naming the columns pressure (Pa), speed (m/s) and mu (others "
                "ignored), one row per point of a full grid (at least 2 x 2). "
                "mu is bilinear between the points and clamped outside (the "
                "share of the node-steps in contact read outside is "
                "summary.json's tabulated_clamped_fraction; a warning above "
                "1 %). Relative paths: from the working directory.");
          e.add("Speed",
                speed,
                "The speed v of mu(p, v): 'local slip rate' (the node's slip "
                "rate of the previous step), or 'plane speed' (the plane's "
                "speed).",
                speed_choices);
          e.add("Pressure scale",
                pressure_scale,
                "The table is read at p = Pressure scale x (the node's contact "
                "pressure p_node = lambda_n / tributary length), or with a "
                "Pressure exponent m other than 1 at Pressure scale x p_ref x "
                "(p_node / p_ref)^m: the map from the pin's pressure to the "
                "table's (e.g. the automata scene's).",
                dealii::Patterns::Double(),
                Interval{0, 1e300, true, false});
          e.add("Pressure exponent",
                pressure_exponent,
                "m of the load-dependent map: the table is read at p = "
                "Pressure scale x p_ref x (p_node / p_ref)^m, p_node the "
                "node's contact pressure and p_ref the Reference pressure. "
                "1 (default): the constant scale above (a real contact area "
                "in proportion to the nominal one); 1/3: Hertzian spots of a "
                "fixed number; 0: Greenwood-Williamson's spots of one mean "
                "pressure whatever the load (the real area grows with it).",
                dealii::Patterns::Double(0, 10));
          e.add("Reference pressure",
                reference_pressure,
                "p_ref of the load-dependent map (Pa): the node pressure that "
                "reads the table at Pressure scale x p_ref whatever the "
                "exponent (e.g. the median contact pressure of the pin's "
                "operating_range.csv). Unused with Pressure exponent = 1.",
                dealii::Patterns::Double(),
                Interval{0, 1e300, true, false});
          e.add("Speed scale",
                speed_scale,
                "The table is read at v = Speed scale x the speed above.",
                dealii::Patterns::Double(),
                Interval{0, 1e300, true, false});
          return e;
        }
      };

      template <class ContactLawParameters>
      Tabulated(const ContactLawParameters &, const Parameters &p, const double)
          : table(
            p.file.empty()
              ? throw InputError(
                "Parameter '" + Parameters().binding().path("File")
                + "' is empty: 'Friction law = tabulated' needs the "
                  "path of a CSV table of mu(pressure, speed).")
              : FrictionTable(p.file, Parameters().binding().path("File")))
          , speed(p.speed)
          , pressure_scale(p.pressure_scale)
          , speed_scale(p.speed_scale)
          , pressure_exponent(p.pressure_exponent)
          , reference_pressure(p.reference_pressure)
      {
      }

      /// The table's pressure for a node of normal multiplier @p lambda_n
      /// and tributary length @p length (p_node = lambda_n / length):
      /// Pressure scale x p_ref x (p_node / p_ref)^m; with m = 1 Pressure
      /// scale x lambda_n / length, the constant map's arithmetic.
      double
      table_pressure(const double lambda_n, const double length) const
      {
        if (pressure_exponent == 1)
          return pressure_scale * lambda_n / length;
        return pressure_scale * reference_pressure
               * std::pow(std::max(lambda_n / length, 0.) / reference_pressure,
                          pressure_exponent);
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
          = table(table_pressure(lambda_n, before.length), speed_scale * v);
        return coulomb_tangential(trial, mu * lambda_n, status);
      }

      /// Count, once per node and step in contact, whether the table was
      /// read outside its grid, and why (the contact loops may evaluate
      /// tangential() several times per step: the Gauss-Seidel sweeps).
      /// law_state[0] keeps the slip rate the next step reads mu at.
      void
      end_step(ContactNode &node, const double) const
      {
        const double v
          = speed == Speed::slip_rate ? node.law_state[0] : plane_speed;
        node.law_state[0] = node.slip_rate;
        if (node.status == separated)
          return;
        const double p = table_pressure(node.lambda_n, node.length);
        const std::vector<double> &P = table.pressure_axis(),
                                  &V = table.speed_axis();
        const bool below             = p < P.front();
        const bool above             = p > P.back();
        const bool fast_or_slow
          = speed_scale * v < V.front() || speed_scale * v > V.back();
        ++counts[contact_steps].leg;
        counts[pressure_below].leg += below;
        counts[pressure_above].leg += above;
        counts[speed_outside].leg += fast_or_slow;
        counts[any_outside].leg += below || above || fast_or_slow;
      }

      /// summary.json: the share of the node-steps in contact whose mu was
      /// read outside the table, in all and by cause; a warning above 1 %.
      void
      report(JsonValue     &summary,
             std::ostream  &figures,
             const MPI_Comm comm) const
      {
        std::array<unsigned long long, n_counts> n;
        for (unsigned int k = 0; k < n_counts; ++k)
          n[k] = counts[k].total(comm);
        const auto share = [&](const unsigned int k) {
          return n[contact_steps] > 0 ? double(n[k]) / n[contact_steps] : 0.;
        };
        summary[count_names[contact_steps]] = n[contact_steps];
        for (unsigned int k = 1; k < n_counts; ++k)
          summary[std::string(count_names[k]) + "_fraction"] = share(k);
        figures << "Tabulated friction: mu read outside the table in "
                << 100 * share(any_outside) << " % of the " << n[contact_steps]
                << " node-steps in contact (pressure below "
                << 100 * share(pressure_below) << " %, above "
                << 100 * share(pressure_above) << " %; speed "
                << 100 * share(speed_outside) << " %)" << std::endl;
        if (share(any_outside) > 0.01)
          figures
            << "Warning: 'Contact/Tabulated friction/File': "
            << 100 * share(any_outside)
            << " % of the pin's friction evaluations fell outside the "
               "table and took its edge values (the table covers "
            << table.pressure_axis().front() << " to "
            << table.pressure_axis().back() << " Pa and "
            << table.speed_axis().front() << " to " << table.speed_axis().back()
            << " m/s, read at the mapped pressure of lambda_n / length and "
               "Speed scale x speed, with Pressure exponent "
            << pressure_exponent
            << "): extend the table over the pin's operating range, "
               "or change the map."
            << std::endl;
      }

      /// f(name, count) for the counts above (checkpointed by name).
      template <class F>
      void
      for_each_counter(const F &f) const
      {
        for (unsigned int k = 0; k < n_counts; ++k)
          f(count_names[k], counts[k]);
      }

      FrictionTable table;

    private:
      enum Count : unsigned int
      {
        contact_steps,
        any_outside,
        pressure_below,
        pressure_above,
        speed_outside,
        n_counts
      };
      /// The counts' names (checkpoints; summary.json: the count of
      /// node-steps, the others as "<name>_fraction" of it).
      static constexpr const char *count_names[n_counts]
        = {"tabulated_contact_node_steps",
           "tabulated_clamped",
           "tabulated_clamped_pressure_below",
           "tabulated_clamped_pressure_above",
           "tabulated_clamped_speed"};

      Speed  speed;
      double pressure_scale, speed_scale, pressure_exponent, reference_pressure,
        plane_speed = 0;
      mutable std::array<RunCounter, n_counts> counts;
    };
  } // namespace contact
} // namespace tribodyn

#endif
