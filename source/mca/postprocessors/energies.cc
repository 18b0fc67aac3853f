// Postprocessor "energies": the time, the energies of the system and the
// works of the loads, the damping and the pairs (the first columns of
// series.csv), and at the end the energy balance since the start (the scene
// starts at rest and unstressed): kinetic + elastic + plastic + friction +
// switching + many-body + damped = work of the loads, in summary.json and
// on the screen (doc/theory/mca.md §8.4).
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
          return {"time",
                  "kinetic_energy",
                  "elastic_energy",
                  "plastic_work",
                  "friction_work",
                  "n_bonded_pairs",
                  "n_unbonded_contacts",
                  "load_work",
                  "damped_work",
                  "pair_work",
                  "switching_work",
                  "many_body_work"};
        }

        void
        record(const SeriesSample &s, std::vector<double> &row) override
        {
          const SystemEnergies &e = s.energies;
          row.insert(row.end(),
                     {s.time,
                      e.kinetic,
                      e.elastic,
                      e.plastic_work,
                      e.friction_work,
                      double(e.n_bonded),
                      double(e.n_unbonded_contacts),
                      e.load_work,
                      e.damped_work,
                      e.pair_work,
                      e.switching_work,
                      e.many_body_work});
        }

        void
        finish(JsonValue &summary, std::ostream &figures) const override
        {
          const SystemEnergies e         = system.energies();
          summary["kinetic_energy"]      = e.kinetic;
          summary["elastic_energy"]      = e.elastic;
          summary["plastic_work"]        = e.plastic_work;
          summary["friction_work"]       = e.friction_work;
          summary["n_bonded_pairs"]      = e.n_bonded;
          summary["n_unbonded_contacts"] = e.n_unbonded_contacts;
          // the pairs' side of the balance: their work on the automata
          // against what they stored or dissipated
          const double stored = e.kinetic + e.elastic + e.plastic_work
                                + e.friction_work + e.switching_work
                                + e.many_body_work + e.damped_work;
          summary["load_work"]               = e.load_work;
          summary["damped_work"]             = e.damped_work;
          summary["pair_work"]               = e.pair_work;
          summary["switching_work"]          = e.switching_work;
          summary["many_body_work"]          = e.many_body_work;
          summary["energy_balance_residual"] = stored - e.load_work;
          summary["energy_balance_relative"]
            = e.load_work != 0 ? (stored - e.load_work) / std::abs(e.load_work)
                               : 0.;
          figures << "Energy: load work " << e.load_work << " J = kinetic "
                  << e.kinetic << " + elastic " << e.elastic << " + plastic "
                  << e.plastic_work << " + friction " << e.friction_work
                  << " + switching " << e.switching_work << " + many-body "
                  << e.many_body_work << " + damped " << e.damped_work
                  << " J + residual " << e.load_work - stored << " J"
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
