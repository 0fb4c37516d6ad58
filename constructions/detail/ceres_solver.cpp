// Ceres Levenberg–Marquardt on the whole ten-unknown system of 004 §3.2 (Eqs. 20–23, 28–33).
// Unknowns: log h and, per segment i, q_i(S) = c_i0 S + c_i1 and ψ_i = φ at the segment's
// start. ψ_i replaces 004's c_i2 (c_i2 = ψ_i − α/((α−1)c_i0)|q_i(S_a)|^((α−1)/α)), which
// is the same unknown without the cancellation as c_i0 → 0 (Appendix A).
#include <ceres/ceres.h>

#include <cmath>

#include "lac/constructions/detail/g2_system.hpp"

namespace lac::hermite::detail {
namespace {

constexpr int kUnknowns = 10;

struct TripleLaResidual {
  const NormalizedG2* p;
  long* evaluations;

  bool operator()(const double* x, double* r) const {
    const double h = std::exp(x[0]);
    const double S[4] = {0.0, kS1, kS2, 1.0};
    std::array<lac::detail::LinearQ, 3> seg;
    for (int i = 0; i < 3; ++i) {
      const double c0 = x[1 + 3 * i], c1 = x[2 + 3 * i], psi = x[3 + 3 * i];
      seg[i] = {S[i], S[i + 1], c0 * S[i] + c1, c0 * S[i + 1] + c1, psi};
    }
    for (const auto& s : seg) {
      if (p->law.alpha > 0 && !(s.qa * p->law.sigma > 0 && s.qb * p->law.sigma > 0)) return false;
    }
    r[0] = seg[0].qa - p->law.q_of_kappa(p->kappa_s * h);  // Eq. (20) as (34)
    r[1] = seg[2].qb - p->law.q_of_kappa(p->kappa_e * h);  // Eq. (21) as (35)
    r[2] = seg[0].phi_a - p->phi_s;                        // Eq. (22)
    r[3] = seg[2].phi_b(p->law) - p->phi_e;                // Eq. (23)
    r[4] = seg[0].qb - seg[1].qa;                          // Eq. (28)
    r[5] = seg[1].qb - seg[2].qa;                          // Eq. (29)
    r[6] = seg[0].phi_b(p->law) - seg[1].phi_a;            // Eq. (30)
    r[7] = seg[1].phi_b(p->law) - seg[2].phi_a;            // Eq. (31)
    std::complex<double> sum{};
    for (const auto& s : seg) sum += lac::detail::integrate_tangent(p->law, s, *evaluations);
    r[8] = h * sum.real() - 1.0;  // Eq. (32)
    r[9] = h * sum.imag();        // Eq. (33)
    for (int k = 0; k < kUnknowns; ++k)
      if (!std::isfinite(r[k])) return false;
    return true;
  }
};

}  // namespace

SolverOutcome solve_ceres(const NormalizedG2& p, const StartEstimate& s, const G2Options& o) {
  SolverOutcome out;
  const double h = s.h;
  const double q1 = joint_q(p, s.k1, h), q2 = joint_q(p, s.k2, h);
  const auto seg = build_segments(p, h, q1, q2);
  double x[kUnknowns];
  x[0] = std::log(h);
  for (int i = 0; i < 3; ++i) {
    x[1 + 3 * i] = seg[i].slope();
    x[2 + 3 * i] = seg[i].qa - seg[i].slope() * seg[i].ua;
    x[3 + 3 * i] = seg[i].phi_a;
  }
  ceres::Problem problem;
  auto* cost = new ceres::NumericDiffCostFunction<TripleLaResidual, ceres::CENTRAL, kUnknowns, kUnknowns>(
      new TripleLaResidual{&p, &out.evaluations});
  problem.AddResidualBlock(cost, nullptr, x);
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = o.max_iterations;
  so.function_tolerance = 1e-30;
  so.gradient_tolerance = 1e-30;
  so.parameter_tolerance = 1e-16;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  out.iterations = static_cast<int>(summary.iterations.size());
  double r[kUnknowns];
  long dummy = 0;
  const bool finite = TripleLaResidual{&p, &dummy}(x, r);
  double worst = 0;
  for (double v : r) worst = std::max(worst, std::abs(v));
  out.h = std::exp(x[0]);
  // q at the joints from the segment on the left (continuity is itself a residual).
  out.q1 = x[1] * kS1 + x[2];
  out.q2 = x[4] * kS2 + x[5];
  if (finite && worst <= o.tolerance) {
    out.status = Status::ok;
  } else {
    out.status = summary.termination_type == ceres::NO_CONVERGENCE ? Status::max_iterations : Status::no_solution;
    out.message = "ceres: " + summary.message + " (largest residual " + std::to_string(worst) + ")";
  }
  return out;
}

}  // namespace lac::hermite::detail
