#pragma once
// Position on a quadratic LA curve by any quadrature method (template on QuadratureMethod),
// or run-time by name (AnyQuadrature from integrators/registry.hpp). s-form:
//   C(s) = ∫₀^s e^(iθ(t)) dt,  θ(t) from κ(t) (quadratic_curve.hpp),
// whose integrand has modulus 1 and stays smooth through the inflection (docs/math.md §1's reason
// for the s-form). The tangent is (cos θ, sin θ) of the returned point. A κ(s) status other
// than ok at a returned point (003's hybrid inverse outside its range) is merged into that
// point's status; inside the quadrature the integrand cannot report it.
#include <complex>
#include <concepts>
#include <string>
#include <vector>

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
}  // namespace detail

/// Position and frame at arc length s (inside s_domain(); InputError otherwise).
template <QuadratureMethod M>
PositionResult position_at(const QuadraticLaCurve& c, double s, const M& method) {
  method.validate();
  PositionResult r;
  KappaSolution k;
  r.point = c.frame_at(s, &k);
  r.form = Form::s;
  detail::merge_status(r, k.status, "kappa(s): " + std::string(to_string(k.status)));
  detail::take_integral(r, method.integrate(detail::QuadraticSFormIntegrand{&c}, 0.0, s));
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
/// have spent polyline_budget(method, n) evaluations, the remaining points are not integrated and
/// carry status max_iterations. A κ(s) status other than ok flags its own point.
template <QuadratureMethod M>
std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const M& method) {
  method.validate();
  if (n < 2) throw_input_error("quadratic polyline", "points", n, "[2, inf)");
  c.check_s(s0, "s_from");
  c.check_s(s1, "s_to");
  std::vector<PositionResult> out(static_cast<size_t>(n));
  std::vector<double> ts(out.size());
  for (int k = 0; k < n; ++k) {
    const double s = k + 1 == n ? s1 : s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(n - 1);
    auto& r = out[static_cast<size_t>(k)];
    KappaSolution ks;
    r.point = c.frame_at(s, &ks);
    detail::merge_status(r, ks.status, "kappa(s) at s = " + format_number(s) + ": " + std::string(to_string(ks.status)));
    r.form = Form::s;
    ts[static_cast<size_t>(k)] = s;
  }
  const detail::QuadraticSFormIntegrand f{&c};
  detail::AnchorState state;
  detail::anchored_samples(out, ts, state, polyline_budget(method, n),
                           [&](double a, double b) { return method.integrate(f, a, b); });
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
std::vector<PositionResult> hermite_polyline(const QuadraticLaCurve& c, double s0, double s1, int n);

/// Run-time choice of the quadrature method (make_quadrature by name). InputError naming
/// "integrator" for igf, a closed form of the planar LA curve in standard form only.
PositionResult position_at(const QuadraticLaCurve& c, double s, const AnyQuadrature& method);
std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const AnyQuadrature& method);

static_assert(PlanarCurveModel<QuadraticLaCurve, GaussKronrod>);

}  // namespace lac
