// geometry/intersections: lines through spirals (many crossings) and tangent lines, curve/curve
// crossings and a tangential touch, against sign changes of the dense long-double model polished
// by bisection (lines) or Newton in long double (curves); the two algorithms against each other
// (a straight segment as a curve); the caps.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "curves.hpp"
#include "lac/geometry/intersections.hpp"
#include "lac/geometry/transforms.hpp"
#include "reference_curve.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using test::cld;
using test::ld;

cld to_ld(std::complex<double> z) { return {z.real(), z.imag()}; }

// Arc lengths where the model crosses the line (sign changes of D × (p − P) between samples).
std::vector<double> reference_line(const test::RefCurve& ref, cld P, cld D) {
  std::vector<double> out;
  const auto& S = ref.samples;
  const auto h = [&](cld p) { return test::cross(D, p - P); };
  for (size_t i = 0; i + 1 < S.size(); ++i) {
    if (S[i].seg != S[i + 1].seg) continue;
    const ld a = h(S[i].p), b = h(S[i + 1].p);
    if (!((a < 0 && b >= 0) || (a > 0 && b <= 0))) continue;
    const size_t k = S[i].seg;
    const ld u = test::bisect([&](ld v) { return h(ref.position(k, v)); }, S[i].u, S[i + 1].u);
    out.push_back(double(ref.segs[k].s_begin + ref.segs[k].scale * (u - ref.segs[k].ua)));
  }
  return out;
}

TEST(GeometryIntersectLine, AllCrossingsMatchTheDenseReference) {
  long most = 0;
  double worst = 0;
  for (const PlanarCurve& c : test::test_curves()) {
    const test::RefCurve ref(c, 4000, 0.005L);
    const double L = c.length();
    const BoundingBox box = c.bounding_box();
    const std::complex<double> mid = 0.5 * (box.lo + box.hi);
    for (int i = 0; i < 12; ++i) {
      const std::complex<double> P = mid + 0.05 * (box.hi - box.lo) * std::complex<double>(std::cos(i), std::sin(2 * i));
      const std::complex<double> D = std::polar(1.0, 0.37 + i * std::numbers::pi / 12);
      const Intersections r = intersect_line(c, P, D);
      ASSERT_EQ(r.status, Status::ok) << r.message;
      const std::vector<double> e = reference_line(ref, to_ld(P), to_ld(D));
      ASSERT_EQ(r.points.size(), e.size()) << "line " << i;
      most = std::max<long>(most, long(e.size()));
      for (size_t j = 0; j < e.size(); ++j) {
        EXPECT_EQ(r.points[j].kind, IntersectionKind::crossing);
        EXPECT_NEAR(r.points[j].s, e[j], 1e-10 * L);
        worst = std::max(worst, std::abs(r.points[j].s - e[j]) / L);
        // On the line: the point is P + t D.
        EXPECT_NEAR(std::abs(r.points[j].point - (P + r.points[j].t * D)), 0.0, 1e-12 * L);
        if (j > 0) {
          EXPECT_LT(r.points[j - 1].s, r.points[j].s);
        }
      }
    }
  }
  EXPECT_GE(most, 8);  // lines through the clothoid spiral's turns
  std::printf("intersect_line: up to %ld crossings per line, worst |Δs|/L = %.2e\n", most, worst);
}

TEST(GeometryIntersectLine, TangentLineGivesATouch) {
  for (const PlanarCurve& c : test::test_curves()) {
    const test::RefCurve ref(c, 4000, 0.005L);
    const double L = c.length();
    for (double f : {0.31, 0.62, 0.9}) {
      const double s0 = f * L;
      const PositionResult p = position_at(c, s0);
      const std::complex<double> T = std::polar(1.0, p.point.theta);
      const Intersections r = intersect_line(c, p.point.position, T);
      ASSERT_EQ(r.status, Status::ok) << r.message;
      int touches = 0;
      std::vector<double> crossings;
      for (const Intersection& x : r.points) {
        if (x.kind == IntersectionKind::tangent) {
          ++touches;
          EXPECT_NEAR(x.s, s0, 1e-6 * L);  // a touch fixes s only to √(tolerance)
        } else {
          crossings.push_back(x.s);
        }
      }
      EXPECT_EQ(touches, 1) << "s0 = " << s0;
      // The reference's sign changes, less the two the touch may create within √tolerance of s0.
      std::vector<double> e;
      for (double s : reference_line(ref, to_ld(p.point.position), to_ld(T)))
        if (std::abs(s - s0) > 1e-4 * L) e.push_back(s);
      ASSERT_EQ(crossings.size(), e.size()) << "s0 = " << s0;
      for (size_t j = 0; j < e.size(); ++j) EXPECT_NEAR(crossings[j], e[j], 1e-10 * L);
    }
  }
}

