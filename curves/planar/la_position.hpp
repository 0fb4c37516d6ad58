#pragma once
// Position on a standard-form planar LA curve (docs/math.md §1; 002 Eqs. 7–8) with any
// quadrature method of integrators/quadrature.hpp, or with a closed form (igf) that
// satisfies LaClosedForm (integrators/quadrature.hpp); or chosen at run time (AnyQuadrature, integrators/registry.hpp).
//   θ-form: C(θ) = ∫₀^θ ρ(ψ) e^{iψ} dψ     s-form: C(s) = ∫₀^s e^{iθ(u)} du
#include <algorithm>
#include <cmath>
#include <complex>
#include <concepts>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "lac/common/accuracy.hpp"
#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/curves/detail/polyline.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/integrators/quadrature.hpp"
#include "lac/integrators/registry.hpp"

namespace lac {

/// The θ-form integrand is bounded where ρ ≤ 1 (θ ≤ 0) and grows without bound toward
/// ρ → ∞; the s-form integrand has modulus 1 everywhere but oscillates without bound
/// toward ρ → 0. `automatic` therefore uses the s-form on intervals that reach ρ > 1 when
/// α ≤ 1/2 (where ρ → ∞ at a finite θ: the inflection for α < 0), as 002 does for α ≤ 0.5,
/// and the θ-form otherwise (including Λ = 0, where both agree).
inline Form resolve_form(const LaCurve& c, double theta_a, double theta_b, Form requested) {
  if (requested != Form::automatic) return requested;
  if (c.lambda() > 0 && c.alpha() <= 0.5 && std::max(theta_a, theta_b) > 0) return Form::s;
  return Form::theta;
}

}  // namespace lac

#include "lac/curves/planar/detail/la_position_kernels.hpp"

namespace lac {

/// Position and frame at θ or s (t inside the domain; InputError otherwise). `accept` (relative,
/// (0, 0.1]): a usable position whose error estimate exceeds accept × its arc length from the
/// reference point s = 0 gets Status::inaccurate (detail::grade_position).
template <class M>
PositionResult position_at(const LaCurve& c, Parameter p, double t, const M& method, Form form = Form::automatic,
                           double accept = kDefaultAccept) {
  method.validate();
  validate_accept("position_at", accept);
  PositionResult r;
  r.point = c.frame_at(p, t);
  r.form = resolve_form(c, 0.0, r.point.theta, form);
  const double end = r.form == Form::s ? r.point.s : r.point.theta;
  detail::take_integral(r, detail::integrate_piece(c, method, r.form, 0.0, end));
  detail::grade_position(r, accept);
  return r;
}

/// n ≥ 2 points uniform in parameter p from t0 to t1 (both inside the domain). Each position is
/// integrated from a point known to be right: the previous point, so that positions are running
/// integrals from the reference point piece by piece (Rk4: one sweep over all pieces sharing end
/// values, detail::polyline_rk4), or, after a point that failed, the nearer of the reference point
/// and the last good point (PositionResult says what a failed point holds). The pieces share one
/// evaluation budget (detail::polyline_budget); the points past it carry status max_iterations.
/// `accept`: as for position_at, per point, relative to the arc length its running integral
/// covers from s = 0 (detail::path_scale: |s_first| + |s − s_first|).
template <class M>
std::vector<PositionResult> polyline(const LaCurve& c, Parameter p, double t0, double t1, int n, const M& method,
                                     Form form = Form::automatic, double accept = kDefaultAccept) {
  method.validate();
  validate_accept("polyline", accept);
  if (n < 2 || n > 1'000'000) throw_input_error("polyline", "points", n, "[2, 1000000]");
  // The domain is an interval: checking both ends covers every point clamped between them.
  const char* name = p == Parameter::theta ? "theta" : "s";
  c.check(p, t0, name);
  c.check(p, t1, name);
  const double t_min = std::min(t0, t1), t_max = std::max(t0, t1);
  std::vector<CurvePoint> frames(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double t = k + 1 == n ? t1 : t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(n - 1);
    (p == Parameter::theta ? frames[static_cast<size_t>(k)].theta : frames[static_cast<size_t>(k)].s) = std::clamp(t, t_min, t_max);
  }
  c.frames_inside(p, frames);
  std::vector<PositionResult> out;
  out.reserve(static_cast<size_t>(n));
  for (const CurvePoint& q : frames) out.emplace_back().point = q;
  const Form used = resolve_form(c, std::min({0.0, out.front().point.theta, out.back().point.theta}),
                                 std::max({0.0, out.front().point.theta, out.back().point.theta}), form);
  std::vector<double> ts(out.size());
  for (size_t k = 0; k < out.size(); ++k) ts[k] = used == Form::s ? out[k].point.s : out[k].point.theta;
  detail::AnchorState state;
  size_t first = 0;  // the points before it are done
  auto piece_method = method;
  long budget = detail::polyline_budget(method, n);
  if constexpr (std::same_as<M, Rk4>) {
    const bool frames_in_form = (used == Form::s) == (p == Parameter::s);
    first = used == Form::s
                ? detail::polyline_rk4(c, method, used, detail::SFormSweepIntegrand{&c}, frames_in_form, out)
                : detail::polyline_rk4(c, method, used, detail::ThetaFormSweepIntegrand{&c}, frames_in_form, out);
    if (first == out.size()) {
      detail::grade_positions(out, accept);
      return out;
    }
    // A running sum that is no longer finite: the remaining points piece by piece, from the last
    // good point, within what is left of the sweep's step budget.
    state.spent = first > 0 ? out[first - 1].evaluations : 0;
    if (first > 0) state.last_good = {ts[first - 1], out[first - 1].point.position, out[first - 1].error_estimate, Status::ok, {}};
    budget = 2 * method.max_steps + 1;
    piece_method.max_steps = std::max(1L, method.max_steps - state.spent / 2);
  }
  for (size_t k = first; k < out.size(); ++k) out[k].form = used;
  detail::anchored_samples(std::span(out).subspan(first), std::span<const double>(ts).subspan(first), state, budget,
                           [&](double a, double b) { return detail::integrate_piece(c, piece_method, used, a, b); });
  detail::grade_positions(out, accept);
  return out;
}

/// Run-time choice of the method (make_quadrature by name): one dispatch, then the templates above.
PositionResult position_at(const LaCurve& c, Parameter p, double t, const AnyQuadrature& method,
                           Form form = Form::automatic, double accept = kDefaultAccept);
std::vector<PositionResult> polyline(const LaCurve& c, Parameter p, double t0, double t1, int n,
                                     const AnyQuadrature& method, Form form = Form::automatic,
                                     double accept = kDefaultAccept);

/// The arc-length forms every curve model offers (PlanarCurveModel, curves/curve.hpp).
template <class M>
PositionResult position_at(const LaCurve& c, double s, const M& method) {
  return position_at(c, Parameter::s, s, method);
}
template <class M>
std::vector<PositionResult> polyline(const LaCurve& c, double s0, double s1, int n, const M& method) {
  return polyline(c, Parameter::s, s0, s1, n, method);
}

static_assert(PlanarCurveModel<LaCurve, GaussKronrod>);

}  // namespace lac
