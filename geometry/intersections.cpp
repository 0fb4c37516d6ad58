#include "lac/geometry/intersections.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "lac/common/error.hpp"
#include "lac/geometry/detail/roots.hpp"
#include "lac/geometry/detail/spans.hpp"

namespace lac {

namespace {

using detail::Known;
using detail::Span;
using detail::SpanTracer;
using cplx = std::complex<double>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
constexpr double kMaxTurn = 0.5;       // initial spans, and the most a transversal span may turn (rad)
constexpr double kMaxGroupTurn = 1.0;  // most a group of near-parallel leaves turns on either curve (rad)
constexpr int kMinSpans = 16;
constexpr double kLeafFraction = 1e-4;  // near-parallel pairs are halved down to this × length
constexpr int kGroupSamples = 33;  // samples of a group of near-parallel leaf pairs: at least this, 16 per pair
constexpr int kMaxGroupSamples = 4097;
constexpr size_t kMaxLeaves = 20000;
constexpr double kMaxInitialPairs = 1e8;  // overlap tests of the initial spans of both curves
constexpr int kNewtonIterations = 40;
constexpr std::uintmax_t kRootIterations = 100;

double cross(cplx a, cplx b) { return a.real() * b.imag() - a.imag() * b.real(); }
double dot(cplx a, cplx b) { return (std::conj(a) * b).real(); }
cplx unit(cplx z) { return z / std::abs(z); }

template <class F>
double root_in(F&& f, double lo, double hi, double flo, double fhi) {
  return detail::root_in(f, lo, hi, flo, fhi, kRootIterations);
}

void conclude(Intersections& out, double L, const GeometryOptions& o, Status capped_status = Status::ok, std::string capped = {}) {
  std::sort(out.points.begin(), out.points.end(), [](const Intersection& x, const Intersection& y) { return x.s < y.s; });
  // The same point found from two sides of a span or piece boundary (a touch, which fixes s only
  // to about √tolerance × length, possibly by two neighbouring groups).
  std::vector<Intersection> merged;
  const double window = 1e-8 * L, touch_window = 2 * std::sqrt(o.tolerance) * L;
  for (const Intersection& p : out.points) {
    const bool tangent = !merged.empty() && (p.kind == IntersectionKind::tangent || merged.back().kind == IntersectionKind::tangent);
    const double w = tangent ? std::max(window, touch_window) : window;
    if (!merged.empty() && std::abs(p.s - merged.back().s) <= w && std::abs(p.t - merged.back().t) <= w) {
      // Keep the better-known of the two (e.g. a joint: the next segment's start is exact).
      if (p.error_estimate < merged.back().error_estimate) merged.back() = p;
      if (tangent) merged.back().kind = IntersectionKind::tangent;
      continue;
    }
    merged.push_back(p);
  }
  out.points = std::move(merged);
  out.error_estimate = 0;
  for (const Intersection& p : out.points) out.error_estimate = std::max(out.error_estimate, p.error_estimate);
  out.error = out.error_estimate / L;
  if (capped_status != Status::ok) {
    out.status = capped_status;
    out.message = std::move(capped);
    return;
  }
  out.status = grade_error(out.error, o.tolerance, o.accept);
  if (out.status != Status::ok) out.message = "error bound " + format_number(out.error) + " (relative to the length)";
}

template <class Tracer>
Intersections failure(Status s, std::string m, const Tracer& tr) {
  Intersections out;
  out.status = s;
  out.message = std::move(m);
  out.evaluations = tr.evaluations();
  out.error_estimate = out.error = kInf;
  return out;
}

void check_line(cplx point, cplx direction) {
  if (!(std::isfinite(point.real()) && std::isfinite(point.imag())))
    throw_input_error("intersect_line", "point", "both coordinates must be finite");
  if (!(std::isfinite(direction.real()) && std::isfinite(direction.imag()) && std::abs(direction) > 0))
    throw_input_error("intersect_line", "direction", "a finite nonzero vector is needed");
}

// intersections.hpp's line search on the pieces of any span source (detail/spans.hpp).
template <class Tracer>
Intersections line_search(Tracer& tr, cplx point, cplx direction, const GeometryOptions& options) {
  const auto& src = tr.source();
  const cplx D = unit(direction), P = point;
  const double beta = std::arg(D), L = src.length(), tol = options.tolerance * L;
  const double angle_tol = std::sqrt(options.tolerance);
  Intersections out;
  const auto h = [&](cplx p) { return cross(D, p - P); };
  const auto record = [&](size_t k, const Known& a, IntersectionKind kind) {
    out.points.push_back({tr.s_of(k, a.u), dot(D, a.p - P), a.p, a.err + std::abs(h(a.p)), kind});
  };
  for (size_t k = 0; k < src.pieces(); ++k) {
    bool capped = false;
    const long left = std::max(0L, options.max_spans - out.spans);
    const std::vector<double> cuts = src.angle_cuts(k, beta, static_cast<size_t>(left), &capped);
    if (capped || out.spans + static_cast<long>(cuts.size()) > options.max_spans) {
      out.evaluations = tr.evaluations();
      conclude(out, L, options, Status::max_iterations,
               "intersect_line: more than max_spans = " + std::to_string(options.max_spans) +
                   " monotonic pieces; the intersections listed are those before s = " + format_number(src.piece_start(k)));
      return out;
    }
    out.spans += static_cast<long>(cuts.size()) - 1;
    std::vector<Known> at(cuts.size());
    std::vector<double> hv(cuts.size());
    for (size_t i = 0; i < cuts.size(); ++i) {
      at[i] = tr.trace(k, i == 0 ? src.origin(k) : at[i - 1], cuts[i]);
      if (tr.failed()) return failure(tr.status(), "intersect_line: " + tr.message(), tr);
      hv[i] = h(at[i].p);
      // On the line within the tolerance: a touch where θ ≡ arg D (mod π), else a crossing at a
      // piece's end or inflection.
      if (std::abs(hv[i]) <= tol + at[i].err) {
        const double off = std::abs(std::sin(tr.theta(k, cuts[i]) - beta));
        record(k, at[i], off <= angle_tol ? IntersectionKind::tangent : IntersectionKind::crossing);
        hv[i] = 0;
      }
    }
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      if (!((hv[i] < 0 && hv[i + 1] > 0) || (hv[i] > 0 && hv[i + 1] < 0))) continue;
      const Known from = at[i];
      const auto f = [&](double u) { return h(tr.trace(k, from, u).p); };
      const double u = root_in(f, cuts[i], cuts[i + 1], hv[i], hv[i + 1]);
      if (tr.failed()) return failure(tr.status(), "intersect_line: " + tr.message(), tr);
      record(k, tr.trace(k, from, u), IntersectionKind::crossing);
    }
    if (static_cast<long>(out.points.size()) > options.max_points) {
      out.evaluations = tr.evaluations();
      conclude(out, L, options, Status::max_iterations,
               "intersect_line: more than max_points = " + std::to_string(options.max_points) +
                   " intersections; those listed are the ones up to s = " + format_number(tr.s_of(k, src.ub(k))));
      return out;
    }
  }
  out.evaluations = tr.evaluations();
  conclude(out, L, options);
  return out;
}

}  // namespace

