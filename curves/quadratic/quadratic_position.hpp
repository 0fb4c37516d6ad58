#pragma once
// Position on a quadratic LA curve by any quadrature method (template on QuadratureMethod),
// or run-time by name (AnyQuadrature from integrators/registry.hpp). s-form:
//   C(s) = ∫₀^s e^(iθ(t)) dt,  θ(t) from κ(t) (quadratic_curve.hpp),
// whose integrand has modulus 1 and stays smooth through the inflection (docs/math.md §1's reason
// for the s-form). The tangent is (cos θ, sin θ) of the returned point. A κ(s) status other
// than ok at a returned point (003's hybrid inverse outside its range) is merged into that
// point's status; inside the quadrature the integrand cannot report it.
#include <algorithm>
#include <complex>
#include <concepts>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lac/common/accuracy.hpp"
#include "lac/curves/detail/polyline.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/integrators/quadrature.hpp"
#include "lac/integrators/registry.hpp"

namespace lac {

namespace detail {
struct QuadraticSFormIntegrand {  // always inlined: see ThetaFormIntegrand (la_position.hpp)
  const QuadraticLaCurve* curve;
  [[gnu::always_inline]] std::complex<double> operator()(double s) const { return std::polar(1.0, curve->theta_at_s(s)); }
};

/// The same integrand with 003's hybrid inverse of κ: it also records the largest first-order θ
/// error of the κ(s) solutions at its nodes (QuadraticLaCurve::solution_error), which the
/// quadrature's estimate cannot see.
struct QuadraticSFormCheckedIntegrand {
  const QuadraticLaCurve* curve;
  double* max_theta_error;
  std::complex<double> operator()(double s) const {
    double e = 0;
    const double theta = curve->theta_at_s(s, e);
    *max_theta_error = std::max(*max_theta_error, e);
    return std::polar(1.0, theta);
  }
  /// |Δ e^(iθ)| ≤ |Δθ|: the value noise so far (NoisyIntegrand), so that adaptive rules do not
  /// refine on it.
  double noise() const { return *max_theta_error; }
};

/// A piece whose log κ changes by more than this is split (bisection in s) unless it turns less
/// than kNegligibleTurning: where κ falls by e^200 within a short arc θ(s) levels off like a kink,
/// which neither Gauss–Kronrod nor tanh-sinh resolves on the whole piece, and whose two estimates
/// can both miss their error.
inline constexpr double kMaxLogKappaPerPiece = 8.0;
inline constexpr double kNegligibleTurning = 1e-14;

/// ∫ e^(iθ) over [a, b] (s inside s_domain()) in pieces of at most kMaxTurningPerPiece rad of
/// |Δθ| and, unless they turn less than kNegligibleTurning, kMaxLogKappaPerPiece of |Δ log κ|
/// each (bisection in s, at most 60 levels; first at the inflection when [a, b] passes it, where θ
/// turns back), so that no quadrature call is given a piece whose oscillation or kink it cannot
/// resolve (near κ → ∞ the turning concentrates in a tiny arc). The estimate adds the rounding of
/// θ(s) over each piece and, with 003's hybrid inverse, |b − a| times twice the largest θ error of
/// the κ(s) solutions at the nodes.
/// `budget`: evaluations this call may spend; past it status max_iterations, naming the CLI option
/// that raises it.
template <QuadratureMethod M>
IntegralResult<std::complex<double>> integrate_quadratic(const QuadraticLaCurve& c, const M& m, double a, double b,
                                                         long budget) {
  IntegralResult<std::complex<double>> r;
  if (a == b) return r;
  const bool checked = c.options().inverse != special::ErfInverseMethod::ours;
  double max_theta_error = 0;
  const QuadraticSFormIntegrand f{&c};
  const QuadraticSFormCheckedIntegrand f_checked{&c, &max_theta_error};
  struct Node {
    double s, theta, log_kappa;  // log|κ| (−inf at the inflection itself)
  };
  auto node = [&](double s) { return Node{s, c.theta_at_s(s), c.solve_log_kappa(s).log_kappa}; };
  // |Δ e^(iθ)| ≤ |Δθ|: θ(s) is computed to a few ulps of |θ| from log κ(s), which is solved to a few
  // ulps of s, moving θ by κ·δs; no quadrature's estimate sees this noise (e.g. θ = 60 rad at
  // s = 330: 1e-12, above tanh-sinh's estimate).
  auto theta_rounding = [](const Node& lo, const Node& hi) {
    const double kappa = std::exp(std::max(lo.log_kappa, hi.log_kappa));  // κ is monotone along a piece
    const double reach = std::max(std::abs(lo.s), std::abs(hi.s));
    return 4 * std::numeric_limits<double>::epsilon() *
           (1 + std::max(std::abs(lo.theta), std::abs(hi.theta)) + (std::isfinite(kappa) ? kappa * reach : 0.0));
  };
  auto piece = [&](auto&& self, const Node& lo, const Node& hi, int depth) -> bool {
    if (r.evaluations >= budget) {
      r.status = Status::max_iterations;
      r.message = std::string(M::name) + ": evaluation budget " + std::to_string(budget) + " exhausted after " +
                  std::to_string(r.evaluations) + " evaluations at s = " + format_number(lo.s) + " of [" +
                  format_number(a) + ", " + format_number(b) + "] (pieces of at most " +
                  format_number(kMaxTurningPerPiece) + " rad); raise --max-evaluations (range [1, 1e10])";
      return false;
    }
    const double turning = std::abs(hi.theta - lo.theta);
    const double log_kappa_change = std::abs(hi.log_kappa - lo.log_kappa);  // NaN/inf at the inflection: no split
    const bool kink = std::isfinite(log_kappa_change) && log_kappa_change > kMaxLogKappaPerPiece && turning > kNegligibleTurning;
    if (depth < 60 && (turning > kMaxTurningPerPiece || kink)) {
      const double mid = 0.5 * (lo.s + hi.s);
      if (mid > std::min(lo.s, hi.s) && mid < std::max(lo.s, hi.s)) {
        const Node middle = node(mid);
        return self(self, lo, middle, depth + 1) && self(self, middle, hi, depth + 1);
      }
    }
    if (checked) add_part(r, m.integrate(f_checked, lo.s, hi.s));
    else add_part(r, m.integrate(f, lo.s, hi.s));
    r.error_estimate += theta_rounding(lo, hi) * std::abs(hi.s - lo.s);
    return true;
  };
  const double inflection = c.s_at_zero_kappa();
  const bool passes = c.options().through_inflection && c.has_inflection() && std::min(a, b) < inflection &&
                      std::max(a, b) > inflection;
  const Node node_a = node(a), node_b = node(b);
  // Every piece costs at least one evaluation: a turning that needs more pieces than the budget
  // allows fails at once (e.g. θ ~ 1e80 rad far out on the curve), not after spending it.
  const double turning = passes ? std::abs(node_a.theta - c.theta_at_zero_kappa()) + std::abs(c.theta_at_zero_kappa() - node_b.theta)
                                : std::abs(node_b.theta - node_a.theta);
  const double min_pieces = std::floor(turning / kMaxTurningPerPiece);
  if (!(min_pieces <= static_cast<double>(budget))) {
    r.status = Status::max_iterations;
    r.message = std::string(M::name) + ": the turning " + format_number(turning) + " rad over [" + format_number(a) + ", " +
                format_number(b) + "] needs at least " + format_number(min_pieces) + " pieces of at most " +
                format_number(kMaxTurningPerPiece) + " rad, more than the evaluation budget " + std::to_string(budget) +
                "; raise --max-evaluations (range [1, 1e10])";
    return r;
  }
  if (passes) {
    const Node node_i{inflection, c.theta_at_zero_kappa(), -std::numeric_limits<double>::infinity()};
    if (piece(piece, node_a, node_i, 0)) piece(piece, node_i, node_b, 0);
  } else {
    piece(piece, node_a, node_b, 0);
  }
  if (checked) r.error_estimate += 2.0 * std::abs(b - a) * max_theta_error;
  if (usable(r.status) && !(std::isfinite(r.error_estimate) && std::isfinite(std::abs(r.value)))) {
    r.status = Status::numerical_failure;
    r.message = "non-finite position or error estimate";
  }
  return r;
}

/// The frame's own error at a point (QuadraticLaCurve::solution_error; nonzero with 003's hybrid
/// inverse only): above accept (θ in rad, κ relative) the point is inaccurate, above the
/// quadrature's 1e-12 class an ok point is tolerance_not_met.
inline void grade_frame(PositionResult& r, const QuadraticLaCurve& c, const KappaSolution& k, double accept) {
  const QuadraticLaCurve::SolutionError e = c.solution_error(r.point.s, k);
  const double worst = std::max(e.theta, e.log_kappa);
  if (!usable(r.status) || !(worst > 1e-12)) return;
  const std::string what = "kappa(s) by 003's hybrid inverse misses theta by " + format_number(e.theta) +
                           " rad and kappa by " + format_number(e.log_kappa) + " relative (first order, its residual)";
  if (worst > accept) {
    r.status = Status::inaccurate;
    r.message = what + ", above accept " + format_number(accept);
  } else {
    merge_status(r, Status::tolerance_not_met, what);
  }
}
}  // namespace detail

/// Evaluation budget of one position call: the method's per-call budget (detail::evaluation_budget).
template <QuadratureMethod M>
long position_budget(const M& m) {
  if constexpr (std::same_as<M, Rk4>) return 2 * m.max_steps + 1;
  else return detail::evaluation_budget(m);
}

/// Position and frame at arc length s (inside s_domain(); InputError otherwise). `accept`
/// (relative, (0, 0.1]): a usable position whose error estimate exceeds accept × |s| (its arc
/// length from the reference point s = 0) gets Status::inaccurate. `max_evaluations` > 0 replaces
/// position_budget(method).
template <QuadratureMethod M>
PositionResult position_at(const QuadraticLaCurve& c, double s, const M& method, double accept = kDefaultAccept,
                           long max_evaluations = 0) {
  method.validate();
  validate_accept("quadratic position_at", accept);
  PositionResult r;
  KappaSolution k;
  r.point = c.frame_at(s, &k);
  r.form = Form::s;
  detail::merge_status(r, k.status, "kappa(s): " + std::string(to_string(k.status)));
  detail::take_integral(r, detail::integrate_quadratic(c, method, 0.0, s, max_evaluations > 0 ? max_evaluations : position_budget(method)));
  if (!usable(r.status)) r.error_estimate = std::numeric_limits<double>::infinity();
  detail::grade_position(r, accept);
  detail::grade_frame(r, c, k, accept);
  return r;
}

/// Evaluation budget of one polyline call of n points (its pieces are separate quadrature calls):
/// as for planar polylines (detail::piecewise_polyline_budget), so that n pieces cannot multiply
/// the method's per-call budget.
template <QuadratureMethod M>
long polyline_budget(const M& m, long n) {
  return detail::piecewise_polyline_budget(m, n);
}

/// n ≥ 2 points uniform in s from s0 to s1 (both inside s_domain()). Each position is integrated
/// from a point known to be right: the previous point (running integrals from the reference point
/// s = 0: first piece 0 → s0, then piece by piece), or, after a point that failed, the nearer of
/// s = 0 and the last good point (PositionResult says what a failed point holds). Once the pieces
/// have spent polyline_budget(method, n) evaluations (or `max_evaluations` when > 0), the
/// remaining points are not integrated and carry status max_iterations. A κ(s) status other than
/// ok flags its own point. `accept`: as for position_at, per point, relative to the arc length
/// its running integral covers from s = 0 (detail::path_scale).
template <QuadratureMethod M>
std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const M& method,
                                     double accept = kDefaultAccept, long max_evaluations = 0) {
  method.validate();
  validate_accept("quadratic polyline", accept);
  if (n < 2) throw_input_error("quadratic polyline", "points", n, "[2, inf)");
  c.check_s(s0, "s_from");
  c.check_s(s1, "s_to");
  std::vector<PositionResult> out(static_cast<size_t>(n));
  std::vector<KappaSolution> kappas(out.size());
  std::vector<double> ts(out.size());
  for (int k = 0; k < n; ++k) {
    const double s = k + 1 == n ? s1 : s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(n - 1);
    auto& r = out[static_cast<size_t>(k)];
    KappaSolution& ks = kappas[static_cast<size_t>(k)];
    r.point = c.frame_at(s, &ks);
    detail::merge_status(r, ks.status, "kappa(s) at s = " + format_number(s) + ": " + std::string(to_string(ks.status)));
    r.form = Form::s;
    ts[static_cast<size_t>(k)] = s;
  }
  const long budget = max_evaluations > 0 ? max_evaluations : polyline_budget(method, n);
  detail::AnchorState state;
  detail::anchored_samples(out, ts, state, budget, [&](double a, double b) {
    // A piece may spend half of what is left: one point that cannot be resolved (its turning too
    // large for the budget) leaves the other points their share.
    return detail::integrate_quadratic(c, method, a, b, std::max(1L, (budget - state.spent) / 2));
  });
  detail::grade_positions(out, accept);
  for (size_t k = 0; k < out.size(); ++k) detail::grade_frame(out[k], c, kappas[k], accept);
  return out;
}

