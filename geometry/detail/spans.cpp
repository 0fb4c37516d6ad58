#include "lac/geometry/detail/spans.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"

namespace lac::detail {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
double cross(std::complex<double> a, std::complex<double> b) { return a.real() * b.imag() - a.imag() * b.real(); }
}  // namespace

Known SpanTracer::trace(size_t k, const Known& from, double u) {
  const LaSegment& seg = curve_.segments()[k];
  if (from.u == u) return from;
  if (!(from.err < kInf)) return {u, from.p, kInf};
  const IntegralResult<std::complex<double>> I = integrate_tangent(seg, from.u, u, method_);
  evaluations_ += I.evaluations;
  if (!usable(I.status)) {
    fail(I.status, I.message);
    return {u, from.p, kInf};
  }
  const std::complex<double> p = from.p + (seg.scale() * seg.rotation()) * I.value;
  const double err = from.err + seg.scale() * I.error_estimate;
  if (!(std::isfinite(p.real()) && std::isfinite(p.imag()) && std::isfinite(err))) {
    fail(Status::numerical_failure, "non-finite position while tracing the curve");
    return {u, from.p, kInf};
  }
  return {u, p, err};
}

double SpanTracer::s_of(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  const double lo = curve_.segment_start(k), hi = curve_.segment_start(k + 1);
  if (u >= seg.ub()) return hi;
  return std::clamp(lo + seg.scale() * (u - seg.ua()), lo, hi);
}

double SpanTracer::theta(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  return seg.rotation_angle() + seg.phi_at(u);
}

std::complex<double> SpanTracer::tangent(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  return seg.rotation() * std::polar(1.0, seg.phi_at(u));
}

double SpanTracer::kappa(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  return seg.curvature_per_u(u) / seg.scale();
}

Span SpanTracer::make(size_t k, double u0, double u1, const Known& from, int depth) {
  const LaSegment& seg = curve_.segments()[k];
  Span sp;
  sp.seg = k;
  sp.u0 = u0;
  sp.u1 = u1;
  sp.uc = 0.5 * (u0 + u1);
  sp.s0 = s_of(k, u0);
  sp.s1 = s_of(k, u1);
  sp.depth = depth;
  const Known c = trace(k, from, sp.uc);
  sp.pc = c.p;
  sp.err = c.err;
  const double phic = seg.phi_at(sp.uc);
  sp.theta_c = seg.rotation_angle() + phic;
  sp.tc = seg.rotation() * std::polar(1.0, phic);
  sp.dev = std::max(std::abs(seg.phi_at(u0) - phic), std::abs(seg.phi_at(u1) - phic));
  if (const auto ui = seg.inflection_u(); ui && *ui > u0 && *ui < u1)
    sp.dev = std::max(sp.dev, std::abs(seg.phi_at(*ui) - phic));
  sp.kappa_c = kappa(k, sp.uc);
  sp.dkappa = std::max(std::abs(kappa(k, u0) - sp.kappa_c), std::abs(kappa(k, u1) - sp.kappa_c));
  ++spans_made_;
  return sp;
}

std::pair<Span, Span> SpanTracer::split(const Span& span) {
  const Known c = span.anchor();
  return {make(span.seg, span.u0, span.uc, c, span.depth + 1), make(span.seg, span.uc, span.u1, c, span.depth + 1)};
}

std::vector<Span> SpanTracer::cover(double max_turn, int min_count, long cap) {
  std::vector<Span> out;
  const double L = curve_.length();
  std::vector<long> counts;
  double total = 0;
  for (const LaSegment& seg : curve_.segments()) {
    double variation = std::abs(seg.turning());
    if (const auto ui = seg.inflection_u(); ui && *ui > seg.ua() && *ui < seg.ub())
      variation = std::abs(seg.phi_at(*ui) - seg.phi_a()) + std::abs(seg.phi_b() - seg.phi_at(*ui));
    const double n = std::max({std::ceil(variation / max_turn), std::ceil(seg.length() / L * min_count), 1.0});
    total += n;
    if (!(total <= static_cast<double>(cap))) {
      fail(Status::max_iterations, "covering the curve needs more than " + std::to_string(cap) +
                                       " spans of at most " + format_number(max_turn) + " rad (max_spans)");
      return {};
    }
    counts.push_back(static_cast<long>(n));
  }
  for (size_t k = 0; k < curve_.segments().size(); ++k) {
    const LaSegment& seg = curve_.segments()[k];
    const long count = counts[k];
    const double n = static_cast<double>(count);
    Known from{seg.ua(), seg.start(), 0.0};
    for (long i = 0; i < count; ++i) {
      const double u0 = i == 0 ? seg.ua() : seg.ua() + (seg.ub() - seg.ua()) * static_cast<double>(i) / n;
      const double u1 = i + 1 == count ? seg.ub() : seg.ua() + (seg.ub() - seg.ua()) * static_cast<double>(i + 1) / n;
      out.push_back(make(k, u0, u1, from));
      from = out.back().anchor();
      if (failed()) return {};
    }
  }
  return out;
}

double point_segment_distance(std::complex<double> z, std::complex<double> a, std::complex<double> b) {
  const std::complex<double> d = b - a;
  const double n = std::norm(d);
  if (n == 0) return std::abs(z - a);
  const double t = std::clamp(((z - a) * std::conj(d)).real() / n, 0.0, 1.0);
  return std::abs(z - (a + t * d));
}

double segment_segment_distance(std::complex<double> a0, std::complex<double> a1, std::complex<double> b0,
                                std::complex<double> b1) {
  const double c0 = cross(a1 - a0, b0 - a0), c1 = cross(a1 - a0, b1 - a0);
  const double c2 = cross(b1 - b0, a0 - b0), c3 = cross(b1 - b0, a1 - b0);
  if (((c0 < 0 && c1 > 0) || (c0 > 0 && c1 < 0)) && ((c2 < 0 && c3 > 0) || (c2 > 0 && c3 < 0))) return 0.0;
  return std::min({point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1),
                   point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)});
}

}  // namespace lac::detail
