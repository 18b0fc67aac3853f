// Postprocessors "friction", "point M" and "contact status": one CSV row
// per sample (`Output/Sample interval`), each file with its columns listed
// once below (doc/theory/contact.md Sec. 5 defines them).
#include <boost/serialization/vector.hpp>
#include <memory>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/output.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      /// A column: its name and its value in a sample.
      struct Column
      {
        const char *name;
        double (*value)(const Sample &);
      };

      /// A CSV file of samples.
      class SampleSeries : public Postprocessor
      {
      public:
        SampleSeries(const PostprocessorInputs &in,
                     const char                *file,
                     std::vector<Column>        columns)
            : path(join_path(in.directory, file))
            , root(in.root)
            , columns(std::move(columns))
        {
        }

        void
        open(const bool resumed) override
        {
          std::vector<std::string> names;
          for (const Column &c : columns)
            names.emplace_back(c.name);
          csv = resumed ? std::make_unique<CsvWriter>(path, names, root, rows)
                        : std::make_unique<CsvWriter>(path, names, root);
        }

        void
        sample(const Sample &s) override
        {
          row.resize(columns.size());
          for (std::size_t c = 0; c < columns.size(); ++c)
            row[c] = columns[c].value(s);
          csv->add_row(row);
        }

        void
        flush(const bool complete) override
        {
          csv->flush(complete);
        }

        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          const std::size_t n = csv->n_rows();
          ar << n;
        }

        void
        load(boost::archive::binary_iarchive &ar) override
        {
          ar >> rows;
        }

      private:
        std::string                path;
        bool                       root;
        std::vector<Column>        columns;
        std::unique_ptr<CsvWriter> csv;
        std::vector<double>        row;
        /// Rows of the checkpointed run to keep.
        std::size_t rows = 0;
      };

      const bool friction = PostprocessorRegistry::add(
        {"friction", 10, [](const PostprocessorInputs &in) {
           return std::make_unique<SampleSeries>(
             in,
             "friction.csv",
             std::vector<Column>{
               {"time", [](const Sample &s) { return s.time; }},
               {"normal_force", [](const Sample &s) { return s.normal_force; }},
               {"tangential_force",
                [](const Sample &s) { return s.tangential_force; }},
               {"mu_global", [](const Sample &s) { return s.mu_global; }},
               {"contact_normal_force",
                [](const Sample &s) { return s.contact_normal_force; }},
               {"contact_tangential_force",
                [](const Sample &s) { return s.contact_tangential_force; }},
               {"mu_contact", [](const Sample &s) { return s.mu_contact; }},
               {"kinetic_energy",
                [](const Sample &s) { return s.kinetic_energy; }},
               {"elastic_energy",
                [](const Sample &s) { return s.elastic_energy; }},
               {"external_work",
                [](const Sample &s) { return s.external_work; }},
               {"contact_work", [](const Sample &s) { return s.contact_work; }},
               {"damping_dissipation",
                [](const Sample &s) { return s.damping_dissipation; }},
               {"friction_dissipation",
                [](const Sample &s) { return s.friction_dissipation; }},
               {"energy_balance_error",
                [](const Sample &s) { return s.energy_balance_error; }},
               {"momentum_x", [](const Sample &s) { return s.momentum_x; }},
               {"momentum_y", [](const Sample &s) { return s.momentum_y; }}});
         }});

      const bool point_M = PostprocessorRegistry::add(
        {"point M", 20, [](const PostprocessorInputs &in) {
           return std::make_unique<SampleSeries>(
             in,
             "point_M.csv",
             std::vector<Column>{
               {"time", [](const Sample &s) { return s.time; }},
               {"tangential_displacement",
                [](const Sample &s) { return s.M_ux; }},
               {"tangential_velocity", [](const Sample &s) { return s.M_vx; }},
               {"normal_displacement", [](const Sample &s) { return s.M_uy; }},
               {"normal_velocity", [](const Sample &s) { return s.M_vy; }},
               {"status", [](const Sample &s) { return double(s.M_status); }}});
         }});

      const bool contact_status = PostprocessorRegistry::add(
        {"contact status", 30, [](const PostprocessorInputs &in) {
           return std::make_unique<SampleSeries>(
             in,
             "contact_status.csv",
             std::vector<Column>{
               {"time", [](const Sample &s) { return s.time; }},
               {"stick_fraction",
                [](const Sample &s) { return s.stick_fraction; }},
               {"slip_fraction",
                [](const Sample &s) { return s.slip_fraction; }},
               {"separation_fraction",
                [](const Sample &s) { return s.separation_fraction; }}});
         }});
    } // namespace
  }   // namespace contact
} // namespace tribodyn
