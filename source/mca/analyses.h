// The analyses of the mca driver besides friction (private header of
// source/mca/mca_problem.cc): the uniaxial test (E, nu, sigma_y, H), the
// pulse time of flight (c_p), and the report of the scene (staged loading,
// inclusions) and of its energy balance.
#ifndef tribodyn_source_mca_analyses_h
#define tribodyn_source_mca_analyses_h

#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <ostream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/inclusions.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Least-squares line y = a x + b.
      std::pair<double, double>
      fit_line(const std::vector<double> &xs, const std::vector<double> &ys)
      {
        const double n  = xs.size();
        double       sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t k = 0; k < xs.size(); ++k)
          {
            sx += xs[k];
            sy += ys[k];
            sxx += xs[k] * xs[k];
            sxy += xs[k] * ys[k];
          }
        const double den = n * sxx - sx * sx;
        if (xs.size() < 2 || den == 0)
          return {std::nan(""), std::nan("")};
        const double a = (n * sxy - sx * sy) / den;
        return {a, (sy - a * sx) / n};
      }


      /**
       * Figures of a uniaxial test: compressive stress from the reactions
       * of the loaded and supporting groups over the cross-section, axial
       * strain from their displacements, lateral strain from the two
       * lateral faces at mid-height.
       */
      class UniaxialAnalysis
      {
      public:
        UniaxialAnalysis(const AutomatonSystem &s,
                         const Parameters      &p,
                         const MPI_Comm         comm)
            : system(s)
            , prm(p)
            , comm(comm)
        {
          axis    = p.analysis.axis;
          lateral = (axis + 1) % 3;
          for (unsigned int g = 0; g < p.boundary.groups.size(); ++g)
            {
              if (p.boundary.groups[g].name == p.analysis.loaded_group)
                loaded = g;
              if (p.boundary.groups[g].name == p.analysis.support_group)
                support = g;
            }
          if (support < 0)
            throw InputError("Parameter 'Analysis/Support group': no "
                             "boundary group is called '"
                             + p.analysis.support_group + "'.");
          const double a    = p.geometry.automaton_size * std::sqrt(2.);
          layer             = a / 2;
          const auto &x     = s.positions();
          const auto &u     = s.displacements();
          double      lo[3] = {1e300, 1e300, 1e300},
                 hi[3]      = {-1e300, -1e300, -1e300};
          for (unsigned int k = 0; k < s.n_owned_automata(); ++k)
            for (unsigned int c = 0; c < 3; ++c)
              {
                lo[c] = std::min(lo[c], x[k][c] - u[k][c]);
                hi[c] = std::max(hi[c], x[k][c] - u[k][c]);
              }
          for (unsigned int c = 0; c < 3; ++c)
            {
              lo[c] = dealii::Utilities::MPI::min(lo[c], comm);
              hi[c] = dealii::Utilities::MPI::max(hi[c], comm);
            }
          lower  = {{lo[0], lo[1], lo[2]}};
          upper  = {{hi[0], hi[1], hi[2]}};
          height = hi[axis] - lo[axis] + layer;
          // nominal section: the volume of the automata over the height
          // (automata of several sizes: their own volumes)
          double volume = 0;
          for (unsigned int k = 0; k < s.n_owned_automata(); ++k)
            volume += s.volumes()[k];
          area = dealii::Utilities::MPI::sum(volume, comm) / height;
          // distance between the centroids of the two groups
          const auto u0 = centroid();
          length        = std::abs(u0.first - u0.second);
          width         = hi[lateral] - lo[lateral];
        }

        /// Centroids along the axis of the two groups' initial positions.
        std::pair<double, double>
        centroid() const
        {
          const auto &x       = system.positions();
          const auto &u       = system.displacements();
          double      sums[4] = {0, 0, 0, 0};
          (void)x;
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double y   = x[k][axis] - u[k][axis];
              const auto  &grp = prm.boundary.groups;
              (void)grp;
              if (in_group(k, loaded))
                {
                  sums[0] += y;
                  sums[1] += 1;
                }
              if (in_group(k, support))
                {
                  sums[2] += y;
                  sums[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, comm);
          return {sums[0] / sums[1], sums[2] / sums[3]};
        }

        bool
        in_group(const unsigned int k, const int g) const
        {
          // group membership from the initial position (same rule as the
          // system's: the group box)
          const auto &grp = prm.boundary.groups[g];
          const auto &x   = system.positions();
          const auto &u   = system.displacements();
          for (unsigned int c = 0; c < 3; ++c)
            {
              const double y = x[k][c] - u[k][c];
              if (y < grp.lower[c] || y > grp.upper[c])
                return false;
            }
          return true;
        }

        void
        record()
        {
          const auto   forces = system.group_forces();
          const auto   disp   = system.group_displacements();
          const double sign   = forces[loaded][axis] >= 0 ? 1 : 1;
          (void)sign;
          const double stress
            = (forces[loaded][axis] - forces[support][axis]) / (2 * area);
          const double strain = -(disp[loaded][axis] - disp[support][axis])
                                / length * (lower_group_is_support() ? 1 : -1);
          // lateral faces at mid-height
          const auto  &x    = system.positions();
          const auto  &u    = system.displacements();
          const double mid  = 0.5 * (lower[axis] + upper[axis]);
          double       s[4] = {0, 0, 0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double ya = x[k][axis] - u[k][axis];
              if (std::abs(ya - mid) > height / 4)
                continue;
              const double yl = x[k][lateral] - u[k][lateral];
              if (yl < lower[lateral] + layer / 2)
                {
                  s[0] += u[k][lateral];
                  s[1] += 1;
                }
              else if (yl > upper[lateral] - layer / 2)
                {
                  s[2] += u[k][lateral];
                  s[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, s, 4, MPI_DOUBLE, MPI_SUM, comm);
          const double lateral_strain
            = (s[2] / std::max(s[3], 1.) - s[0] / std::max(s[1], 1.)) / width;
          // interior stress: automata of the central part, one FCC cell
          // away from the lateral faces
          const unsigned int third = 3 - axis - lateral;
          const auto        &st    = system.stresses();
          double             in[2] = {0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double ya = x[k][axis] - u[k][axis];
              const double yl = x[k][lateral] - u[k][lateral];
              const double yt = x[k][third] - u[k][third];
              if (std::abs(ya - mid) > height / 4
                  || yl < lower[lateral] + 2 * layer
                  || yl > upper[lateral] - 2 * layer
                  || yt < lower[third] + 2 * layer
                  || yt > upper[third] - 2 * layer)
                continue;
              // (volume-weighted: automata of several sizes)
              in[0] += -st[k][axis] * system.volumes()[k];
              in[1] += system.volumes()[k];
            }
          MPI_Allreduce(MPI_IN_PLACE, in, 2, MPI_DOUBLE, MPI_SUM, comm);
          strains.push_back(strain);
          stresses.push_back(in[1] > 0 ? in[0] / in[1] : stress);
          nominal_stresses.push_back(stress);
          lateral_strains.push_back(lateral_strain);
        }

        bool
        lower_group_is_support() const
        {
          const auto c = centroid();
          return c.second < c.first;
        }

        void
        finish(JsonValue &summary, std::ostream &out) const
        {
          // nominal yield of the material of the first body sets the window
          const double sy0
            = prm.materials[prm.geometry.bodies[0].material].yield_stress;
          std::vector<double> ex, sx, lx;
          double              max_strain = 0;
          for (std::size_t k = 0; k < strains.size(); ++k)
            {
              max_strain = std::max(max_strain, strains[k]);
              if (stresses[k] > 0.05 * sy0
                  && stresses[k] < prm.analysis.elastic_fit_fraction * sy0)
                {
                  ex.push_back(strains[k]);
                  sx.push_back(stresses[k]);
                  lx.push_back(lateral_strains[k]);
                }
            }
          std::vector<double> nx, ns;
          for (std::size_t k = 0; k < strains.size(); ++k)
            if (nominal_stresses[k] > 0.05 * sy0
                && nominal_stresses[k]
                     < prm.analysis.elastic_fit_fraction * sy0)
              {
                nx.push_back(strains[k]);
                ns.push_back(nominal_stresses[k]);
              }
          summary["youngs_modulus_nominal"] = fit_line(nx, ns).first;
          const auto   elastic              = fit_line(ex, sx);
          const auto   nu_fit               = fit_line(ex, lx);
          const double E                    = elastic.first;
          const double nu                   = nu_fit.first;
          summary["youngs_modulus"]         = E;
          summary["poisson_ratio"]          = nu;
          summary["elastic_fit_points"] = static_cast<unsigned long>(ex.size());
          out << "Uniaxial test (stress of the interior automata, strain "
                 "between the loading layers): E = "
              << E / 1e9 << " GPa, nu = " << nu;
          // hardening branch: the last 40 % of the strain range, if plastic
          std::vector<double> ep, sp;
          for (std::size_t k = 0; k < strains.size(); ++k)
            if (strains[k] > 0.6 * max_strain)
              {
                ep.push_back(strains[k]);
                sp.push_back(stresses[k]);
              }
          const auto   hardening = fit_line(ep, sp);
          const double Et        = hardening.first;
          if (!sp.empty() && sp.back() > 1.02 * E * ep.back() + elastic.second)
            {
              // not plastic: the branch lies on the elastic line
            }
          if (!ep.empty() && std::isfinite(Et) && Et < 0.8 * E)
            {
              const double eps_y
                = (hardening.second - elastic.second) / (E - Et);
              const double sigma_y         = E * eps_y + elastic.second;
              summary["yield_stress"]      = sigma_y;
              summary["tangent_modulus"]   = Et;
              summary["hardening_modulus"] = E * Et / (E - Et);
              out << ", sigma_y = " << sigma_y / 1e6
                  << " MPa, tangent modulus = " << Et / 1e9
                  << " GPa (plastic modulus H = " << E * Et / (E - Et) / 1e9
                  << " GPa)";
            }
          else
            summary["yield_stress"] = JsonValue();
          out << "\n  nominal E (reaction / nominal cross-section, lower by "
                 "the surface layer) = "
              << fit_line(nx, ns).first / 1e9 << " GPa" << std::endl;
          summary["max_strain"]         = max_strain;
          summary["cross_section_area"] = area;
          summary["gauge_length"]       = length;
        }

        /// The recorded series (checkpoints save and restore them).
        std::vector<std::vector<double> *>
        recorded_series()
        {
          return {&strains, &stresses, &nominal_stresses, &lateral_strains};
        }

        /// Columns of series.csv this analysis adds (values of the last
        /// record()): the strain between the loading layers, the axial
        /// stress of the interior automata behind E and sigma_y
        /// (compression positive, Pa), the nominal stress (reaction over
        /// the cross-section) and the lateral strain behind nu.
        static std::vector<std::string>
        series_columns()
        {
          return {"interior_strain",
                  "interior_stress",
                  "nominal_stress",
                  "lateral_strain"};
        }

        std::vector<double>
        series_values() const
        {
          if (strains.empty())
            return {0., 0., 0., 0.};
          return {strains.back(),
                  stresses.back(),
                  nominal_stresses.back(),
                  lateral_strains.back()};
        }

        std::vector<double> strains, stresses, nominal_stresses,
          lateral_strains;

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
        MPI_Comm               comm;
        unsigned int           axis = 2, lateral = 0;
        int                    loaded = -1, support = -1;
        double layer = 0, height = 0, area = 0, length = 0, width = 0;
        Vec3   lower, upper;
      };


      /// Arrival of a pulse at two probe planes (peak of the mean axial
      /// velocity of the automata of each plane).
      class PulseAnalysis
      {
      public:
        PulseAnalysis(const AutomatonSystem &s,
                      const Parameters      &p,
                      const MPI_Comm         comm)
            : system(s)
            , prm(p)
            , comm(comm)
        {
        }

        void
        record(const double t)
        {
          const auto        &x = system.positions();
          const auto        &u = system.displacements();
          const auto        &v = system.velocities();
          const unsigned int a = prm.analysis.axis;
          const double half = prm.geometry.automaton_size * std::sqrt(2.) / 8;
          double       s[4] = {0, 0, 0, 0};
          for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
            {
              const double y = x[k][a] - u[k][a];
              if (std::abs(y - prm.analysis.probe_1) < half)
                {
                  s[0] += v[k][a];
                  s[1] += 1;
                }
              if (std::abs(y - prm.analysis.probe_2) < half)
                {
                  s[2] += v[k][a];
                  s[3] += 1;
                }
            }
          MPI_Allreduce(MPI_IN_PLACE, s, 4, MPI_DOUBLE, MPI_SUM, comm);
          if (s[1] == 0 || s[3] == 0)
            throw InputError("Parameters 'Analysis/Probe 1' and 'Probe 2' "
                             "must lie on layers of automata (none found "
                             "within a/8 of them).");
          times.push_back(t);
          v1.push_back(s[0] / s[1]);
          v2.push_back(s[2] / s[3]);
        }

        static double
        peak_time(const std::vector<double> &t, const std::vector<double> &v)
        {
          std::size_t best = 0;
          for (std::size_t k = 0; k < v.size(); ++k)
            if (std::abs(v[k]) > std::abs(v[best]))
              best = k;
          if (best == 0 || best + 1 >= v.size())
            return t[best];
          // parabola through three points
          const double y0 = v[best - 1], y1 = v[best], y2 = v[best + 1];
          const double h   = t[best + 1] - t[best];
          const double den = y0 - 2 * y1 + y2;
          return den == 0 ? t[best] : t[best] + 0.5 * h * (y0 - y2) / den;
        }

        void
        finish(JsonValue &summary, std::ostream &out) const
        {
          const double t1 = peak_time(times, v1), t2 = peak_time(times, v2);
          const double c
            = std::abs(prm.analysis.probe_2 - prm.analysis.probe_1) / (t2 - t1);
          summary["arrival_time_1"] = t1;
          summary["arrival_time_2"] = t2;
          summary["wave_speed"]     = c;
          const double cp
            = prm.materials[prm.geometry.bodies[0].material].p_wave_speed();
          summary["p_wave_speed_reference"] = cp;
          out << "Pulse: arrival at the probes " << t1 << " s and " << t2
              << " s, wave speed " << c
              << " m/s (c_p = sqrt((K + 4G/3)/rho) = " << cp << " m/s)"
              << std::endl;
        }

        /// The recorded series (checkpoints save and restore them).
        std::vector<std::vector<double> *>
        recorded_series()
        {
          return {&times, &v1, &v2};
        }

        /// Columns of series.csv this analysis adds: the mean velocity
        /// along the axis of the automata of each probe layer (m/s), whose
        /// peaks time the pulse (the automata start at rest).
        static std::vector<std::string>
        series_columns()
        {
          return {"probe_1_velocity", "probe_2_velocity"};
        }

        std::vector<double>
        series_values() const
        {
          if (times.empty())
            return {0., 0.};
          return {v1.back(), v2.back()};
        }

      private:
        const AutomatonSystem &system;
        const Parameters      &prm;
        MPI_Comm               comm;
        std::vector<double>    times, v1, v2;
      };


      /// Staged loading and inclusions: what the set-up produced.
      void
      report_scene(const AutomatonSystem      &system,
                   const Parameters           &p,
                   dealii::ConditionalOStream &out)
      {
        if (p.loading.enabled)
          out << "Friction loading: separation " << p.geometry.interface_gap
              << " m, shift " << p.geometry.interface_shift_y
              << " m along y, damping of the loading layers "
              << p.loading_damping << " 1/s"
              << (p.loading.damping > 0 ? " (given)"
                                        : " (seed criterion c_p / (2 h))")
              << std::endl;
        if (const auto *layout = p.geometry.inclusion_layout.get())
          {
            const auto counts = system.contacting_part_counts();
            out << "Inclusions:";
            for (const auto &part : layout->parts)
              out << " body " << part.body << ": " << part.set.n_cylinders
                  << " cylinders (" << 100 * part.set.cylinder_volume_fraction
                  << " % of the "
                  << "part's box), " << part.set.n_voids << " voids ("
                  << 100 * part.set.void_volume_fraction << " %);";
            out << " automata: " << counts.second << " of " << counts.first
                << " in the contacting parts = "
                << 100. * counts.second / std::max(1ull, counts.first) << " %"
                << std::endl;
          }
      }


      void
      add_scene_keys(const AutomatonSystem &system,
                     const Parameters      &p,
                     JsonValue             &summary)
      {
        summary["contact_time"] = system.contact_time() >= 0
                                    ? JsonValue(system.contact_time())
                                    : JsonValue();
        if (p.loading.enabled)
          {
            summary["loading_damping"]    = p.loading_damping;
            summary["loading_separation"] = p.geometry.interface_gap;
            summary["loading_shift_y"]    = p.geometry.interface_shift_y;
          }
        if (const auto *layout = p.geometry.inclusion_layout.get())
          {
            const auto counts = system.contacting_part_counts();
            summary["inclusion_volume_fraction"]
              = double(counts.second) / std::max(1ull, counts.first);
            double f = 0, fv = 0;
            for (const auto &part : layout->parts)
              {
                f += part.set.cylinder_volume_fraction / layout->parts.size();
                fv += part.set.void_volume_fraction / layout->parts.size();
              }
            summary["inclusion_volume_fraction_generated"] = f;
            summary["void_volume_fraction_generated"]      = fv;
          }
        else
          summary["inclusion_volume_fraction"] = 0.;
      }


      /// Energy balance since the start (the scene starts at rest and
      /// unstressed): kinetic + elastic + plastic + friction + damped =
      /// work of the loads; and the pairs' side of it (their work on the
      /// automata against what they stored or dissipated).
      void
      add_energy_balance(const SystemEnergies &e,
                         JsonValue            &summary,
                         std::ostream         &figures)
      {
        const double stored = e.kinetic + e.elastic + e.plastic_work
                              + e.friction_work + e.damped_work;
        summary["load_work"]               = e.load_work;
        summary["damped_work"]             = e.damped_work;
        summary["pair_work"]               = e.pair_work;
        summary["energy_balance_residual"] = stored - e.load_work;
        summary["energy_balance_relative"]
          = e.load_work != 0 ? (stored - e.load_work) / std::abs(e.load_work)
                             : 0.;
        figures << "Energy: load work " << e.load_work << " J = kinetic "
                << e.kinetic << " + elastic " << e.elastic << " + plastic "
                << e.plastic_work << " + friction " << e.friction_work
                << " + damped " << e.damped_work << " J + residual "
                << e.load_work - stored << " J" << std::endl;
      }
    } // namespace


  } // namespace mca
} // namespace tribodyn

#endif
