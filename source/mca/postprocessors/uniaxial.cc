// Postprocessor "uniaxial" (`Analysis/Type = uniaxial`): the figures of a
// uniaxial test. Compressive stress from the reactions of the loaded and
// supporting groups over the cross-section and from the interior automata,
// axial strain from the groups' displacements, lateral strain from the two
// lateral faces at mid-height; at the end E, nu (line fits in the elastic
// window) and, if the test went plastic, sigma_y and the hardening modulus.
#include <cmath>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/postprocessor.h>

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
      class UniaxialAnalysis : public Postprocessor
      {
      public:
        explicit UniaxialAnalysis(const PostprocessorInputs &in)
            : system(in.system)
            , prm(in.parameters)
            , comm(in.comm)
        {
          const AutomatonSystem &s = in.system;
          const Parameters      &p = in.parameters;
          axis                     = p.analysis.axis;
          lateral                  = (axis + 1) % 3;
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
            volume += s.volume_of(k);
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
        record(const SeriesSample &sample, std::vector<double> &row) override
        {
          const auto  &forces = sample.group_forces;
          const auto  &disp   = sample.group_displacements;
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
              in[0] += -st[k][axis] * system.volume_of(k);
              in[1] += system.volume_of(k);
            }
          MPI_Allreduce(MPI_IN_PLACE, in, 2, MPI_DOUBLE, MPI_SUM, comm);
          strains.push_back(strain);
          stresses.push_back(in[1] > 0 ? in[0] / in[1] : stress);
          nominal_stresses.push_back(stress);
          lateral_strains.push_back(lateral_strain);
          row.insert(row.end(),
                     {strains.back(),
                      stresses.back(),
                      nominal_stresses.back(),
                      lateral_strains.back()});
        }

        bool
        lower_group_is_support() const
        {
          const auto c = centroid();
          return c.second < c.first;
        }

        void
        finish(JsonValue &summary, std::ostream &out) const override
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

        std::vector<std::vector<double> *>
        saved_series() override
        {
          return {&strains, &stresses, &nominal_stresses, &lateral_strains};
        }

        /// Columns of series.csv: the strain between the loading layers,
        /// the axial stress of the interior automata behind E and sigma_y
        /// (compression positive, Pa), the nominal stress (reaction over
        /// the cross-section) and the lateral strain behind nu.
        std::vector<std::string>
        series_columns() const override
        {
          return {"interior_strain",
                  "interior_stress",
                  "nominal_stress",
                  "lateral_strain"};
        }

      private:
        std::vector<double> strains, stresses, nominal_stresses,
          lateral_strains;
        const AutomatonSystem &system;
        const Parameters      &prm;
        MPI_Comm               comm;
        unsigned int           axis = 2, lateral = 0;
        int                    loaded = -1, support = -1;
        double layer = 0, height = 0, area = 0, length = 0, width = 0;
        Vec3   lower, upper;
      };


      const bool uniaxial_registered = PostprocessorRegistry::add(
        {"uniaxial",
         40,
         [](const PostprocessorInputs &in) -> std::unique_ptr<Postprocessor> {
           if (in.parameters.analysis.type
               != AnalysisParameters::Type::uniaxial)
             return nullptr;
           return std::make_unique<UniaxialAnalysis>(in);
         },
         "when Analysis/Type = uniaxial"});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
