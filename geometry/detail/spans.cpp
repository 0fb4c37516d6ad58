#include "lac/geometry/detail/spans.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>
#include <numbers>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"

namespace lac::detail {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
double cross(std::complex<double> a, std::complex<double> b) { return a.real() * b.imag() - a.imag() * b.real(); }
}  // namespace

Step PlanarSource::integrate(size_t k, double u0, double u1) const {
  const LaSegment& seg = curve_.segments()[k];
  const IntegralResult<std::complex<double>> I = integrate_tangent(seg, u0, u1, method_);
  return {(seg.scale() * seg.rotation()) * I.value, seg.scale() * I.error_estimate, I.evaluations, I.status, I.message};
}

double PlanarSource::s_of(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  const double lo = curve_.segment_start(k), hi = curve_.segment_start(k + 1);
  if (u >= seg.ub()) return hi;
  return std::clamp(lo + seg.scale() * (u - seg.ua()), lo, hi);
}

double PlanarSource::theta(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  return seg.rotation_angle() + seg.phi_at(u);
}

std::complex<double> PlanarSource::tangent(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  return seg.rotation() * std::polar(1.0, seg.phi_at(u));
}

double PlanarSource::kappa(size_t k, double u) const {
  const LaSegment& seg = curve_.segments()[k];
  return seg.curvature_per_u(u) / seg.scale();
}

double PlanarSource::theta_dev(size_t k, double u0, double u1, double uc) const {
  const LaSegment& seg = curve_.segments()[k];
  const double phic = seg.phi_at(uc);
  double dev = std::max(std::abs(seg.phi_at(u0) - phic), std::abs(seg.phi_at(u1) - phic));
  if (const auto ui = seg.inflection_u(); ui && *ui > u0 && *ui < u1) dev = std::max(dev, std::abs(seg.phi_at(*ui) - phic));
  return dev;
}

double PlanarSource::variation(size_t k) const {
  const LaSegment& seg = curve_.segments()[k];
  if (const auto ui = seg.inflection_u(); ui && *ui > seg.ua() && *ui < seg.ub())
    return std::abs(seg.phi_at(*ui) - seg.phi_a()) + std::abs(seg.phi_b() - seg.phi_at(*ui));
  return std::abs(seg.turning());
}

std::vector<double> PlanarSource::angle_cuts(size_t k, double beta, size_t cap, bool* capped) const {
  return detail::angle_cuts(curve_.segments()[k], beta, std::numbers::pi, cap, capped);
}

std::vector<double> QuadraticSource::angle_cuts(size_t k, double beta, size_t cap, bool* capped) const {
  constexpr double pi = std::numbers::pi;
  std::vector<double> ends{s0_};
  if (inside(s0_, s1_)) ends.push_back(curve_.s_at_zero_kappa());
  ends.push_back(s1_);
  std::vector<double> out{s0_};
  for (size_t j = 0; j + 1 < ends.size(); ++j) {
    const double a = ends[j], b = ends[j + 1];
    const double ta = theta(k, a), tb = theta(k, b);
    const double lo = std::min(ta, tb), hi = std::max(ta, tb);
    // Targets beta + mπ strictly inside (lo, hi), in the order s meets them.
    const double m0 = std::floor((lo - beta) / pi) + 1, m1 = std::ceil((hi - beta) / pi) - 1;
    if (m1 - m0 + 1 >= static_cast<double>(cap)) {
      *capped = true;
      return {};
    }
    const double dir = tb >= ta ? 1.0 : -1.0;
    double left = a;
    for (double i = 0; i <= m1 - m0; ++i) {
      const double target = beta + pi * (dir > 0 ? m0 + i : m1 - i);
      if (!(target > lo && target < hi)) continue;
      const auto f = [&](double s) { return dir * (theta(k, s) - target); };
      const double fl = f(left), fb = f(b);
      if (!(fl < 0 && fb > 0)) continue;  // rounding at an end: the value is that end
      std::uintmax_t it = 100;
      const double eps = std::numeric_limits<double>::epsilon(), floor = eps * (b - a);
      const auto close = [eps, floor](double x, double y) {
        return std::abs(y - x) <= 4 * eps * std::max(std::abs(x), std::abs(y)) + floor;
      };
      const auto r = boost::math::tools::toms748_solve(f, left, b, fl, fb, close, it);
      const double root = std::abs(f(r.first)) <= std::abs(f(r.second)) ? r.first : r.second;
      if (root > out.back()) out.push_back(root);
      left = root;
    }
    if (b > out.back()) out.push_back(b);
  }
  return out;
}

QuadraticSource::QuadraticSource(const QuadraticLaCurve& curve, double s0, double s1, const GaussLegendre& method,
                                 double tolerance)
    : curve_(curve), s0_(s0), s1_(s1), method_(method), tolerance_(tolerance) {}

