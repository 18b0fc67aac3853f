#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_system.h>
#include <unordered_map>

namespace tribodyn
{
  namespace mca
  {
    using dealii::Tensor;

    namespace
    {
      // Layout of the automaton part of the particle properties.
      namespace prop
      {
        constexpr unsigned int v = 0, w = 3, f = 6, torque = 9, mat = 12,
                               body = 13, groups = 14, eps_p = 15, sigma_y = 16,
                               dsm_prev = 17, u = 18, n_automaton = 21;
      } // namespace prop
      // Fields of one pair slot (MPI runs).
      namespace slot
      {
        constexpr unsigned int partner = 0, bonded = 1, q = 2, sig_i = 3,
                               sig_j = 4, tau_i = 5, tau_j = 8, heat = 11,
                               contact = 12, n_fields = 13;
      } // namespace slot

      inline std::uint64_t
      pair_key(const std::uint64_t a, const std::uint64_t b)
      {
        return (a << 32) | b;
      }

      inline double
      dot(const Vec3 &a, const Vec3 &b)
      {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      }

      inline Vec3
      cross(const Vec3 &a, const Vec3 &b)
      {
        return {{a[1] * b[2] - a[2] * b[1],
                 a[2] * b[0] - a[0] * b[2],
                 a[0] * b[1] - a[1] * b[0]}};
      }

      /// Add c * sym(n (x) t) to s (xx yy zz yz xz xy).
      inline void
      add_sym(Sym3 &s, const double c, const Vec3 &n, const Vec3 &t)
      {
        s[0] += c * n[0] * t[0];
        s[1] += c * n[1] * t[1];
        s[2] += c * n[2] * t[2];
        s[3] += c * 0.5 * (n[1] * t[2] + n[2] * t[1]);
        s[4] += c * 0.5 * (n[0] * t[2] + n[2] * t[0]);
        s[5] += c * 0.5 * (n[0] * t[1] + n[1] * t[0]);
      }

      inline double
      von_mises(const Sym3 &s)
      {
        const double m = (s[0] + s[1] + s[2]) / 3;
        const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
        const double j2 = 0.5 * (a * a + b * b + c * c) + s[3] * s[3]
                          + s[4] * s[4] + s[5] * s[5];
        return std::sqrt(3 * j2);
      }

      /// Plastic strain increment of the radial return from trial
      /// equivalent stress @p q_trial (piecewise linear hardening).
      inline double
      plastic_increment(const MaterialParameters &m,
                        const double              G,
                        const double              eps_p,
                        const double              q_trial)
      {
        double s0 = m.yield_stress, e0 = 0, H = m.hardening_modulus;
        if (m.hardening == Hardening::bilinear
            && eps_p >= m.second_hardening_onset)
          {
            s0 = m.yield_stress_at(m.second_hardening_onset);
            e0 = m.second_hardening_onset;
            H  = m.second_hardening_modulus;
          }
        double de = (q_trial - s0 - H * (eps_p - e0)) / (3 * G + H);
        if (m.hardening == Hardening::bilinear
            && eps_p < m.second_hardening_onset
            && eps_p + de > m.second_hardening_onset)
          {
            s0 = m.yield_stress_at(m.second_hardening_onset);
            e0 = m.second_hardening_onset;
            H  = m.second_hardening_modulus;
            de = (q_trial - s0 - H * (eps_p - e0)) / (3 * G + H);
          }
        return std::max(de, 0.);
      }
    } // namespace


    // ------------------------------------------------------------------
    void
    GhostExchange::setup(const MPI_Comm                    communicator,
                         const std::vector<unsigned int>  &ghost_owner,
                         const std::vector<std::uint64_t> &ghost_ids,
                         const std::vector<std::uint64_t> &owned_ids,
                         const unsigned int                n_owned_automata)
    {
      comm    = communicator;
      n_owned = n_owned_automata;
      neighbors.clear();
      send_indices.clear();
      recv_indices.clear();
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(comm);
      if (n_ranks == 1)
        return;
      // Requests: the ids I need from each owner.
      std::vector<std::vector<std::uint64_t>> request(n_ranks);
      std::vector<std::vector<unsigned int>>  recv_of(n_ranks);
      for (unsigned int k = 0; k < ghost_ids.size(); ++k)
        {
          request[ghost_owner[k]].push_back(ghost_ids[k]);
          recv_of[ghost_owner[k]].push_back(n_owned + k);
        }
      std::vector<int> send_count(n_ranks), recv_count(n_ranks);
      for (unsigned int r = 0; r < n_ranks; ++r)
        send_count[r] = request[r].size();
      MPI_Alltoall(
        send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, comm);
      std::vector<int> sdispl(n_ranks + 1, 0), rdispl(n_ranks + 1, 0);
      for (unsigned int r = 0; r < n_ranks; ++r)
        {
          sdispl[r + 1] = sdispl[r] + send_count[r];
          rdispl[r + 1] = rdispl[r] + recv_count[r];
        }
      std::vector<std::uint64_t> flat_requests(sdispl[n_ranks]);
      for (unsigned int r = 0; r < n_ranks; ++r)
        std::copy(request[r].begin(),
                  request[r].end(),
                  flat_requests.begin() + sdispl[r]);
      std::vector<std::uint64_t> asked(rdispl[n_ranks]);
      MPI_Alltoallv(flat_requests.data(),
                    send_count.data(),
                    sdispl.data(),
                    MPI_UINT64_T,
                    asked.data(),
                    recv_count.data(),
                    rdispl.data(),
                    MPI_UINT64_T,
                    comm);
      std::unordered_map<std::uint64_t, unsigned int> owned_index;
      owned_index.reserve(owned_ids.size());
      for (unsigned int k = 0; k < owned_ids.size(); ++k)
        owned_index[owned_ids[k]] = k;
      for (unsigned int r = 0; r < n_ranks; ++r)
        {
          if (send_count[r] == 0 && recv_count[r] == 0)
            continue;
          neighbors.push_back(r);
          std::vector<unsigned int> s;
          for (int k = rdispl[r]; k < rdispl[r + 1]; ++k)
            {
              const auto it = owned_index.find(asked[k]);
              if (it == owned_index.end())
                throw RunError("Internal inconsistency: rank "
                               + std::to_string(r)
                               + " asked for an automaton this rank does "
                                 "not own.");
              s.push_back(it->second);
            }
          send_indices.push_back(s);
          recv_indices.push_back(recv_of[r]);
        }
      send_buffers.resize(neighbors.size());
      recv_buffers.resize(neighbors.size());
    }


    void
    GhostExchange::update(double *data, const unsigned int width) const
    {
      if (neighbors.empty())
        return;
      std::vector<MPI_Request> requests(2 * neighbors.size());
      for (unsigned int n = 0; n < neighbors.size(); ++n)
        {
          recv_buffers[n].resize(recv_indices[n].size() * width);
          MPI_Irecv(recv_buffers[n].data(),
                    recv_buffers[n].size(),
                    MPI_DOUBLE,
                    neighbors[n],
                    77,
                    comm,
                    &requests[n]);
        }
      for (unsigned int n = 0; n < neighbors.size(); ++n)
        {
          auto &buf = send_buffers[n];
          buf.resize(send_indices[n].size() * width);
          for (unsigned int k = 0; k < send_indices[n].size(); ++k)
            std::copy(data + send_indices[n][k] * width,
                      data + (send_indices[n][k] + 1) * width,
                      buf.data() + k * width);
          MPI_Isend(buf.data(),
                    buf.size(),
                    MPI_DOUBLE,
                    neighbors[n],
                    77,
                    comm,
                    &requests[neighbors.size() + n]);
        }
      MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
      for (unsigned int n = 0; n < neighbors.size(); ++n)
        for (unsigned int k = 0; k < recv_indices[n].size(); ++k)
          std::copy(recv_buffers[n].data() + k * width,
                    recv_buffers[n].data() + (k + 1) * width,
                    data + recv_indices[n][k] * width);
    }


    // ------------------------------------------------------------------
    AutomatonSystem::AutomatonSystem(const Parameters &parameters,
                                     const MPI_Comm    communicator)
        : prm(parameters)
        , comm(communicator)
        , n_ranks(dealii::Utilities::MPI::n_mpi_processes(communicator))
        , rank(dealii::Utilities::MPI::this_mpi_process(communicator))
        , tria(communicator)
    {
      const auto &g = prm.geometry;
      d             = g.automaton_size;
      r0            = d / 2;
      S             = d * d / (2 * std::sqrt(2.));
      V             = d * d * d / std::sqrt(2.);
      periodic      = g.periodic;
      for (unsigned int c = 0; c < 3; ++c)
        period[c] = g.domain_upper[c] - g.domain_lower[c];
      rotations = prm.interaction.rotations;
      for (const auto &m : prm.materials)
        {
          MaterialConstants k;
          k.m       = m;
          k.rho     = m.density;
          k.G       = m.shear_modulus();
          k.K       = m.bulk_modulus();
          k.D       = m.many_body_coefficient();
          k.two_G   = 2 * k.G;
          k.yield0  = m.is_plastic() ? m.yield_stress
                                     : std::numeric_limits<double>::max();
          k.sigma_b = m.bond_breaking_stress;
          k.w_b     = m.bond_energy_density;
          mc.push_back(k);
        }
    }


    dealii::Tensor<1, 3>
    AutomatonSystem::min_image(const Point3 &xi, const Point3 &xj) const
    {
      Tensor<1, 3> r = xj - xi;
      for (unsigned int c = 0; c < 3; ++c)
        if (periodic[c])
          r[c] -= period[c] * std::round(r[c] / period[c]);
      return r;
    }


