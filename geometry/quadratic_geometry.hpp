#pragma once
// Geometry on a quadratic LA curve (QuadraticLaCurve, curves/quadratic/quadratic_curve.hpp; 003):
// the one-call evaluation with normal and dκ/ds, offsets and their first cusp. The curve is a
// standard form (no placement), so the transforms and the global searches of geometry/ (which
// work on the segments of a PlanarCurve) do not apply to it.
//
// dκ/ds is a closed form: κ · d log|κ|/ds, with d log|κ|/ds = −Λ e^(−E(u)) at u = log|κ| before the
// inflection and its negative past it (QuadraticLaCurve::dlog_kappa_ds); −inf at the inflection
// itself, where κ = 0 is reached with an infinite slope.
// The signed curvature decreases along the whole curve (κ = e^u with du/ds < 0, and past the
// inflection κ(s_i + t) = −κ(s_i − t)), so 1 − dκ is monotonic: its first zero or sign change on
// [s0, s1] — the offset's cusp — is found by TOMS 748 on κ(s), nothing sampled.
//
//   lac::QuadraticLaCurve c(-1.0, -0.3, 1.0);
//   auto e = lac::evaluate(c, 0.5);                       // e.position, e.normal, e.dkappa_ds
//   auto k = lac::first_offset_cusp(c, 0.5, -1.0, 1.0);   // k.s: where κ = 1/d
#include <cmath>
#include <complex>
#include <limits>

#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/geometry/evaluation.hpp"
#include "lac/geometry/offset.hpp"

namespace lac {

/// dκ/ds at s ∈ s_domain() (InputError "s" otherwise).
double dkappa_ds_at(const QuadraticLaCurve& curve, double s);

/// Position (integrated from s = 0 with `method`, as position_at), tangent, normal, θ, κ, dκ/ds.
template <QuadratureMethod M = GaussKronrod>
PlanarEvaluation evaluate(const QuadraticLaCurve& curve, double s, const M& method = M{}) {
  const PositionResult p = position_at(curve, s, method);
  PlanarEvaluation e;
  e.s = s;
  e.position = p.point.position;
  e.error_estimate = p.error_estimate;
  e.theta = p.point.theta;
  e.kappa = p.point.kappa;
  e.dkappa_ds = dkappa_ds_at(curve, s);
  e.tangent = std::polar(1.0, e.theta);
  e.normal = std::complex<double>(0, 1) * e.tangent;
  e.evaluations = p.evaluations;
  e.status = p.status;
  e.message = p.message;
  return e;
}

/// p(s) + d N(s), as offset_at of a PlanarCurve (d finite: InputError "d").
template <QuadratureMethod M = GaussKronrod>
OffsetPoint offset_at(const QuadraticLaCurve& curve, double s, double d, const M& method = M{}) {
  require_finite("offset_at", "d", d);
  const PlanarEvaluation e = evaluate(curve, s, method);
  OffsetPoint o;
  o.s = s;
  o.d = d;
  o.position = e.position + d * e.normal;
  o.error_estimate = usable(e.status) ? e.error_estimate : std::numeric_limits<double>::infinity();
  o.factor = 1.0 - d * e.kappa;
  o.tangent = o.factor < 0 ? -e.tangent : e.tangent;
  o.kappa = o.factor == 0 ? std::copysign(std::numeric_limits<double>::infinity(), e.kappa) : e.kappa / o.factor;
  o.evaluations = e.evaluations;
  o.status = e.status;
  o.message = e.message;
  return o;
}

/// The first s in [s0, s1] ⊂ s_domain() (s0 < s1; InputError "s0" / "s1") where 1 − dκ(s) is 0
/// or loses the sign it has at s0; d finite (InputError "d"). A κ(s) that cannot be solved (003's
/// hybrid inverse out of range) gives its status.
OffsetCusp first_offset_cusp(const QuadraticLaCurve& curve, double d, double s0, double s1);

}  // namespace lac