Step QuadraticSource::integrate(size_t, double u0, double u1) const {
  // Gauss–Legendre is not adaptive, and along a quadratic curve the turning can crowd into a small
  // part of a long piece (κ decays fast toward κ → 0): pieces are halved until each estimate is
  // within 1 % of the tolerance (relative to min(|u1 − u0|, arc length)), pro rata.
  Step out;
  const double target = 0.01 * tolerance_ * std::min(std::abs(u1 - u0), length()) / std::abs(u1 - u0);
  const long budget = 1'000'000;
  const auto piece = [&](auto&& self, double a, double b, int depth) -> void {
    if (!usable(out.status)) return;
    const IntegralResult<std::complex<double>> I =
        integrate_quadratic(curve_, method_, a, b, std::max(1L, budget - out.evaluations));
    out.evaluations += I.evaluations;
    if (!usable(I.status)) {
      out.status = I.status, out.message = I.message;
      return;
    }
    const double mid = 0.5 * (a + b);
    if (I.error_estimate > target * std::abs(b - a) && depth < 40 && out.evaluations < budget && mid != a && mid != b) {
      self(self, a, mid, depth + 1);
      self(self, mid, b, depth + 1);
      return;
    }
    out.value += I.value;
    out.err += I.error_estimate;
  };
  piece(piece, u0, u1, 0);
  return out;
}

bool QuadraticSource::inside(double u0, double u1) const {
  if (!(curve_.options().through_inflection && curve_.has_inflection())) return false;
  const double si = curve_.s_at_zero_kappa();
  return si > u0 && si < u1;
}

double QuadraticSource::theta_dev(size_t k, double u0, double u1, double uc) const {
  const double tc = theta(k, uc);
  double dev = std::max(std::abs(theta(k, u0) - tc), std::abs(theta(k, u1) - tc));
  if (inside(u0, u1)) dev = std::max(dev, std::abs(curve_.theta_at_zero_kappa() - tc));
  return dev;
}

double QuadraticSource::variation(size_t k) const {
  const double t0 = theta(k, s0_), t1 = theta(k, s1_);
  if (inside(s0_, s1_)) {
    const double ti = curve_.theta_at_zero_kappa();
    return std::abs(ti - t0) + std::abs(t1 - ti);
  }
  return std::abs(t1 - t0);
}

template <class Source>
Known SpanTracerT<Source>::trace(size_t k, const Known& from, double u) {
  if (from.u == u) return from;
  if (!(from.err < kInf)) return {u, from.p, kInf};
  const Step I = src_.integrate(k, from.u, u);
  evaluations_ += I.evaluations;
  if (!usable(I.status)) {
    fail(I.status, I.message);
    return {u, from.p, kInf};
  }
  const std::complex<double> p = from.p + I.value;
  const double err = from.err + I.err;
  if (!(std::isfinite(p.real()) && std::isfinite(p.imag()) && std::isfinite(err))) {
    fail(Status::numerical_failure, "non-finite position while tracing the curve");
    return {u, from.p, kInf};
  }
  return {u, p, err};
}

template <class Source>
Span SpanTracerT<Source>::make(size_t k, double u0, double u1, const Known& from, int depth) {
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
  sp.theta_c = theta(k, sp.uc);
  sp.tc = tangent(k, sp.uc);
  sp.dev = src_.theta_dev(k, u0, u1, sp.uc);
  sp.kappa_c = kappa(k, sp.uc);
  sp.dkappa = std::max(std::abs(kappa(k, u0) - sp.kappa_c), std::abs(kappa(k, u1) - sp.kappa_c));
  ++spans_made_;
  return sp;
}

template <class Source>
std::pair<Span, Span> SpanTracerT<Source>::split(const Span& span) {
  const Known c = span.anchor();
  return {make(span.seg, span.u0, span.uc, c, span.depth + 1), make(span.seg, span.uc, span.u1, c, span.depth + 1)};
}

template <class Source>
std::vector<Span> SpanTracerT<Source>::cover(double max_turn, int min_count, long cap) {
  std::vector<Span> out;
  const double L = src_.length();
  std::vector<long> counts;
  double total = 0;
  for (size_t k = 0; k < src_.pieces(); ++k) {
    const double n =
        std::max({std::ceil(src_.variation(k) / max_turn), std::ceil(src_.piece_length(k) / L * min_count), 1.0});
    total += n;
    if (!(total <= static_cast<double>(cap))) {
      fail(Status::max_iterations, "covering the curve needs more than " + std::to_string(cap) +
                                       " spans of at most " + format_number(max_turn) + " rad (max_spans)");
      return {};
    }
    counts.push_back(static_cast<long>(n));
  }
  for (size_t k = 0; k < src_.pieces(); ++k) {
    const double ua = src_.ua(k), ub = src_.ub(k);
    const long count = counts[k];
    const double n = static_cast<double>(count);
    Known from = src_.origin(k);
    for (long i = 0; i < count; ++i) {
      const double u0 = i == 0 ? ua : ua + (ub - ua) * static_cast<double>(i) / n;
      const double u1 = i + 1 == count ? ub : ua + (ub - ua) * static_cast<double>(i + 1) / n;
      out.push_back(make(k, u0, u1, from));
      from = out.back().anchor();
      if (failed()) return {};
    }
  }
  return out;
}

template class SpanTracerT<PlanarSource>;
template class SpanTracerT<QuadraticSource>;

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