TEST(GeometryIntersectCurves, CrossingsMatchTheDenseReference) {
  const PlanarCurve a = test::clothoid_spiral();
  const BoundingBox box = a.bounding_box();
  const std::complex<double> mid = 0.5 * (box.lo + box.hi);
  // The other two test curves, scaled and moved onto the spiral's turns, and a rotated copy of it.
  const std::vector<PlanarCurve> others{
      translated(scaled(test::log_spiral(), 0.8), mid - 0.3),
      translated(scaled(test::compound(), 0.7), mid - std::complex<double>(1.5, 1.0)),
      rotated(a, 0.9, mid + std::complex<double>(0.1, 0.05))};
  const test::RefCurve ra(a, 1500, 0.01L);
  long total = 0, spans = 0, evaluations = 0;
  double worst = 0;
  for (const PlanarCurve& b : others) {
    const Intersections r = intersect_curves(a, b);
    spans += r.spans, evaluations += r.evaluations;
    ASSERT_EQ(r.status, Status::ok) << r.message;
    const test::RefCurve rb(b, 1500, 0.01L);
    const std::vector<test::RefCrossing> e = test::reference_curves(ra, rb);
    ASSERT_EQ(r.points.size(), e.size());
    total += long(e.size());
    for (size_t j = 0; j < e.size(); ++j) {
      EXPECT_EQ(r.points[j].kind, IntersectionKind::crossing);
      EXPECT_NEAR(r.points[j].s, e[j].s, 1e-10 * a.length());
      EXPECT_NEAR(r.points[j].t, e[j].t, 1e-10 * a.length());
      worst = std::max({worst, std::abs(r.points[j].s - e[j].s) / a.length(), std::abs(r.points[j].t - e[j].t) / a.length()});
    }
  }
  EXPECT_GE(total, 10);
  std::printf("intersect_curves: %ld crossings over 3 pairs, worst |Δs|/L = %.2e; %ld spans, %ld evaluations in all\n", total,
              worst, spans, evaluations);
}

TEST(GeometryIntersectCurves, TangentSegmentAgreesWithTheLine) {
  for (const PlanarCurve& c : test::test_curves()) {
    const double L = c.length();
    const BoundingBox box = c.bounding_box();
    const double reach = 2 * std::abs(box.hi - box.lo);
    for (double f : {0.31, 0.62}) {
      const double s0 = f * L;
      const PositionResult p = position_at(c, s0);
      const std::complex<double> T = std::polar(1.0, p.point.theta);
      // A straight LA segment (α = −1, q = 0: κ = 0) along the tangent at s0, through the box.
      const PlanarCurve line({LaSegment(LaLaw{-1.0}, 0.0, 1.0, 0.0, 0.0, 0.0, {p.point.position - 0.5 * reach * T, reach, T})});
      const Intersections x = intersect_curves(c, line), y = intersect_line(c, p.point.position, T);
      ASSERT_EQ(x.status, Status::ok) << x.message;
      ASSERT_EQ(x.points.size(), y.points.size()) << "s0 = " << s0;
      for (size_t j = 0; j < x.points.size(); ++j) {
        EXPECT_EQ(x.points[j].kind, y.points[j].kind) << "s = " << x.points[j].s;
        const double tol = x.points[j].kind == IntersectionKind::tangent ? 1e-6 * L : 1e-10 * L;
        EXPECT_NEAR(x.points[j].s, y.points[j].s, tol);
        EXPECT_NEAR(x.points[j].t, y.points[j].t + 0.5 * reach, tol);  // arc length on the segment
      }
    }
  }
}