    void
    AutomatonSystem::make_background_mesh()
    {
      const auto           &g     = prm.geometry;
      const double          h_min = d * (1 + prm.interaction.skin);
      std::array<double, 3> L;
      for (unsigned int c = 0; c < 3; ++c)
        L[c] = g.domain_upper[c] - g.domain_lower[c];
      // Coarse mesh: one cell across x and y and slabs along z (p4est
      // trees), refined globally `level` times to cells of at least the
      // interaction range h_min (and not too many: about 40 000 at most).
      // Under MPI each rank owns whole trees (see below), i.e. slabs along
      // z spanning the periodic directions x and y.
      const double h_target
        = std::max(h_min, std::cbrt(L[0] * L[1] * L[2] / 40000.));
      for (unsigned int c = 0; c < 3; ++c)
        if (periodic[c] && L[c] < 2 * h_min * 1.0000001)
          throw InputError(
            std::string("The periodic length in ") + "xyz"[c] + " ("
            + format_number(L[c])
            + " m) must exceed twice the interaction range (automaton size "
              "times 1 + Interaction/Skin = "
            + format_number(h_min) + " m).");
      unsigned int level = 0;
      while (std::min(L[0], L[1]) / std::pow(2., level + 1) >= h_target
             && L[2] / std::pow(2., level + 1) >= h_target * 2 && level < 10)
        ++level;
      const double              scale = std::pow(2., level);
      std::vector<unsigned int> repetitions
        = {1,
           1,
           std::max(1u,
                    static_cast<unsigned int>(
                      std::floor(L[2] / (h_target * scale))))};
      if (n_ranks > 1 && periodic[2])
        throw InputError(
          "Parameter 'Geometry/Periodic z': periodicity in z is not "
          "supported on several MPI ranks (the ranks own slabs along z, and "
          "deal.II 9.4's particle ghost exchange does not follow periodic "
          "faces). Run on one rank or make z non-periodic.");
      if (n_ranks > repetitions[2])
        throw InputError(
          "The MCA domain is split into slabs along z, at least one per MPI "
          "rank; this domain (height "
          + format_number(L[2]) + " m) has " + std::to_string(repetitions[2])
          + " slab(s) for " + std::to_string(n_ranks)
          + " ranks. Use fewer ranks or a taller "
            "domain.");
      dealii::GridGenerator::subdivided_hyper_rectangle(
        tria, repetitions, g.domain_lower, g.domain_upper, true);
      std::vector<dealii::GridTools::PeriodicFacePair<
        dealii::parallel::distributed::Triangulation<3>::cell_iterator>>
        faces;
      for (unsigned int c = 0; c < 3; ++c)
        if (periodic[c])
          dealii::GridTools::collect_periodic_faces(
            tria, 2 * c, 2 * c + 1, c, faces);
      if (!faces.empty())
        tria.add_periodicity(faces);
      if (level > 0)
        tria.refine_global(level);
      if (n_ranks > 1)
        {
          // The first cell (in p4est's Morton order: the lowest corner) of
          // each tree carries nearly all the weight, so the partition cuts
          // fall at tree boundaries: every rank owns whole slabs. Periodic
          // neighbours in x and y are then also vertex neighbours of cells
          // of the same slab, as deal.II 9.4's (vertex based, periodicity
          // unaware) ghost exchange needs, and automata wrapped across a
          // periodic face stay on their rank.
          const double       n_per_tree  = std::pow(8., level);
          const unsigned int tree_weight = static_cast<unsigned int>(
            std::min(4.0e9 / repetitions[2], 20000. * n_per_tree + 1));
          const double hx = L[0] / scale, hy = L[1] / scale,
                       hz       = L[2] / (repetitions[2] * scale);
          const auto connection = tria.signals.weight.connect(
            [&](
              const dealii::parallel::distributed::Triangulation<
                3>::cell_iterator &cell,
              const dealii::parallel::distributed::Triangulation<3>::CellStatus)
              -> unsigned int {
              const Point3 c  = cell->center();
              const long   iz = static_cast<long>(
                std::floor((c[2] - g.domain_lower[2]) / hz));
              return (c[0] < g.domain_lower[0] + hx
                      && c[1] < g.domain_lower[1] + hy
                      && iz % static_cast<long>(scale) == 0)
                       ? tree_weight
                       : 1u;
            });
          tria.repartition();
          connection.disconnect();
        }
    }


    void
    AutomatonSystem::setup()
    {
      const auto &g = prm.geometry;
      make_background_mesh();

      // Which features does the scene need?
      const std::vector<PackedAutomaton> packed
        = pack_automata(g, prm.materials.size());
      n_global = packed.size();
      std::vector<bool> used(prm.materials.size(), false);
      for (const auto &a : packed)
        used[a.material] = true;
      double c_max  = 0;
      plastic_scene = false;
      for (unsigned int m = 0; m < prm.materials.size(); ++m)
        if (used[m])
          {
            c_max = std::max(c_max, prm.materials[m].p_wave_speed());
            if (prm.interaction.plasticity && prm.materials[m].is_plastic())
              plastic_scene = true;
          }
      bond_scene
        = prm.interaction.bond_breaking || prm.interaction.bond_formation;
      critical_dt = d / c_max;
      if (prm.time.time_step == 0)
        dt = prm.time.courant * critical_dt;
      else
        {
          dt = prm.time.time_step;
          if (dt > TimeParameters::max_courant * critical_dt)
            throw InputError(
              "Parameter 'Time/Time step' = " + format_number(dt)
              + " s is too large: the limit is "
              + format_number(TimeParameters::max_courant * critical_dt)
              + " s, half the sound-crossing time d_min / c_p,max = "
              + format_number(critical_dt)
              + " s of the smallest automaton. Use a smaller step or 0 "
                "(automatic).");
        }

      n_slot_fields
        = n_ranks > 1 ? prm.interaction.pair_slots * slot::n_fields : 0;
      n_automaton_properties = prop::n_automaton + n_slot_fields;
      particles = std::make_unique<dealii::Particles::ParticleHandler<3>>(
        tria, mapping, n_automaton_properties);

      // Insert the automata that fall in locally owned cells. The mesh is a
      // structured box: locate cells by integer coordinates.
      std::array<unsigned int, 3> nc{{0, 0, 0}};
      std::array<double, 3>       h;
      {
        // number of active cells per direction
        const auto cell0 = tria.begin_active();
        for (unsigned int c = 0; c < 3; ++c)
          {
            h[c]  = cell0->extent_in_direction(c);
            nc[c] = static_cast<unsigned int>(
              std::round((g.domain_upper[c] - g.domain_lower[c]) / h[c]));
          }
      }
      std::vector<
        dealii::parallel::distributed::Triangulation<3>::active_cell_iterator>
        cell_of(static_cast<std::size_t>(nc[0]) * nc[1] * nc[2]);
      std::vector<bool> owned_cell(cell_of.size(), false);
      auto              cell_index = [&](const Point3 &p) {
        std::array<long, 3> i;
        for (unsigned int c = 0; c < 3; ++c)
          i[c] = std::min<long>(
            nc[c] - 1,
            std::max<long>(0,
                           static_cast<long>(
                             std::floor((p[c] - g.domain_lower[c]) / h[c]))));
        return (i[2] * nc[1] + i[1]) * nc[0] + i[0];
      };
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const long k  = cell_index(cell->center());
            cell_of[k]    = cell;
            owned_cell[k] = true;
          }

      std::vector<double> props(n_automaton_properties, 0.);
      for (std::size_t k = 0; k < packed.size(); ++k)
        {
          const Point3 &p  = packed[k].position;
          const long    ci = cell_index(p);
          if (!owned_cell[ci])
            continue;
          const auto   cell = cell_of[ci];
          Point3       ref;
          const Point3 lower = cell->vertex(0);
          for (unsigned int c = 0; c < 3; ++c)
            ref[c] = std::min(1., std::max(0., (p[c] - lower[c]) / h[c]));
          std::fill(props.begin(), props.end(), 0.);
          props[prop::mat]   = packed[k].material;
          props[prop::body]  = packed[k].body;
          std::uint32_t mask = 0;
          for (unsigned int gi = 0; gi < prm.boundary.groups.size(); ++gi)
            {
              const auto &grp = prm.boundary.groups[gi];
              bool        in  = true;
              for (unsigned int c = 0; c < 3; ++c)
                if (p[c] < grp.lower[c] || p[c] > grp.upper[c])
                  in = false;
              if (in)
                mask |= (1u << gi);
            }
          props[prop::groups]  = mask;
          props[prop::sigma_y] = mc[packed[k].material].yield0;
          particles->insert_particle(
            p,
            ref,
            k,
            cell,
            dealii::ArrayView<const double>(props.data(), props.size()));
        }
      particles->update_cached_numbers();
      if (particles->n_global_particles() != n_global)
        throw RunError("Internal error: "
                       + std::to_string(particles->n_global_particles())
                       + " of " + std::to_string(n_global)
                       + " automata were placed in the background mesh.");
      group_force_local.assign(prm.boundary.groups.size(), {{0, 0, 0}});
      rebuild(true);
    }


