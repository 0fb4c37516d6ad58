#include "lac/geometry/transforms.hpp"

#include <cmath>
#include <vector>

#include "lac/common/error.hpp"

namespace lac {

namespace {

std::complex<double> unit(std::complex<double> z) { return z / std::abs(z); }

template <class F>
PlanarCurve map_segments(const PlanarCurve& curve, F&& f) {
  curve.check_s(0.0, "curve");
  std::vector<LaSegment> out;
  out.reserve(curve.segments().size());
  for (const LaSegment& seg : curve.segments()) out.push_back(f(seg));
  return PlanarCurve(std::move(out));
}

void require_point(const char* who, const char* name, std::complex<double> z) {
  if (!(std::isfinite(z.real()) && std::isfinite(z.imag())))
    throw_input_error(who, name, "both coordinates must be finite");
}

// The error estimate of a cut or reversed curve relative to its length, graded.
template <class C>
void grade(Result<C>& r, double error_estimate, double scale, const GeometryOptions& o) {
  r.summary.error_estimate = error_estimate;
  r.summary.error = error_estimate / scale;
  r.summary.accept = o.accept;
  r.conclude(grade_error(*r.summary.error, o.tolerance, o.accept), "");
}

}  // namespace

PlanarCurve translated(const PlanarCurve& curve, std::complex<double> offset) {
  require_point("translated", "offset", offset);
  return map_segments(curve, [&](const LaSegment& seg) {
    return seg.placed({seg.start() + offset, seg.scale(), seg.rotation()});
  });
}

PlanarCurve rotated(const PlanarCurve& curve, double angle, std::complex<double> center) {
  require_finite("rotated", "angle", angle);
  require_point("rotated", "center", center);
  const std::complex<double> e = std::polar(1.0, angle);
  return map_segments(curve, [&](const LaSegment& seg) {
    return seg.placed({center + e * (seg.start() - center), seg.scale(), unit(e * seg.rotation())});
  });
}

PlanarCurve scaled(const PlanarCurve& curve, double factor, std::complex<double> center) {
  if (!(factor > 0) || !std::isfinite(factor)) throw_input_error("scaled", "factor", factor, "(0, inf)");
  require_point("scaled", "center", center);
  return map_segments(curve, [&](const LaSegment& seg) {
    return seg.placed({center + factor * (seg.start() - center), factor * seg.scale(), seg.rotation()});
  });
}

PlanarCurve mirrored(const PlanarCurve& curve, std::complex<double> point, std::complex<double> direction) {
  require_point("mirrored", "point", point);
  require_point("mirrored", "direction", direction);
  if (!(std::abs(direction) > 0)) throw_input_error("mirrored", "direction", "a nonzero vector is needed");
  const std::complex<double> d = unit(direction), d2 = d * d;
  // LaSegment::mirrored reflects across the line through its start along R; composed with the
  // reflection across this line, R becomes D² conj(R) and the start its mirror image.
  return map_segments(curve, [&](const LaSegment& seg) {
    return seg.mirrored().placed({point + d2 * std::conj(seg.start() - point), seg.scale(), unit(d2 * std::conj(seg.rotation()))});
  });
}

Result<PlanarCurve> trimmed(const PlanarCurve& curve, double s0, double s1, const GeometryOptions& options) {
  options.validate("trimmed");
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  if (!(s1 > s0)) throw_input_error("trimmed", "s1", s1, interval_text(s0, curve.length(), false, true));
  Result<PlanarCurve> r;
  std::vector<LaSegment> out;
  double error = 0;
  for (size_t k = 0; k < curve.segments().size(); ++k) {
    const LaSegment& seg = curve.segments()[k];
    const double lo = curve.segment_start(k), hi = curve.segment_start(k + 1);
    const double a = std::max(s0, lo), b = std::min(s1, hi);
    if (!(b > a)) continue;
    const double u0 = a <= lo ? seg.ua() : seg.u_at(a - lo);
    const double u1 = b >= hi ? seg.ub() : seg.u_at(b - lo);
    if (!(u1 > u0)) continue;  // below the resolution of u
    std::complex<double> start = seg.start();
    if (u0 > seg.ua()) {
      const PositionResult p = position_at(seg, a - lo, options.method);
      r.summary.evaluations += p.evaluations;
      if (!usable(p.status)) {
        r.conclude(p.status, "position at s0: " + p.message);
        return r;
      }
      start = p.point.position;
      error = std::max(error, p.error_estimate);
    }
    out.push_back(LaSegment(seg.law(), seg.part(u0, u1), {start, seg.scale(), seg.rotation()}));
  }
  if (out.empty())
    throw_input_error("trimmed", "s1", s1, "values farther from s0 = " + format_number(s0) + " than the resolution of the segment's parameter");
  r.curve = PlanarCurve(std::move(out));
  grade(r, error, curve.length(), options);
  return r;
}

Result<CurvePair> split(const PlanarCurve& curve, double s, const GeometryOptions& options) {
  options.validate("split");
  curve.check_s(0.0, "s");
  if (!(s > 0 && s < curve.length())) throw_input_error("split", "s", s, interval_text(0, curve.length()));
  Result<CurvePair> r;
  const Result<PlanarCurve> a = trimmed(curve, 0.0, s, options), b = trimmed(curve, s, curve.length(), options);
  r.summary.evaluations = a.summary.evaluations + b.summary.evaluations;
  if (!a.usable() || !b.usable()) {
    r.conclude(!a.usable() ? a.summary.status : b.summary.status, !a.usable() ? a.summary.message : b.summary.message);
    return r;
  }
  r.curve = {a.curve, b.curve};
  grade(r, std::max(a.summary.error_estimate.value_or(0), b.summary.error_estimate.value_or(0)), curve.length(), options);
  return r;
}

Result<PlanarCurve> appended(const PlanarCurve& a, const PlanarCurve& b, double gap_tolerance, const GeometryOptions& options) {
  options.validate("appended");
  a.check_s(0.0, "a");
  b.check_s(0.0, "b");
  if (!(gap_tolerance >= 0) || !std::isfinite(gap_tolerance))
    throw_input_error("appended", "gap_tolerance", gap_tolerance, "[0, inf)");
  Result<PlanarCurve> r;
  const PositionResult end = position_at(a, a.length(), options.method);
  r.summary.evaluations = end.evaluations;
  if (!usable(end.status)) {
    r.conclude(end.status, "end of a: " + end.message);
    return r;
  }
  const double gap = std::abs(b.segments().front().start() - end.point.position);
  if (!(gap <= gap_tolerance))
    throw_input_error("appended", "b", gap,
                      "[0, " + format_number(gap_tolerance) + "] (the gap between the start of b and the end of a, gap_tolerance)");
  std::vector<LaSegment> segs = a.segments();
  segs.insert(segs.end(), b.segments().begin(), b.segments().end());
  r.curve = PlanarCurve(std::move(segs));
  r.summary.residuals.position = gap;
  grade(r, end.error_estimate, a.length() + b.length(), options);
  return r;
}

Result<PlanarCurve> reversed(const PlanarCurve& curve, const GeometryOptions& options) {
  options.validate("reversed");
  curve.check_s(0.0, "curve");
  Result<PlanarCurve> r;
  const PositionResult end = position_at(curve, curve.length(), options.method);
  r.summary.evaluations = end.evaluations;
  if (!usable(end.status)) {
    r.conclude(end.status, "end point: " + end.message);
    return r;
  }
  r.curve = curve.reversed(end.point.position);
  grade(r, end.error_estimate, curve.length(), options);
  return r;
}

}  // namespace lac