// The spiral and its mirror image about its tangent line at s0: they touch at s0, meet on the
// line where the spiral crosses it (s = t), and elsewhere in mirror pairs (s, t) and (t, s).
TEST(GeometryIntersectCurves, MirrorImageAboutATangentLine) {
  const PlanarCurve c = test::clothoid_spiral();
  const double L = c.length(), s0 = 6.0;
  const PositionResult p = position_at(c, s0);
  const std::complex<double> T = std::polar(1.0, p.point.theta);
  const Intersections x = intersect_curves(c, mirrored(c, p.point.position, T));
  ASSERT_EQ(x.status, Status::ok) << x.message;
  const Intersections line = intersect_line(c, p.point.position, T);
  std::vector<double> on_line, line_s;
  int touches = 0;
  for (const Intersection& q : x.points) {
    if (q.kind == IntersectionKind::tangent) {
      ++touches;
      EXPECT_NEAR(q.s, s0, 1e-6 * L);
      EXPECT_NEAR(q.t, s0, 1e-6 * L);
      continue;
    }
    if (std::abs(q.s - q.t) <= 1e-9 * L) {
      on_line.push_back(q.s);
      continue;
    }
    int mates = 0;  // its mirror pair
    for (const Intersection& r : x.points) mates += std::abs(r.s - q.t) <= 1e-10 * L && std::abs(r.t - q.s) <= 1e-10 * L;
    EXPECT_EQ(mates, 1) << "s = " << q.s;
  }
  EXPECT_EQ(touches, 1);
  for (const Intersection& q : line.points)
    if (q.kind == IntersectionKind::crossing) line_s.push_back(q.s);
  ASSERT_EQ(on_line.size(), line_s.size());
  for (size_t j = 0; j < line_s.size(); ++j) EXPECT_NEAR(on_line[j], line_s[j], 1e-10 * L);
  EXPECT_GE(x.points.size(), 10u);
}

TEST(GeometryIntersect, CapsAndBadInput) {
  const PlanarCurve c = test::log_spiral();
  // A curve along itself: near-parallel pairs everywhere; the search stops with a status that
  // is not usable.
  GeometryOptions o;
  o.max_spans = 5000;
  const Intersections self = intersect_curves(c, c, o);
  EXPECT_FALSE(usable(self.status)) << to_string(self.status);
  EXPECT_FALSE(self.message.empty());
  EXPECT_LE(self.spans, o.max_spans);
  o.max_spans = 16;
  // A clothoid turning 101 rad: about 32 pieces where the tangent is not parallel to the line.
  const PlanarCurve tight = test::chain({{LaLaw{-1.0}, 0.0, 1.0, 2.0, 200.0, 10.0}}, 0.0, {0, 0}, 0.0);
  const Intersections few = intersect_line(tight, {0, 0}, {1, 0}, o);
  EXPECT_EQ(few.status, Status::max_iterations);
  // More intersections than max_points: not usable, the first ones kept.
  GeometryOptions few_points;
  few_points.max_points = 3;
  const std::complex<double> eye = position_at(tight, 0.999 * tight.length()).point.position;  // inside every turn
  const Intersections all = intersect_line(tight, eye, {1, 0});
  ASSERT_EQ(all.status, Status::ok);
  ASSERT_GT(all.points.size(), 3u);
  const Intersections many = intersect_line(tight, eye, {1, 0}, few_points);
  EXPECT_EQ(many.status, Status::max_iterations) << many.message;
  EXPECT_GT(many.points.size(), 3u);
  const PlanarCurve spiral = test::clothoid_spiral();
  const BoundingBox sb = spiral.bounding_box();
  const Intersections pairs =
      intersect_curves(spiral, rotated(spiral, 0.9, 0.5 * (sb.lo + sb.hi) + std::complex<double>(0.1, 0.05)), few_points);
  EXPECT_EQ(pairs.status, Status::max_iterations) << pairs.message;
  GeometryOptions bad;
  bad.max_points = 0;
  EXPECT_EQ(test::thrown_parameter([&] { intersect_line(c, {0, 0}, {1, 0}, bad); }), "max_points");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_line(c, {0, 0}, {0, 0}); }), "direction");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_line(c, {NAN, 0}, {1, 0}); }), "point");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_curves(c, PlanarCurve{}); }), "b");
}

}  // namespace
}  // namespace lac
