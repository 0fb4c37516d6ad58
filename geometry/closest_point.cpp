#include "lac/geometry/closest_point.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/geometry/detail/spans.hpp"

namespace lac {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxTurn = 0.5;  // initial spans turn at most this much (rad)
constexpr int kMinSpans = 16;
constexpr std::uintmax_t kPolishIterations = 100;

double dot(std::complex<double> a, std::complex<double> b) { return (std::conj(a) * b).real(); }

struct Candidate {
  double u = 0, d = kInf, err = kInf;
  std::complex<double> p{};
};

// The smallest distance from q any point of the span can have (rigorous, detail/spans.hpp).
double lower_bound(const detail::Span& sp, std::complex<double> q) {
  const double disc = std::abs(q - sp.pc) - sp.half() - sp.err;
  const double capsule = detail::point_segment_distance(q, sp.a(), sp.b()) - sp.radius();
  return std::max({disc, capsule, 0.0});
}

// g(s) = (p − q)·T increases over the whole span: a lower bound on g' = 1 + (p − q)·κN there.
bool convex(const detail::Span& sp, std::complex<double> q) {
  const std::complex<double> w = sp.pc - q, Kc = sp.kappa_c * std::complex<double>(0, 1) * sp.tc;
  const double dK = sp.dkappa + std::abs(sp.kappa_c) * std::min(sp.dev, 2.0);
  const double bound = 1.0 + dot(w, Kc) - std::abs(w) * dK - (sp.half() + sp.err) * (std::abs(sp.kappa_c) + dK);
  return bound > 0;
}

// The minimum of |p − q| over the span: at an end, or at the root of g where g goes from − to +.
template <class Tracer>
Candidate polish(Tracer& tr, const detail::Span& sp, std::complex<double> q) {
  const detail::Known c = sp.anchor();
  const auto g_of = [&](const detail::Known& a) { return dot(a.p - q, tr.tangent(sp.seg, a.u)); };
  const detail::Known a0 = tr.trace(sp.seg, c, sp.u0), a1 = tr.trace(sp.seg, c, sp.u1);
  Candidate best;
  const auto consider = [&](const detail::Known& a) {
    const double d = std::abs(a.p - q);
    if (d < best.d) best = {a.u, d, a.err, a.p};
  };
  consider(a0);
  consider(a1);
  const double g0 = g_of(a0), g1 = g_of(a1);
  if (g0 < 0 && g1 > 0) {
    const auto g = [&](double u) { return g_of(tr.trace(sp.seg, c, u)); };
    std::uintmax_t iterations = kPolishIterations;
    const double floor = std::numeric_limits<double>::epsilon() * (sp.u1 - sp.u0);  // u near 0
    const auto tol = [floor](double a, double b) {
      return std::abs(b - a) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)) + floor;
    };
    const auto r = boost::math::tools::toms748_solve(g, sp.u0, sp.u1, g0, g1, tol, iterations);
    consider(tr.trace(sp.seg, c, r.first));
    consider(tr.trace(sp.seg, c, r.second));
  }
  return best;
}

