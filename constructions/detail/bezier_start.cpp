// 004 §3.4: initial values from a quintic Bézier curve that meets the end data and minimizes
// J_LAC = ∫ sqrt(1 + α² ρ^(2α−2) ρ_s²) ds / h (Eq. 45) over a grid of its four free leg lengths.
// Control points (normalized frame, unit chord, h taken as the chord length):
//   P1 = P0 + l0 t0,  P2 = P1 + l1 t0 + (5 κs l0² / 4) n0,
//   P4 = P5 − l3 t1,  P3 = P4 − l2 t1 + (5 κe l3² / 4) n1,
// which fixes the end curvatures (κ(0) = (4/5) cross(P1−P0, P2−P1)/|P1−P0|³), and
// l_i ∈ {0.05, 0.10, …, 0.5}: 10^4 candidates.
// The derivatives are linear in the control points and P1, P2 depend only on (l0, l1), P3, P4 only
// on (l3, l2): they are tabulated per side and node, so a candidate costs additions. J is screened
// by the 7-point rule in single precision and the best kScreened candidates ranked by the
// 20-point rule in double. J is flat near its minimum, below what these rules resolve
// (docs/hermite.md): a candidate near the minimum, not one particular candidate, is the start.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "lac/constructions/detail/g2_system.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac::detail {
namespace {

using Vec = Eigen::Vector2d;
using Ctrl = std::array<Vec, 6>;

constexpr int kLegs = 10;            // l = 0.05, 0.10, …, 0.5
constexpr size_t kScreened = 32;     // candidates ranked in double precision
constexpr size_t kScreenNodes = 7;   // Gauss–Legendre nodes of the screening
constexpr int kNotInteger = 1000;

// The exponent −2α − 2 of |κ| in J as an integer when it is one of at most 12 in magnitude.
int integer_power(double alpha) {
  const double e = -2 * alpha - 2;
  return e == std::round(e) && std::abs(e) <= 12 ? static_cast<int>(e) : kNotInteger;
}

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

// Weights of P_0 … P_5 in the first, second and third derivatives at t (Bernstein differences).
struct Basis {
  std::array<double, 6> d1{}, d2{}, d3{};
};
Basis basis(double t) {
  const double u = 1 - t;
  const double b4[5] = {u * u * u * u, 4 * t * u * u * u, 6 * t * t * u * u, 4 * t * t * t * u, t * t * t * t};
  const double b3[4] = {u * u * u, 3 * t * u * u, 3 * t * t * u, t * t * t};
  const double b2[3] = {u * u, 2 * t * u, t * t};
  Basis b;
  for (int i = 0; i < 5; ++i) b.d1[i + 1] += 5 * b4[i], b.d1[i] -= 5 * b4[i];
  for (int i = 0; i < 4; ++i) b.d2[i + 2] += 20 * b3[i], b.d2[i + 1] -= 40 * b3[i], b.d2[i] += 20 * b3[i];
  for (int i = 0; i < 3; ++i)
    b.d3[i + 3] += 60 * b2[i], b.d3[i + 2] -= 180 * b2[i], b.d3[i + 1] += 180 * b2[i], b.d3[i] -= 60 * b2[i];
  return b;
}

struct Derivs {
  Vec d1, d2, d3;
};
Derivs derivs(const Ctrl& P, const Basis& b) {
  Derivs d{Vec::Zero(), Vec::Zero(), Vec::Zero()};
  for (int j = 0; j < 6; ++j) d.d1 += b.d1[j] * P[j], d.d2 += b.d2[j] * P[j], d.d3 += b.d3[j] * P[j];
  return d;
}
Derivs derivs(const Ctrl& P, double t) { return derivs(P, basis(t)); }

// x^P for an integer P, by products; P = kNotInteger: x^power by std::pow.
template <int P, class T>
T power_of(T x, T power) {
  if constexpr (P == kNotInteger) {
    return std::pow(x, power);
  } else if constexpr (P < 0) {
    return 1 / power_of<-P>(x, power);
  } else if constexpr (P == 0) {
    return T(1);
  } else {
    return x * power_of<P - 1>(x, power);
  }
}

// f.template operator()<P>() with P = p as a constant (p ∈ [−12, 12] or kNotInteger).
template <int P = -12, class F>
void with_power(int p, F&& f) {
  if constexpr (P > 12) {
    f.template operator()<kNotInteger>();
  } else {
    if (p == P) return f.template operator()<P>();
    with_power<P + 1>(p, f);
  }
}

// The integrand of J (times the speed) and the speed at one node, from the derivatives.
template <class T, int P>
void j_terms(T d1x, T d1y, T d2x, T d2y, T d3x, T d3y, T alpha2, T power, T& num, T& speed) {
  const T s2 = d1x * d1x + d1y * d1y;
  speed = std::sqrt(s2);
  const T c = d1x * d2y - d1y * d2x;
  const T kappa = c / (s2 * speed);
  // κ_s = κ_t / speed, κ_t = (cross(d1, d3)·s² − 3c·(d1·d2)) / speed⁵.
  const T kappa_s = ((d1x * d3y - d1y * d3x) * s2 - 3 * c * (d1x * d2x + d1y * d2y)) / (s2 * s2 * s2);
  const T rhs = alpha2 * power_of<P>(std::abs(kappa), power) * kappa_s * kappa_s;
  num = std::sqrt(1 + rhs) * speed;
}

// J of one candidate by the N-point rule in double (the rule's Bernstein weights computed once).
template <size_t N>
double j_of(const Ctrl& P, double alpha) {
  const auto& g = gauss_legendre_rule<N>();
  static const std::array<Basis, N> bases = [&g] {
    std::array<Basis, N> b;
    for (size_t k = 0; k < N; ++k) b[k] = basis(g.nodes[k]);
    return b;
  }();
  double num = 0, len = 0;
  for (size_t k = 0; k < N; ++k) {
    const Derivs d = derivs(P, bases[k]);
    double n = 0, speed = 0;
    j_terms<double, kNotInteger>(d.d1.x(), d.d1.y(), d.d2.x(), d.d2.y(), d.d3.x(), d.d3.y(), alpha * alpha, -2 * alpha - 2, n, speed);
    num += g.weights[k] * n;
    len += g.weights[k] * speed;
  }
  return num / len;
}

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

double curvature(const Derivs& d) { return cross(d.d1, d.d2) / std::pow(d.d1.norm(), 3); }

// The estimate from the chosen curve: its length and its curvatures at the joints.
G2StartEstimate from_curve(const Ctrl& P, const G2System& p, G2StartEstimate e) {
  const double total = arc_length(P, 1.0);
  e.h = total;
  e.k1 = curvature(derivs(P, t_at_length(P, p.s1 * total, total))) * total;
  e.k2 = curvature(derivs(P, t_at_length(P, p.s2 * total, total))) * total;
  return e;
}

}  // namespace

