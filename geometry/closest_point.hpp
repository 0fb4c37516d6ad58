#pragma once
// The point of a PlanarCurve closest to a query point, global over the whole curve.
//
// Method: branch and bound on spans (detail/spans.hpp). The curve is covered by spans turning at
// most 0.5 rad, each with its centre position; a span cannot come closer to q than
//   max(|q − p(c)| − h/2, dist(q, tangent segment) − capsule radius) − e,
// a rigorous lower bound. Spans are taken in order of that bound; one whose bound exceeds the
// best distance found so far (minus the tolerance) is discarded, the others are halved (the halves'
// centres integrated from the parent's centre), until the distance function is provably convex on
// a span: with g(s) = (p(s) − q)·T(s), g'(s) = 1 + κ(s)(p(s) − q)·N(s) > 0 over the span
// (bounded from the centre's values and the span's closed-form ranges of θ and κ). On such a
// span the minimum is at an end or at the one root of g, polished by TOMS 748 on g with positions
// integrated from the span's centre. Spans shorter than the tolerance are polished the same way
// without the proof (the distance varies by less than the tolerance over them). The search ends
// when the smallest bound left is within the tolerance of the best distance: the distance is then
// the global minimum to the tolerance plus the position error estimates — whatever the number of
// local minima (spirals turning many times, query points on the evolute).
//
// The same search runs on an arc [s0, s1] of a quadratic LA curve (003): its spans are pieces of
// the arc, θ and κ closed forms of the curve (κ(s) by inversion), θ monotonic on each side of
// the inflection and the signed κ decreasing along the whole curve, so the ranges of θ and κ over
// a span are those at its ends (and at the inflection); positions ∫ e^{iθ} ds from s = 0.
//
//   auto c = lac::closest_point(curve, {0.3, 0.2});  // c.s, c.point, c.distance, c.status
//   auto d = lac::closest_point(quadratic, -1.0, 2.0, {0.3, 0.2});  // d.s in [-1, 2]
#include <complex>
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/geometry/options.hpp"

namespace lac {

struct ClosestPoint {
  double s = 0;                  ///< arc length of the closest point (the curve's own s for a quadratic arc)
  std::complex<double> point{};  ///< its position
  double distance = 0;           ///< |point − query|
  /// Absolute bound on the error of `distance` as the global minimum (the positions' error
  /// estimates plus the gap between it and the smallest lower bound left by the search).
  double error_estimate = 0;
  double error = 0;  ///< error_estimate / length (s1 − s0 for a quadratic arc) (graded against tolerance and accept)
  long evaluations = 0;  ///< integrand evaluations
  long spans = 0;        ///< spans created
  Status status = Status::ok;  ///< max_iterations when options.max_spans was reached (not usable)
  std::string message;
};

/// query finite (InputError "query"); options validated (InputError naming the option).
ClosestPoint closest_point(const PlanarCurve& curve, std::complex<double> query, const GeometryOptions& options = {});

/// The point of the arc [s0, s1] of a quadratic LA curve closest to query, global over the arc,
/// with the guarantees above (tolerance and accept relative to s1 − s0). s0 < s1 inside
/// s_domain() (InputError "s0" / "s1"), query finite (InputError "query"). The turning of the arc
/// sets the number of spans: near κ → ∞ it may exceed max_spans (status max_iterations).
ClosestPoint closest_point(const QuadraticLaCurve& curve, double s0, double s1, std::complex<double> query,
                           const GeometryOptions& options = {});

}  // namespace lac
