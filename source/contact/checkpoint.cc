// Checkpoints of the contact solver: the state of the time loop as a Boost
// binary archive per rank, keyed by place, not by rank: each owned degree of
// freedom is saved with its node's coordinates and each contact node with
// its x, so that a checkpoint written on N ranks resumes on any number M
// (doc/user_guide.md, "Checkpoints"). On resume every rank reads its share
// of the writers' files, sends each record to the ranks whose cells hold
// its node (PointRouter) and keeps those of the dofs it owns.
// The values are copied exactly: the resumed run continues bit for bit on
// the same number of ranks, and to the round-off of the cross-rank sums on
// another (ctests stability_contact_restart_*).
#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/binary_object.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/redistribution.h>
#include <type_traits>

namespace tribodyn
{
  namespace contact
  {
    namespace
    {
      // 2: records keyed by place (any number of ranks); 3: a contact
      // node's state is ContactNode::for_each_state_field() (with the
      // friction law's state); 4: the outputs' states are their
      // postprocessors' (by name); 5: the friction law's run counters (by
      // name)
      constexpr unsigned int state_version = 5;

      static_assert(std::is_trivially_copyable<Sample>::value,
                    "Sample is saved as raw bytes");

      // A dof record: its node's x, y, the component, then u, u_prev, p,
      // w, a. A contact-node record: x, 0, then the node's state.
      constexpr unsigned int dof_stride  = 8;
      const unsigned int     node_stride = 2 + ContactNode::n_state_fields();

    } // namespace


    std::vector<std::array<double, 2>>
    ContactSolver::owned_dof_points() const
    {
      const auto                        &partitioner = *u.get_partitioner();
      std::vector<std::array<double, 2>> points(mass.size());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < 2; ++c)
              {
                const auto g = cell->vertex_dof_index(v, c);
                if (locally_owned.is_element(g))
                  points[partitioner.global_to_local(g)]
                    = {{cell->vertex(v)[0], cell->vertex(v)[1]}};
              }
      return points;
    }


    std::string
    ContactSolver::save_state(const LoopState &loop) const
    {
      const unsigned int n_owned = mass.size();
      // The friction law's counts over the run so far (collective).
      std::vector<std::pair<std::string, unsigned long long>> counters;
      FrictionLaws::visit(friction_law, [&](const auto &law) {
        law.for_each_counter([&](const char *name, RunCounter &c) {
          counters.emplace_back(name, c.total(comm));
        });
      });
      std::ostringstream out(std::ios::binary);
      {
        boost::archive::binary_oarchive ar(out);
        // The run's state, the same on every rank: what the writer of rank
        // 0 saved is what every rank of the resumed run takes.
        std::ostringstream global_out(std::ios::binary);
        {
          boost::archive::binary_oarchive g(global_out);
          g << dt << step_count << energy_initial << scale_energy;
          // The samples so far (the summary's averages and spectra).
          const std::size_t n_samples = history.size();
          g << n_samples;
          if (n_samples > 0)
            g << boost::serialization::make_binary_object(
              const_cast<Sample *>(history.data()), n_samples * sizeof(Sample));
          // The outputs' states (rows written, fields), by name.
          g << loop.outputs;
          g << counters;
        }
        const std::string global = global_out.str();
        ar << state_version << global;
        // This rank's partial sums (the samples add them over the ranks).
        ar << pgs_iterations_max << work_external << work_internal
           << work_contact << dissipation_friction;
        // The vectors the next step reads (u_n, u_{n-1}, p_n,
        // w = u_n + beta p_n, a_{n-1} for the samples), by node.
        const auto          points = owned_dof_points();
        std::vector<double> dofs;
        dofs.reserve(std::size_t(dof_stride) * n_owned);
        for (unsigned int i = 0; i < n_owned; ++i)
          dofs.insert(dofs.end(),
                      {points[i][0],
                       points[i][1],
                       double(component[i]),
                       u.local_element(i),
                       u_prev.local_element(i),
                       p.local_element(i),
                       w.local_element(i),
                       a.local_element(i)});
        ar << dofs;
        // Contact nodes: position, then the state variables of
        // ContactNode::for_each_state_field().
        std::vector<double> nodes;
        for (ContactNode node : contact_nodes)
          {
            nodes.insert(nodes.end(), {node.x, 0.});
            node.for_each_state_field(
              [&](const char *, double &value) { nodes.push_back(value); });
          }
        ar << nodes;
      }
      return out.str();
    }


