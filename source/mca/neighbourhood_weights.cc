// Neighbourhood weights of the many-body term and the fabric correction of
// the eq.-(4) stress (doc/theory/mca.md §3): per automaton, a 6 x 6 least
// squares fit of a strain tensor to its pairs' normal strains, and the 3 x 3
// fabric tensor of its neighbourhood. Recomputed only for the automata
// whose contacts or bonds changed.

#include "pair_energy.h"

#include <Eigen/Dense>
#include <cmath>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Voigt vector of n (x) n with doubled shear entries.
      inline Eigen::Matrix<double, 6, 1>
      voigt(const Vec3 &n)
      {
        Eigen::Matrix<double, 6, 1> N;
        N << n[0] * n[0], n[1] * n[1], n[2] * n[2], 2 * n[1] * n[2],
          2 * n[0] * n[2], 2 * n[0] * n[1];
        return N;
      }

      /// Is the symmetric positive semi-definite @p A (with its LDLT
      /// factors @p ldlt) certainly better conditioned than lambda_min >
      /// 1e-6 lambda_max, the test of the weights' fit? From the bounds
      /// lambda_max <= tr A and lambda_min >= 1 / tr A^-1, a factor 2 away
      /// from the limit (round-off of A^-1): a few hundred operations where
      /// the eigenvalues cost thousands. False for the rest, which the
      /// caller tests with the eigenvalues, so the test's outcome is the
      /// same.
      template <class Matrix, class Factors>
      bool
      surely_well_conditioned(const Matrix &A, const Factors &ldlt)
      {
        if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0))
          return false;
        const double trace_inverse
          = ldlt.solve(Matrix::Identity()).diagonal().sum();
        return trace_inverse > 0 && A.trace() * trace_inverse < 5e5;
      }
    } // namespace


    void
    AutomatonSystem::update_neighbourhood_weights(const bool all)
    {
      const unsigned int n_pairs = pi.size();
      if (all)
        {
          beta_i.assign(n_pairs, 0);
          beta_j.assign(n_pairs, 0);
          // stored only where the stress is needed every step
          if (plastic_scene || bond_scene)
            fabric_inverse.assign(n_owned, Sym3{{1, 1, 1, 0, 0, 0}});
          else
            std::vector<Sym3>().swap(fabric_inverse);
          index_by_automaton(n_owned);
          mb_state.assign(n_owned, {});
          mb_shape.assign(n_owned, ManyBodyShape::general);
        }
      using Matrix6 = Eigen::Matrix<double, 6, 6>;
      using Vector6 = Eigen::Matrix<double, 6, 1>;
      Vector6 e;
      e << 1, 1, 1, 0, 0, 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          if (!all && !changed[k])
            continue;
          // A = sum_j N_j N_j^T over the interacting pairs (bonded or in
          // contact)
          Matrix6      A     = Matrix6::Zero();
          unsigned int count = 0;
          for_each_pair_of(k, [&](const unsigned int p, const unsigned int) {
            if (!bonded[p] && !in_contact[p])
              return;
            double     r;
            const Vec3 n = unit_normal(p, r);
            const auto N = voigt(n);
            A.noalias() += N * N.transpose();
            ++count;
          });
          // Least-squares weights of the volumetric strain: beta_j = g.N_j
          // with A g = (1 1 1 0 0 0), for well-conditioned neighbourhoods
          // (bulk: |g| ~ 1); otherwise an equal share of the trace.
          bool         full_rank = false;
          Vector6      g         = Vector6::Zero();
          const double scale     = A.diagonal().maxCoeff();
          if (count > 0 && scale > 0)
            {
              // full rank: smallest eigenvalue of A not negligible against
              // the largest (A is symmetric positive semi-definite); the
              // eigenvalues only where a cheap bound leaves it open
              const Eigen::LDLT<Matrix6> ldlt(A);
              const auto                 eigenvalue_test = [&] {
                const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(
                  A, Eigen::EigenvaluesOnly);
                const auto &lambda = eigen.eigenvalues();
                return lambda(0) > 1e-6 * lambda(5);
              };
              if (surely_well_conditioned(A, ldlt) || eigenvalue_test())
                {
                  g         = ldlt.solve(e);
                  full_rank = g.cwiseAbs().maxCoeff() < 8;
                }
            }
          double beta_sum = 0;
          for_each_pair_of(k,
                           [&](const unsigned int p, const unsigned int side) {
                             double beta = 0;
                             if (bonded[p] || in_contact[p])
                               {
                                 if (full_rank)
                                   {
                                     double r;
                                     beta = g.dot(voigt(unit_normal(p, r)));
                                   }
                                 else
                                   beta = 3. / count;
                               }
                             (side ? beta_j : beta_i)[p] = beta;
                             beta_sum += std::abs(beta);
                           });
          // Bound the many-body stiffness by its bulk value (sum of |beta|
          // = 3 in a complete FCC neighbourhood): sparse, nearly degenerate
          // neighbourhoods (e.g. around broken bonds) could otherwise make
          // an automaton far stiffer than the bulk and the explicit step
          // unstable.
          if (beta_sum > 3)
            for_each_pair_of(k,
                             [&](const unsigned int p,
                                 const unsigned int side) {
                               (side ? beta_j : beta_i)[p] *= 3 / beta_sum;
                             });
          if (!fabric_inverse.empty())
            fabric_inverse[k] = inverse_fabric(k);
          // kappa, gamma and G of the new weights: the jump of kappa G^2
          // is booked as switching work (doc/theory/mca.md §8.4; that of
          // all the automata, by rebuild())
          const auto  &st     = mb_state[k];
          const double before = st.kappa * st.G * st.G;
          update_many_body_state(k);
          if (!all)
            work[switching_work] += before - st.kappa * st.G * st.G;
          changed[k] = 0;
        }
      any_changed = false;
      // (the j side's pair lists are read again only at the next rebuild
      // where no event can move a side's weight or offset: the pairs store
      // no offsets of their own, mb_stored; also after a restart on another
      // number of ranks, whose first step comes here: any_changed)
      if (!mb_stored)
        release_j_lists();
    }


    Sym3
    AutomatonSystem::inverse_fabric(const unsigned int k) const
    {
      // B = sum_j (q S / V) n n over the interacting pairs (complete FCC:
      // B = I). Inverted for well-conditioned fabrics only; otherwise
      // eq. (4) as is: B^-1 of a nearly planar neighbourhood would blow the
      // stress (and the radial return's mean stress) up.
      Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
      for_each_pair_of(k, [&](const unsigned int p, const unsigned int side) {
        if (!bonded[p] && !in_contact[p])
          return;
        double                r;
        const Vec3            n = unit_normal(p, r);
        const double          q = moment_arm(p, r, side);
        const Eigen::Vector3d nv(n[0], n[1], n[2]);
        B.noalias() += (q * area_of(p) / automaton_volume(*this, k)) * nv
                       * nv.transpose();
      });
      const double tr3 = B.trace() / 3;
      if (B.determinant() > 0.1 * tr3 * tr3 * tr3)
        {
          const Eigen::Matrix3d Bi = B.inverse();
          return {{Bi(0, 0), Bi(1, 1), Bi(2, 2), Bi(1, 2), Bi(0, 2), Bi(0, 1)}};
        }
      return {{1, 1, 1, 0, 0, 0}};
    }


    Sym3
    AutomatonSystem::fabric_corrected(const unsigned int k, const Mat3 &t) const
    {
      // sym(B^-1 T) of the full (unsymmetric) T = B sigma: at surfaces B is
      // anisotropic and sym(B^-1 sym(T)) would not recover sigma
      const Sym3 b
        = fabric_inverse.empty() ? inverse_fabric(k) : fabric_inverse[k];
      // P = B^-1 T entry by entry, summed as Eigen's 3 x 3 product did
      // before (rows 0 and 1 in packets, (b_i0 T_0j + b_i1 T_1j) + b_i2
      // T_2j; row 2 by coefficient, b_20 T_0j + (b_21 T_1j + b_22 T_2j)):
      // the same bits, without its matrices (a quarter of the time).
      const double Bi[3][3]
        = {{b[0], b[5], b[4]}, {b[5], b[1], b[3]}, {b[4], b[3], b[2]}};
      const auto P = [&](const unsigned int i, const unsigned int j) {
        const double p0 = Bi[i][0] * t[j], p1 = Bi[i][1] * t[3 + j],
                     p2 = Bi[i][2] * t[6 + j];
        return i < 2 ? (p0 + p1) + p2 : p0 + (p1 + p2);
      };
      return {{P(0, 0),
               P(1, 1),
               P(2, 2),
               0.5 * (P(1, 2) + P(2, 1)),
               0.5 * (P(0, 2) + P(2, 0)),
               0.5 * (P(0, 1) + P(1, 0))}};
    }


    Sym3
    AutomatonSystem::automaton_stress(const unsigned int k) const
    {
      // Over the automaton's pairs, in pair order (the order of the pair
      // loop): no tensor array of all automata is needed.
      Mat3 t{{0, 0, 0, 0, 0, 0, 0, 0, 0}};
      for_each_pair_of(k, [&](const unsigned int p, const unsigned int is_j) {
        if (!bonded[p] && !in_contact[p])
          return;
        double       r;
        const Vec3   n     = unit_normal(p, r);
        const double sg    = side_sigma(p, is_j);
        const Vec3   shear = side_shear(p, is_j);
        const double q     = moment_arm(p, r, is_j);
        Vec3         traction;
        for (unsigned int c = 0; c < 3; ++c)
          traction[c] = sg * n[c] + shear[c];
        add_outer(t, q * area_of(p) / automaton_volume(*this, k), n, traction);
      });
      return fabric_corrected(k, t);
    }


    std::vector<Sym3>
    AutomatonSystem::bond_criterion_stresses() const
    {
      // (bond_switching() keeps them in its exchange buffer: six
      // components and the yield stress per local automaton)
      std::vector<Sym3> out(n_owned, Sym3{{0, 0, 0, 0, 0, 0}});
      if (bond_buffer.size() >= 7 * static_cast<std::size_t>(n_owned))
        for (unsigned int k = 0; k < n_owned; ++k)
          for (unsigned int c = 0; c < 6; ++c)
            out[k][c] = bond_buffer[7 * k + c];
      return out;
    }


    std::vector<Sym3>
    AutomatonSystem::stresses() const
    {
      std::vector<Sym3> out(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        out[k] = automaton_stress(k);
      return out;
    }
  } // namespace mca
} // namespace tribodyn