    void
    AutomatonSystem::write_state_to_particles()
    {
      // Pair states in the slots of the automaton with the smaller id
      // (which is always i of a pair, and owned or ghost here).
      std::vector<unsigned int> n_used(n_owned, 0);
      std::vector<double>       slots;
      if (n_slot_fields > 0)
        {
          slots.assign(static_cast<std::size_t>(n_owned) * n_slot_fields, -1.);
          const unsigned int max_slots = prm.interaction.pair_slots;
          for (unsigned int p = 0; p < pi.size(); ++p)
            {
              if (!owned_i[p])
                continue;
              const unsigned int a = pi[p];
              if (n_used[a] == max_slots)
                throw RunError(
                  "An automaton has more than Interaction/Pair slots = "
                  + std::to_string(max_slots)
                  + " pairs in which it has the smaller id; raise the "
                    "parameter.");
              double *s = slots.data()
                          + static_cast<std::size_t>(a) * n_slot_fields
                          + n_used[a] * slot::n_fields;
              ++n_used[a];
              s[slot::partner] = id[pj[p]];
              s[slot::bonded]  = bonded[p];
              s[slot::q]       = q_i[p];
              s[slot::sig_i]   = sig_i[p];
              s[slot::sig_j]   = sig_j[p];
              for (unsigned int c = 0; c < 3; ++c)
                {
                  s[slot::tau_i + c] = tau_i[p][c];
                  s[slot::tau_j + c] = tau_j[p][c];
                }
              s[slot::heat]    = heat[p];
              s[slot::contact] = in_contact[p];
            }
        }
      unsigned int k = 0;
      for (auto it = particles->begin(); it != particles->end(); ++it, ++k)
        {
          Assert(it->get_id() == id[k], dealii::ExcInternalError());
          Point3 p = x[k];
          for (unsigned int c = 0; c < 3; ++c)
            if (periodic[c])
              {
                const double lo = prm.geometry.domain_lower[c];
                p[c]            = lo
                       + std::fmod(std::fmod(p[c] - lo, period[c]) + period[c],
                                   period[c]);
                if (p[c] >= lo + period[c])
                  p[c] = lo;
              }
          it->set_location(p);
          auto props = it->get_properties();
          for (unsigned int c = 0; c < 3; ++c)
            {
              props[prop::v + c]      = v[k][c];
              props[prop::w + c]      = w[k][c];
              props[prop::f + c]      = f_tot[k][c];
              props[prop::torque + c] = torque[k][c];
              props[prop::u + c]      = u[k][c];
            }
          props[prop::mat]      = mat[k];
          props[prop::body]     = body[k];
          props[prop::groups]   = groups[k];
          props[prop::eps_p]    = eps_p[k];
          props[prop::sigma_y]  = sigma_y[k];
          props[prop::dsm_prev] = dsm_prev[k];
          if (n_slot_fields > 0)
            std::copy(slots.begin()
                        + static_cast<std::size_t>(k) * n_slot_fields,
                      slots.begin()
                        + static_cast<std::size_t>(k + 1) * n_slot_fields,
                      props.begin() + prop::n_automaton);
        }
    }


    void
    AutomatonSystem::read_state_from_particles(const bool initial)
    {
      n_owned                    = particles->n_locally_owned_particles();
      const unsigned int width   = 4 + n_automaton_properties;
      const unsigned int n_ghost = ghost_records.size() / width;
      n_local                    = n_owned + n_ghost;
      id.resize(n_local);
      x.resize(n_local);
      x_at_rebuild.resize(n_local);
      for (auto *vec : {&dx, &v, &w, &f, &f_tot, &torque, &u})
        vec->assign(n_local, {{0, 0, 0}});
      mass.assign(n_local, 0);
      inertia.assign(n_local, 0);
      mat.assign(n_local, 0);
      body.assign(n_local, 0);
      groups.assign(n_local, 0);
      eps_p.assign(n_local, 0);
      sigma_y.assign(n_local, 0);
      dsm_prev.assign(n_local, 0);
      stress.assign(n_local, Sym3{{0, 0, 0, 0, 0, 0}});
      std::vector<unsigned int>  ghost_owner(n_ghost);
      std::vector<std::uint64_t> ghost_ids(n_ghost), owned_ids(n_owned);

      auto read = [&](const std::uint64_t the_id,
                      const Point3       &location,
                      const double       *props,
                      const unsigned int  k) {
        id[k] = the_id;
        x[k]  = location;
        for (unsigned int c = 0; c < 3; ++c)
          {
            v[k][c]      = props[prop::v + c];
            w[k][c]      = props[prop::w + c];
            f[k][c]      = props[prop::f + c];
            f_tot[k][c]  = props[prop::f + c];
            torque[k][c] = props[prop::torque + c];
            u[k][c]      = props[prop::u + c];
          }
        mat[k]      = static_cast<unsigned char>(props[prop::mat]);
        body[k]     = static_cast<unsigned char>(props[prop::body]);
        groups[k]   = static_cast<std::uint32_t>(props[prop::groups]);
        eps_p[k]    = props[prop::eps_p];
        sigma_y[k]  = props[prop::sigma_y];
        dsm_prev[k] = props[prop::dsm_prev];
        mass[k]     = mc[mat[k]].rho * V;
        inertia[k]  = mass[k] * d * d / 10;
      };
      unsigned int k = 0;
      for (auto it = particles->begin(); it != particles->end(); ++it, ++k)
        {
          read(it->get_id(),
               it->get_location(),
               it->get_properties().data(),
               k);
          owned_ids[k] = id[k];
        }
      for (unsigned int g = 0; g < n_ghost; ++g, ++k)
        {
          const double *r
            = ghost_records.data() + static_cast<std::size_t>(g) * width;
          read(static_cast<std::uint64_t>(r[0]),
               Point3(r[1], r[2], r[3]),
               r + 4,
               k);
          ghost_ids[g]   = id[k];
          ghost_owner[g] = ghost_record_owner[g];
        }
      x_at_rebuild = x;
      ghosts.setup(comm, ghost_owner, ghost_ids, owned_ids, n_owned);
      (void)initial;
    }


