// to_bspline for an arc of a quadratic LA curve (003): the span machinery of to_bspline.cpp
// (export/detail/hermite_bound.hpp) with the curve's own bounds on the curvature's derivatives.
//
// The derivatives of κ in arc length: κ^(j) = (−Λ)^j P_j(u) e^(φ_j(u)), u = log κ
// (curves/quadratic/detail/kappa_derivatives.hpp); past the inflection |κ^(j)| is the same function of
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
#include "lac/curves/quadratic/detail/kappa_derivatives.hpp"
#include "lac/curves/quadratic/certified_position.hpp"
#include "lac/export/detail/hermite_bound.hpp"
#include "lac/export/to_bspline.hpp"

namespace lac {

namespace {

constexpr const char* kWho = "to_bspline";
constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

std::array<double, 5> detail::quadratic_derivative_bounds(const QuadraticLaCurve& c, double s0, double s1) {
  const auto P = detail::kappa_derivative_polynomials(c.alpha(), c.gamma(), 4);
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
    const double p = detail::max_abs_polynomial(P[static_cast<size_t>(j)], lo, hi);
    k[static_cast<size_t>(j)] =
        p == 0 ? 0.0 : std::pow(c.lambda(), j) * p * std::exp(detail::max_quadratic(1 + j * c.alpha(), j * c.gamma(), lo, hi));
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
  /// Called with increasing w: each position continues the proven integration
  /// (curves/quadratic/certified_position.hpp) from the previous one (the first from s = 0, where
  /// the position is 0), and the bounds add up.
  detail::SpanEndPosition position(double w) const override {
    if (!(w >= last_w_)) last_w_ = 0, last_ = {};
    if (w == last_w_) return last_;
    const CertifiedTangentIntegral a = integrate_quadratic_certified(c_, last_w_, w);
    detail::SpanEndPosition e = last_;
    e.point += a.value;
    e.error += a.error;
    e.evaluations = a.steps;
    if (a.status != Status::ok) e.status = a.status, e.message = a.message;
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
  mutable double last_w_ = 0;
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
