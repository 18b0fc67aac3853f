// Postprocessor "energies": the time, the energies of the system and the
// works of the loads, the damping and the pairs (the first columns of
// series.csv), and at the end the energy balance since the start (the scene
// starts at rest and unstressed): the held terms of the energy ledger
// (system_figures.h: kinetic + elastic + plastic + friction + damped +
// switching + many-body) = its supplied one (the work of the loads), in
// summary.json and on the screen (doc/theory/mca.md §8.4); and the same
// balance with the dissipation the laws prescribe (the flow rule's plastic
// work, the friction law's traction times the slip) in place of the booked
// plastic and friction work.
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      class Energies : public Postprocessor
      {
      public:
        explicit Energies(const AutomatonSystem &system)
            : system(system)
        {
        }

        std::vector<std::string>
        series_columns() const override
        {
          std::vector<std::string> columns = {"time"};
          for (const LedgerEntry &entry : energy_ledger)
            columns.emplace_back(entry.name);
          return columns;
        }

        void
        record(const SeriesSample &s, std::vector<double> &row) override
        {
          row.push_back(s.time);
          row.insert(row.end(),
                     s.energies.value.begin(),
                     s.energies.value.end());
        }

        void
        finish(JsonValue &summary, std::ostream &figures) const override
        {
          const SystemEnergies e = system.energies();
          // the ledger's terms, and its roles for the test tools
          JsonValue roles = JsonValue::object();
          for (const char *role : {"held", "supplied", "diagnostic"})
            roles[role] = JsonValue::array();
          for (const LedgerEntry &entry : energy_ledger)
            {
              const double value = e[entry.term];
              switch (entry.role)
                {
                  case EnergyRole::count:
                    summary[entry.name]
                      = static_cast<unsigned long long>(value);
                    continue;
                  case EnergyRole::held:
                    roles["held"].push_back(entry.name);
                    break;
                  case EnergyRole::supplied:
                    roles["supplied"].push_back(entry.name);
                    break;
                  case EnergyRole::diagnostic:
                    roles["diagnostic"].push_back(entry.name);
                    break;
                }
              summary[entry.name] = value;
            }
          summary["energy_ledger"] = roles;
          // the balance: what the scene holds or dissipated against the
          // work of the loads
          const double residual              = e.balance_residual();
          const double W                     = e[Energy::load];
          summary["energy_balance_residual"] = residual;
          summary["energy_balance_relative"]
            = W != 0 ? residual / std::abs(W) : 0.;
          figures << "Energy: load work " << W << " J = ";
          const char *plus = "";
          for (const LedgerEntry &entry : energy_ledger)
            if (entry.role == EnergyRole::held)
              {
                figures << plus << entry.label << " " << e[entry.term];
                plus = " + ";
              }
          // (the residual as summary.json gives it: held - load work)
          figures << " J; residual (held - load work) " << residual << " J"
                  << std::endl;
          // the balance with the dissipation the laws prescribe in place
          // of the booked plastic and friction work (§8.4): it sees a
          // stress update that does not dissipate what its law says
          const double physical = e.physical_balance_residual();
          summary["energy_balance_residual_physical"] = physical;
          summary["energy_balance_relative_physical"]
            = W != 0 ? physical / std::abs(W) : 0.;
          if (e[Energy::plastic] != 0 || e[Energy::friction] != 0)
            figures << "Energy with the laws' dissipation (plastic "
                    << e[Energy::plastic_flow_rule] << " J by the flow rule, "
                    << "friction " << e[Energy::friction_law]
                    << " J by the law): residual " << physical << " J"
                    << std::endl;
        }

      private:
        const AutomatonSystem &system;
      };


      const bool energies_registered = PostprocessorRegistry::add(
        {"energies", 10, [](const PostprocessorInputs &in) {
           return std::make_unique<Energies>(in.system);
         }});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