Intersections intersect_line(const PlanarCurve& curve, cplx point, cplx direction, const GeometryOptions& options) {
  options.validate("intersect_line");
  check_line(point, direction);
  curve.check_s(0.0, "curve");
  SpanTracer tr(curve, options.method);
  return line_search(tr, point, direction, options);
}

Intersections intersect_line(const QuadraticLaCurve& curve, double s0, double s1, cplx point, cplx direction,
                             const GeometryOptions& options) {
  options.validate("intersect_line");
  check_line(point, direction);
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  if (!(s1 > s0)) throw_input_error("intersect_line", "s1", s1, interval_text(s0, curve.s_domain().hi));
  detail::QuadraticSpanTracer tr(curve, s0, s1, options.method, options.tolerance);
  return line_search(tr, point, direction, options);
}

namespace {

bool overlap(const Span& x, const Span& y) {
  if (std::abs(x.pc - y.pc) > x.half() + y.half() + x.err + y.err) return false;
  return detail::segment_segment_distance(x.a(), x.b(), y.a(), y.b()) <= x.radius() + y.radius();
}

bool transversal(const Span& x, const Span& y) {
  return x.dev < kMaxTurn && y.dev < kMaxTurn && std::abs(std::remainder(x.theta_c - y.theta_c, kPi)) > x.dev + y.dev;
}

// Spans of one curve with their halves computed once.
template <class Tracer>
struct SpanTree {
  Tracer tracer;
  std::vector<Span> spans;
  std::vector<std::optional<std::pair<size_t, size_t>>> children;
  template <class... Args>
  explicit SpanTree(const Args&... args) : tracer(args...) {}
  void init(long cap) {
    spans = tracer.cover(kMaxTurn, kMinSpans, cap);
    children.assign(spans.size(), std::nullopt);
  }
  std::pair<size_t, size_t> halves(size_t i) {
    if (!children[i]) {
      const auto [x, y] = tracer.split(spans[i]);
      spans.push_back(x);
      spans.push_back(y);
      children.push_back(std::nullopt);
      children.push_back(std::nullopt);
      children[i] = std::pair{spans.size() - 2, spans.size() - 1};
    }
    return *children[i];
  }
};

template <class TA, class TB>
struct PairSolver {
  SpanTree<TA>& A;
  SpanTree<TB>& B;
  double tol;
  double angle_tol;
  Intersections& out;