/// Fast polyline (n ≥ 2 points uniform in s, s0..s1 inside the base domain, no inflection
/// continuation): marches outward from the grid point nearest s = 0. Per node log κ by one Halley
/// step on the closed form from a third-order Taylor predictor (solve_kappa_near), θ by the local
/// series of theta_difference from the previous node, the tangent by rotating the previous one;
/// each segment's ∫e^(iθ) by 4-point Gauss–Legendre over the quintic Hermite interpolant of θ
/// (θ, κ, dκ/ds at both ends). error_estimate: Σ h·max|θ_quintic − θ_cubic| along the march from
/// s = 0, a pessimistic bound. Segments turning more than 0.25 rad or changing log κ by more than
/// 0.05 are split (at most 1e4 pieces per grid step). InputError naming s_from / s_to where κ, ρ or
/// θ leaves the double range on the way (docs/quadratic.md).
/// `accept`: as for polyline.
std::vector<PositionResult> hermite_polyline(const QuadraticLaCurve& c, double s0, double s1, int n,
                                             double accept = kDefaultAccept);

/// Run-time choice of the quadrature method (make_quadrature by name). InputError naming
/// "integrator" for igf, a closed form of the planar LA curve in standard form only.
PositionResult position_at(const QuadraticLaCurve& c, double s, const AnyQuadrature& method,
                           double accept = kDefaultAccept, long max_evaluations = 0);
std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const AnyQuadrature& method,
                                     double accept = kDefaultAccept, long max_evaluations = 0);

static_assert(PlanarCurveModel<QuadraticLaCurve, GaussKronrod>);

}  // namespace lac
