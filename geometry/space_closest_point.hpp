#pragma once
// The point of a SpaceCurve (curves/space/space_curve.hpp) closest to a query point, global over
// the whole curve: the branch and bound of closest_point.hpp on spans of arc length. κ is a closed
// form of each piece's law and decreases along a piece (dκ/ds = −λ e^(−(1+α) log ρ) < 0), so
// κ_max over a span [a, b] of one piece is κ(a). With h the span's length, c its centre and T(c)
// its unit tangent, the tangent turns by at most Δ = κ_max h/2 from T(c) (|T'| = κ), so
//   |p(c + t) − p(c) − t T(c)| ≤ |t| min(Δ, 2):
// the span lies in the capsule of radius (h/2) min(Δ, 2) around p(c) ± (h/2) T(c) and in the ball
// of radius h/2 around p(c); the larger distance bound discards spans. With g(s) = (p − q)·T,
// g' = 1 + κ (p − q)·N ≥ 1 − κ_max (|p(c) − q| + h/2): where that is positive the distance is
// convex on the span and its minimum is at an end or at the root of g (TOMS 748).
// Positions are the curve's own frame_at (Frenet–Serret integrated from the start of the piece
// with the curve's ODE settings), which carry a status but no error estimate: error_estimate
// bounds the search's gap only, relative to those positions.
//
//   auto c = lac::closest_point(space_curve, lac::Vec3(0.3, 0.2, 0.1));  // c.s, c.point, c.distance
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/geometry/options.hpp"

namespace lac {

struct SpaceClosestPoint {
  double s = 0;                  ///< arc length of the closest point
  Vec3 point = Vec3::Zero();     ///< its position (frame_at(s).p)
  double distance = 0;           ///< |point − query|
  /// Bound on |distance − global minimum| from the search (the positions' own integration error
  /// excluded: frame_at gives none).
  double error_estimate = 0;
  double error = 0;              ///< error_estimate / length
  long evaluations = 0;          ///< frame_at calls
  long spans = 0;                ///< spans created
  Status status = Status::ok;    ///< max_iterations when options.max_spans was reached (not usable)
  std::string message;
};

/// query finite (InputError "query"); curve not empty (InputError "curve"); options validated
/// (`method` is not used: positions are the curve's).
SpaceClosestPoint closest_point(const SpaceCurve& curve, const Vec3& query, const GeometryOptions& options = {});

}  // namespace lac
