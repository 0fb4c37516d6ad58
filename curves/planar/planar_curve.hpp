#pragma once
// A planar curve made of LA segments (la_segment.hpp) placed one after the other and joined G1 or
// G2, possibly with different α (compound curves, 001 §3; G2 triples and S-curves, 004): what the
// planar constructions return. Evaluated at any arc length s ∈ [0, length()]: tangent angle
// (continuous along the curve), signed curvature and dκ/ds in closed form; positions with a
// quadrature method (default GaussLegendre). Each segment carries its own start point, so a
// position never integrates across segments.
//
//   lac::PlanarCurve curve({seg0, seg1, seg2});
//   auto p = lac::position_at(curve, 0.3 * curve.length());   // p.point, p.error_estimate, p.status
//   auto pts = curve.sample(200);                              // uniform in s
//   auto box = curve.bounding_box();
#include <complex>
#include <string>
#include <vector>

#include "lac/curves/curve.hpp"
#include "lac/curves/planar/la_segment.hpp"
#include "lac/curves/planar/la_segment_igf.hpp"

namespace lac {

/// Where two segments meet, with the gaps of position, tangent angle and curvature (a check: a
/// construction's curve has them at its solver's accuracy).
struct Joint {
  double s = 0;              ///< arc length of the joint
  double position_gap = 0;   ///< |next start − previous end| (the end by the method)
  double angle_gap = 0;      ///< next θ − previous θ, in (−π, π]
  double curvature_gap = 0;  ///< next κ − previous κ
  double error_estimate = 0;  ///< of the previous end's position
  Status status = Status::ok;  ///< of the previous end's position
  std::string message;
};

/// The smallest axis-parallel box holding the curve: lo = (min x, min y), hi = (max x, max y).
/// Exact to the positions' accuracy: the extremes of x and y are at the segments' ends or where
/// θ ≡ 0 (mod π/2), found in closed form.
struct BoundingBox {
  std::complex<double> lo, hi;
  double error_estimate = 0;
  long evaluations = 0;
  Status status = Status::ok;  ///< the box is meaningful only when usable
  std::string message;
};

class PlanarCurve {
 public:
  /// An empty curve (length 0; every evaluation throws InputError).
  PlanarCurve() = default;
  /// At least one segment (InputError otherwise). The joints are not enforced: joints() reports them.
  explicit PlanarCurve(std::vector<LaSegment> segments);

  const std::vector<LaSegment>& segments() const { return segments_; }
  double length() const { return length_; }
  Interval s_domain() const { return {0.0, length_, true, true}; }
  /// Arc length at which segment k starts (k = segments().size(): the length).
  double segment_start(size_t k) const { return starts_.at(k); }
  /// The segment holding s (the later one at a joint) and s within it.
  size_t segment_at(double s) const;
  double local_s(size_t k, double s) const;

  /// Closed forms at s ∈ [0, length()]: θ continuous along the curve (a segment's θ plus a
  /// multiple of 2π), signed κ, dκ/ds. frame_at: s, θ, κ, ρ = 1/κ, position not computed (0).
  CurvePoint frame_at(double s) const;
  double theta_at(double s) const;
  double kappa_at(double s) const;
  double dkappa_ds_at(double s) const;

  /// n ≥ 2 points uniform in s over [0, length()] (polyline(*this, 0, length(), n, method)).
  template <QuadratureMethod M = GaussLegendre>
  std::vector<PositionResult> sample(int n, const M& method = M{}) const;
  /// The joints between consecutive segments.
  template <QuadratureMethod M = GaussLegendre>
  std::vector<Joint> joints(const M& method = M{}) const;
  template <QuadratureMethod M = GaussLegendre>
  BoundingBox bounding_box(const M& method = M{}) const;

  /// The same curve traversed from its end: the segments in reverse order, each reversed
  /// (LaSegment::reversed) from the next one's start, the last from `end_point` (the user position
  /// at s = length(), e.g. a construction's end point). Assumes the joints are G0.
  PlanarCurve reversed(std::complex<double> end_point) const;

  /// InputError naming `name` unless s ∈ [0, length()] (and the curve is not empty).
  void check_s(double s, const char* name) const;

  /// u values of segment k where its x or y can be extreme: its ends and where θ ≡ 0 (mod π/2),
  /// ascending (closed form: φ is monotonic between inflections and F is invertible there).
  /// InputError "segment" beyond 10^6 such points.
  std::vector<double> extreme_candidates(size_t k) const;

 private:
  std::vector<LaSegment> segments_;
  std::vector<double> starts_{0.0};
  std::vector<double> turns_;  // multiples of 2π added to each segment's θ
  double length_ = 0;
};

/// Position and frame at s ∈ [0, length()], integrated from the start of the segment holding s
/// (any quadrature method, or igf: la_segment_igf.hpp).
template <class M = GaussLegendre>
  requires QuadratureMethod<M> || std::same_as<M, Igf>
PositionResult position_at(const PlanarCurve& curve, double s, const M& method = M{});

/// n ≥ 2 points uniform in s from s0 to s1 (both in [0, length()]). Each position is integrated
/// from a point known to be right: the start of its segment or the previous point of the same
/// segment (after a point that failed, the nearer of the segment's start and the last good point).
/// The pieces share one evaluation budget; PositionResult says what a failed point holds.
template <QuadratureMethod M>
std::vector<PositionResult> polyline(const PlanarCurve& curve, double s0, double s1, int n, const M& method);

/// The same by igf (integrators/igf.hpp: the closed form of each segment's standard-form pieces,
/// la_segment_igf.hpp), each point from the start of its segment; `evaluations` cumulative.
std::vector<PositionResult> polyline(const PlanarCurve& curve, double s0, double s1, int n, const Igf& method);

}  // namespace lac

#include "lac/curves/planar/detail/planar_curve_templates.hpp"

namespace lac {
static_assert(PlanarCurveModel<PlanarCurve, GaussLegendre>);
static_assert(PlanarCurveModel<PlanarCurve, GaussKronrod>);
}  // namespace lac