  Intersection make(const Span& sa, const Known& pa, const Span& sb, const Known& pb, IntersectionKind kind) const {
    const cplx ta = A.tracer.tangent(sa.seg, pa.u), tb = B.tracer.tangent(sb.seg, pb.u);
    if (kind == IntersectionKind::crossing && std::abs(cross(ta, tb)) <= angle_tol) kind = IntersectionKind::tangent;
    return {A.tracer.s_of(sa.seg, pa.u), B.tracer.s_of(sb.seg, pb.u), 0.5 * (pa.p + pb.p),
            pa.err + pb.err + std::abs(pa.p - pb.p), kind};
  }

  // Newton on p_a(u) − p_b(v) = 0, its steps kept in the pair's box: true when it converged to a
  // root there (the pair holds at most one: transversal). Otherwise the pair is halved further.
  bool newton(const Span& sa, const Span& sb) {
    const auto& ga = A.tracer.source();  // two declarations: the sources may differ in type
    const auto& gb = B.tracer.source();
    const double la = ga.ds_du(sa.seg), lb = gb.ds_du(sb.seg);
    const double wa = sa.u1 - sa.u0, wb = sb.u1 - sb.u0;
    const double alo = std::max(ga.ua(sa.seg), sa.u0 - 1e-9 * wa), ahi = std::min(ga.ub(sa.seg), sa.u1 + 1e-9 * wa);
    const double blo = std::max(gb.ua(sb.seg), sb.u0 - 1e-9 * wb), bhi = std::min(gb.ub(sb.seg), sb.u1 + 1e-9 * wb);
    // Start: the crossing of the tangent lines at the centres.
    const cplx c = sb.pc - sa.pc, ta = sa.tc, tb = -sb.tc;
    const double det = cross(ta, tb);
    double u = std::clamp(sa.uc + cross(c, tb) / det / la, alo, ahi);
    double v = std::clamp(sb.uc + cross(ta, c) / det / lb, blo, bhi);
    for (int it = 0; it < kNewtonIterations; ++it) {
      const Known pa = A.tracer.trace(sa.seg, sa.anchor(), u), pb = B.tracer.trace(sb.seg, sb.anchor(), v);
      if (A.tracer.failed() || B.tracer.failed()) return true;
      const cplx F = pa.p - pb.p;
      const cplx a = la * A.tracer.tangent(sa.seg, u), b = -lb * B.tracer.tangent(sb.seg, v), r = -F;
      const double d = cross(a, b);
      if (!(d != 0)) return false;
      const double du = cross(r, b) / d, dv = cross(a, r) / d;
      const double nu = std::clamp(u + du, alo, ahi), nv = std::clamp(v + dv, blo, bhi);
      const bool small = std::abs(nu - u) * la + std::abs(nv - v) * lb <= 8 * std::numeric_limits<double>::epsilon() * (std::abs(pa.p) + la * std::abs(u) + 1e-300);
      u = nu;
      v = nv;
      if (small || std::abs(F) <= std::numeric_limits<double>::epsilon() * std::abs(pa.p)) {
        const Known qa = A.tracer.trace(sa.seg, sa.anchor(), u), qb = B.tracer.trace(sb.seg, sb.anchor(), v);
        if (!(std::abs(qa.p - qb.p) <= tol + qa.err + qb.err)) return false;  // stuck at the box's edge
        out.points.push_back(make(sa, qa, sb, qb, IntersectionKind::crossing));
        return true;
      }
    }
    return false;
  }

