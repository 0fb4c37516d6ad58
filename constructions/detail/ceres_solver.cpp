// The ten-unknown system of 004 §3.2 (Eqs. 20–23, 28–33) that the `ceres` G2 solver hands to
// solve_nonlinear (solvers/nonlinear.hpp: Levenberg–Marquardt, central differences).
// Unknowns: log h and, per segment i, q_i(S) = c_i0 S + c_i1 and ψ_i = φ at the segment's start.
// ψ_i replaces 004's c_i2 (c_i2 = ψ_i − α/((α−1)c_i0)|q_i(S_a)|^((α−1)/α)), which is the same
// unknown without the cancellation as c_i0 → 0 (Appendix A).
#include <cmath>

#include "lac/constructions/detail/g2_system.hpp"

namespace lac::detail {

NonlinearResidual g2_ten_unknown_residual(const G2System& p, long& evaluations) {
  return {10, [&p, &evaluations](ConstVectorMap x, VectorMap r) {
            const double h = std::exp(x[0]);
            const double S[4] = {0.0, p.s1, p.s2, 1.0};
            std::array<LinearQ, 3> seg;
            for (int i = 0; i < 3; ++i) {
              const double c0 = x[1 + 3 * i], c1 = x[2 + 3 * i], psi = x[3 + 3 * i];
              seg[i] = {S[i], S[i + 1], c0 * S[i] + c1, c0 * S[i + 1] + c1, psi};
            }
            for (const auto& s : seg)
              if (p.law.alpha > 0 && !(p.law.t_of_q(s.qa) * p.law.sigma > 0 && p.law.t_of_q(s.qb) * p.law.sigma > 0)) return false;
            r[0] = seg[0].qa - p.law.q_of_kappa(p.kappa_s * h);  // Eq. (20) as (34)
            r[1] = seg[2].qb - p.law.q_of_kappa(p.kappa_e * h);  // Eq. (21) as (35)
            r[2] = seg[0].phi_a - p.phi_s;                        // Eq. (22)
            r[3] = seg[2].phi_b(p.law) - p.phi_e;                 // Eq. (23)
            r[4] = seg[0].qb - seg[1].qa;                         // Eq. (28)
            r[5] = seg[1].qb - seg[2].qa;                         // Eq. (29)
            r[6] = seg[0].phi_b(p.law) - seg[1].phi_a;            // Eq. (30)
            r[7] = seg[1].phi_b(p.law) - seg[2].phi_a;            // Eq. (31)
            std::complex<double> sum{};
            for (const auto& s : seg) sum += p.integrate(p.law, s, evaluations);
            r[8] = h * sum.real() - 1.0;  // Eq. (32)
            r[9] = h * sum.imag();        // Eq. (33)
            return true;
          }};
}

Eigen::VectorXd g2_ten_unknown_start(const G2System& p, const G2StartEstimate& s) {
  const double h = s.h;
  const auto seg = g2_segments(p, h, g2_joint_q(p, s.k1, h), g2_joint_q(p, s.k2, h));
  Eigen::VectorXd x(10);
  x[0] = std::log(h);
  for (int i = 0; i < 3; ++i) {
    x[1 + 3 * i] = seg[i].slope();
    x[2 + 3 * i] = seg[i].qa - seg[i].slope() * seg[i].ua;
    x[3 + 3 * i] = seg[i].phi_a;
  }
  return x;
}

// q at the joints from the segment on the left (continuity is itself a residual).
std::array<double, 3> g2_ten_unknown_solution(const G2System& p, const Eigen::VectorXd& x) {
  return {std::exp(x[0]), x[1] * p.s1 + x[2], x[4] * p.s2 + x[5]};
}

}  // namespace lac::detail
