#pragma once
// Positions on a planar LA segment with a proven error bound: the Taylor-series frame integrator
// of curves/detail/taylor_frame.hpp with τ = 0, in the segment's normalized parameter u.
//
// Coefficients: with k(u) = K(q(u)) (la_law.hpp), g = k'/k = q'·d log|K|/dq is a power of |k|
// (plain form: −q'/(αq); Box–Cox form: q'/(1 − αq); α = 0: q'), so
//   k^(i) = k g^i ∏_{l<i}(1 + lα)          (the planar case of 000 Eq. (3): κ' = −Λκ^{1+α}),
// a power of |t| (la_law.hpp's t, linear in u) times constants: on a step where t keeps its sign
// |k^(i)| is largest at an end of the step.
// Inflection (α < 0, t = 0 at u_i): k is not analytic there unless −1/α is an integer, so a zone
// |u − u_i| ≤ d with d·max|k| ≤ ε/16 is crossed in one step along the tangent at its start: its
// error is at most (length)²·max|k| (the turning over the zone times its length).
#include <complex>
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/detail/taylor_frame.hpp"
#include "lac/curves/planar/la_segment.hpp"

namespace lac {

/// ∫_{u0}^{u1} e^{iφ(u)} du for ua ≤ u0 ≤ u1 ≤ ub (InputError otherwise). Status max_iterations
/// (no bound) when the integrator's step or step-count cap is reached.
CertifiedTangentIntegral integrate_tangent_certified(const LaSegment& seg, double u0, double u1);

struct CertifiedPoint {
  std::complex<double> position;  ///< user plane
  double error = 0;               ///< proven bound on |position − exact| (user units)
  long steps = 0;
  Status status = Status::ok;
  std::string message;
};

/// The user position at arc length s ∈ [0, length()], integrated from the segment's start.
CertifiedPoint position_certified(const LaSegment& seg, double s);
/// The user position at u1 from a known one at u0 ≤ u1 (`p0` with bound `p0_error`).
CertifiedPoint position_certified(const LaSegment& seg, double u0, std::complex<double> p0, double p0_error,
                                  double u1);

}  // namespace lac