    void
    ContactSolver::load_state(const std::vector<std::string> &blobs,
                              LoopState                      &loop)
    {
      // This rank's share of the writers' records, and their sums.
      std::string         global;
      std::vector<double> dofs, nodes;
      work_external = work_internal = work_contact = dissipation_friction = 0;
      pgs_iterations_max                                                  = 0;
      read_checkpoint_blobs(comm, blobs, [&](auto &ar) {
        unsigned int version = 0;
        ar >> version;
        if (version != state_version)
          throw InputError(
            "The checkpoint was written by another version of tribodyn "
            "(state format "
            + std::to_string(version) + ", this one "
            + std::to_string(state_version)
            + "). Start afresh with 'Checkpoint/Resume = false'.");
        std::string         g;
        unsigned int        pgs = 0;
        double              works[4];
        std::vector<double> d, n;
        ar >> g >> pgs >> works[0] >> works[1] >> works[2] >> works[3];
        ar >> d >> n;
        if (global.empty())
          global = std::move(g);
        pgs_iterations_max = std::max(pgs_iterations_max, pgs);
        work_external += works[0];
        work_internal += works[1];
        work_contact += works[2];
        dissipation_friction += works[3];
        dofs.insert(dofs.end(), d.begin(), d.end());
        nodes.insert(nodes.end(), n.begin(), n.end());
      });

      // The run's state from the writer of rank 0 (read by rank 0).
      global = dealii::Utilities::MPI::broadcast(comm, global, 0);
      read_checkpoint_blobs(comm, {global}, [&](auto &g) {
        double saved_dt = 0;
        g >> saved_dt >> step_count >> energy_initial >> scale_energy;
        if (saved_dt != dt)
          throw InputError("The checkpoint does not fit this run: its time "
                           "step is "
                           + format_number(saved_dt) + " s, this run's "
                           + format_number(dt)
                           + " s. Resume with the parameters of the "
                             "checkpointed run.");
        std::size_t n_samples = 0;
        g >> n_samples;
        history.resize(n_samples);
        if (n_samples > 0)
          g >> boost::serialization::make_binary_object(history.data(),
                                                        n_samples
                                                          * sizeof(Sample));
        g >> loop.outputs;
        // The friction law's counts of the earlier legs, by name.
        std::vector<std::pair<std::string, unsigned long long>> counters;
        g >> counters;
        FrictionLaws::visit(friction_law, [&](const auto &law) {
          law.for_each_counter([&](const char *name, RunCounter &c) {
            c.leg = c.earlier = 0;
            for (const auto &[saved_name, value] : counters)
              if (saved_name == name)
                c.earlier = value;
          });
        });
      });

      // Each record to the ranks whose cells hold its node (the pin's
      // coarse cells: boxes at level 0).
      const PointRouter<2> router(triangulation, 0, comm);
      dofs  = router.route(dofs, dof_stride);
      nodes = router.route(nodes, node_stride);

      // Keep those of the owned dofs and contact nodes, found by place (the
      // coordinates to a millionth of a cell: the mesh is made anew from
      // the same parameters).
      const double scale = 1e-6 * std::min(cell_hx, cell_hy);
      using Key          = std::array<long long, 3>;
      auto key           = [scale](const double x, const double y, int c) {
        return Key{{std::llround(x / scale), std::llround(y / scale), c}};
      };
      const unsigned int                        n_owned = mass.size();
      const auto                                points  = owned_dof_points();
      std::vector<std::pair<Key, unsigned int>> owned(n_owned);
      for (unsigned int i = 0; i < n_owned; ++i)
        owned[i] = {key(points[i][0], points[i][1], component[i]), i};
      std::sort(owned.begin(), owned.end());
      std::vector<unsigned char> filled(n_owned, 0);
      auto                       find = [](const auto &list, const Key &k) {
        const auto it
          = std::lower_bound(list.begin(), list.end(), std::make_pair(k, 0u));
        return it != list.end() && it->first == k ? int(it->second) : -1;
      };
      for (std::size_t o = 0; o + dof_stride <= dofs.size(); o += dof_stride)
        {
          const double *r = dofs.data() + o;
          const int     i = find(owned, key(r[0], r[1], int(r[2])));
          if (i < 0)
            continue;
          VectorType *const targets[5] = {&u, &u_prev, &p, &w, &a};
          for (unsigned int v = 0; v < 5; ++v)
            targets[v]->local_element(i) = r[3 + v];
          filled[i] = 1;
        }
      std::vector<std::pair<Key, unsigned int>> bottom;
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        bottom.emplace_back(key(contact_nodes[k].x, 0, 0), k);
      std::sort(bottom.begin(), bottom.end());
      unsigned int n_nodes_filled = 0;
      for (std::size_t o = 0; o + node_stride <= nodes.size(); o += node_stride)
        {
          const double *r = nodes.data() + o;
          const int     k = find(bottom, key(r[0], 0, 0));
          if (k < 0)
            continue;
          unsigned int field = 2;
          contact_nodes[k].for_each_state_field(
            [&](const char *, double &value) { value = r[field++]; });
          ++n_nodes_filled;
        }
      const unsigned int n_filled = std::count(filled.begin(), filled.end(), 1);
      refuse_collectively(
        comm,
        n_filled != n_owned || n_nodes_filled != contact_nodes.size(),
        "The checkpoint does not fit this run: it holds no state for "
          + std::to_string(n_owned - n_filled) + " degrees of freedom and "
          + std::to_string(contact_nodes.size() - n_nodes_filled)
          + " contact nodes of this rank's part of the pin (another mesh?). "
            "Resume with the parameters of the checkpointed run.");
      r = 0;
    }
  } // namespace contact
} // namespace tribodyn
