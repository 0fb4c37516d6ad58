// 004 §3.4: initial values from a quintic Bézier curve that meets the end data and minimizes
// J_LAC = ∫ sqrt(1 + α² ρ^(2α−2) ρ_s²) ds / h (Eq. 45) over a grid of its four free leg lengths.
// Control points (normalized frame, unit chord, h taken as the chord length):
//   P1 = P0 + l0 t0,  P2 = P1 + l1 t0 + (5 κs l0² / 4) n0,
//   P4 = P5 − l3 t1,  P3 = P4 − l2 t1 + (5 κe l3² / 4) n1,
// which fixes the end curvatures (κ(0) = (4/5) cross(P1−P0, P2−P1)/|P1−P0|³), and
// l_i ∈ {0.05, 0.10, …, 0.5}: 10^4 candidates.
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <limits>

#include "lac/constructions/detail/g2_system.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac::detail {
namespace {

using Vec = Eigen::Vector2d;
using Ctrl = std::array<Vec, 6>;

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

struct Derivs {
  Vec d1, d2, d3;
};

Derivs derivs(const Ctrl& P, double t) {
  const double u = 1 - t;
  // Bernstein bases of degrees 4, 3, 2.
  const double b4[5] = {u * u * u * u, 4 * t * u * u * u, 6 * t * t * u * u, 4 * t * t * t * u, t * t * t * t};
  const double b3[4] = {u * u * u, 3 * t * u * u, 3 * t * t * u, t * t * t};
  const double b2[3] = {u * u, 2 * t * u, t * t};
  Derivs d{Vec::Zero(), Vec::Zero(), Vec::Zero()};
  for (int i = 0; i < 5; ++i) d.d1 += 5.0 * b4[i] * (P[i + 1] - P[i]);
  for (int i = 0; i < 4; ++i) d.d2 += 20.0 * b3[i] * (P[i + 2] - 2 * P[i + 1] + P[i]);
  for (int i = 0; i < 3; ++i) d.d3 += 60.0 * b2[i] * (P[i + 3] - 3 * P[i + 2] + 3 * P[i + 1] - P[i]);
  return d;
}

double curvature(const Derivs& d) { return cross(d.d1, d.d2) / std::pow(d.d1.norm(), 3); }

// Arc length from 0 to t by 20-point Gauss–Legendre (the speed is a smooth function of t).
double arc_length(const Ctrl& P, double t) {
  double L = 0;
  for (size_t k = 0; k < 20; ++k) L += gauss_legendre_20().weights[k] * t * derivs(P, t * gauss_legendre_20().nodes[k]).d1.norm();
  return L;
}

// t at which the arc length equals `target` (Newton with bisection safeguard, capped).
double t_at_length(const Ctrl& P, double target, double total) {
  double lo = 0, hi = 1, t = target / total;
  for (int it = 0; it < 40; ++it) {
    const double g = arc_length(P, t) - target;
    if (std::abs(g) < 1e-13 * total) break;
    if (g > 0)
      hi = t;
    else
      lo = t;
    const double tn = t - g / derivs(P, t).d1.norm();
    t = (tn > lo && tn < hi) ? tn : 0.5 * (lo + hi);
  }
  return t;
}

}  // namespace

G2StartEstimate g2_bezier_grid_start(const G2System& p) {
  const double alpha = p.law.alpha;
  const Vec P0(0, 0), P5(1, 0);
  const Vec t0(std::cos(p.phi_s), std::sin(p.phi_s)), n0(-t0.y(), t0.x());
  const Vec t1(std::cos(p.phi_e), std::sin(p.phi_e)), n1(-t1.y(), t1.x());
  const auto& x = gauss_legendre_20().nodes;
  const auto& w = gauss_legendre_20().weights;
  G2StartEstimate e;
  double best = std::numeric_limits<double>::infinity();
  Ctrl best_ctrl{};
  Ctrl P;
  P[0] = P0;
  P[5] = P5;
  for (int i0 = 1; i0 <= 10; ++i0) {
    const double l0 = 0.05 * i0;
    P[1] = P0 + l0 * t0;
    for (int i3 = 1; i3 <= 10; ++i3) {
      const double l3 = 0.05 * i3;
      P[4] = P5 - l3 * t1;
      for (int i1 = 1; i1 <= 10; ++i1) {
        P[2] = P[1] + 0.05 * i1 * t0 + (1.25 * p.kappa_s * l0 * l0) * n0;
        for (int i2 = 1; i2 <= 10; ++i2) {
          P[3] = P[4] - 0.05 * i2 * t1 + (1.25 * p.kappa_e * l3 * l3) * n1;
          // J = ∫ sqrt(1 + α² |κ|^(−2α−2) κ_s²) ds / ∫ ds, 20-point Gauss–Legendre in t.
          double num = 0, len = 0;
          for (size_t k = 0; k < 20; ++k) {
            const Derivs d = derivs(P, x[k]);
            const double speed = d.d1.norm();
            const double c = cross(d.d1, d.d2);
            const double kappa = c / (speed * speed * speed);
            const double kappa_t = (cross(d.d1, d.d3) * speed * speed - 3.0 * c * d.d1.dot(d.d2)) / std::pow(speed, 5);
            const double kappa_s = kappa_t / speed;
            const double rhs = alpha * alpha * std::pow(std::abs(kappa), -2.0 * alpha - 2.0) * kappa_s * kappa_s;
            num += w[k] * std::sqrt(1.0 + rhs) * speed;
            len += w[k] * speed;
          }
          e.evaluations += 20;
          const double J = num / len;
          if (J < best) best = J, best_ctrl = P;
        }
      }
    }
  }
  if (!std::isfinite(best)) return g2_fast_start(p);  // every candidate has an infinite J: no better guess
  const double total = arc_length(best_ctrl, 1.0);
  e.h = total;
  e.k1 = curvature(derivs(best_ctrl, t_at_length(best_ctrl, p.s1 * total, total))) * total;
  e.k2 = curvature(derivs(best_ctrl, t_at_length(best_ctrl, p.s2 * total, total))) * total;
  return e;
}

}  // namespace lac::detail
