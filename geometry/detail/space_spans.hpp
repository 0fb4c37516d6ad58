#pragma once
// Spans of a SpaceCurve for the global searches of geometry/ (closest point, plane intersections):
// a piece [s0, s1] of arc length inside one of the curve's pieces, with the frame at its centre
// and κ_max, the largest curvature on it. κ is a closed form of each piece's law and decreases
// along a piece (dκ/ds = −λ e^(−(1+α) log ρ) < 0), so κ_max is the larger of the ends' values.
// With h = (s1 − s0)/2 and T(c) the unit tangent at the centre, the tangent turns by at most
// Δ = min(κ_max h, 2) from T(c) over the span (|T'| = κ), so
//   |p(c + t) − p(c) − t T(c)| ≤ |t| Δ.
// Positions are the curve's own frame_at (Frenet–Serret integrated from the start of the piece
// with the curve's ODE settings): a status, no error estimate.
#include <string>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/geometry/options.hpp"

namespace lac::detail {

struct SpaceSpan {
  size_t piece = 0;
  double s0 = 0, s1 = 0;
  Vec3 pc = Vec3::Zero(), tc = Vec3::UnitX();
  double kappa_max = 0;
  double half() const { return 0.5 * (s1 - s0); }
  double sc() const { return 0.5 * (s0 + s1); }
  /// Δ above: the most the tangent turns (as a chord of the unit sphere) from T(c) over the span.
  double turn() const;
};

/// frame_at of one piece, counted, with the first failed status kept.
class SpaceTracer {
 public:
  explicit SpaceTracer(const SpaceCurve& c) : c_(c) {}
  const SpaceCurve& curve() const { return c_; }
  /// The frame at s on `piece` (just inside its end at a joint: frame_at takes the later piece).
  SpacePoint at(size_t piece, double s);
  SpaceSpan make(size_t piece, double s0, double s1);
  bool failed() const { return !usable(status); }
  long evaluations = 0, spans = 0;
  Status status = Status::ok;
  std::string message;

 private:
  const SpaceCurve& c_;
};

/// The initial cover, in order of s: per piece, spans turning at most 0.5 rad (∫κ ≤ κ(start) ·
/// length) and at most 1/16 of the length. Empty with tracer status max_iterations (message
/// naming options.max_spans) when it needs more spans than that, or with the tracer's failed status.
std::vector<SpaceSpan> cover(SpaceTracer& tracer, const GeometryOptions& options);

}  // namespace lac::detail
