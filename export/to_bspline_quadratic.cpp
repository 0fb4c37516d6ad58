// to_bspline for an arc of a quadratic LA curve (003): the span machinery of to_bspline.cpp
// (export/detail/hermite_bound.hpp) with the curve's own bounds on the curvature's derivatives.
//
// The derivatives of κ in arc length. 003's Eq. (4.3), ds/dκ = −κ^(−α + γ log κ − 1)/Λ, is in
// u = log κ: ds/du = −e^(E(u))/Λ with E(u) = γu² − αu, so d/ds = −Λ e^(−E(u)) d/du and, by
// induction on j (κ = e^u),
//   κ^(j) = (−Λ)^j P_j(u) e^(φ_j(u)),   φ_j(u) = u − j E(u) = (1 + jα) u − jγ u²,
//   P_1 = 1,   P_(j+1) = P_j' + (1 + jα − 2jγ u) P_j
// (κ' = −Λ e^(u − E): geometry/quadratic_geometry.hpp's dκ/ds). Past the inflection the curve is
// the point-symmetric image (quadratic_curve.hpp), so |κ^(j)| there is the same function of
// u = log|κ|. On a span without the inflection u is monotone in s, so u covers exactly the
// interval between its ends' values, and
//   |κ^(j)| ≤ Λ^j · max|P_j| · exp(max φ_j)   on that interval,
// the maximum of the quadratic φ_j exactly (its ends, or its vertex when jγ > 0 puts it inside),
// and max|P_j| (degree j − 1) from the Taylor coefficients at the interval's middle:
// |P(c + t)| ≤ Σ |P^(i)(c)/i!| |t|^i. Both factors tend to their values at the same point as the
// span shrinks, so the bound is tight on short spans. At the inflection itself (u → −∞) κ' is
// unbounded unless γ = 0 and 1 + jα ≥ 0: the span then takes the cubic's h²|κ|/16.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/export/detail/hermite_bound.hpp"
#include "lac/export/to_bspline.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac {

namespace {

constexpr const char* kWho = "to_bspline";
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Coefficients (in powers of u) of P_1 … P_4 of the header comment.
std::array<std::array<double, 4>, 5> derivative_polynomials(double alpha, double gamma) {
  std::array<std::array<double, 4>, 5> P{};
  P[1][0] = 1;
  for (int j = 1; j < 4; ++j) {
    const auto& p = P[static_cast<size_t>(j)];
    auto& q = P[static_cast<size_t>(j + 1)];
    for (int i = 1; i < 4; ++i) q[static_cast<size_t>(i - 1)] += i * p[static_cast<size_t>(i)];  // P_j'
    for (int i = 0; i < 4; ++i) {
      const double c = p[static_cast<size_t>(i)];
      if (c == 0) continue;
      q[static_cast<size_t>(i)] += (1 + j * alpha) * c;
      if (i + 1 < 4) q[static_cast<size_t>(i + 1)] += -2 * j * gamma * c;
    }
  }
  return P;
}

/// max |P(u)| over [lo, hi] (lo may be −inf), from the Taylor coefficients at the middle, with
/// a rounding allowance.
double max_abs_poly(const std::array<double, 4>& a, double lo, double hi) {
  int degree = 3;
  while (degree > 0 && a[static_cast<size_t>(degree)] == 0) --degree;
  if (!std::isfinite(lo)) return degree == 0 ? std::abs(a[0]) : kInf;
  const double c = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
  std::array<double, 4> t = a;  // Taylor shift to c by repeated synthetic division
  for (int k = 0; k <= degree; ++k)
    for (int i = degree - 1; i >= k; --i) t[static_cast<size_t>(i)] += c * t[static_cast<size_t>(i + 1)];
  double bound = 0, scale = 0, rk = 1, mk = 1;
  const double m = std::max(std::abs(lo), std::abs(hi));
  for (int i = 0; i <= degree; ++i, rk *= r, mk *= m) {
    bound += std::abs(t[static_cast<size_t>(i)]) * rk;
    scale += std::abs(a[static_cast<size_t>(i)]) * mk;
  }
  return bound + 1e-12 * scale;
}

/// max of φ(u) = b u − c u² over [lo, hi] (lo may be −inf), with a rounding allowance.
double max_quadratic(double b, double c, double lo, double hi) {
  auto phi = [&](double u) {
    if (std::isfinite(u)) return b * u - c * u * u + 1e-12 * (std::abs(b * u) + std::abs(c * u * u));
    return c < 0 || (c == 0 && b < 0) ? kInf : (c == 0 && b == 0 ? 0.0 : -kInf);  // u → −∞
  };
  double v = std::max(phi(lo), phi(hi));
  if (c > 0) {
    const double vertex = b / (2 * c);
    if (vertex > lo && vertex < hi) v = std::max(v, phi(vertex));
  }
  return v;
}

}  // namespace

