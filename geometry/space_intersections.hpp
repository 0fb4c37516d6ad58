#pragma once
// All intersections of a SpaceCurve with a plane, ordered by arc length; each a crossing or a
// tangential touch. (Two space curves, or a space curve and a line, meet only in special
// positions: the plane is the query a CAD user sections a curve with.)
//
// Signed distance h(s) = n·(p(s) − P), h' = n·T. On a span (detail/space_spans.hpp: centre c,
// half-length r, tangent turning at most Δ from T(c)):
//   |h(c + t) − h(c) − t n·T(c)| ≤ |t| Δ,
// so a span with |h(c)| > r (|n·T(c)| + Δ) holds no root and is dropped, and one with
// |n·T(c)| > Δ has h strictly monotonic, so at most one root: a sign change of h at its ends is a
// crossing, polished by TOMS 748 on h. Other spans are halved, down to tolerance × length; such a
// leaf (the tangent direction within Δ of the plane) with a sign change is a crossing too, and
// one without but with |h| within the touch tolerance (tolerance × length) is a tangential touch
// at its smallest |h| (Brent). Tangent points (tangent within √tolerance rad of the plane) closer
// than 2√tolerance × length are one contact (near a touch the sign of h is rounding noise).
// Complete, like the planar searches: nothing is sampled (options.max_spans caps the spans).
// Positions are the curve's own frame_at, which carry a status but no error estimate: `residual`
// is |h| at the reported point, relative to those positions.
//
//   auto x = lac::intersect_plane(space_curve, lac::Vec3(0, 0, 0.1), lac::Vec3(0, 0, 1));  // x.points[i].s
#include <string>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/geometry/intersections.hpp"
#include "lac/geometry/options.hpp"

namespace lac {

struct SpaceIntersection {
  double s = 0;               ///< arc length on the curve
  Vec3 point = Vec3::Zero();  ///< frame_at(s).p
  double residual = 0;        ///< |n·(point − P)| (unit n)
  IntersectionKind kind = IntersectionKind::crossing;
};

struct SpaceIntersections {
  std::vector<SpaceIntersection> points;  ///< ascending in s; complete only when the status is usable
  long evaluations = 0;                   ///< frame_at calls
  long spans = 0;                         ///< spans created
  Status status = Status::ok;             ///< max_iterations at options.max_spans or max_points (points kept)
  std::string message;
};

/// The plane through `point` with normal `normal` (finite, nonzero: InputError naming them);
/// curve not empty (InputError "curve"); options validated (`method` is not used: positions are
/// the curve's). A crossing is s to about 4 ulp, a touch to about √(tolerance) × length (h is
/// quadratic there); one whose tangent lies within √tolerance rad of the plane is marked tangent.
SpaceIntersections intersect_plane(const SpaceCurve& curve, const Vec3& point, const Vec3& normal,
                                   const GeometryOptions& options = {});

}  // namespace lac
