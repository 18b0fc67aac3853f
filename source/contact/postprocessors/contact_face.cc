// Postprocessor "contact face": the space-time series of the contact face
// every `Output/Contact face interval` samples: contact_face_lambda_n.csv,
// contact_face_lambda_t.csv and contact_face_status.csv, one row per
// sample taken, one column per contact node in increasing x (rank 0
// gathers them). Written under `.part` names, renamed when complete.
#include <algorithm>
#include <array>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      class ContactFace : public Postprocessor
      {
      public:
        ContactFace(const PostprocessorInputs &in)
            : solver(in.solver)
            , directory(in.directory)
            , comm(in.comm)
            , root(in.root)
            , every(in.prm.output.contact_face_interval)
        {
        }

        /// The three files with their header (the nodes' x), or the rows
        /// of the checkpointed run's files: from the unfinished file if it
        /// was interrupted, else the final one.
        void
        open(const bool resumed) override
        {
          std::vector<double> x;
          for (const ContactNode &node : solver.contact_node_states())
            x.push_back(node.x);
          const auto all = dealii::Utilities::MPI::gather(comm, x, 0);
          if (!root)
            return;
          std::vector<double> xs;
          for (const auto &v : all)
            xs.insert(xs.end(), v.begin(), v.end());
          std::sort(xs.begin(), xs.end());
          std::ostringstream header;
          header << "time" << std::setprecision(10);
          for (const double xi : xs)
            header << "," << xi;
          for (const std::string name : {"contact_face_lambda_n.csv",
                                         "contact_face_lambda_t.csv",
                                         "contact_face_status.csv"})
            {
              paths.push_back(join_path(directory, name));
              const std::string part = paths.back() + ".part";
              std::string       kept = header.str() + "\n";
              if (resumed)
                kept = read_csv_rows(std::ifstream(part) ? part : paths.back(),
                                     rows);
              files.push_back(std::make_unique<std::ofstream>(part));
              if (!*files.back())
                throw InputError("Cannot write '" + part
                                 + "'; check the output directory.");
              *files.back() << kept << std::setprecision(8);
            }
        }

        /// (x, lambda_n, lambda_t, status) of every contact node, every
        /// `every` samples.
        void
        sample(const Sample &s) override
        {
          if (samples++ % every != 0)
            return;
          ++rows;
          std::vector<double> local;
          local.reserve(4 * solver.contact_node_states().size());
          for (const ContactNode &node : solver.contact_node_states())
            local.insert(
              local.end(),
              {node.x, node.lambda_n, node.lambda_t, double(node.status)});
          const auto all = dealii::Utilities::MPI::gather(comm, local, 0);
          if (!root)
            return;
          std::vector<std::array<double, 4>> nodes;
          for (const auto &v : all)
            for (std::size_t i = 0; i + 3 < v.size(); i += 4)
              nodes.push_back({{v[i], v[i + 1], v[i + 2], v[i + 3]}});
          std::sort(nodes.begin(), nodes.end());
          for (unsigned int q = 0; q < 3; ++q)
            {
              std::ofstream &out = *files[q];
              out << s.time;
              for (const auto &r : nodes)
                out << "," << r[q + 1];
              out << "\n";
            }
        }

        void
        flush(const bool complete) override
        {
          if (complete)
            for (auto &f : files)
              f->flush();
        }

        void
        close() override
        {
          for (std::size_t q = 0; q < files.size(); ++q)
            {
              files[q]->close();
              if (std::rename((paths[q] + ".part").c_str(), paths[q].c_str())
                  != 0)
                throw InputError("Cannot rename '" + paths[q] + ".part'.");
            }
          files.clear();
        }

        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          ar << samples << rows;
        }

        void
        load(boost::archive::binary_iarchive &ar) override
        {
          ar >> samples >> rows;
        }

      private:
        ContactSolver                              &solver;
        std::string                                 directory;
        MPI_Comm                                    comm;
        bool                                        root;
        unsigned int                                every;
        std::vector<std::unique_ptr<std::ofstream>> files;
        std::vector<std::string>                    paths;
        /// Samples seen and rows written (with those of a resumed run).
        unsigned long samples = 0;
        std::size_t   rows    = 0;
      };

      const bool contact_face_registered = PostprocessorRegistry::add(
        {"contact face",
         40,
         [](const PostprocessorInputs &in) {
           return in.prm.output.contact_face_interval > 0
                    ? std::make_unique<ContactFace>(in)
                    : nullptr;
         },
         "when Output/Contact face interval > 0"});
    } // namespace
  }   // namespace contact
} // namespace tribodyn
