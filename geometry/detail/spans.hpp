#pragma once
// Spans for the global searches of geometry/, over a span source (the segments of a PlanarCurve,
// or an arc of a QuadraticLaCurve): a piece [u0, u1] of one segment or arc with its position at
// the centre (integrated from a known point) and closed-form bounds on how far the piece strays
// from its tangent line there. With h the span's arc length, c its centre,
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
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac::detail {

/// A position known on segment `seg` at parameter u, with its error estimate.
struct Known {
  double u = 0;
  std::complex<double> p{};
  double err = 0;
};

struct Span {
  size_t seg = 0;                 ///< the source's piece (segment)
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

/// A displacement ∫ e^{iθ} ds between two parameters of one piece, with its error estimate.
struct Step {
  std::complex<double> value{};
  double err = 0;
  long evaluations = 0;
  Status status = Status::ok;
  std::string message;
};

/// Span source of a PlanarCurve: its pieces are the segments, u the segment's parameter.
/// A span source gives, per piece k over [ua(k), ub(k)]: a known position (origin), displacements
/// between parameters (integrate), the arc length s_of(k, u), the closed forms θ, T, κ, and the
/// closed-form bounds: max |θ − θ(c)| over [u0, u1] (theta_dev), the turning of a whole piece
/// (variation) and κ at any u (κ monotonic on a piece, so its range over [u0, u1] is that of the ends).
class PlanarSource {
 public:
  PlanarSource(const PlanarCurve& curve, const GaussLegendre& method) : curve_(curve), method_(method) {}
  const PlanarCurve& curve() const { return curve_; }
  size_t pieces() const { return curve_.segments().size(); }
  double ua(size_t k) const { return curve_.segments()[k].ua(); }
  double ub(size_t k) const { return curve_.segments()[k].ub(); }
  double length() const { return curve_.length(); }
  double piece_length(size_t k) const { return curve_.segments()[k].length(); }
  double ds_du(size_t k) const { return curve_.segments()[k].scale(); }  ///< arc length per unit u
  Known origin(size_t k) const { return {ua(k), curve_.segments()[k].start(), 0.0}; }
  Step integrate(size_t k, double u0, double u1) const;
  double s_of(size_t k, double u) const;
  double theta(size_t k, double u) const;
  std::complex<double> tangent(size_t k, double u) const;
  double kappa(size_t k, double u) const;
  double theta_dev(size_t k, double u0, double u1, double uc) const;
  double variation(size_t k) const;
  /// The u values of piece k where θ ≡ beta (mod π), with its ends and inflection (la_segment_angles.hpp).
  std::vector<double> angle_cuts(size_t k, double beta, size_t cap, bool* capped) const;
  /// Where piece k's end is measured from (for messages).
  double piece_start(size_t k) const { return curve_.segment_start(k); }

 private:
  const PlanarCurve& curve_;
  GaussLegendre method_;
};

/// Span source of the arc [s0, s1] of a QuadraticLaCurve (003): one piece, u = s (the curve's arc
/// length), positions integrated from the standard form's origin (s = 0, position 0) by
/// detail::integrate_quadratic, halved until each estimate meets the tolerance. θ is monotonic on each side of the inflection (dθ/ds = κ keeps
/// its sign there) and the signed κ decreases along the whole curve (quadratic_geometry.hpp).
class QuadraticSource {
 public:
  /// `tolerance`: relative to s1 − s0, the target of the adaptive position integrals.
  QuadraticSource(const QuadraticLaCurve& curve, double s0, double s1, const GaussLegendre& method, double tolerance);
  const QuadraticLaCurve& curve() const { return curve_; }
  size_t pieces() const { return 1; }
  double ua(size_t) const { return s0_; }
  double ub(size_t) const { return s1_; }
  double length() const { return s1_ - s0_; }
  double piece_length(size_t) const { return s1_ - s0_; }
  double ds_du(size_t) const { return 1.0; }
  Known origin(size_t) const { return {0.0, {0.0, 0.0}, 0.0}; }
  Step integrate(size_t k, double u0, double u1) const;
  double s_of(size_t, double u) const { return u; }
  double theta(size_t, double u) const { return curve_.theta_at_s(u); }
  std::complex<double> tangent(size_t k, double u) const { return std::polar(1.0, theta(k, u)); }
  double kappa(size_t, double u) const { return curve_.kappa_at_s(u); }
  double theta_dev(size_t k, double u0, double u1, double uc) const;
  double variation(size_t k) const;
  /// The s values in [s0, s1] where θ ≡ beta (mod π), ascending, with s0, s1 and the inflection:
  /// on each monotonic piece of θ the targets beta + mπ it passes, each solved by TOMS 748 on
  /// θ(s). Empty (with *capped set) when a monotonic piece holds `cap` values or more.
  std::vector<double> angle_cuts(size_t k, double beta, size_t cap, bool* capped) const;
  double piece_start(size_t) const { return s0_; }

 private:
  bool inside(double u0, double u1) const;  // the inflection lies in (u0, u1)
  const QuadraticLaCurve& curve_;
  double s0_, s1_;
  GaussLegendre method_;
  double tolerance_;
};

/// Positions along one curve from known points, counting evaluations and remembering the first
/// failure (a failed position makes the search's result unusable, never NaN). The same branch
/// and bound runs on any span source.
template <class Source>
class SpanTracerT {
 public:
  template <class... Args>
  explicit SpanTracerT(const Args&... args) : src_(args...) {}

  const Source& source() const { return src_; }
  long evaluations() const { return evaluations_; }
  long spans_made() const { return spans_made_; }
  Status status() const { return status_; }
  const std::string& message() const { return message_; }
  bool failed() const { return !usable(status_); }

  /// Position at u on piece k, integrated from `from` (same piece).
  Known trace(size_t k, const Known& from, double u);
  /// Arc length along the curve of u on piece k.
  double s_of(size_t k, double u) const { return src_.s_of(k, u); }
  /// θ, unit tangent and κ at u of piece k (closed forms).
  double theta(size_t k, double u) const { return src_.theta(k, u); }
  std::complex<double> tangent(size_t k, double u) const { return src_.tangent(k, u); }
  double kappa(size_t k, double u) const { return src_.kappa(k, u); }
  /// The span [u0, u1] of piece k, its centre integrated from `from`.
  Span make(size_t k, double u0, double u1, const Known& from, int depth = 0);
  /// The two halves of a span.
  std::pair<Span, Span> split(const Span& span);
  /// Spans covering the whole curve, each turning at most `max_turn` and at most 1/min_count of
  /// the curve's length, their centres chained from each piece's origin. Empty on failure, and
  /// with status max_iterations when more than `cap` spans would be needed.
  std::vector<Span> cover(double max_turn, int min_count, long cap);

 private:
  void fail(Status s, const std::string& m) {
    if (usable(status_)) status_ = s, message_ = m;
  }
  Source src_;
  long evaluations_ = 0;
  long spans_made_ = 0;
  Status status_ = Status::ok;
  std::string message_;
};

using SpanTracer = SpanTracerT<PlanarSource>;
using QuadraticSpanTracer = SpanTracerT<QuadraticSource>;
extern template class SpanTracerT<PlanarSource>;
extern template class SpanTracerT<QuadraticSource>;

/// Distance from z to the segment [a, b].
double point_segment_distance(std::complex<double> z, std::complex<double> a, std::complex<double> b);
/// Distance between the segments [a0, a1] and [b0, b1] (0 when they cross).
double segment_segment_distance(std::complex<double> a0, std::complex<double> a1, std::complex<double> b0,
                                std::complex<double> b1);

}  // namespace lac::detail