  // A group of near-parallel leaf pairs: the signed distance of a from b through the foot point.
  void group(size_t seg_a, double u0, double u1, const Known& anchor_a, const Span& span_a, size_t seg_b, double v0,
             double v1, const Known& anchor_b, const Span& span_b, size_t leaves) {
    const int n = static_cast<int>(std::min<size_t>(kMaxGroupSamples, std::max<size_t>(kGroupSamples, 16 * leaves + 1)));
    struct Sample {
      bool valid = false;
      double sigma = 0;
      Known pa, pb;
    };
    const auto foot = [&](double u) {
      Sample s;
      s.pa = A.tracer.trace(seg_a, anchor_a, u);
      const auto g = [&](double v) {
        const Known pb = B.tracer.trace(seg_b, anchor_b, v);
        return dot(pb.p - s.pa.p, B.tracer.tangent(seg_b, v));
      };
      const double g0 = g(v0), g1 = g(v1);
      if (!(g0 < 0 && g1 > 0)) return s;  // the foot is not inside b's range
      const double v = root_in(g, v0, v1, g0, g1);
      s.pb = B.tracer.trace(seg_b, anchor_b, v);
      s.sigma = cross(B.tracer.tangent(seg_b, v), s.pa.p - s.pb.p);
      s.valid = true;
      return s;
    };
    std::vector<double> us(n);
    std::vector<Sample> samples(n);
    for (int i = 0; i < n; ++i) {
      us[i] = u0 + (u1 - u0) * i / (n - 1);
      samples[i] = foot(us[i]);
    }
    bool crossed = false;
    for (int i = 0; i + 1 < n; ++i) {
      const Sample &x = samples[i], &y = samples[i + 1];
      if (!x.valid || !y.valid) continue;
      if (x.sigma == 0) {
        out.points.push_back(make(span_a, x.pa, span_b, x.pb, IntersectionKind::crossing));
        crossed = true;
        continue;
      }
      if (!((x.sigma < 0 && y.sigma > 0) || (x.sigma > 0 && y.sigma < 0))) continue;
      const auto f = [&](double u) {
        const Sample s = foot(u);
        return s.valid ? s.sigma : (u - us[i] < us[i + 1] - u ? x.sigma : y.sigma);
      };
      const Sample r = foot(root_in(f, us[i], us[i + 1], x.sigma, y.sigma));
      if (r.valid) out.points.push_back(make(span_a, r.pa, span_b, r.pb, IntersectionKind::crossing));
      crossed = true;
    }
    if (crossed) return;
    // No sign change: the smallest |σ|, refined by Brent, is a touch if within the tolerance.
    int best = -1;
    for (int i = 0; i < n; ++i)
      if (samples[i].valid && (best < 0 || std::abs(samples[i].sigma) < std::abs(samples[best].sigma))) best = i;
    if (best < 0) return;
    const double lo = us[std::max(0, best - 1)], hi = us[std::min(n - 1, best + 1)];
    const auto m = [&](double u) {
      const Sample s = foot(u);
      return s.valid ? std::abs(s.sigma) : kInf;
    };
    std::uintmax_t iterations = kRootIterations;
    const auto r = boost::math::tools::brent_find_minima(m, lo, hi, 40, iterations);
    Sample s = foot(r.first);
    if (!s.valid) s = samples[best];
    if (std::abs(s.sigma) <= tol + s.pa.err + s.pb.err)
      out.points.push_back(make(span_a, s.pa, span_b, s.pb, IntersectionKind::tangent));
  }
};

// The two-curve search of intersections.hpp on the spans of any two span sources.
template <class TA, class TB>
Intersections curves_search(SpanTree<TA>& A, SpanTree<TB>& B, double L, double scale, const GeometryOptions& options) {
  const double tol = options.tolerance * scale;
  A.init(options.max_spans);
  if (A.tracer.failed()) return failure(A.tracer.status(), "intersect_curves: a: " + A.tracer.message(), A.tracer);
  B.init(options.max_spans - static_cast<long>(A.spans.size()));
  if (B.tracer.failed()) return failure(B.tracer.status(), "intersect_curves: b: " + B.tracer.message(), B.tracer);
  Intersections out;
  PairSolver<TA, TB> solver{A, B, tol, std::sqrt(options.tolerance), out};
  const double leaf = kLeafFraction * scale;
  const auto made = [&] { return A.tracer.spans_made() + B.tracer.spans_made(); };
  const auto finish = [&](Status s, std::string m) {
    out.evaluations = A.tracer.evaluations() + B.tracer.evaluations();
    out.spans = made();
    conclude(out, L, options, s, std::move(m));
    return out;
  };
  if (made() > options.max_spans)
    return finish(Status::max_iterations, "intersect_curves: covering the curves needs more than max_spans = " +
                                              std::to_string(options.max_spans) + " spans");

  if (static_cast<double>(A.spans.size()) * static_cast<double>(B.spans.size()) > kMaxInitialPairs)
    return finish(Status::max_iterations, "intersect_curves: " + std::to_string(A.spans.size()) + " × " +
                                              std::to_string(B.spans.size()) + " initial span pairs, more than " +
                                              format_number(kMaxInitialPairs) + " to test");
  std::vector<std::pair<size_t, size_t>> stack, leaves;
  for (size_t i = A.spans.size(); i-- > 0;)
    for (size_t j = B.spans.size(); j-- > 0;)
      if (overlap(A.spans[i], B.spans[j])) stack.push_back({i, j});
  while (!stack.empty()) {
    if (static_cast<long>(out.points.size()) > options.max_points)
      return finish(Status::max_iterations, "intersect_curves: more than max_points = " + std::to_string(options.max_points) +
                                                " intersections; those found so far are listed, not all");
    const auto [i, j] = stack.back();
    stack.pop_back();
    const Span sa = A.spans[i], sb = B.spans[j];
    // A leaf: both spans short and turning little (a short span can still turn many rad where κ
    // is large, e.g. in the coil of a spiral: halved further).
    const bool curled = !(sa.dev < kMaxTurn && sb.dev < kMaxTurn);
    const bool at_leaf = std::max(2 * sa.half(), 2 * sb.half()) <= leaf && !curled;
    if (transversal(sa, sb)) {
      const bool done = solver.newton(sa, sb);
      if (A.tracer.failed() || B.tracer.failed()) break;
      if (done) continue;
    }
    // A leaf pair, near-parallel or transversal where Newton found nothing (a crossing at a small
    // angle, whose cones are disjoint by less than Newton resolves): the group step decides.
    if (at_leaf) {
      leaves.push_back({i, j});
      if (leaves.size() > kMaxLeaves)
        return finish(Status::not_converged, "intersect_curves: more than " + std::to_string(kMaxLeaves) +
                                                 " near-parallel span pairs: the curves run along each other near s = " +
                                                 format_number(sa.sc()) + " on a");
      continue;
    }
    if (made() + 2 > options.max_spans)
      return finish(Status::max_iterations, "intersect_curves: max_spans = " + std::to_string(options.max_spans) +
                                                " reached near s = " + format_number(sa.sc()) + " on a");
    if (curled ? sa.dev >= sb.dev : sa.half() >= sb.half()) {
      const auto [x, y] = A.halves(i);
      if (A.tracer.failed()) break;
      for (size_t c : {y, x})
        if (overlap(A.spans[c], sb)) stack.push_back({c, j});
    } else {
      const auto [x, y] = B.halves(j);
      if (B.tracer.failed()) break;
      for (size_t c : {y, x})
        if (overlap(sa, B.spans[c])) stack.push_back({i, c});
    }
  }
  if (A.tracer.failed()) return failure(A.tracer.status(), "intersect_curves: a: " + A.tracer.message(), A.tracer);
  if (B.tracer.failed()) return failure(B.tracer.status(), "intersect_curves: b: " + B.tracer.message(), B.tracer);

  // Group the leaves: same segments and touching ranges on both curves.
  std::sort(leaves.begin(), leaves.end(), [&](auto x, auto y) {
    const Span &p = A.spans[x.first], &q = A.spans[y.first];
    return std::tie(p.seg, p.u0, B.spans[x.second].seg) < std::tie(q.seg, q.u0, B.spans[y.second].seg);
  });
  std::vector<bool> used(leaves.size(), false);
  for (size_t g = 0; g < leaves.size(); ++g) {
    if (used[g]) continue;
    used[g] = true;
    const Span &fa = A.spans[leaves[g].first], &fb = B.spans[leaves[g].second];
    double u0 = fa.u0, u1 = fa.u1, v0 = fb.u0, v1 = fb.u1;
    // The range of θ over each curve's part of the group (θ is continuous on a segment, so the
    // union of the members' [θ(c) − Δ, θ(c) + Δ] bounds it): a group turns at most kMaxGroupTurn
    // on either curve, so that the foot point on b is the one root of (p_b − p_a)·T_b in its range.
    double alo = fa.theta_c - fa.dev, ahi = fa.theta_c + fa.dev, blo = fb.theta_c - fb.dev, bhi = fb.theta_c + fb.dev;
    size_t members = 1;
    for (bool grew = true; grew;) {
      grew = false;
      for (size_t m = g + 1; m < leaves.size(); ++m) {
        if (used[m]) continue;
        const Span &pa = A.spans[leaves[m].first], &pb = B.spans[leaves[m].second];
        if (pa.seg != fa.seg || pb.seg != fb.seg) continue;
        if (pa.u0 > u1 || pa.u1 < u0 || pb.u0 > v1 || pb.u1 < v0) continue;
        const double nalo = std::min(alo, pa.theta_c - pa.dev), nahi = std::max(ahi, pa.theta_c + pa.dev);
        const double nblo = std::min(blo, pb.theta_c - pb.dev), nbhi = std::max(bhi, pb.theta_c + pb.dev);
        if (nahi - nalo > kMaxGroupTurn || nbhi - nblo > kMaxGroupTurn) continue;
        alo = nalo, ahi = nahi, blo = nblo, bhi = nbhi;
        u0 = std::min(u0, pa.u0), u1 = std::max(u1, pa.u1), v0 = std::min(v0, pb.u0), v1 = std::max(v1, pb.u1);
        used[m] = grew = true;
        ++members;
      }
    }
    solver.group(fa.seg, u0, u1, fa.anchor(), fa, fb.seg, v0, v1, fb.anchor(), fb, members);
    if (A.tracer.failed()) return failure(A.tracer.status(), "intersect_curves: a: " + A.tracer.message(), A.tracer);
    if (B.tracer.failed()) return failure(B.tracer.status(), "intersect_curves: b: " + B.tracer.message(), B.tracer);
  }
  return finish(Status::ok, "");
}

}  // namespace

