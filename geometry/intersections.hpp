#pragma once
// All intersections of a PlanarCurve or an arc of a quadratic LA curve with a line and with another
// such curve, ordered by arc length along the (first) curve; each a crossing or a tangential touch.
//
// Line (point P, unit direction D): the signed distance h(s) = D × (p(s) − P) has h' = sin(θ − arg D),
// so h is strictly monotonic between the arc lengths where θ ≡ arg D (mod π). Those are found in
// closed form on each segment (φ is monotonic between inflections and F⁻¹ is explicit, as for the
// bounding box), the positions there integrated one after the other from the segment's start.
// Each monotonic piece holds at most one root: a sign change of h gives a crossing, polished by
// TOMS 748 on h with positions integrated from the piece's start. Where θ ≡ arg D and
// |h| ≤ tolerance·length + the position's error estimate the curve touches the line: a tangent
// intersection (and the pieces beside it are not searched again for the same point). Complete:
// nothing is sampled, so no crossing is missed however many there are (options.max_spans caps
// the number of monotonic pieces).
//
// Two curves: branch and bound on pairs of spans (detail/spans.hpp). A pair whose capsules are
// farther apart than the sum of their radii cannot meet and is dropped. A pair whose tangent
// directions lie in disjoint cones (mod π; each span turning less than 0.5 rad) meets at most once
// (a chord between two common points would be a mean tangent of both): Newton's method on
// p_a(s) − p_b(t) = 0 from the crossing of the two tangent segments, kept in the pair's box, finds
// it; where it does not converge the pair is halved further. Other pairs are halved (the longer span) down to
// spans of 1e-4 of the length; the near-parallel pairs left are grouped, and on each group the
// signed distance of a from b (through the foot point on b) is sampled (16 points per pair, 33 to 4097):
// a sign change is a crossing (TOMS 748), a minimum of |distance| within the touch tolerance without
// a sign change (Brent) is a tangential touch. A group of a curve running along the other (e.g. overlapping
// pieces) is reported as not_converged after options.max_spans spans in all.
// An intersection found there whose tangents differ by less than √tolerance (rad) is marked tangent.
//
//   auto r = lac::intersect_line(curve, {0, 0}, {1, 0});   // r.points[i].s, .point, .kind
//   auto x = lac::intersect_curves(a, b);                  // x.points[i].s (on a), .t (on b)
#include <complex>
#include <string>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/geometry/options.hpp"

namespace lac {

enum class IntersectionKind { crossing, tangent };

struct Intersection {
  double s = 0;  ///< arc length on the curve (the first curve)
  /// On a line: the coordinate along the unit direction from its point (point = P + t D); on a
  /// second curve: the arc length on it.
  double t = 0;
  std::complex<double> point{};
  double error_estimate = 0;  ///< absolute, of the position (and of the residual)
  IntersectionKind kind = IntersectionKind::crossing;
};

struct Intersections {
  std::vector<Intersection> points;  ///< ascending in s; complete only when the status is usable
  double error_estimate = 0;         ///< the largest of the points'
  double error = 0;                  ///< error_estimate / length, graded against tolerance and accept
  long evaluations = 0;
  long spans = 0;  ///< monotonic pieces (line) or spans (two curves) created
  Status status = Status::ok;
  std::string message;
};

/// The line through `point` along `direction` (finite, nonzero: InputError naming them).
Intersections intersect_line(const PlanarCurve& curve, std::complex<double> point, std::complex<double> direction,
                             const GeometryOptions& options = {});
/// The line's intersections with the arc [s0, s1] of a quadratic LA curve (003), by the same
/// search: θ is monotonic on each side of the inflection, so the arc lengths where θ ≡ arg D
/// (mod π) are TOMS 748 roots of the closed form θ(s); positions from s = 0. s0 < s1 inside
/// s_domain() (InputError "s0" / "s1"); tolerance relative to s1 − s0; `s` is the curve's arc length.
Intersections intersect_line(const QuadraticLaCurve& curve, double s0, double s1, std::complex<double> point,
                             std::complex<double> direction, const GeometryOptions& options = {});
/// Every common point of a and b.
Intersections intersect_curves(const PlanarCurve& a, const PlanarCurve& b, const GeometryOptions& options = {});
/// Every common point of the arc [s0, s1] of a quadratic LA curve a and the PlanarCurve b, by the
/// same search (s on a: the curve's arc length; t on b). Tolerance relative to max(s1 − s0, length of b).
Intersections intersect_curves(const QuadraticLaCurve& a, double s0, double s1, const PlanarCurve& b,
                               const GeometryOptions& options = {});
/// Every common point of the arcs [a0, a1] of a and [b0, b1] of b, two quadratic LA curves, by the
/// same search (s on a, t on b: each curve's arc length). InputError naming a0, a1, b0 or b1 for an
/// arc outside its curve's s_domain() or empty. Tolerance relative to max(a1 − a0, b1 − b0).
Intersections intersect_curves(const QuadraticLaCurve& a, double a0, double a1, const QuadraticLaCurve& b, double b0,
                               double b1, const GeometryOptions& options = {});

constexpr std::string_view to_string(IntersectionKind k) { return k == IntersectionKind::crossing ? "crossing" : "tangent"; }

}  // namespace lac