std::array<double, 5> detail::quadratic_derivative_bounds(const QuadraticLaCurve& c, double s0, double s1) {
  const auto P = derivative_polynomials(c.alpha(), c.gamma());
  auto log_kappa = [&](double s) {
    if (c.has_inflection() && s == c.s_at_zero_kappa()) return -kInf;
    return c.solve_log_kappa(s).log_kappa;
  };
  // u = log|κ| at the ends, widened by 1e-9 (1 + |u|) for the solver's rounding.
  double u0 = log_kappa(s0), u1 = log_kappa(s1);
  if (u0 > u1) std::swap(u0, u1);
  const double lo = u0 - 1e-9 * (1 + std::abs(u0)), hi = u1 + 1e-9 * (1 + std::abs(u1));
  std::array<double, 5> k{};
  k[0] = std::exp(hi);
  for (int j = 1; j < 5; ++j) {
    const double p = max_abs_poly(P[static_cast<size_t>(j)], lo, hi);
    k[static_cast<size_t>(j)] =
        p == 0 ? 0.0 : std::pow(c.lambda(), j) * p * std::exp(max_quadratic(1 + j * c.alpha(), j * c.gamma(), lo, hi));
  }
  return k;
}

namespace {

/// The arc [s0, s1] of the curve in the parameter w = s.
class QuadraticSource final : public detail::SpanSource {
 public:
  QuadraticSource(const QuadraticLaCurve& c, double s0, double s1)
      : c_(c), s0_(s0), s1_(s1) {}
  double w_begin() const override { return s0_; }
  double w_end() const override { return s1_; }
  std::vector<double> breaks() const override {
    const double si = c_.s_at_zero_kappa();
    if (c_.options().through_inflection && c_.has_inflection() && si > s0_ && si < s1_) return {si};
    return {};
  }
  double arc(double w) const override { return w - s0_; }
  double span_length(double w0, double w1) const override { return w1 - w0; }
  std::array<double, 5> derivative_bounds(double w0, double w1) const override {
    return detail::quadratic_derivative_bounds(c_, w0, w1);
  }
  double theta(double w) const override { return c_.theta_at_s(w); }
  double kappa(double w) const override { return c_.kappa_at_s(w); }
  /// Called with increasing w: each position integrates from the previous one (the first from
  /// s = 0, where the position is 0), by Gauss–Kronrod and by Gauss–Legendre in panels; the piece's error
  /// is the larger of the two estimates and their difference, and the errors add up. All positions
  /// together may spend kBudgetCalls times one position call's budget per method (status
  /// max_iterations past it).
  detail::SpanEndPosition position(double w) const override {
    if (!(w >= last_w_)) last_w_ = 0, last_ = {};
    if (w == last_w_) return last_;
    const GaussKronrod gk;
    // Gauss–Legendre in panels turning at most 0.05 rad each (|κ| is largest at an end of the piece:
    // monotone on each side of the inflection), so that the long first piece from s = 0 is resolved.
    const double turning = std::abs(w - last_w_) * std::max(std::abs(kappa(w)), std::abs(kappa(last_w_)));
    const GaussLegendre gl{.panels = static_cast<int>(std::clamp(std::ceil(turning / 0.05), 1.0, 1e5))};
    const long budget_gk = kBudgetCalls * position_budget(gk), budget_gl = kBudgetCalls * position_budget(gl);
    const auto a = detail::integrate_quadratic(c_, gk, last_w_, w, std::max(1L, budget_gk - spent_gk_));
    const auto b = detail::integrate_quadratic(c_, gl, last_w_, w, std::max(1L, budget_gl - spent_gl_));
    spent_gk_ += a.evaluations;
    spent_gl_ += b.evaluations;
    detail::SpanEndPosition e = last_;
    e.point += a.value;
    e.error += std::max({a.error_estimate, b.error_estimate, std::abs(a.value - b.value)});
    e.evaluations = a.evaluations + b.evaluations;
    for (const auto* x : {&a, &b})
      if (!usable(x->status)) e.status = x->status, e.message = x->message;
    if (e.status == Status::max_iterations)
      e.message = "the export's positions spent their budget (" + std::to_string(kBudgetCalls) +
                  " position calls per method): " + e.message;
    last_w_ = w;
    last_ = e;
    return e;
  }
  double theta_scale() const override {
    double t = std::max(std::abs(theta(s0_)), std::abs(theta(s1_)));
    if (!breaks().empty()) t = std::max(t, std::abs(c_.theta_at_zero_kappa()));
    return t;
  }

 private:
  const QuadraticLaCurve& c_;
  double s0_, s1_;
  static constexpr long kBudgetCalls = 4;
  mutable double last_w_ = 0;
  mutable long spent_gk_ = 0, spent_gl_ = 0;
  mutable detail::SpanEndPosition last_;
};

}  // namespace

ExportResult to_bspline(const QuadraticLaCurve& curve, double s0, double s1, const ExportOptions& options) {
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  if (!(s0 < s1)) throw_input_error(kWho, "s1", s1, "(s0, end of the domain]: the arc needs s0 < s1");
  detail::validate_export_options(options);
  const QuadraticSource source(curve, s0, s1);
  const double length = s1 - s0;
  // Position 0 at s = 0: every point of the arc is within max(|s0|, |s1|) of the origin.
  const double extent = std::max(std::abs(s0), std::abs(s1)) + length;
  const double kappa0 = curve.kappa_at_s(s0), kappa1 = curve.kappa_at_s(s1);
  return detail::certified_bspline({&source}, {0.0, length}, extent, options, [&](const BSpline& b, ExportInfo& info) {
    // κ decreases along the whole curve (also through the inflection): one monotone stretch.
    info.curvature_monotone = detail::curvature_monotone(b, {{length, kappa0, kappa1, 0.0}}, length, &info.monotone_segments,
                                                         &info.max_curvature_jump, &info.constant_curvature_segments);
  });
}

}  // namespace lac
