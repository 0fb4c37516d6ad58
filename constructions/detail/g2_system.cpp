#include "lac/constructions/detail/g2_system.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace lac::hermite::detail {
namespace {

// Newton unknowns: z = (log h, z1, z2) with q = z for α ≤ 0 and q = σ e^(−αz) (z = log|κ̃|)
// for α > 0, so that h > 0 and q keeps the only sign an α > 0 segment allows.
double q_of_z(const NormalizedG2& p, double z) {
  return p.law.alpha > 0 ? p.law.sigma * std::exp(-p.law.alpha * z) : z;
}
double z_of_q(const NormalizedG2& p, double q) { return p.law.alpha > 0 ? -std::log(std::abs(q)) / p.law.alpha : q; }

}  // namespace

std::array<lac::detail::LinearQ, 3> build_segments(const NormalizedG2& p, double h, double q1, double q2) {
  const double q0 = p.law.q_of_kappa(p.kappa_s * h);
  const double q3 = p.law.q_of_kappa(p.kappa_e * h);
  std::array<lac::detail::LinearQ, 3> seg;
  seg[0] = {0.0, kS1, q0, q1, p.phi_s};
  seg[1] = {kS1, kS2, q1, q2, seg[0].phi_b(p.law)};
  seg[2] = {kS2, 1.0, q2, q3, seg[1].phi_b(p.law)};
  return seg;
}

std::array<double, 3> residuals(const NormalizedG2& p, double h, double q1, double q2, long& evaluations) {
  const auto seg = build_segments(p, h, q1, q2);
  std::complex<double> sum{};
  for (const auto& s : seg) sum += lac::detail::integrate_tangent(p.law, s, evaluations);
  return {seg[2].phi_b(p.law) - p.phi_e, h * sum.imag(), h * sum.real() - 1.0};
}

double joint_q(const NormalizedG2& p, double kappa_tilde, double h) {
  if (p.law.alpha >= 0 && !(kappa_tilde * p.law.sigma > 0 && std::isfinite(kappa_tilde))) {
    kappa_tilde = p.law.sigma * std::sqrt(std::abs(p.kappa_s * p.kappa_e)) * h;  // geometric mean of the ends
  }
  return p.law.q_of_kappa(kappa_tilde);
}

StartEstimate fast_start(const NormalizedG2& p) {
  // Small-angle triple clothoid: κ̃ piecewise linear on the nodes 0, S1, S2, 1. With
  // sin φ ≈ φ the end conditions become linear in κ̃1, κ̃2:
  //   ∫κ̃ dS = φe − φs,   ∫φ dS = φs + ∫(1 − S)κ̃ dS = 0.
  // Then h = 1 / ∫cos φ dS of that clothoid (exact quadrature); two passes.
  const std::array<double, 4> nodes{0.0, kS1, kS2, 1.0};
  std::array<double, 4> A{}, B{};
  for (int i = 0; i < 3; ++i) {
    const double a = nodes[i], L = nodes[i + 1] - nodes[i];
    A[i] += 0.5 * L;
    A[i + 1] += 0.5 * L;
    B[i] += L * ((1.0 - a) / 2.0 - L / 6.0);
    B[i + 1] += L * ((1.0 - a) / 2.0 - L / 3.0);
  }
  StartEstimate e;
  const LaLaw clothoid{-1.0, 1.0};
  NormalizedG2 c = p;
  c.law = clothoid;
  for (int pass = 0; pass < 2; ++pass) {
    const double k0 = p.kappa_s * e.h, k3 = p.kappa_e * e.h;
    Eigen::Matrix2d M;
    M << A[1], A[2], B[1], B[2];
    const Eigen::Vector2d rhs(p.phi_e - p.phi_s - A[0] * k0 - A[3] * k3, -p.phi_s - B[0] * k0 - B[3] * k3);
    const Eigen::Vector2d k = M.partialPivLu().solve(rhs);
    e.k1 = k(0);
    e.k2 = k(1);
    const auto seg = build_segments(c, e.h, e.k1, e.k2);
    std::complex<double> sum{};
    for (const auto& s : seg) sum += lac::detail::integrate_tangent(clothoid, s, e.evaluations);
    if (!(sum.real() > 0.05) || !std::isfinite(sum.real())) break;  // keep the last usable h
    const double h_new = 1.0 / sum.real();
    e.k1 *= h_new / e.h;
    e.k2 *= h_new / e.h;
    e.h = h_new;
  }
  return e;
}

SolverOutcome solve_newton(const NormalizedG2& p, const StartEstimate& s, const G2Options& o) {
  SolverOutcome out;
  Eigen::Vector3d z(std::log(s.h), z_of_q(p, joint_q(p, s.k1, s.h)), z_of_q(p, joint_q(p, s.k2, s.h)));
  auto eval = [&](const Eigen::Vector3d& v) {
    const auto r = residuals(p, std::exp(v(0)), q_of_z(p, v(1)), q_of_z(p, v(2)), out.evaluations);
    return Eigen::Vector3d(r[0], r[1], r[2]);
  };
  auto norm = [](const Eigen::Vector3d& r) { return r.allFinite() ? r.lpNorm<Eigen::Infinity>() : HUGE_VAL; };
  Eigen::Vector3d r = eval(z);
  double rn = norm(r);
  if (!std::isfinite(rn)) {
    out.status = Status::numerical_failure;
    out.message = "newton: the initial estimate gives a non-finite curve";
    return out;
  }
  out.status = Status::max_iterations;
  out.message = "newton: iteration cap reached";
  for (out.iterations = 0; out.iterations < o.max_iterations; ++out.iterations) {
    if (rn <= o.tolerance) {
      out.status = Status::ok;
      out.message.clear();
      break;
    }
    Eigen::Matrix3d J;
    for (int j = 0; j < 3; ++j) {  // forward differences
      Eigen::Vector3d zj = z;
      const double step = 1e-7 * std::max(1.0, std::abs(z(j)));
      zj(j) += step;
      J.col(j) = (eval(zj) - r) / step;
    }
    const Eigen::Vector3d dz = J.fullPivLu().solve(-r);
    if (!dz.allFinite()) {
      out.status = Status::numerical_failure;
      out.message = "newton: singular Jacobian";
      break;
    }
    // Backtracking: halve the step until the residual decreases (at most 30 halvings).
    double lambda = 1.0;
    bool moved = false;
    for (int k = 0; k < 30; ++k, lambda *= 0.5) {
      Eigen::Vector3d zt = z + lambda * dz;
      if (std::abs(zt(0) - z(0)) > 2.0) continue;  // length may change by e^2 per step at most
      const Eigen::Vector3d rt = eval(zt);
      const double nt = norm(rt);
      if (nt < rn) {
        z = zt, r = rt, rn = nt, moved = true;
        break;
      }
    }
    if (!moved) {
      out.status = rn <= 1e3 * o.tolerance ? Status::ok : Status::no_solution;
      out.message = rn <= 1e3 * o.tolerance ? "" : "newton: no descent from here (residual " + std::to_string(rn) + ")";
      break;
    }
  }
  if (out.status == Status::max_iterations && rn <= o.tolerance) out.status = Status::ok, out.message.clear();
  out.h = std::exp(z(0));
  out.q1 = q_of_z(p, z(1));
  out.q2 = q_of_z(p, z(2));
  return out;
}

}  // namespace lac::hermite::detail