    void
    AutomatonSystem::exchange_ghosts()
    {
      // deal.II 9.4's exchange_ghost_particles() does not follow periodic
      // faces; the ranks own slabs along z (see make_background_mesh()), so
      // the ghosts of a rank are the automata of the other slabs within the
      // interaction range of its slab: sent here with all their properties.
      const double range     = d * (1 + prm.interaction.skin);
      double       bounds[2] = {std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max()};
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            bounds[0] = std::min(bounds[0], cell->vertex(0)[2]);
            bounds[1] = std::max(bounds[1], cell->vertex(7)[2]);
          }
      std::vector<double> all(2 * n_ranks);
      MPI_Allgather(bounds, 2, MPI_DOUBLE, all.data(), 2, MPI_DOUBLE, comm);
      const unsigned int               width = 4 + n_automaton_properties;
      std::vector<std::vector<double>> out(n_ranks);
      for (auto it = particles->begin(); it != particles->end(); ++it)
        {
          const Point3 p = it->get_location();
          for (unsigned int r = 0; r < n_ranks; ++r)
            {
              if (r == rank)
                continue;
              const double gap
                = std::max({0., all[2 * r] - p[2], p[2] - all[2 * r + 1]});
              if (gap >= range)
                continue;
              auto &buf = out[r];
              buf.push_back(static_cast<double>(it->get_id()));
              for (unsigned int c = 0; c < 3; ++c)
                buf.push_back(p[c]);
              const auto props = it->get_properties();
              buf.insert(buf.end(), props.begin(), props.end());
            }
        }
      std::vector<int> send_count(n_ranks), recv_count(n_ranks);
      for (unsigned int r = 0; r < n_ranks; ++r)
        send_count[r] = out[r].size();
      MPI_Alltoall(
        send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, comm);
      std::vector<int> sd(n_ranks + 1, 0), rd(n_ranks + 1, 0);
      for (unsigned int r = 0; r < n_ranks; ++r)
        {
          sd[r + 1] = sd[r] + send_count[r];
          rd[r + 1] = rd[r] + recv_count[r];
        }
      std::vector<double> flat(sd[n_ranks]);
      for (unsigned int r = 0; r < n_ranks; ++r)
        std::copy(out[r].begin(), out[r].end(), flat.begin() + sd[r]);
      ghost_records.resize(rd[n_ranks]);
      MPI_Alltoallv(flat.data(),
                    send_count.data(),
                    sd.data(),
                    MPI_DOUBLE,
                    ghost_records.data(),
                    recv_count.data(),
                    rd.data(),
                    MPI_DOUBLE,
                    comm);
      ghost_record_owner.clear();
      for (unsigned int r = 0; r < n_ranks; ++r)
        for (int k = rd[r]; k < rd[r + 1]; k += width)
          ghost_record_owner.push_back(r);
    }


    void
    AutomatonSystem::rebuild(const bool initial)
    {
      // Keep the pair states of this rank (used directly on one rank; under
      // MPI they travel in the particle slots).
      std::unordered_map<std::uint64_t, unsigned int> old_index;
      std::vector<unsigned char> o_bonded = bonded, o_contact = in_contact;
      std::vector<double> o_q = q_i, o_si = sig_i, o_sj = sig_j, o_heat = heat;
      std::vector<Vec3>   o_ti = tau_i, o_tj = tau_j;
      if (!initial)
        {
          if (n_slot_fields == 0)
            for (unsigned int p = 0; p < pi.size(); ++p)
              old_index[pair_key(id[pi[p]], id[pj[p]])] = p;
          write_state_to_particles();
          std::string lost;
          auto        connection = particles->signals.particle_lost.connect(
            [&](const auto &particle, const auto &) {
              if (lost.size() < 400)
                {
                  std::ostringstream s;
                  s << " (" << particle->get_location() << ")";
                  for (unsigned int k = 0; k < n_owned; ++k)
                    if (id[k] == particle->get_id())
                      s << " [id " << id[k] << " x " << x[k] << " at rebuild "
                        << x_at_rebuild[k] << "]";
                  lost += s.str();
                }
            });
          particles->sort_particles_into_subdomains_and_cells();
          connection.disconnect();
          if (particles->n_global_particles() != n_global)
            throw RunError(
              std::to_string(n_global - particles->n_global_particles())
              + " automata left the simulation box (Geometry/Domain lower and "
                "upper) through a non-periodic side"
              + (lost.empty() ? std::string() : ", e.g. at" + lost)
              + ". Enlarge the box to leave room for the motion.");
        }
      if (n_ranks > 1)
        exchange_ghosts();
      read_state_from_particles(initial);

      // Slots of every local automaton (owned and ghost) under MPI.
      std::vector<double> slots;
      if (!initial && n_slot_fields > 0)
        {
          slots.resize(static_cast<std::size_t>(n_local) * n_slot_fields);
          unsigned int k    = 0;
          auto         copy = [&](const auto &it) {
            const auto props = it->get_properties();
            std::copy(props.begin() + prop::n_automaton,
                      props.end(),
                      slots.begin()
                        + static_cast<std::size_t>(k) * n_slot_fields);
            ++k;
          };
          for (auto it = particles->begin(); it != particles->end(); ++it)
            copy(it);
          const unsigned int width = 4 + n_automaton_properties;
          for (std::size_t g = 0; g < ghost_records.size() / width; ++g)
            std::copy(ghost_records.begin() + g * width + 4 + prop::n_automaton,
                      ghost_records.begin() + (g + 1) * width,
                      slots.begin()
                        + static_cast<std::size_t>(n_owned + g)
                            * n_slot_fields);
        }

      build_pair_list(initial);

      // Pair states.
      const unsigned int n_pairs = pi.size();
      bonded.assign(n_pairs, 0);
      in_contact.assign(n_pairs, 0);
      q_i.assign(n_pairs, 0);
      sig_i.assign(n_pairs, 0);
      sig_j.assign(n_pairs, 0);
      heat.assign(n_pairs, 0);
      tau_i.assign(n_pairs, {{0, 0, 0}});
      tau_j.assign(n_pairs, {{0, 0, 0}});
      normal.assign(n_pairs, {{0, 0, 0}});
      r_now.assign(n_pairs, 0);
      deps_i.assign(n_pairs, 0);
      deps_j.assign(n_pairs, 0);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          const double       r = min_image(x[i], x[j]).norm();
          r_now[p]             = r;
          q_i[p]               = r / 2;
          if (initial)
            {
              bonded[p]     = body[i] == body[j] && r < d * (1 + 1e-6);
              in_contact[p] = r < d * (1 + 1e-6);
              continue;
            }
          if (n_slot_fields == 0)
            {
              const auto it = old_index.find(pair_key(id[i], id[j]));
              if (it == old_index.end())
                continue;
              const unsigned int o = it->second;
              bonded[p]            = o_bonded[o];
              in_contact[p]        = o_contact[o];
              q_i[p]               = o_q[o];
              sig_i[p]             = o_si[o];
              sig_j[p]             = o_sj[o];
              tau_i[p]             = o_ti[o];
              tau_j[p]             = o_tj[o];
              heat[p]              = o_heat[o];
            }
          else
            {
              const double *s
                = slots.data() + static_cast<std::size_t>(i) * n_slot_fields;
              for (unsigned int sl = 0; sl < prm.interaction.pair_slots;
                   ++sl, s += slot::n_fields)
                if (s[slot::partner] == static_cast<double>(id[j]))
                  {
                    bonded[p]     = s[slot::bonded] != 0;
                    in_contact[p] = s[slot::contact] != 0;
                    q_i[p]        = s[slot::q];
                    sig_i[p]      = s[slot::sig_i];
                    sig_j[p]      = s[slot::sig_j];
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        tau_i[p][c] = s[slot::tau_i + c];
                        tau_j[p][c] = s[slot::tau_j + c];
                      }
                    heat[p] = s[slot::heat];
                    break;
                  }
            }
        }
      update_neighbourhood_weights();
      ++rebuild_count;
    }


    void
    AutomatonSystem::build_pair_list(const bool initial)
    {
      (void)initial;
      const auto           &g     = prm.geometry;
      const double          range = d * (1 + prm.interaction.skin);
      std::array<int, 3>    nb;
      std::array<double, 3> bs;
      for (unsigned int c = 0; c < 3; ++c)
        {
          nb[c] = std::max(1, static_cast<int>(std::floor(period[c] / range)));
          bs[c] = period[c] / nb[c];
        }
      auto bin_coord = [&](const Point3 &p, const unsigned int c) {
        double y = p[c] - g.domain_lower[c];
        if (periodic[c])
          y = std::fmod(std::fmod(y, period[c]) + period[c], period[c]);
        int b = static_cast<int>(std::floor(y / bs[c]));
        return std::min(nb[c] - 1, std::max(0, b));
      };
      const std::size_t n_bins
        = static_cast<std::size_t>(nb[0]) * nb[1] * nb[2];
      std::vector<unsigned int>       count(n_bins + 1, 0), bin_of(n_local);
      std::vector<std::array<int, 3>> coords(n_local);
      for (unsigned int k = 0; k < n_local; ++k)
        {
          for (unsigned int c = 0; c < 3; ++c)
            coords[k][c] = bin_coord(x[k], c);
          bin_of[k]
            = (coords[k][2] * nb[1] + coords[k][1]) * nb[0] + coords[k][0];
          ++count[bin_of[k] + 1];
        }
      for (std::size_t b = 0; b < n_bins; ++b)
        count[b + 1] += count[b];
      std::vector<unsigned int> sorted(n_local),
        fill(count.begin(), count.end() - 1);
      for (unsigned int k = 0; k < n_local; ++k)
        sorted[fill[bin_of[k]]++] = k;

      pi.clear();
      pj.clear();
      owned_i.clear();
      owned_j.clear();
      std::vector<std::size_t> neighbour_bins;
      for (unsigned int a = 0; a < n_owned; ++a)
        {
          neighbour_bins.clear();
          for (int oz = -1; oz <= 1; ++oz)
            for (int oy = -1; oy <= 1; ++oy)
              for (int ox = -1; ox <= 1; ++ox)
                {
                  const int o[3] = {ox, oy, oz};
                  int       b[3];
                  bool      valid = true;
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      b[c] = coords[a][c] + o[c];
                      if (b[c] < 0 || b[c] >= nb[c])
                        {
                          if (periodic[c])
                            b[c] = (b[c] + nb[c]) % nb[c];
                          else
                            valid = false;
                        }
                    }
                  if (valid)
                    neighbour_bins.push_back(
                      (static_cast<std::size_t>(b[2]) * nb[1] + b[1]) * nb[0]
                      + b[0]);
                }
          std::sort(neighbour_bins.begin(), neighbour_bins.end());
          neighbour_bins.erase(std::unique(neighbour_bins.begin(),
                                           neighbour_bins.end()),
                               neighbour_bins.end());
          for (const std::size_t bin : neighbour_bins)
            for (unsigned int s = count[bin]; s < count[bin + 1]; ++s)
              {
                const unsigned int b = sorted[s];
                if (b == a)
                  continue;
                if (b < n_owned && id[b] < id[a])
                  continue; // counted from b
                const double r = min_image(x[a], x[b]).norm();
                if (r >= range)
                  continue;
                const bool a_first = id[a] < id[b];
                pi.push_back(a_first ? a : b);
                pj.push_back(a_first ? b : a);
                owned_i.push_back(a_first ? 1 : (b < n_owned));
                owned_j.push_back(a_first ? (b < n_owned) : 1);
              }
        }
      // Deterministic order (sorted by ids) so that sums do not depend on
      // the binning order.
      std::vector<unsigned int> order(pi.size());
      for (unsigned int p = 0; p < order.size(); ++p)
        order[p] = p;
      std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
        return std::make_pair(id[pi[a]], id[pj[a]])
               < std::make_pair(id[pi[b]], id[pj[b]]);
      });
      auto permute = [&](auto &vec) {
        auto copy = vec;
        for (unsigned int p = 0; p < order.size(); ++p)
          vec[p] = copy[order[p]];
      };
      permute(pi);
      permute(pj);
      permute(owned_i);
      permute(owned_j);
    }


    // ------------------------------------------------------------------
    double
    AutomatonSystem::ramp(const double t) const
    {
      const double T = prm.boundary.ramp_time;
      if (T <= 0 || t >= T)
        return 1;
      if (t <= 0)
        return 0;
      const double s = t / T;
      return s * s * (3 - 2 * s);
    }


    Vec3
    AutomatonSystem::group_value(const BoundaryGroup &g, const double t) const
    {
      Vec3 value;
      if (g.switch_time < 0 || t <= g.switch_time)
        {
          for (unsigned int c = 0; c < 3; ++c)
            value[c] = g.value[c]
                       * (g.type == BoundaryGroup::Type::damping ? 1 : ramp(t));
          return value;
        }
      const double s = ramp(t - g.switch_time);
      for (unsigned int c = 0; c < 3; ++c)
        value[c] = (1 - s) * g.value[c] + s * g.second_value[c];
      return value;
    }


    void
    AutomatonSystem::apply_kinematic_constraints(const double t)
    {
      const auto &grp = prm.boundary.groups;
      if (grp.empty())
        return;
      std::vector<Vec3> values(grp.size());
      for (unsigned int gi = 0; gi < grp.size(); ++gi)
        values[gi] = group_value(grp[gi], t);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          if (groups[k] == 0)
            continue;
          for (unsigned int gi = 0; gi < grp.size(); ++gi)
            if (groups[k] & (1u << gi))
              {
                if (grp[gi].type == BoundaryGroup::Type::fixed)
                  v[k] = {{0, 0, 0}};
                else if (grp[gi].type == BoundaryGroup::Type::velocity)
                  for (unsigned int c = 0; c < 3; ++c)
                    if (!std::isnan(values[gi][c]))
                      v[k][c] = values[gi][c];
              }
        }
    }


    void
    AutomatonSystem::apply_boundary_forces(const double t)
    {
      // Adds external and damping forces to f (after the reaction has been
      // recorded by the caller).
      const auto                     &grp      = prm.boundary.groups;
      const double                    c_global = prm.boundary.global_damping;
      std::vector<Vec3>               values(grp.size());
      std::vector<unsigned long long> sizes;
      bool                            any_force = false;
      for (unsigned int gi = 0; gi < grp.size(); ++gi)
        {
          values[gi] = group_value(grp[gi], t);
          any_force  = any_force || grp[gi].type == BoundaryGroup::Type::force;
        }
      if (any_force)
        sizes = group_sizes();
      f_tot.resize(n_local);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          f_tot[k] = f[k];
          if (c_global > 0)
            for (unsigned int c = 0; c < 3; ++c)
              f_tot[k][c] -= c_global * mass[k] * v[k][c];
          if (groups[k] == 0)
            continue;
          for (unsigned int gi = 0; gi < grp.size(); ++gi)
            if (groups[k] & (1u << gi))
              {
                if (grp[gi].type == BoundaryGroup::Type::force)
                  for (unsigned int c = 0; c < 3; ++c)
                    f_tot[k][c] += values[gi][c] / sizes[gi];
                else if (grp[gi].type == BoundaryGroup::Type::damping)
                  for (unsigned int c = 0; c < 3; ++c)
                    f_tot[k][c] -= values[gi][c] * mass[k] * v[k][c];
              }
        }
      // A force group is a rigid loading plate: its automata share the
      // acceleration of the group's total force over its total mass.
      for (unsigned int gi = 0; gi < grp.size(); ++gi)
        {
          if (grp[gi].type != BoundaryGroup::Type::force)
            continue;
          double sums[4] = {0, 0, 0, 0};
          for (unsigned int k = 0; k < n_owned; ++k)
            if (groups[k] & (1u << gi))
              {
                for (unsigned int c = 0; c < 3; ++c)
                  sums[c] += f_tot[k][c];
                sums[3] += mass[k];
              }
          MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, comm);
          if (sums[3] == 0)
            continue;
          for (unsigned int k = 0; k < n_owned; ++k)
            if (groups[k] & (1u << gi))
              for (unsigned int c = 0; c < 3; ++c)
                f_tot[k][c] = mass[k] * sums[c] / sums[3];
        }
    }


    void
    AutomatonSystem::step()
    {
      // Rebuild the pair list when an automaton moved more than skin/2.
      {
        double max_disp2 = 0;
        for (unsigned int k = 0; k < n_owned; ++k)
          max_disp2
            = std::max(max_disp2, x[k].distance_square(x_at_rebuild[k]));
        const double limit = 0.5 * prm.interaction.skin * d;
        // one all-reduction for the rebuild test and the neighbourhood
        // flag of the last step
        double flags[2] = {max_disp2, weights_stale ? 1. : 0.};
        if (n_ranks > 1)
          MPI_Allreduce(MPI_IN_PLACE, flags, 2, MPI_DOUBLE, MPI_MAX, comm);
        weights_stale = flags[1] > 0;
        if (flags[0] > limit * limit)
          rebuild(false);
      }
      const double t = current_time;
      // First half kick (f holds pair + external forces of the last step).
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const double a = 0.5 * dt / mass[k];
          for (unsigned int c = 0; c < 3; ++c)
            v[k][c] += a * f_tot[k][c];
          if (rotations)
            {
              const double b = 0.5 * dt / inertia[k];
              for (unsigned int c = 0; c < 3; ++c)
                w[k][c] += b * torque[k][c];
            }
        }
      apply_kinematic_constraints(t + 0.5 * dt);
      // Drift.
      for (unsigned int k = 0; k < n_owned; ++k)
        for (unsigned int c = 0; c < 3; ++c)
          {
            dx[k][c] = dt * v[k][c];
            x[k][c] += dx[k][c];
            u[k][c] += dx[k][c];
          }
      current_time = t + dt;
      evaluate_pairs(dt, true);
      apply_boundary_forces(current_time);
      // Second half kick.
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const double a = 0.5 * dt / mass[k];
          for (unsigned int c = 0; c < 3; ++c)
            v[k][c] += a * f_tot[k][c];
          if (rotations)
            {
              const double b = 0.5 * dt / inertia[k];
              for (unsigned int c = 0; c < 3; ++c)
                w[k][c] += b * torque[k][c];
            }
        }
      apply_kinematic_constraints(current_time);
      ++n_steps_done;
      if (!std::isfinite(v[0][0] + x[0][0]) && n_owned > 0)
        throw RunError("The velocities became NaN at step "
                       + std::to_string(n_steps_done)
                       + "; the time step is probably too large.");
    }


    void
    AutomatonSystem::evaluate_pairs(const double step_dt, const bool integrate)
    {
      // Ghost kinematics: x, dx, w.
      if (ghosts.active())
        {
          kin.resize(static_cast<std::size_t>(n_local) * 9);
          for (unsigned int k = 0; k < n_owned; ++k)
            for (unsigned int c = 0; c < 3; ++c)
              {
                kin[9 * k + c]     = x[k][c];
                kin[9 * k + 3 + c] = dx[k][c];
                kin[9 * k + 6 + c] = w[k][c];
              }
          ghosts.update(kin.data(), 9);
          for (unsigned int k = n_owned; k < n_local; ++k)
            for (unsigned int c = 0; c < 3; ++c)
              {
                x[k][c]  = kin[9 * k + c];
                dx[k][c] = kin[9 * k + 3 + c];
                w[k][c]  = kin[9 * k + 6 + c];
              }
        }
      // Neighbourhoods changed (contacts, bonds): recompute the weights on
      // every rank at the same step (results independent of the partition).
      if (n_ranks > 1 && !integrate)
        weights_stale
          = dealii::Utilities::MPI::max(weights_stale ? 1 : 0, comm) > 0;
      if (weights_stale)
        update_neighbourhood_weights();
      const bool rot = rotations;
      if (rot && plastic_scene && bond_scene)
        pair_kernel<true, true, true>(step_dt);
      else if (rot && plastic_scene)
        pair_kernel<true, true, false>(step_dt);
      else if (rot && bond_scene)
        pair_kernel<true, false, true>(step_dt);
      else if (rot)
        pair_kernel<true, false, false>(step_dt);
      else if (plastic_scene && bond_scene)
        pair_kernel<false, true, true>(step_dt);
      else if (plastic_scene)
        pair_kernel<false, true, false>(step_dt);
      else if (bond_scene)
        pair_kernel<false, false, true>(step_dt);
      else
        pair_kernel<false, false, false>(step_dt);
    }


    template <bool rot, bool plastic, bool bonds>
    void
    AutomatonSystem::pair_kernel(const double step_dt)
    {
      (void)step_dt;
      const unsigned int n_pairs = pi.size();
      const double       mu      = prm.interaction.friction_coefficient;
      const double       inv_r0  = 1. / r0;
      sum_qs.assign(n_local, 0);
      acc_qse.assign(n_local, 0);
      dsm.assign(n_local, 0);

      // Pass A: geometry, tangential stresses, split of the normal
      // increment, strain increments of both sides.
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          const Tensor<1, 3> dn = min_image(x[i], x[j]);
          Vec3               dnew{{dn[0], dn[1], dn[2]}}, dold;
          for (unsigned int c = 0; c < 3; ++c)
            dold[c] = dnew[c] - (dx[j][c] - dx[i][c]);
          const double r  = std::sqrt(dot(dnew, dnew));
          const double ro = std::sqrt(dot(dold, dold));
          Vec3         n, nm, sum, diff;
          for (unsigned int c = 0; c < 3; ++c)
            {
              n[c]    = dnew[c] / r;
              nm[c]   = n[c] + dold[c] / ro;
              sum[c]  = dnew[c] + dold[c];
              diff[c] = dnew[c] - dold[c];
            }
          const double nmn = std::sqrt(dot(nm, nm));
          for (unsigned int c = 0; c < 3; ++c)
            nm[c] /= nmn;
          double dr = dot(diff, sum) / (r + ro), r_prev = ro;
          normal[p]              = n;
          r_now[p]               = r;
          const unsigned char mi = mat[i], mj = mat[j];
          const double ki = mc[mi].two_G * inv_r0, kj = mc[mj].two_G * inv_r0;

          if (!bonded[p])
            {
              if (r >= d)
                {
                  // separated: no interaction
                  if (in_contact[p])
                    weights_stale = true;
                  in_contact[p] = 0;
                  sig_i[p] = sig_j[p] = 0;
                  tau_i[p] = tau_j[p] = {{0, 0, 0}};
                  q_i[p]              = r / 2;
                  deps_i[p] = deps_j[p] = 0;
                  continue;
                }
              if (!in_contact[p])
                {
                  // touching now: only the overlap counts, from r = d
                  in_contact[p] = 1;
                  weights_stale = true;
                  q_i[p]        = d / 2;
                  r_prev        = d;
                  dr            = r - d;
                }
            }
          const double qi = q_i[p], qj = r_prev - qi;

          // Tangential: relative displacement of the contact points.
          Vec3 du;
          for (unsigned int c = 0; c < 3; ++c)
            du[c] = dx[j][c] - dx[i][c];
          if constexpr (rot)
            {
              Vec3 th;
              for (unsigned int c = 0; c < 3; ++c)
                th[c] = step_dt * (qi * w[i][c] + qj * w[j][c]);
              const Vec3 rc = cross(th, nm);
              for (unsigned int c = 0; c < 3; ++c)
                du[c] -= rc[c];
            }
          const double dun = dot(du, nm);
          for (unsigned int c = 0; c < 3; ++c)
            du[c] -= dun * nm[c];
          // rotate stored shear stresses into the new tangent plane
          for (Vec3 *tp : {&tau_i[p], &tau_j[p]})
            {
              Vec3        &t  = *tp;
              const double t2 = dot(t, t);
              if (t2 > 0)
                {
                  const double tn = dot(t, n);
                  for (unsigned int c = 0; c < 3; ++c)
                    t[c] -= tn * n[c];
                  const double p2 = dot(t, t);
                  const double s  = p2 > 1e-12 * t2 ? std::sqrt(t2 / p2) : 0.;
                  for (unsigned int c = 0; c < 3; ++c)
                    t[c] *= s;
                }
            }
          {
            const double inv = 1. / (ki + kj);
            for (unsigned int c = 0; c < 3; ++c)
              {
                const double tn
                  = (kj * tau_i[p][c] + ki * tau_j[p][c] + ki * kj * du[c])
                    * inv;
                tau_i[p][c] = tn;
                tau_j[p][c] = tn;
              }
          }
          // Normal split: equal stresses from both sides (many-body term of
          // the previous step as predictor).
          // Normal split: equal elastic increments 2G de from both sides
          // (series springs); the many-body parts D dsm of the two sides
          // differ and the force uses the mean of the two sides.
          const double dqi = kj * dr / (ki + kj);
          const double dei = dqi * inv_r0, dej = (dr - dqi) * inv_r0;
          deps_i[p]        = dei;
          deps_j[p]        = dej;
          q_i[p]           = qi + dqi;
          const double qin = qi + dqi, qjn = r - qin;
          if (owned_i[p])
            {
              sum_qs[i] += qin * S;
              acc_qse[i] += beta_i[p] * dei;
            }
          if (owned_j[p])
            {
              sum_qs[j] += qjn * S;
              acc_qse[j] += beta_j[p] * dej;
            }
        }

      // Mean-stress increment of each automaton: K times its volumetric
      // strain increment, the trace of the strain tensor fitted (least
      // squares) to its pairs' normal strains: dtheta = sum_j beta_ij
      // deps_ij (beta = 1/4 in a complete FCC neighbourhood).
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const auto &m = mc[mat[k]];
          dsm[k]        = m.K * acc_qse[k];
        }
      if (ghosts.active())
        ghosts.update(dsm.data(), 1);

      for (unsigned int k = 0; k < n_owned; ++k)
        {
          f[k]      = {{0, 0, 0}};
          torque[k] = {{0, 0, 0}};
        }

      // Pass B: side stresses; with plasticity, trial tensors.
      if constexpr (plastic)
        {
          trial.assign(n_local, Sym3{{0, 0, 0, 0, 0, 0}});
          for (unsigned int p = 0; p < n_pairs; ++p)
            {
              if (!bonded[p] && !in_contact[p])
                continue;
              const unsigned int i = pi[p], j = pj[p];
              sig_i[p] += mc[mat[i]].two_G * deps_i[p] + mc[mat[i]].D * dsm[i];
              sig_j[p] += mc[mat[j]].two_G * deps_j[p] + mc[mat[j]].D * dsm[j];
              add_pair_stress(p, trial);
            }
          // Radial return per automaton.
          plast.assign(static_cast<std::size_t>(n_local) * 3, 0.);
          for (unsigned int k = 0; k < n_owned; ++k)
            {
              const auto  &m  = mc[mat[k]];
              const Sym3   s  = fabric_corrected(k, trial[k]);
              const double sm = (s[0] + s[1] + s[2]) / 3;
              const double q  = von_mises(s);
              double       M = 1, share = 0;
              if (m.m.is_plastic() && q > sigma_y[k])
                {
                  const double de = plastic_increment(m.m, m.G, eps_p[k], q);
                  const double sy_new = m.m.yield_stress_at(eps_p[k] + de);
                  M                   = sy_new / q;
                  const double work   = V * 0.5 * (sigma_y[k] + sy_new) * de;
                  eps_p[k] += de;
                  sigma_y[k] = sy_new;
                  plastic_work += work;
                  share = sum_qs[k] > 0 ? work / sum_qs[k] : 0;
                }
              plast[3 * k]     = sm;
              plast[3 * k + 1] = M;
              plast[3 * k + 2] = share;
            }
          if (ghosts.active())
            ghosts.update(plast.data(), 3);
        }

      // Pass C: plastic correction, contact constraints, forces, torques.
      if constexpr (bonds)
        stress.assign(n_local, Sym3{{0, 0, 0, 0, 0, 0}});
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          if (!bonded[p] && !in_contact[p])
            continue;
          const unsigned int i = pi[p], j = pj[p];
          const double       qi = q_i[p], qj = r_now[p] - qi;
          if constexpr (plastic)
            {
              const double smi = plast[3 * i], Mi = plast[3 * i + 1];
              const double smj = plast[3 * j], Mj = plast[3 * j + 1];
              if (Mi < 1)
                {
                  sig_i[p] = smi + Mi * (sig_i[p] - smi);
                  for (unsigned int c = 0; c < 3; ++c)
                    tau_i[p][c] *= Mi;
                }
              if (Mj < 1)
                {
                  sig_j[p] = smj + Mj * (sig_j[p] - smj);
                  for (unsigned int c = 0; c < 3; ++c)
                    tau_j[p][c] *= Mj;
                }
              heat[p] += qi * S * plast[3 * i + 2] + qj * S * plast[3 * j + 2];
            }
          else
            {
              sig_i[p] += mc[mat[i]].two_G * deps_i[p] + mc[mat[i]].D * dsm[i];
              sig_j[p] += mc[mat[j]].two_G * deps_j[p] + mc[mat[j]].D * dsm[j];
            }
          if (!bonded[p])
            {
              // no tension; Amontons-Coulomb on each side
              sig_i[p] = std::min(sig_i[p], 0.);
              sig_j[p] = std::min(sig_j[p], 0.);
              for (const int side : {0, 1})
                {
                  Vec3        &t     = side == 0 ? tau_i[p] : tau_j[p];
                  const double limit = -mu * (side == 0 ? sig_i[p] : sig_j[p]);
                  const double tn    = std::sqrt(dot(t, t));
                  if (tn > limit)
                    {
                      const double s = tn > 0 ? limit / tn : 0;
                      if (side == 0 && owned_i[p])
                        {
                          const double ki = mc[mat[i]].two_G * inv_r0,
                                       kj = mc[mat[j]].two_G * inv_r0;
                          friction_work
                            += S * limit * (tn - limit) * (ki + kj) / (ki * kj);
                        }
                      for (unsigned int c = 0; c < 3; ++c)
                        t[c] *= s;
                    }
                }
            }
          const Vec3  &n  = normal[p];
          const double sn = 0.5 * (sig_i[p] + sig_j[p]);
          Vec3         ft, F;
          for (unsigned int c = 0; c < 3; ++c)
            {
              ft[c] = 0.5 * S * (tau_i[p][c] + tau_j[p][c]);
              F[c]  = S * sn * n[c] + ft[c];
            }
          Vec3 nxf;
          if constexpr (rot)
            nxf = cross(n, ft);
          if (owned_i[p])
            {
              for (unsigned int c = 0; c < 3; ++c)
                f[i][c] += F[c];
              if constexpr (rot)
                for (unsigned int c = 0; c < 3; ++c)
                  torque[i][c] += qi * nxf[c];
            }
          if (owned_j[p])
            {
              for (unsigned int c = 0; c < 3; ++c)
                f[j][c] -= F[c];
              if constexpr (rot)
                for (unsigned int c = 0; c < 3; ++c)
                  torque[j][c] += qj * nxf[c];
            }
          if constexpr (bonds)
            {
              if (owned_i[p])
                {
                  Vec3 t;
                  for (unsigned int c = 0; c < 3; ++c)
                    t[c] = sig_i[p] * n[c] + tau_i[p][c];
                  add_sym(stress[i], qi * S / V, n, t);
                }
              if (owned_j[p])
                {
                  Vec3 t;
                  for (unsigned int c = 0; c < 3; ++c)
                    t[c] = sig_j[p] * n[c] + tau_j[p][c];
                  add_sym(stress[j], qj * S / V, n, t);
                }
            }
        }
      for (unsigned int k = 0; k < n_local; ++k)
        dsm_prev[k] = dsm[k];

      // Bond switching (takes effect at the next step).
      if constexpr (bonds)
        {
          std::vector<double> ex(static_cast<std::size_t>(n_local) * 7, 0.);
          for (unsigned int k = 0; k < n_owned; ++k)
            {
              stress[k] = fabric_corrected(k, stress[k]);
              for (unsigned int c = 0; c < 6; ++c)
                ex[7 * k + c] = stress[k][c];
              ex[7 * k + 6] = sigma_y[k];
            }
          if (ghosts.active())
            ghosts.update(ex.data(), 7);
          const double heat_fraction
            = prm.interaction.bond_formation_heat_fraction;
          for (unsigned int p = 0; p < n_pairs; ++p)
            {
              const unsigned int i = pi[p], j = pj[p];
              const Vec3        &n  = normal[p];
              const double       sn = 0.5 * (sig_i[p] + sig_j[p]);
              if (bonded[p] && prm.interaction.bond_breaking)
                {
                  Sym3 s;
                  for (unsigned int c = 0; c < 6; ++c)
                    s[c] = 0.5 * (ex[7 * i + c] + ex[7 * j + c]);
                  // replace the normal and shear parts by the pair's own
                  const double sxx = s[0], syy = s[1], szz = s[2], syz = s[3],
                               sxz = s[4], sxy = s[5];
                  Vec3         sn_vec{{sxx * n[0] + sxy * n[1] + sxz * n[2],
                                       sxy * n[0] + syy * n[1] + syz * n[2],
                                       sxz * n[0] + syz * n[1] + szz * n[2]}};
                  const double snn = dot(sn_vec, n);
                  Vec3         corr;
                  for (unsigned int c = 0; c < 3; ++c)
                    corr[c] = 0.5 * (tau_i[p][c] + tau_j[p][c])
                              - (sn_vec[c] - snn * n[c]);
                  add_sym(s, sn - snn, n, n);
                  add_sym(s, 1, n, corr);
                  add_sym(s, 1, corr, n);
                  const double limit
                    = std::min(mc[mat[i]].sigma_b, mc[mat[j]].sigma_b);
                  if (von_mises(s) >= limit)
                    {
                      weights_stale = true;
                      bonded[p]     = 0;
                      in_contact[p] = r_now[p] < d;
                    }
                }
              else if (!bonded[p] && in_contact[p]
                       && prm.interaction.bond_formation)
                {
                  const double sy = std::min(ex[7 * i + 6], ex[7 * j + 6]);
                  const double Eb
                    = std::min(mc[mat[i]].w_b, mc[mat[j]].w_b) * S * r_now[p];
                  if (sn <= -sy && heat[p] >= heat_fraction * Eb)
                    {
                      bonded[p]     = 1;
                      weights_stale = true;
                    }
                }
            }
        }
    }


    void
    AutomatonSystem::add_pair_stress(const unsigned int p,
                                     std::vector<Sym3> &target) const
    {
      // Seed eq. (4): sigma^i += (q_ij S / V_i) n_ij (x) F_ij / S, for each
      // owned side of the pair (q_ji = r_ij - q_ij).
      const Vec3 &n = normal[p];
      if (owned_i[p])
        {
          Vec3 t;
          for (unsigned int c = 0; c < 3; ++c)
            t[c] = sig_i[p] * n[c] + tau_i[p][c];
          add_sym(target[pi[p]], q_i[p] * S / V, n, t);
        }
      if (owned_j[p])
        {
          Vec3 t;
          for (unsigned int c = 0; c < 3; ++c)
            t[c] = sig_j[p] * n[c] + tau_j[p][c];
          add_sym(target[pj[p]], (r_now[p] - q_i[p]) * S / V, n, t);
        }
    }

    void
    AutomatonSystem::compute_automaton_stresses()
    {
      stress.assign(n_local, Sym3{{0, 0, 0, 0, 0, 0}});
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          if (!bonded[p] && !in_contact[p])
            continue;
          add_pair_stress(p, stress);
        }
      for (unsigned int k = 0; k < n_owned; ++k)
        stress[k] = fabric_corrected(k, stress[k]);
    }


    Sym3
    AutomatonSystem::fabric_corrected(const unsigned int k, const Sym3 &t) const
    {
      // sym(B^-1 T), B^-1 stored as xx yy zz yz xz xy
      const Sym3  &b = fabric_inverse[k];
      const double B[3][3]
        = {{b[0], b[5], b[4]}, {b[5], b[1], b[3]}, {b[4], b[3], b[2]}};
      const double T[3][3]
        = {{t[0], t[5], t[4]}, {t[5], t[1], t[3]}, {t[4], t[3], t[2]}};
      double P[3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            P[i][j] = 0;
            for (unsigned int l = 0; l < 3; ++l)
              P[i][j] += B[i][l] * T[l][j];
          }
      return {{P[0][0],
               P[1][1],
               P[2][2],
               0.5 * (P[1][2] + P[2][1]),
               0.5 * (P[0][2] + P[2][0]),
               0.5 * (P[0][1] + P[1][0])}};
    }


    void
    AutomatonSystem::update_neighbourhood_weights()
    {
      // Per owned automaton: A = sum_j N_j N_j^T (N_j = Voigt of n n with
      // doubled shear entries) for the least-squares strain fit, and the
      // fabric B = sum_j (q S / V) n n.
      const unsigned int                  n_pairs = pi.size();
      std::vector<std::array<double, 21>> A(n_owned);
      std::vector<Sym3>                   B(n_owned, Sym3{{0, 0, 0, 0, 0, 0}});
      std::vector<unsigned int>           count(n_owned, 0);
      for (auto &a : A)
        a.fill(0);
      auto voigt = [](const Vec3 &n) {
        return std::array<double, 6>{{n[0] * n[0],
                                      n[1] * n[1],
                                      n[2] * n[2],
                                      2 * n[1] * n[2],
                                      2 * n[0] * n[2],
                                      2 * n[0] * n[1]}};
      };
      std::vector<Vec3> nvec(n_pairs);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const Tensor<1, 3> dn = min_image(x[pi[p]], x[pj[p]]);
          const double       r  = dn.norm();
          nvec[p]               = {{dn[0] / r, dn[1] / r, dn[2] / r}};
          if (!bonded[p] && !in_contact[p])
            continue;
          const auto N = voigt(nvec[p]);
          for (const unsigned int k : {pi[p], pj[p]})
            if (k < n_owned)
              {
                unsigned int e = 0;
                for (unsigned int a = 0; a < 6; ++a)
                  for (unsigned int b = a; b < 6; ++b)
                    A[k][e++] += N[a] * N[b];
                const double q = k == pi[p] ? q_i[p] : r - q_i[p];
                add_sym(B[k], q * S / V, nvec[p], nvec[p]);
                ++count[k];
              }
        }
      std::vector<std::array<double, 6>> g(n_owned);
      std::vector<bool>                  full_rank(n_owned, false);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          // solve A g = (1 1 1 0 0 0) by Gaussian elimination
          double       M[6][7];
          unsigned int e = 0;
          for (unsigned int a = 0; a < 6; ++a)
            for (unsigned int b = a; b < 6; ++b, ++e)
              M[a][b] = M[b][a] = A[k][e];
          double scale = 0;
          for (unsigned int a = 0; a < 6; ++a)
            {
              M[a][6] = a < 3 ? 1 : 0;
              scale   = std::max(scale, std::abs(M[a][a]));
            }
          bool ok = scale > 0;
          for (unsigned int c = 0; c < 6 && ok; ++c)
            {
              unsigned int piv = c;
              for (unsigned int r = c + 1; r < 6; ++r)
                if (std::abs(M[r][c]) > std::abs(M[piv][c]))
                  piv = r;
              if (std::abs(M[piv][c]) < 1e-3 * scale)
                {
                  ok = false;
                  break;
                }
              for (unsigned int l = 0; l < 7; ++l)
                std::swap(M[c][l], M[piv][l]);
              for (unsigned int r = 0; r < 6; ++r)
                if (r != c)
                  {
                    const double fct = M[r][c] / M[c][c];
                    for (unsigned int l = c; l < 7; ++l)
                      M[r][l] -= fct * M[c][l];
                  }
            }
          if (ok)
            for (unsigned int a = 0; a < 6; ++a)
              {
                g[k][a] = M[a][6] / M[a][a];
                // well-conditioned neighbourhoods only (bulk: |g| ~ 1)
                if (!(std::abs(g[k][a]) < 8))
                  ok = false;
              }
          full_rank[k] = ok;
        }
      beta_i.assign(n_pairs, 0);
      beta_j.assign(n_pairs, 0);
      std::vector<double> beta_sum(n_owned, 0.);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          if (!bonded[p] && !in_contact[p])
            continue;
          const auto N = voigt(nvec[p]);
          for (const int side : {0, 1})
            {
              const unsigned int k = side == 0 ? pi[p] : pj[p];
              if (k >= n_owned)
                continue;
              double beta = 0;
              if (full_rank[k])
                for (unsigned int a = 0; a < 6; ++a)
                  beta += g[k][a] * N[a];
              else
                beta = 3. / count[k];
              (side == 0 ? beta_i : beta_j)[p] = beta;
              beta_sum[k] += std::abs(beta);
            }
        }
      // Bound the many-body stiffness by its bulk value (sum of |beta| = 3
      // in a complete FCC neighbourhood): sparse, nearly degenerate
      // neighbourhoods (e.g. around broken bonds) could otherwise make an
      // automaton far stiffer than the bulk and the explicit step unstable.
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          if (pi[p] < n_owned && beta_sum[pi[p]] > 3)
            beta_i[p] *= 3 / beta_sum[pi[p]];
          if (pj[p] < n_owned && beta_sum[pj[p]] > 3)
            beta_j[p] *= 3 / beta_sum[pj[p]];
        }
      // inverse fabric (identity if B is singular)
      fabric_inverse.assign(n_local, Sym3{{1, 1, 1, 0, 0, 0}});
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const Sym3  &b   = B[k];
          const double det = b[0] * (b[1] * b[2] - b[3] * b[3])
                             - b[5] * (b[5] * b[2] - b[3] * b[4])
                             + b[4] * (b[5] * b[3] - b[1] * b[4]);
          // well-conditioned fabrics only (complete FCC: B = I); otherwise
          // keep eq. (4) as is: B^-1 of a nearly planar neighbourhood would
          // blow the stress (and the radial return's mean stress) up
          const double tr3 = (b[0] + b[1] + b[2]) / 3;
          if (!(det > 0.1 * tr3 * tr3 * tr3))
            continue;
          fabric_inverse[k] = {{(b[1] * b[2] - b[3] * b[3]) / det,
                                (b[0] * b[2] - b[4] * b[4]) / det,
                                (b[0] * b[1] - b[5] * b[5]) / det,
                                (b[4] * b[5] - b[0] * b[3]) / det,
                                (b[5] * b[3] - b[1] * b[4]) / det,
                                (b[4] * b[3] - b[5] * b[2]) / det}};
        }
      weights_stale = false;
    }


    SystemEnergies
    AutomatonSystem::energies() const
    {
      SystemEnergies e;
      double         kinetic = 0, elastic = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          kinetic += 0.5 * mass[k] * dot(v[k], v[k])
                     + 0.5 * inertia[k] * dot(w[k], w[k]);
          const Sym3  &s  = stress[k];
          const double sm = (s[0] + s[1] + s[2]) / 3;
          const double a = s[0] - sm, b = s[1] - sm, c = s[2] - sm;
          const double ss = a * a + b * b + c * c
                            + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
          elastic
            += V * (sm * sm / (2 * mc[mat[k]].K) + ss / (4 * mc[mat[k]].G));
        }
      unsigned long long nb = 0, nu = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (owned_i[p]) // each pair counted once: by the owner of i
          {
            if (bonded[p])
              ++nb;
            else if (in_contact[p])
              ++nu;
          }
      e.kinetic             = dealii::Utilities::MPI::sum(kinetic, comm);
      e.elastic             = dealii::Utilities::MPI::sum(elastic, comm);
      e.plastic_work        = dealii::Utilities::MPI::sum(plastic_work, comm);
      e.friction_work       = dealii::Utilities::MPI::sum(friction_work, comm);
      e.n_bonded            = dealii::Utilities::MPI::sum(nb, comm);
      e.n_unbonded_contacts = dealii::Utilities::MPI::sum(nu, comm);
      return e;
    }


    unsigned long long
    AutomatonSystem::n_global_pairs() const
    {
      unsigned long long n = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        n += owned_i[p];
      return dealii::Utilities::MPI::sum(n, comm);
    }


    std::vector<Vec3>
    AutomatonSystem::sum_over_groups(const std::vector<Vec3> &field) const
    {
      const unsigned int  n_groups = prm.boundary.groups.size();
      std::vector<double> sums(3 * n_groups, 0.);
      for (unsigned int k = 0; k < n_owned; ++k)
        if (groups[k] != 0)
          for (unsigned int gi = 0; gi < n_groups; ++gi)
            if (groups[k] & (1u << gi))
              for (unsigned int c = 0; c < 3; ++c)
                sums[3 * gi + c] += field[k][c];
      dealii::Utilities::MPI::sum(sums, comm, sums);
      std::vector<Vec3> out(n_groups);
      for (unsigned int gi = 0; gi < n_groups; ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          out[gi][c] = sums[3 * gi + c];
      return out;
    }


    std::vector<Vec3>
    AutomatonSystem::group_forces() const
    {
      // f holds the pair forces only (the reaction of the group).
      return sum_over_groups(f);
    }


    std::vector<Vec3>
    AutomatonSystem::group_displacements() const
    {
      std::vector<Vec3> out   = sum_over_groups(u);
      const auto        sizes = group_sizes();
      for (unsigned int gi = 0; gi < out.size(); ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          out[gi][c] = sizes[gi] > 0 ? out[gi][c] / sizes[gi] : 0;
      return out;
    }


    std::vector<unsigned long long>
    AutomatonSystem::group_sizes() const
    {
      const unsigned int              n_groups = prm.boundary.groups.size();
      std::vector<unsigned long long> n(n_groups, 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        for (unsigned int gi = 0; gi < n_groups; ++gi)
          if (groups[k] & (1u << gi))
            ++n[gi];
      dealii::Utilities::MPI::sum(n, comm, n);
      return n;
    }


    std::vector<unsigned int>
    AutomatonSystem::bonded_neighbour_counts() const
    {
      std::vector<unsigned int> n(n_local, 0);
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (bonded[p])
          {
            ++n[pi[p]];
            ++n[pj[p]];
          }
      return n;
    }


    std::vector<AutomatonSystem::PairView>
    AutomatonSystem::pair_views() const
    {
      std::vector<PairView> out;
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          PairView pv;
          pv.id_i   = id[pi[p]];
          pv.id_j   = id[pj[p]];
          pv.bonded = bonded[p];
          pv.sigma  = 0.5 * (sig_i[p] + sig_j[p]);
          for (unsigned int c = 0; c < 3; ++c)
            pv.tau[c] = 0.5 * (tau_i[p][c] + tau_j[p][c]);
          pv.heat     = heat[p];
          pv.distance = r_now[p];
          out.push_back(pv);
        }
      return out;
    }


    void
    AutomatonSystem::set_pair_heat(const double value)
    {
      std::fill(heat.begin(), heat.end(), value);
    }


    std::string
    AutomatonSystem::write_particles(const std::string &directory,
                                     const std::string &base,
                                     const unsigned int number,
                                     const bool         with_stress,
                                     const bool         slab,
                                     const unsigned int axis,
                                     const double       slab_lo,
                                     const double       slab_hi) const
    {
      char tag[32];
      std::snprintf(tag, sizeof(tag), "%s_%04u", base.c_str(), number);
      const std::string         name    = tag;
      const auto                nbonded = bonded_neighbour_counts();
      std::vector<unsigned int> selected;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          if (slab)
            {
              double y = x[k][axis];
              if (periodic[axis])
                {
                  const double lo = prm.geometry.domain_lower[axis];
                  y               = lo
                      + std::fmod(std::fmod(y - lo, period[axis])
                                    + period[axis],
                                  period[axis]);
                }
              if (y < slab_lo || y > slab_hi)
                continue;
            }
          selected.push_back(k);
        }
      std::ostringstream o;
      o << std::setprecision(8);
      o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << selected.size()
        << "\" NumberOfCells=\"" << selected.size() << "\">\n";
      o << "<PointData Scalars=\"material\">\n";
      auto scalar = [&](const std::string &field, const auto &value) {
        o << "<DataArray type=\"Float64\" Name=\"" << field
          << "\" format=\"ascii\">\n";
        for (const unsigned int k : selected)
          o << value(k) << "\n";
        o << "</DataArray>\n";
      };
      auto vector = [&](const std::string &field, const auto &value) {
        o << "<DataArray type=\"Float64\" Name=\"" << field
          << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const unsigned int k : selected)
          {
            const Vec3 a = value(k);
            o << a[0] << " " << a[1] << " " << a[2] << "\n";
          }
        o << "</DataArray>\n";
      };
      scalar("id", [&](unsigned k) { return static_cast<double>(id[k]); });
      scalar("material", [&](unsigned k) { return double(mat[k]); });
      scalar("body", [&](unsigned k) { return double(body[k]); });
      scalar("bonded_neighbours",
             [&](unsigned k) { return double(nbonded[k]); });
      scalar("plastic_strain", [&](unsigned k) { return eps_p[k]; });
      vector("velocity", [&](unsigned k) { return v[k]; });
      vector("displacement", [&](unsigned k) { return u[k]; });
      vector("angular_velocity", [&](unsigned k) { return w[k]; });
      if (with_stress)
        {
          o << "<DataArray type=\"Float64\" Name=\"stress\" "
               "NumberOfComponents=\"9\" format=\"ascii\">\n";
          for (const unsigned int k : selected)
            {
              const Sym3 &s = stress[k];
              o << s[0] << " " << s[5] << " " << s[4] << " " << s[5] << " "
                << s[1] << " " << s[3] << " " << s[4] << " " << s[3] << " "
                << s[2] << "\n";
            }
          o << "</DataArray>\n";
          scalar("pressure", [&](unsigned k) {
            return -(stress[k][0] + stress[k][1] + stress[k][2]) / 3;
          });
          scalar("von_mises", [&](unsigned k) { return von_mises(stress[k]); });
        }
      o << "</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int k : selected)
        o << x[k][0] << " " << x[k][1] << " " << x[k][2] << "\n";
      o << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" "
           "Name=\"connectivity\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < selected.size(); ++k)
        o << k << "\n";
      o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n";
      for (std::size_t k = 0; k < selected.size(); ++k)
        o << k + 1 << "\n";
      o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
      for (std::size_t k = 0; k < selected.size(); ++k)
        o << "1\n";
      o << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</"
           "VTKFile>\n";
      write_file_atomically(
        join_path(directory, name + "." + std::to_string(rank) + ".vtu"),
        o.str());
      if (rank == 0)
        {
          std::ostringstream pv;
          pv << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" "
                "version=\"0.1\" byte_order=\"LittleEndian\">\n"
                "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData "
                "Scalars=\"material\">\n";
          for (const char *s : {"id",
                                "material",
                                "body",
                                "bonded_neighbours",
                                "plastic_strain"})
            pv << "<PDataArray type=\"Float64\" Name=\"" << s << "\"/>\n";
          for (const char *s : {"velocity", "displacement", "angular_velocity"})
            pv << "<PDataArray type=\"Float64\" Name=\"" << s
               << "\" NumberOfComponents=\"3\"/>\n";
          if (with_stress)
            pv << "<PDataArray type=\"Float64\" Name=\"stress\" "
                  "NumberOfComponents=\"9\"/>\n<PDataArray type=\"Float64\" "
                  "Name=\"pressure\"/>\n<PDataArray type=\"Float64\" "
                  "Name=\"von_mises\"/>\n";
          pv << "</PPointData>\n<PPoints><PDataArray type=\"Float64\" "
                "NumberOfComponents=\"3\"/></PPoints>\n";
          for (unsigned int r = 0; r < n_ranks; ++r)
            pv << "<Piece Source=\"" << name << "." << r << ".vtu\"/>\n";
          pv << "</PUnstructuredGrid>\n</VTKFile>\n";
          write_file_atomically(join_path(directory, name + ".pvtu"), pv.str());
        }
      return name + ".pvtu";
    }
  } // namespace mca
} // namespace tribodyn