G2StartEstimate g2_bezier_grid_start(const G2System& p) {
  const double alpha = p.law.alpha;
  const Vec P0(0, 0), P5(1, 0);
  const Vec t0(std::cos(p.phi_s), std::sin(p.phi_s)), n0(-t0.y(), t0.x());
  const Vec t1(std::cos(p.phi_e), std::sin(p.phi_e)), n1(-t1.y(), t1.x());
  const auto leg = [](int i) { return 0.05 * (i + 1); };
  // Control points of candidate (a, b): a = 10·i0 + i1 (left legs l0, l1), b = 10·i3 + i2 (right).
  const auto left = [&](int a) {
    const double l0 = leg(a / kLegs), l1 = leg(a % kLegs);
    const Vec P1 = P0 + l0 * t0;
    return std::pair{P1, Vec(P1 + l1 * t0 + (1.25 * p.kappa_s * l0 * l0) * n0)};
  };
  const auto right = [&](int b) {
    const double l3 = leg(b / kLegs), l2 = leg(b % kLegs);
    const Vec P4 = P5 - l3 * t1;
    return std::pair{Vec(P4 - l2 * t1 + (1.25 * p.kappa_e * l3 * l3) * n1), P4};
  };

  G2StartEstimate e;
  if (alpha == 0) {  // J ≡ 1: every candidate ties, and the first is taken
    const auto [P1, P2] = left(0);
    const auto [P3, P4] = right(0);
    return from_curve(Ctrl{P0, P1, P2, P3, P4, P5}, p, e);
  }
  // Per side and node of the screening rule, the side's share of d1, d2, d3: the left side's as
  // (x, y) pairs, the right side's per component over all 100 right sides (the inner loop runs over
  // them, in SIMD lanes).
  constexpr int kSide = kLegs * kLegs;
  const auto& gs = gauss_legendre_rule<kScreenNodes>();
  std::array<Basis, kScreenNodes> bases;
  for (size_t k = 0; k < kScreenNodes; ++k) bases[k] = basis(gs.nodes[k]);
  std::vector<std::array<float, 6>> L(kSide * kScreenNodes);
  std::vector<float> R(kScreenNodes * 6 * kSide);  // [node][component][right side]
  for (int a = 0; a < kSide; ++a) {
    const auto [P1, P2] = left(a);
    const auto [P3, P4] = right(a);
    for (size_t k = 0; k < kScreenNodes; ++k) {
      const Basis& B = bases[k];
      const Vec l1 = B.d1[1] * P1 + B.d1[2] * P2, l2 = B.d2[1] * P1 + B.d2[2] * P2, l3 = B.d3[1] * P1 + B.d3[2] * P2;
      const Vec r1 = B.d1[3] * P3 + B.d1[4] * P4 + B.d1[5] * P5, r2 = B.d2[3] * P3 + B.d2[4] * P4 + B.d2[5] * P5,
                r3 = B.d3[3] * P3 + B.d3[4] * P4 + B.d3[5] * P5;
      L[a * kScreenNodes + k] = {float(l1.x()), float(l1.y()), float(l2.x()), float(l2.y()), float(l3.x()), float(l3.y())};
      const float rk[6] = {float(r1.x()), float(r1.y()), float(r2.x()), float(r2.y()), float(r3.x()), float(r3.y())};
      for (int c = 0; c < 6; ++c) R[(k * 6 + c) * kSide + a] = rk[c];
    }
  }
  std::vector<std::pair<float, int>> screened;  // (J, candidate a·100 + b)
  screened.reserve(kSide * kSide);
  const float alpha2 = static_cast<float>(alpha * alpha), power = static_cast<float>(-2 * alpha - 2);
  with_power(integer_power(alpha), [&]<int P>() {
    for (int a = 0; a < kSide; ++a) {
      std::array<float, kSide> num{}, len{};
      for (size_t k = 0; k < kScreenNodes; ++k) {
        const auto& l = L[a * kScreenNodes + k];
        const float* r = &R[k * 6 * kSide];
        const float w = static_cast<float>(gs.weights[k]);
        for (int b = 0; b < kSide; ++b) {
          float n, speed;
          j_terms<float, P>(l[0] + r[b], l[1] + r[kSide + b], l[2] + r[2 * kSide + b], l[3] + r[3 * kSide + b],
                            l[4] + r[4 * kSide + b], l[5] + r[5 * kSide + b], alpha2, power, n, speed);
          num[b] += w * n;
          len[b] += w * speed;
        }
      }
      for (int b = 0; b < kSide; ++b) {
        const float J = num[b] / len[b];
        if (std::isfinite(J)) screened.emplace_back(J, a * kSide + b);
      }
    }
  });
  e.evaluations += static_cast<long>(kScreenNodes) * kSide * kSide;
  const size_t keep = std::min(kScreened, screened.size());
  std::partial_sort(screened.begin(), screened.begin() + keep, screened.end());
  double best = std::numeric_limits<double>::infinity();
  Ctrl best_ctrl{};
  for (size_t i = 0; i < keep; ++i) {
    const int a = screened[i].second / kSide, b = screened[i].second % kSide;
    const auto [P1, P2] = left(a);
    const auto [P3, P4] = right(b);
    const Ctrl P{P0, P1, P2, P3, P4, P5};
    const double J = j_of<20>(P, alpha);
    e.evaluations += 20;
    if (J < best) best = J, best_ctrl = P;
  }
  if (!std::isfinite(best)) return g2_fast_start(p);  // every candidate has an infinite J: no better guess
  return from_curve(best_ctrl, p, e);
}

}  // namespace lac::detail