Intersections intersect_curves(const PlanarCurve& a, const PlanarCurve& b, const GeometryOptions& options) {
  options.validate("intersect_curves");
  a.check_s(0.0, "a");
  b.check_s(0.0, "b");
  SpanTree<SpanTracer> A(a, options.method), B(b, options.method);
  return curves_search(A, B, a.length(), std::max(a.length(), b.length()), options);
}

Intersections intersect_curves(const QuadraticLaCurve& a, double s0, double s1, const PlanarCurve& b,
                               const GeometryOptions& options) {
  options.validate("intersect_curves");
  a.check_s(s0, "s0");
  a.check_s(s1, "s1");
  if (!(s1 > s0)) throw_input_error("intersect_curves", "s1", s1, interval_text(s0, a.s_domain().hi));
  b.check_s(0.0, "b");
  SpanTree<detail::QuadraticSpanTracer> A(a, s0, s1, options.method, options.tolerance);
  SpanTree<SpanTracer> B(b, options.method);
  return curves_search(A, B, s1 - s0, std::max(s1 - s0, b.length()), options);
}

Intersections intersect_curves(const QuadraticLaCurve& a, double a0, double a1, const QuadraticLaCurve& b, double b0,
                               double b1, const GeometryOptions& options) {
  options.validate("intersect_curves");
  a.check_s(a0, "a0");
  a.check_s(a1, "a1");
  if (!(a1 > a0)) throw_input_error("intersect_curves", "a1", a1, interval_text(a0, a.s_domain().hi));
  b.check_s(b0, "b0");
  b.check_s(b1, "b1");
  if (!(b1 > b0)) throw_input_error("intersect_curves", "b1", b1, interval_text(b0, b.s_domain().hi));
  SpanTree<detail::QuadraticSpanTracer> A(a, a0, a1, options.method, options.tolerance),
      B(b, b0, b1, options.method, options.tolerance);
  return curves_search(A, B, a1 - a0, std::max(a1 - a0, b1 - b0), options);
}

}  // namespace lac
