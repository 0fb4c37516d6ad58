// PlanarCurve (curves/planar/planar_curve.hpp): a G2 triple in the normalized frame of 004 placed
// by a similarity, a compound curve of different α; evaluation at any s, continuity at the joints,
// sampling with every method, the bounding box, reversal, and the curve-model concept.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"

namespace lac {
namespace {

static_assert(PlanarCurveModel<LaCurve, Rk45>);
static_assert(PlanarCurveModel<QuadraticLaCurve, Rk4>);
static_assert(PlanarCurveModel<PlanarCurve, Rk4>);

// Three segments on S ∈ [0, 0.25], [0.25, 0.75], [0.75, 1] with q linear on each and continuous,
// φ continuous (as the G2 construction builds them), placed with scale h·chord and the chord's
// direction; each start from the integral of the previous segments (Gauss–Legendre, as 004's
// solvers do).
PlanarCurve triple(double alpha, std::array<double, 4> q, double phi_s, std::complex<double> origin, double scale,
                   double angle) {
  const LaLaw law{alpha, 1.0};
  const double S[4] = {0.0, 0.25, 0.75, 1.0};
  std::vector<LaSegment> segs;
  std::complex<double> start = origin;
  double phi = phi_s;
  const std::complex<double> rotation = std::polar(1.0, angle);
  for (int i = 0; i < 3; ++i) {
    const LaSegment seg(law, S[i], S[i + 1], q[i], q[i + 1], phi, Placement{start, scale, rotation});
    segs.push_back(seg);
    start = position_at(seg, seg.length(), GaussLegendre{}).point.position;
    phi = seg.phi_b();
  }
  return PlanarCurve(segs);
}

std::vector<PlanarCurve> curves() {
  return {triple(-1.0, {2.0, -1.0, 0.5, 3.0}, 0.3, {1, 2}, 4.0, 0.4),       // clothoids, two inflections
          triple(-0.5, {1.5, -0.75, -2.0, 0.25}, -0.2, {0, 0}, 1.0, -1.0),  // graded pieces
          triple(2.0, {0.5, 1.0, 2.0, 1.5}, 0.0, {-3, 1}, 2.5, 2.0),
          triple(0.0, {0.0, 1.0, -0.5, 0.25}, 0.1, {0, 5}, 0.75, 3.0)};
}

TEST(PlanarCurve, JointsAreG2AndEvaluationIsContinuous) {
  for (const PlanarCurve& c : curves()) {
    const auto joints = c.joints();
    ASSERT_EQ(joints.size(), 2u);
    for (size_t k = 0; k < joints.size(); ++k) {
      EXPECT_EQ(joints[k].status, Status::ok);
      EXPECT_EQ(joints[k].position_gap, 0.0);  // each start is the previous end by the same method
      EXPECT_EQ(joints[k].angle_gap, 0.0);
      EXPECT_EQ(joints[k].curvature_gap, 0.0);
      EXPECT_EQ(joints[k].s, c.segment_start(k + 1));
      EXPECT_LT(c.joints(GaussKronrod{})[k].position_gap, 1e-14 * c.length());
    }
    for (size_t k = 1; k < c.segments().size(); ++k) {
      const double s = c.segment_start(k), d = 1e-9 * c.length();
      EXPECT_EQ(c.segment_at(s), k);
      EXPECT_NEAR(c.theta_at(s - d), c.theta_at(s), 1e-7);
      EXPECT_NEAR(c.kappa_at(s - d), c.kappa_at(s), 1e-6 * (1 + std::abs(c.kappa_at(s))));
      const auto before = position_at(c, s - d), at = position_at(c, s);
      EXPECT_LT(std::abs(before.point.position - at.point.position), 2 * d);
      EXPECT_EQ(at.point.position, c.segments()[k].start());
    }
    // frame_at is the closed forms; dκ/ds against a central difference.
    for (double f : {0.1, 0.4, 0.9}) {
      const double s = f * c.length(), h = 1e-6 * c.length();
      const CurvePoint p = c.frame_at(s);
      EXPECT_EQ(p.theta, c.theta_at(s));
      EXPECT_EQ(p.kappa, c.kappa_at(s));
      EXPECT_NEAR(c.dkappa_ds_at(s), (c.kappa_at(s + h) - c.kappa_at(s - h)) / (2 * h),
                  1e-5 * (1 + std::abs(c.dkappa_ds_at(s))));
    }
  }
}

template <class M>
void check_sampling(const PlanarCurve& c, const M& method, double tolerance) {
  const auto pts = c.sample(41, method);
  ASSERT_EQ(pts.size(), 41u);
  EXPECT_EQ(pts.front().point.s, 0.0);
  EXPECT_EQ(pts.back().point.s, c.length());
  for (const auto& p : pts) {
    ASSERT_TRUE(usable(p.status)) << p.message;
    const auto direct = position_at(c, p.point.s, GaussKronrod{});
    EXPECT_LT(std::abs(p.point.position - direct.point.position), tolerance * c.length());
    EXPECT_EQ(p.point.theta, c.theta_at(p.point.s));
  }
}

TEST(PlanarCurve, SamplingWithEveryMethod) {
  for (const PlanarCurve& c : curves()) {
    check_sampling(c, GaussLegendre{}, 1e-13);
    check_sampling(c, GaussKronrod{}, 1e-13);
    check_sampling(c, Rk45{}, 1e-11);
    check_sampling(c, Rk4{.h = 1e-3}, 1e-9);
  }
}

// The box holds every point of a dense polyline, and its sides are reached (to the polyline's
// resolution): the extremes are at segment ends or where θ ≡ 0 (mod π/2).
TEST(PlanarCurve, BoundingBoxIsExact) {
  for (const PlanarCurve& c : curves()) {
    const BoundingBox box = c.bounding_box();
    ASSERT_EQ(box.status, Status::ok) << box.message;
    const auto pts = c.sample(4001, GaussKronrod{});
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const auto& p : pts) {
      const auto z = p.point.position;
      x0 = std::min(x0, z.real()), x1 = std::max(x1, z.real()), y0 = std::min(y0, z.imag()), y1 = std::max(y1, z.imag());
    }
    const double tiny = 1e-13 * c.length(), resolution = 1e-5 * c.length();
    EXPECT_LE(box.lo.real(), x0 + tiny);
    EXPECT_LE(box.lo.imag(), y0 + tiny);
    EXPECT_GE(box.hi.real(), x1 - tiny);
    EXPECT_GE(box.hi.imag(), y1 - tiny);
    EXPECT_GT(box.lo.real(), x0 - resolution);
    EXPECT_GT(box.lo.imag(), y0 - resolution);
    EXPECT_LT(box.hi.real(), x1 + resolution);
    EXPECT_LT(box.hi.imag(), y1 + resolution);
    // The candidates lie where the tangent is axis-parallel.
    for (size_t k = 0; k < c.segments().size(); ++k) {
      const LaSegment& seg = c.segments()[k];
      const auto us = c.extreme_candidates(k);
      ASSERT_GE(us.size(), 2u);
      for (size_t i = 1; i + 1 < us.size(); ++i) {
        const double theta = seg.rotation_angle() + seg.phi_at(us[i]);
        if (us[i] == us[i - 1] || us[i] == us[i + 1]) continue;  // a piece end
        const bool inflection = seg.inflection_u() && us[i] == *seg.inflection_u();
        if (!inflection) EXPECT_NEAR(std::remainder(theta, std::numbers::pi / 2), 0.0, 1e-12);
      }
    }
  }
}

TEST(PlanarCurve, ReversedIsTheSameCurveBackwards) {
  for (const PlanarCurve& c : curves()) {
    const auto end = position_at(c, c.length(), GaussKronrod{});
    const PlanarCurve r = c.reversed(end.point.position);
    ASSERT_EQ(r.segments().size(), c.segments().size());
    EXPECT_NEAR(r.length(), c.length(), 1e-14 * c.length());
    for (double f : {0.0, 0.2, 0.5, 0.77, 1.0}) {
      const double s = f * c.length();
      const double back = std::clamp(r.length() - s, 0.0, r.length());
      EXPECT_LT(std::abs(position_at(r, back, GaussKronrod{}).point.position - position_at(c, s, GaussKronrod{}).point.position),
                1e-13 * c.length());
      EXPECT_NEAR(r.kappa_at(back), -c.kappa_at(s), 1e-12 * (1 + std::abs(c.kappa_at(s))));
    }
  }
}

// A piece neither the segment kernel nor the graded fast path resolves (between two samples near
// the end of a spiral whose κ grows like e^(25u), turning 7e10 rad) flags those samples only: they
// hold the last good sample's position (the point they were to be integrated from) with an
// infinite estimate; the samples before them and those of the next segment (integrated from its own
// start) are computed, and agree with rk45 wherever rk45 itself succeeds.
TEST(PlanarCurve, FailedSamplesAreFlaggedAndDoNotShiftOthers) {
  const LaSegment a(LaLaw{-1.0}, 0.0, 1.0, 1.0, 2.0, 0.0);
  const LaSegment spiral(LaLaw{0.0, 1.0}, 0.0, 1.0, 0.0, 25.0, 0.0, Placement{{1, 0}, 1.0, {1, 0}});
  const LaSegment b(LaLaw{-1.0}, 0.0, 1.0, 1.0, 2.0, 0.0, Placement{{5, 5}, 1.0, {0, 1}});
  const PlanarCurve c({a, spiral, b});
  const auto pts = c.sample(31);
  const auto reference = c.sample(31, Rk45{});
  int flagged = 0, computed = 0;
  std::complex<double> last_good;
  for (size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    SCOPED_TRACE("s = " + std::to_string(p.point.s));
    if (p.status == Status::ok) {
      if (reference[i].status == Status::ok) EXPECT_LT(std::abs(p.point.position - reference[i].point.position), 1e-10);
      ++computed;
      last_good = p.point.position;
      continue;
    }
    EXPECT_EQ(c.segment_at(p.point.s), 1u);
    EXPECT_EQ(p.status, Status::max_iterations);
    EXPECT_FALSE(p.message.empty());
    EXPECT_EQ(p.point.position, last_good);
    EXPECT_TRUE(std::isinf(p.error_estimate));
    ++flagged;
  }
  EXPECT_GE(flagged, 1);
  EXPECT_GE(computed, 21);  // segments a and b, and the spiral's first samples
}

TEST(PlanarCurve, InvalidInput) {
  EXPECT_THROW(PlanarCurve(std::vector<LaSegment>{}), InputError);
  const PlanarCurve empty;
  EXPECT_EQ(empty.length(), 0.0);
  EXPECT_THROW(empty.frame_at(0.0), InputError);
  EXPECT_THROW(empty.sample(3), InputError);
  const PlanarCurve c = curves()[0];
  EXPECT_THROW(c.frame_at(-1e-9), InputError);
  EXPECT_THROW(position_at(c, c.length() * 1.001), InputError);
  EXPECT_THROW(c.sample(1), InputError);
}

TEST(Numeric, IntervalAndWrapAngle) {
  const Interval open{0, 1}, closed{0, 1, true, true};
  EXPECT_FALSE(open.contains(0));
  EXPECT_TRUE(closed.contains(0));
  EXPECT_TRUE(closed.contains(1));
  EXPECT_FALSE(closed.contains(1.5));
  EXPECT_EQ(wrap_angle(-std::numbers::pi), std::numbers::pi);
  EXPECT_EQ(wrap_angle(std::numbers::pi), std::numbers::pi);
  EXPECT_NEAR(wrap_angle(7.0), 7.0 - 2 * std::numbers::pi, 1e-15);
  EXPECT_EQ(log1p_ratio(0.0), 1.0);
  EXPECT_EQ(expm1_ratio(0.0), 1.0);
}

// power(x, e): products and sqrt for the exponents of α = ±1, ±2, ±1/2 within 4 ulp of std::pow
// (correctly rounded to < 1 ulp in glibc), std::pow itself for every other exponent.
TEST(Numeric, PowerMatchesStdPow) {
  std::vector<double> xs{0.0, 1e-80, 3.7e-9, 0.1, 0.75, 1.0, 1.3, 2.0, 123.456, 4.4e13, 1e75};
  for (int i = -8; i <= 8; ++i) {
    const double e = 0.5 * i;
    for (double x : xs) {
      const double want = std::pow(x, e), got = power(x, e);
      if (std::isinf(want) || want == 0) {
        EXPECT_EQ(got, want) << x << "^" << e;
      } else {
        EXPECT_LE(std::abs(got - want), 4 * std::numeric_limits<double>::epsilon() * std::abs(want)) << x << "^" << e;
      }
    }
  }
  // Thirds: against long double, the exponent k/3 exact there (std::pow(x, k/3.0) differs by
  // |log x|·ulp(k/3) from x^(k/3) itself).
  for (int k = -8; k <= 8; ++k) {
    if (k % 3 == 0) continue;
    for (double x : xs) {
      if (x == 0) continue;
      const long double want = std::pow(static_cast<long double>(x), static_cast<long double>(k) / 3);
      const double got = power(x, k / 3.0);
      EXPECT_LE(std::abs(got - want), 12 * std::numeric_limits<double>::epsilon() * std::abs(want)) << x << "^" << k << "/3";
    }
  }
  EXPECT_EQ(power(0.0, 2.0 / 3), 0.0);
  EXPECT_EQ(power(0.0, -1.0 / 3), HUGE_VAL);
  for (double e : {0.3, 4.5, -4.5, 7.0, 3.0 + 1.0 / 3, 1e-9})
    for (double x : xs) EXPECT_EQ(power(x, e), std::pow(x, e)) << x << "^" << e;
  EXPECT_EQ(power(-2.0, 3.0), -8.0);
  EXPECT_EQ(power(-2.0, -2.0), 0.25);
  EXPECT_TRUE(std::isnan(power(-2.0, 0.5)));
  EXPECT_TRUE(std::isnan(power(std::nan(""), 2.0)));
}

}  // namespace
}  // namespace lac

namespace lac {
namespace {
// igf samples a PlanarCurve by its closed form per segment (la_segment_igf.hpp), each point from its
// segment's start: the same points as the segment kernel within both estimates.
TEST(PlanarCurve, IgfSamplesByItsClosedForm) {
  for (const PlanarCurve& c : curves()) {
    const auto by_igf = polyline(c, 0.0, c.length(), 17, Igf{});
    const auto by_kernel = c.sample(17);
    ASSERT_EQ(by_igf.size(), by_kernel.size());
    for (size_t i = 0; i < by_igf.size(); ++i) {
      SCOPED_TRACE("point " + std::to_string(i));
      ASSERT_TRUE(usable(by_igf[i].status)) << by_igf[i].message;
      EXPECT_LE(std::abs(by_igf[i].point.position - by_kernel[i].point.position),
                by_igf[i].error_estimate + by_kernel[i].error_estimate + 1e-14 * (1 + c.length()));
    }
    EXPECT_GT(by_igf.back().evaluations, 0);
  }
}
}  // namespace
}  // namespace lac
