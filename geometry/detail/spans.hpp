#pragma once
// Spans of a PlanarCurve for the global searches of geometry/: a piece [u0, u1] of one segment
// with its position at the centre (integrated from a known point) and closed-form bounds on how
// far the piece strays from its tangent line there. With h the span's arc length, c its centre,
// T(c) the unit tangent and Δ = max |θ(s) − θ(c)| over the span (θ is monotonic between
// inflections, so Δ is the largest difference at the span's ends and its inflection):
//   |p(c + t) − p(c) − t T(c)| = |∫_0^t (T(c + τ) − T(c)) dτ| ≤ |t| min(Δ, 2),
// so every point of the span lies in the capsule of radius (h/2) min(Δ, 2) + e around the tangent
// segment p(c) ± (h/2) T(c) (e: the centre's error estimate), and in the disc of radius h/2 + e
// around p(c) (arc length bounds the chord). Both are rigorous bounds used to discard spans.
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/planar/la_segment_angles.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac::detail {

/// A position known on segment `seg` at parameter u, with its error estimate.
struct Known {
  double u = 0;
  std::complex<double> p{};
  double err = 0;
};

struct Span {
  size_t seg = 0;
  double u0 = 0, u1 = 0, uc = 0;  ///< the segment's parameter at the ends and the centre
  double s0 = 0, s1 = 0;          ///< arc length along the curve at the ends
  std::complex<double> pc{};      ///< position at the centre
  double err = 0;                 ///< its error estimate
  std::complex<double> tc{1, 0};  ///< unit tangent at the centre
  double theta_c = 0;             ///< θ at the centre (the segment's angle, not the curve's turns)
  double dev = 0;                 ///< max |θ − θ(c)| over the span
  double kappa_c = 0;             ///< κ at the centre
  double dkappa = 0;              ///< max |κ − κ(c)| over the span (κ is monotonic on a segment)
  int depth = 0;

  double half() const { return 0.5 * (s1 - s0); }
  double sc() const { return 0.5 * (s0 + s1); }
  /// Radius of the capsule around p(c) ± half() T(c) that holds the span.
  double radius() const { return half() * (dev < 2 ? dev : 2.0) + err; }
  Known anchor() const { return {uc, pc, err}; }
  /// The tangent segment's ends.
  std::complex<double> a() const { return pc - half() * tc; }
  std::complex<double> b() const { return pc + half() * tc; }
};

/// Positions along one curve from known points, counting evaluations and remembering the first
/// failure (a failed position makes the search's result unusable, never NaN).
class SpanTracer {
 public:
  SpanTracer(const PlanarCurve& curve, const GaussLegendre& method) : curve_(curve), method_(method) {}

  const PlanarCurve& curve() const { return curve_; }
  long evaluations() const { return evaluations_; }
  long spans_made() const { return spans_made_; }
  Status status() const { return status_; }
  const std::string& message() const { return message_; }
  bool failed() const { return !usable(status_); }

  /// Position at u on segment k, integrated from `from` (same segment).
  Known trace(size_t k, const Known& from, double u);
  /// Arc length along the curve of u on segment k.
  double s_of(size_t k, double u) const;
  /// θ (segment angle + φ), unit tangent and κ at u of segment k (closed forms).
  double theta(size_t k, double u) const;
  std::complex<double> tangent(size_t k, double u) const;
  double kappa(size_t k, double u) const;
  /// The span [u0, u1] of segment k, its centre integrated from `from`.
  Span make(size_t k, double u0, double u1, const Known& from, int depth = 0);
  /// The two halves of a span.
  std::pair<Span, Span> split(const Span& span);
  /// Spans covering the whole curve, each turning at most `max_turn` and at most 1/min_count of
  /// the curve's length, their centres chained from each segment's start. Empty on failure, and
  /// with status max_iterations when more than `cap` spans would be needed.
  std::vector<Span> cover(double max_turn, int min_count, long cap);

 private:
  void fail(Status s, const std::string& m) {
    if (usable(status_)) status_ = s, message_ = m;
  }
  const PlanarCurve& curve_;
  GaussLegendre method_;
  long evaluations_ = 0;
  long spans_made_ = 0;
  Status status_ = Status::ok;
  std::string message_;
};

/// Distance from z to the segment [a, b].
double point_segment_distance(std::complex<double> z, std::complex<double> a, std::complex<double> b);
/// Distance between the segments [a0, a1] and [b0, b1] (0 when they cross).
double segment_segment_distance(std::complex<double> a0, std::complex<double> a1, std::complex<double> b0,
                                std::complex<double> b1);

}  // namespace lac::detail
