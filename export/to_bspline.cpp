#include "lac/export/to_bspline.hpp"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/export/write.hpp"

namespace lac {

namespace {

constexpr const char* kWho = "to_bspline";

// Peano-kernel constants of the cubic Hermite interpolant on [0, 1] (max over t of ∫|K_m(t, τ)| dτ
// for the error written with the m-th derivative): 1/384 (m = 4, the classical one), 1/96 (m = 3,
// at t = 1/2) and 0.0624987... < 1/16 (m = 2); computed in tests/reference/export_kernels.py.
constexpr double kC4 = 1.0 / 384.0, kC3 = 1.0 / 96.0, kC2 = 1.0 / 16.0;
// Relative slack on the derivative bounds for the rounding of q, κ and the powers at the span ends.
constexpr double kSlack = 1e-9;

/// |K'(q)| and |K''(q)| (la_law.hpp): powers of |t|, t the plain q (or σ(1 − αq)), e^q for α = 0;
/// each monotone in |t| on a side of t = 0; +inf where a negative power meets t = 0.
double abs_dK(const LaLaw& law, double q, int order) {
  if (law.alpha == 0) return std::exp(q);
  const double b = -1.0 / law.alpha;
  double coeff, t;
  if (law.offset) {  // dt/dq = −σα: |K'| = |t|^(b−1), |K''| = |1 + α| |t|^(b−2)
    t = std::abs(1.0 - law.alpha * q);
    coeff = order == 1 ? 1.0 : std::abs(1.0 + law.alpha);
  } else {
    t = std::abs(q);
    coeff = order == 1 ? std::abs(b) : std::abs(b * (b - 1.0));
  }
  if (coeff == 0) return 0.0;
  return coeff * std::pow(t, b - order);
}

struct SpanBound {
  double value = 0;  // the interpolation bound
  int order = 4;     // the derivative it uses (its rate in h)
};

/// The interpolation bound of the Hermite cubic on the part [u0, u1] of `seg` (no inflection inside).
SpanBound span_bound(const LaSegment& seg, double u0, double u1) {
  const LaLaw& law = seg.law();
  const double l = seg.scale(), m = std::abs(seg.normalized().slope());
  const double q0 = seg.q_at(u0), q1 = seg.q_at(u1);
  const double h = l * (u1 - u0);
  const double up = 1.0 + kSlack;
  const double k0 = up * std::max(std::abs(law.kappa_of_q(q0)), std::abs(law.kappa_of_q(q1))) / l;
  const double k1 = up * std::max(abs_dK(law, q0, 1), abs_dK(law, q1, 1)) * m / (l * l);
  const double k2 = up * std::max(abs_dK(law, q0, 2), abs_dK(law, q1, 2)) * m * m / (l * l * l);
  const double h2 = h * h;
  SpanBound best{kC2 * h2 * k0, 2};
  const double b3 = kC3 * h2 * h * (k1 + k0 * k0);
  if (b3 < best.value) best = {b3, 3};
  const double b4 = kC4 * h2 * h2 * (k2 + 3 * k0 * k1 + k0 * k0 * k0);
  if (b4 < best.value) best = {b4, 4};
  if (!(best.value >= 0)) best = {HUGE_VAL, 2};
  return best;
}

/// Splits [u0, u1] until every span's bound is at most `target`, appending the span ends after u0
/// to `ends` (in order). False when the cap on spans is reached.
bool split(const LaSegment& seg, double u0, double u1, double target, long cap, long& count,
           std::vector<double>& ends, double& worst) {
  const SpanBound b = span_bound(seg, u0, u1);
  if (b.value <= target || !(u1 - u0 > 4 * DBL_EPSILON * std::max(std::abs(u0), std::abs(u1)))) {
    if (++count > cap) return false;
    ends.push_back(u1);
    worst = std::max(worst, b.value);
    return true;
  }
  // Into n equal parts with n from the rate h^order (at least 2, at most 64 per level).
  const double ratio = b.value / target;
  const double n_real = std::isfinite(ratio) ? std::ceil(std::pow(ratio, 1.0 / b.order) * 1.01) : 2.0;
  const int n = static_cast<int>(std::clamp(n_real, 2.0, 64.0));
  double a = u0;
  for (int i = 1; i <= n; ++i) {
    const double c = i == n ? u1 : u0 + (u1 - u0) * i / n;
    if (!split(seg, a, c, target, cap, count, ends, worst)) return false;
    a = c;
  }
  return true;
}

/// Signed curvature of the cubic Bézier b0..b3 at t ∈ [0, 1].
double bezier_curvature(const std::complex<double>* b, double t) {
  const std::complex<double> d0 = b[1] - b[0], d1 = b[2] - b[1], d2 = b[3] - b[2];
  const double s = 1 - t;
  const std::complex<double> v = 3.0 * (s * s * d0 + 2 * s * t * d1 + t * t * d2);
  const std::complex<double> a = 6.0 * (s * (d1 - d0) + t * (d2 - d1));
  const double cross = v.real() * a.imag() - v.imag() * a.real();
  const double speed = std::abs(v);
  return cross / (speed * speed * speed);
}

}  // namespace

bool curvature_monotone(const BSpline& b, const PlanarCurve& curve, long* monotone_segments, double* max_jump) {
  const auto pieces = bezier_pieces(b);
  std::vector<double> knots;
  std::vector<int> mult;
  b.distinct_knots(knots, mult);  // piece j spans [knots[j], knots[j + 1]]
  double jump = 0;
  long good = 0;
  size_t j = 0;
  double previous_end_kappa = NAN;
  for (size_t k = 0; k < curve.segments().size(); ++k) {
    const LaSegment& seg = curve.segments()[k];
    const double dir = seg.kappa_end() > seg.kappa_start() ? 1.0 : seg.kappa_end() < seg.kappa_start() ? -1.0 : 0.0;
    const double end = curve.segment_start(k + 1);
    std::vector<double> values;
    double scale = std::max(std::abs(seg.kappa_start()), std::abs(seg.kappa_end()));
    for (; j < pieces.size() && j + 1 < knots.size() && knots[j + 1] <= end; ++j) {
      const std::complex<double>* p = pieces[j].data();
      const double first = bezier_curvature(p, 0.0);
      if (std::isfinite(previous_end_kappa)) jump = std::max(jump, std::abs(first - previous_end_kappa));
      for (int i = 0; i <= 32; ++i) values.push_back(bezier_curvature(p, i / 32.0));
      previous_end_kappa = values.back();
    }
    for (double v : values) scale = std::max(scale, std::abs(v));
    const double slack = 1e-9 * scale;
    bool up = true, down = true;
    for (size_t i = 1; i < values.size(); ++i) {
      if (values[i] < values[i - 1] - slack) up = false;
      if (values[i] > values[i - 1] + slack) down = false;
    }
    if (!values.empty() && ((dir > 0 && up) || (dir < 0 && down) || (dir == 0 && (up || down)))) ++good;
  }
  if (monotone_segments) *monotone_segments = good;
  if (max_jump) *max_jump = jump;
  return good == static_cast<long>(curve.segments().size());
}

ExportResult to_bspline(const PlanarCurve& curve, const ExportOptions& options) {
  const auto t_start = std::chrono::steady_clock::now();
  if (curve.segments().empty()) throw_input_error(kWho, "curve", "an empty curve has nothing to export");
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    throw_input_error(kWho, "tolerance", options.tolerance, "[0, inf) (0: 1e-6 x length)");
  if (options.max_spans < 1) throw_input_error(kWho, "max_spans", static_cast<double>(options.max_spans), "[1, inf)");
  ExportResult r;
  const double length = curve.length();
  const double tol = options.tolerance > 0 ? options.tolerance : kDefaultExportTolerance * length;
  r.info.tolerance = tol;
  r.summary.accept = tol / length;
  // 9/10 of the tolerance for the interpolation, the rest for positions and rounding; no finer
  // than the rounding of the coordinates (a tolerance below it ends inaccurate without a flood of spans).
  double extent = length;
  for (const LaSegment& seg : curve.segments()) extent = std::max(extent, std::abs(seg.start()) + length);
  const double target = std::max(0.9 * tol, 64 * DBL_EPSILON * extent);

  BSpline& b = r.curve;
  b.degree = 3;
  b.knots = {0, 0, 0, 0};
  long count = 0;
  double interpolation = 0, positions = 0, deviation = 0;
  std::complex<double> p_end{};
  const auto& segs = curve.segments();
  for (size_t k = 0; k < segs.size(); ++k) {
    const LaSegment& seg = segs[k];
    std::vector<double> ends;
    const auto infl = seg.inflection_u();
    bool within_cap = true;
    if (infl && *infl > seg.ua() && *infl < seg.ub()) {
      within_cap = split(seg, seg.ua(), *infl, target, options.max_spans, count, ends, interpolation) &&
                   split(seg, *infl, seg.ub(), target, options.max_spans, count, ends, interpolation);
    } else {
      within_cap = split(seg, seg.ua(), seg.ub(), target, options.max_spans, count, ends, interpolation);
    }
    if (!within_cap) {
      r.conclude(Status::max_iterations, "more than max_spans = " + std::to_string(options.max_spans) +
                                              " spans needed for tolerance " + format_number(tol));
      r.summary.seconds = seconds_since(t_start);
      return r;
    }
    const double s_base = curve.segment_start(k);
    // The segment's first point and tangent: its own start (exact) and θ (closed form).
    std::complex<double> p0 = seg.start();
    double err0 = 0;
    std::complex<double> t0 = std::polar(1.0, seg.theta_start());
    double u_prev = seg.ua();
    if (k == 0) b.control_points.push_back(p0);  // then B1, B2 of every span, then the end point
    for (size_t i = 0; i < ends.size(); ++i) {
      const double u1 = ends[i];
      const bool last = i + 1 == ends.size();
      const double s1 = last ? seg.length() : std::min(seg.length(), seg.scale() * (u1 - seg.ua()));
      const double h = seg.scale() * (u1 - u_prev);
      const PositionResult pr = position_at(seg, s1);
      r.summary.evaluations += pr.evaluations;
      if (!usable(pr.status) || !std::isfinite(pr.error_estimate)) {
        r.conclude(Status::numerical_failure, "the position at s = " + format_number(s_base + s1) +
                                                  " failed: " + pr.message);
        r.summary.seconds = seconds_since(t_start);
        return r;
      }
      std::complex<double> p1 = pr.point.position;
      double err1 = pr.error_estimate;
      std::complex<double> t1 = std::polar(1.0, seg.theta_at(s1));
      double extra = 0;  // the joint's tangent gap moves the third Bézier point by (h/3)|Δt|, weight ≤ 4/9
      if (last && k + 1 < segs.size()) {
        // The chain's next segment starts at its own start point and θ: the B-spline uses those.
        const LaSegment& next = segs[k + 1];
        const std::complex<double> p_next = next.start(), t_next = std::polar(1.0, next.theta_start());
        err1 += std::abs(p_next - p1);
        extra = h / 3.0 * std::abs(t_next - t1) * (4.0 / 9.0);
        p1 = p_next;
        t1 = t_next;
      }
      // C1 at the double knot: the junction point P1 is the h-weighted mean of its neighbours
      // (P1 − (h/3)t1 and P1 + (h'/3)t1), so the B-spline keeps only the inner Bézier points.
      b.control_points.push_back(p0 + (h / 3.0) * t0);
      b.control_points.push_back(p1 - (h / 3.0) * t1);
      const double knot = last ? curve.segment_start(k + 1) : s_base + s1;
      b.knots.push_back(knot);
      b.knots.push_back(knot);
      // Rounding: the control points (a few ulps of their size) and the closed-form θ (ulps of |θ|).
      const double size = std::max(std::abs(p0), std::abs(p1)) + h;
      const double rounding = 16 * DBL_EPSILON * size +
                              h * 4 * DBL_EPSILON * (1 + std::max(std::abs(seg.theta_start()), std::abs(seg.theta_end())));
      const double interp = span_bound(seg, u_prev, u1).value;
      const double pos = std::max(err0, err1) + extra + rounding;
      positions = std::max(positions, pos);
      deviation = std::max(deviation, interp + pos);
      p0 = p1;
      p_end = p1;
      t0 = t1;
      err0 = err1;
      u_prev = u1;
    }
  }
  // Close: the end point, and the last double knot becomes the end's quadruple one.
  b.control_points.push_back(p_end);
  b.knots.pop_back();
  b.knots.pop_back();
  for (int i = 0; i < 4; ++i) b.knots.push_back(length);
  r.info.spans = count;
  r.info.interpolation = interpolation;
  r.info.positions = positions;
  r.info.max_deviation = deviation;
  r.info.curvature_monotone = curvature_monotone(b, curve, &r.info.monotone_segments, &r.info.max_curvature_jump);
  r.summary.error = deviation / length;
  r.summary.error_estimate = deviation;
  r.summary.iterations = static_cast<int>(std::min<long>(count, std::numeric_limits<int>::max()));
  r.summary.seconds = seconds_since(t_start);
  if (deviation <= tol) {
    r.conclude(Status::ok, "");
  } else {
    r.conclude(Status::inaccurate, "certified deviation " + format_number(deviation) + " exceeds the tolerance " +
                                       format_number(tol));
  }
  return r;
}

}  // namespace lac
