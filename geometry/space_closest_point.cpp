#include "lac/geometry/space_closest_point.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/geometry/detail/space_spans.hpp"

namespace lac {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uintmax_t kPolishIterations = 100;

using detail::SpaceSpan;
using Tracer = detail::SpaceTracer;

double segment_distance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double n = d.squaredNorm();
  if (n == 0) return (q - a).norm();
  const double t = std::clamp((q - a).dot(d) / n, 0.0, 1.0);
  return (q - (a + t * d)).norm();
}

double lower_bound(const SpaceSpan& sp, const Vec3& q) {
  const double h = sp.half();
  const double ball = (q - sp.pc).norm() - h;
  const double capsule = segment_distance(q, sp.pc - h * sp.tc, sp.pc + h * sp.tc) - h * sp.turn();
  return std::max({ball, capsule, 0.0});
}

bool convex(const SpaceSpan& sp, const Vec3& q) { return 1.0 - sp.kappa_max * ((sp.pc - q).norm() + sp.half()) > 0; }

struct Candidate {
  double s = 0, d = kInf;
  Vec3 p = Vec3::Zero();
};

Candidate polish(Tracer& tr, const SpaceSpan& sp, const Vec3& q) {
  Candidate best;
  const auto consider = [&](double s, const SpacePoint& a) {
    const double d = (a.p - q).norm();
    if (d < best.d) best = {s, d, a.p};
  };
  const SpacePoint a0 = tr.at(sp.piece, sp.s0), a1 = tr.at(sp.piece, sp.s1);
  consider(sp.s0, a0);
  consider(sp.s1, a1);
  const double g0 = (a0.p - q).dot(a0.t), g1 = (a1.p - q).dot(a1.t);
  if (g0 < 0 && g1 > 0) {
    const auto g = [&](double s) {
      const SpacePoint a = tr.at(sp.piece, s);
      return (a.p - q).dot(a.t);
    };
    std::uintmax_t iterations = kPolishIterations;
    const double floor = std::numeric_limits<double>::epsilon() * (sp.s1 - sp.s0);
    const auto tol = [floor](double a, double b) {
      return std::abs(b - a) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)) + floor;
    };
    const auto r = boost::math::tools::toms748_solve(g, sp.s0, sp.s1, g0, g1, tol, iterations);
    consider(r.first, tr.at(sp.piece, r.first));
    consider(r.second, tr.at(sp.piece, r.second));
  }
  return best;
}

}  // namespace

SpaceClosestPoint closest_point(const SpaceCurve& curve, const Vec3& query, const GeometryOptions& options) {
  options.validate("closest_point");
  if (!query.allFinite()) throw_input_error("closest_point", "query", "all three coordinates must be finite");
  curve.check_s(0.0, "curve");
  const double L = curve.length(), tol = options.tolerance * L;
  SpaceClosestPoint out;
  Tracer tr(curve);
  const auto finish = [&](Status s, std::string m) {
    out.evaluations = tr.evaluations;
    out.spans = tr.spans;
    out.status = s;
    out.message = std::move(m);
    if (!usable(out.status) && out.status != Status::inaccurate) out.error_estimate = out.error = kInf;
    return out;
  };
  const auto failed = [&] { return !usable(tr.status); };

  std::vector<SpaceSpan> store = detail::cover(tr, options);
  if (store.empty()) return finish(tr.status, "closest_point: " + tr.message);

  Candidate best;
  size_t best_span = 0;
  bool best_polished = false;
  double leaf_lb = kInf, dropped_lb = kInf;
  const auto offer = [&](const Candidate& c, size_t span, bool polished) {
    if (c.d < best.d) best = c, best_span = span, best_polished = polished;
  };
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  const auto push = [&](size_t i) {
    const double lb = lower_bound(store[i], query);
    if (lb < best.d - tol) heap.push({lb, i});
    else if (lb < best.d) dropped_lb = std::min(dropped_lb, lb);
  };
  for (size_t i = 0; i < store.size(); ++i) offer({store[i].sc(), (store[i].pc - query).norm(), store[i].pc}, i, false);
  for (size_t i = 0; i < store.size(); ++i) push(i);

  double stop_lb = kInf;
  bool capped = false;
  while (!heap.empty()) {
    const auto [lb, i] = heap.top();
    if (lb >= best.d - tol) {
      stop_lb = lb;
      break;
    }
    heap.pop();
    const SpaceSpan sp = store[i];
    const bool proven = convex(sp, query);
    if (proven || 2 * sp.half() <= tol) {
      const Candidate c = polish(tr, sp, query);
      if (failed()) return finish(tr.status, "closest_point: " + tr.message);
      leaf_lb = std::min(leaf_lb, c.d - (proven ? 0.0 : 2 * sp.half()));
      offer(c, i, true);
      continue;
    }
    if (tr.spans + 2 > options.max_spans) {
      capped = true;
      stop_lb = lb;
      break;
    }
    const double mid = sp.sc();
    for (const auto& [a, b] : {std::pair{sp.s0, mid}, std::pair{mid, sp.s1}}) {
      store.push_back(tr.make(sp.piece, a, b));
      if (failed()) return finish(tr.status, "closest_point: " + tr.message);
      const size_t j = store.size() - 1;
      offer({store[j].sc(), (store[j].pc - query).norm(), store[j].pc}, j, false);
      push(j);
    }
  }
  if (!best_polished) {
    const Candidate c = polish(tr, store[best_span], query);
    if (failed()) return finish(tr.status, "closest_point: " + tr.message);
    if (c.d <= best.d) best = c;
  }
  out.s = best.s;
  out.point = best.p;
  out.distance = best.d;
  const double lower = std::min({stop_lb, leaf_lb, dropped_lb});
  out.error_estimate = best.d - std::min(lower, best.d);
  out.error = out.error_estimate / L;
  if (capped)
    return finish(Status::max_iterations, "closest_point: max_spans = " + std::to_string(options.max_spans) +
                                              " reached; best distance " + format_number(best.d) +
                                              ", global minimum not below " + format_number(lower));
  const Status s = grade_error(out.error, options.tolerance, options.accept);
  return finish(s, s == Status::ok ? "" : "closest_point: error bound " + format_number(out.error) + " above the tolerance");
}

}  // namespace lac
