#include "lac/geometry/space_intersections.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "lac/common/error.hpp"
#include "lac/geometry/detail/roots.hpp"
#include "lac/geometry/detail/space_spans.hpp"

namespace lac {

namespace {

constexpr std::uintmax_t kPolishIterations = 100;
constexpr int kBrentBits = 40;

struct End {
  size_t piece = 0;
  double s = 0, h = 0;
  SpacePoint frame;
};

}  // namespace

SpaceIntersections intersect_plane(const SpaceCurve& curve, const Vec3& point, const Vec3& normal,
                                   const GeometryOptions& options) {
  options.validate("intersect_plane");
  if (!point.allFinite()) throw_input_error("intersect_plane", "point", "all three coordinates must be finite");
  if (!normal.allFinite() || !(normal.norm() > 0))
    throw_input_error("intersect_plane", "normal", "all three coordinates finite and not all zero");
  curve.check_s(0.0, "curve");
  const Vec3 n = normal.normalized();
  // Leaves are halved down to, and touches found within, tolerance × length.
  const double L = curve.length(), resolution = options.tolerance * L;
  const double tangent_angle = std::sqrt(options.tolerance);
  SpaceIntersections out;
  detail::SpaceTracer tr(curve);
  const auto finish = [&](Status s, std::string m) {
    std::sort(out.points.begin(), out.points.end(), [](const auto& a, const auto& b) { return a.s < b.s; });
    // One point per tangency: near a touch the sign of h is rounding noise (h is quadratic in s
    // there), which shows as pairs of crossings; tangent points within the touch's resolution
    // (√tolerance × length) of each other are one contact, kept at its smallest |h|.
    std::vector<SpaceIntersection> kept;
    for (const SpaceIntersection& x : out.points) {
      if (!kept.empty() && x.s - kept.back().s <= 2 * tangent_angle * L &&
          (x.kind == IntersectionKind::tangent || kept.back().kind == IntersectionKind::tangent)) {
        if (x.residual < kept.back().residual) kept.back() = x;
        continue;
      }
      kept.push_back(x);
    }
    out.points = std::move(kept);
    out.evaluations = tr.evaluations;
    out.spans = tr.spans;
    out.status = s;
    out.message = std::move(m);
    return out;
  };
  const auto h_of = [&](const SpacePoint& f) { return n.dot(f.p - point); };
  const auto kind_of = [&](const SpacePoint& f) {
    return std::asin(std::min(1.0, std::abs(n.dot(f.t)))) < tangent_angle ? IntersectionKind::tangent
                                                                          : IntersectionKind::crossing;
  };
  // The last span end evaluated: the next span in s order starts there (on the same piece; a
  // joint is evaluated on each side, by each piece's own integration).
  std::optional<End> cached;
  const auto end_at = [&](size_t piece, double s) {
    if (cached && cached->piece == piece && cached->s == s) return *cached;
    const SpacePoint f = tr.at(piece, s);
    cached = End{piece, s, h_of(f), f};
    return *cached;
  };
  const auto add = [&](double s, const SpacePoint& f, IntersectionKind kind) {
    out.points.push_back({s, f.p, std::abs(h_of(f)), kind});
  };
  const auto crossing = [&](const detail::SpaceSpan& sp, const End& a, const End& b) {
    const double s = detail::root_in([&](double x) { return h_of(tr.at(sp.piece, x)); }, a.s, b.s, a.h, b.h,
                                     kPolishIterations);
    const SpacePoint f = tr.at(sp.piece, s);
    add(s, f, kind_of(f));
  };

  std::vector<detail::SpaceSpan> stack = detail::cover(tr, options);
  if (stack.empty()) return finish(tr.status, "intersect_plane: " + tr.message);
  std::reverse(stack.begin(), stack.end());  // the back is the next span in s order
  while (!stack.empty()) {
    const detail::SpaceSpan sp = stack.back();
    stack.pop_back();
    const double r = sp.half(), slope = std::abs(n.dot(sp.tc)), hc = n.dot(sp.pc - point);
    if (std::abs(hc) - r * (slope + sp.turn()) > resolution) continue;  // no root and no touch on the span
    const bool monotonic = slope > sp.turn();
    if (monotonic || 2 * r <= resolution || !(sp.sc() > sp.s0 && sp.sc() < sp.s1)) {
      const End a = end_at(sp.piece, sp.s0), b = end_at(sp.piece, sp.s1);
      if (tr.failed()) return finish(tr.status, "intersect_plane: " + tr.message);
      if (a.h == 0) add(a.s, a.frame, kind_of(a.frame));
      else if ((a.h < 0 && b.h > 0) || (a.h > 0 && b.h < 0)) crossing(sp, a, b);
      else if (!monotonic && b.h != 0) {
        // A leaf whose tangent may lie in the plane, without a sign change: the extremum of h
        // (Brent on ±h) is a touch when it comes within the touch tolerance of the plane.
        const double sign = a.h > 0 ? 1.0 : -1.0;
        std::uintmax_t iterations = kPolishIterations;
        const auto m = boost::math::tools::brent_find_minima([&](double s) { return sign * h_of(tr.at(sp.piece, s)); },
                                                             sp.s0, sp.s1, kBrentBits, iterations);
        if (std::abs(m.second) <= resolution) add(m.first, tr.at(sp.piece, m.first), IntersectionKind::tangent);
      }
      if (tr.failed()) return finish(tr.status, "intersect_plane: " + tr.message);
      if (static_cast<long>(out.points.size()) > options.max_points)
        return finish(Status::max_iterations, "intersect_plane: more than max_points = " +
                                                  std::to_string(options.max_points) + " intersections");
      continue;
    }
    if (tr.spans + 2 > options.max_spans)
      return finish(Status::max_iterations, "intersect_plane: max_spans = " + std::to_string(options.max_spans) +
                                                " reached before s = " + format_number(sp.s0) + " (points before it kept)");
    const double mid = sp.sc();
    stack.push_back(tr.make(sp.piece, mid, sp.s1));
    stack.push_back(tr.make(sp.piece, sp.s0, mid));
    if (tr.failed()) return finish(tr.status, "intersect_plane: " + tr.message);
  }
  // The curve's end: a root exactly there has no span after it to start at.
  const size_t last = curve.pieces().size() - 1;
  const End e = end_at(last, L);
  if (e.h == 0 && (out.points.empty() || out.points.back().s < L)) add(L, e.frame, kind_of(e.frame));
  return finish(tr.failed() ? tr.status : Status::ok, tr.failed() ? "intersect_plane: " + tr.message : "");
}

}  // namespace lac