// The branch and bound of closest_point.hpp on the spans of any span source (detail/spans.hpp).
template <class Tracer>
ClosestPoint search(Tracer& tr, std::complex<double> query, const GeometryOptions& options) {
  const double L = tr.source().length(), tol = options.tolerance * L;
  ClosestPoint out;
  const auto finish = [&](Status s, std::string m) {
    out.evaluations = tr.evaluations();
    out.spans = tr.spans_made();
    out.status = s;
    out.message = std::move(m);
    if (!usable(out.status) && out.status != Status::inaccurate) out.error_estimate = out.error = kInf;
    return out;
  };

  std::vector<detail::Span> store = tr.cover(kMaxTurn, kMinSpans, options.max_spans);
  if (tr.failed()) return finish(tr.status(), "closest_point: " + tr.message());

  // Best point so far: a span centre (not polished) or a polished minimum of a span.
  Candidate best;
  size_t best_span = 0;
  bool best_polished = false;
  double leaf_lb = kInf;  // smallest (distance − error) over polished spans
  // Smallest bound of the spans discarded as within the tolerance of the best (their minimum may
  // still lie below it by up to the tolerance: part of the error bound).
  double dropped_lb = kInf;
  const auto best_ub = [&] { return best.d + best.err; };
  const auto offer = [&](const Candidate& c, size_t span, bool polished) {
    if (c.d + c.err < best_ub()) best = c, best_span = span, best_polished = polished;
  };

  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  for (size_t i = 0; i < store.size(); ++i) offer({store[i].uc, std::abs(store[i].pc - query), store[i].err, store[i].pc}, i, false);
  for (size_t i = 0; i < store.size(); ++i) {
    const double lb = lower_bound(store[i], query);
    if (lb < best_ub() - tol) heap.push({lb, i});
    else if (lb < best_ub()) dropped_lb = std::min(dropped_lb, lb);
  }

  double stop_lb = kInf;
  bool capped = false;
  while (!heap.empty()) {
    const auto [lb, i] = heap.top();
    if (lb >= best_ub() - tol) {
      stop_lb = lb;
      break;
    }
    heap.pop();
    const detail::Span sp = store[i];
    const bool proven = convex(sp, query);
    if (proven || 2 * sp.half() <= tol) {
      const Candidate c = polish(tr, sp, query);
      if (tr.failed()) return finish(tr.status(), "closest_point: " + tr.message());
      // Without the proof the span's minimum is within its length of the one found.
      leaf_lb = std::min(leaf_lb, c.d - c.err - (proven ? 0.0 : 2 * sp.half()));
      offer(c, i, true);
      continue;
    }
    if (tr.spans_made() + 2 > options.max_spans) {
      capped = true;
      stop_lb = lb;
      break;
    }
    const auto [x, y] = tr.split(sp);
    if (tr.failed()) return finish(tr.status(), "closest_point: " + tr.message());
    for (const detail::Span& child : {x, y}) {
      store.push_back(child);
      const size_t j = store.size() - 1;
      offer({child.uc, std::abs(child.pc - query), child.err, child.pc}, j, false);
      const double clb = lower_bound(child, query);
      if (clb < best_ub() - tol) heap.push({clb, j});
      else if (clb < best_ub()) dropped_lb = std::min(dropped_lb, clb);
    }
  }
  if (!best_polished) {  // the best is a span's centre: its span's own minimum is at most as far
    const Candidate c = polish(tr, store[best_span], query);
    if (tr.failed()) return finish(tr.status(), "closest_point: " + tr.message());
    if (c.d <= best.d) best = c;
  }

  const detail::Span& bs = store[best_span];
  out.s = tr.s_of(bs.seg, best.u);
  out.point = best.p;
  out.distance = best.d;
  const double lower = std::min({stop_lb, leaf_lb, dropped_lb});
  out.error_estimate = std::max(best.err, best.d - std::min(lower, best.d));
  out.error = out.error_estimate / L;
  if (capped)
    return finish(Status::max_iterations,
                  "closest_point: max_spans = " + std::to_string(options.max_spans) + " reached; best distance " +
                      format_number(best.d) + ", global minimum not below " + format_number(lower));
  const Status s = grade_error(out.error, options.tolerance, options.accept);
  return finish(s, s == Status::ok ? "" : "closest_point: error bound " + format_number(out.error) + " above the tolerance");
}

void check_query(std::complex<double> query) {
  if (!(std::isfinite(query.real()) && std::isfinite(query.imag())))
    throw_input_error("closest_point", "query", "both coordinates must be finite");
}

}  // namespace

ClosestPoint closest_point(const PlanarCurve& curve, std::complex<double> query, const GeometryOptions& options) {
  options.validate("closest_point");
  check_query(query);
  curve.check_s(0.0, "curve");
  detail::SpanTracer tr(curve, options.method);
  return search(tr, query, options);
}

ClosestPoint closest_point(const QuadraticLaCurve& curve, double s0, double s1, std::complex<double> query,
                           const GeometryOptions& options) {
  options.validate("closest_point");
  check_query(query);
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  if (!(s1 > s0)) throw_input_error("closest_point", "s1", s1, interval_text(s0, curve.s_domain().hi));
  detail::QuadraticSpanTracer tr(curve, s0, s1, options.method, options.tolerance);
  return search(tr, query, options);
}

}  // namespace lac
