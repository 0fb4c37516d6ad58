// Polylines compute every point from a point known to be right (the reference point, a segment's
// start or the last good point), so a point that fails never shifts the others
// (curves/curve.hpp, PositionResult).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"

namespace lac {
namespace {

// The reproducer: the first piece (0 → −0.5, 15810 rad of turning) exhausted Gauss–Kronrod's
// budget and left s = 0.27, 0.655 and 1.04 at the coordinates of s = −0.115. Now that point is
// flagged and the others are integrated from the reference point and from each other.
TEST(Polyline, QuadraticFailedPointDoesNotShiftTheOthers) {
  const QuadraticLaCurve c(2.612227706329021, 0.23347280458415112, 1.92314224068905);
  const auto pts = polyline(c, -0.5, 1.04, 5, GaussKronrod{});
  ASSERT_EQ(pts.size(), 5u);
  EXPECT_NE(pts[0].status, Status::ok);  // tolerance_not_met: 21 Kronrod nodes per panel over 15810 rad
  for (size_t k = 1; k < pts.size(); ++k) {
    SCOPED_TRACE("s = " + std::to_string(pts[k].point.s));
    EXPECT_EQ(pts[k].status, Status::ok) << pts[k].message;
    const auto direct = position_at(c, pts[k].point.s, GaussKronrod{});
    EXPECT_LT(std::abs(pts[k].point.position - direct.point.position), 1e-13);
    EXPECT_LT(pts[k].error_estimate, 1e-13);
  }
  EXPECT_NE(pts[2].point.position, pts[3].point.position);
}

// LaCurve, per-piece path: a first piece that cannot meet the tolerance (a tiny interval budget)
// is flagged; the later points are integrated from the reference point and then from each other.
TEST(Polyline, LaCurveRecoversAfterAFailedPoint) {
  const LaCurve c(2.0, 1.0);
  GaussKronrod gk;
  gk.max_intervals = 2;
  gk.tol = 1e-15;
  const auto pts = polyline(c, Parameter::theta, 30.0, 0.5, 4, gk, Form::theta);
  EXPECT_EQ(pts[0].status, Status::tolerance_not_met);
  for (size_t k = 1; k < pts.size(); ++k) {
    const auto direct = position_at(c, Parameter::theta, pts[k].point.theta, GaussKronrod{}, Form::theta);
    if (usable(pts[k].status))
      EXPECT_LT(std::abs(pts[k].point.position - direct.point.position), 1e-6 * std::abs(direct.point.position));
  }
  EXPECT_EQ(pts.back().status, Status::ok) << pts.back().message;  // from θ = 0, not through θ = 30
}

// The RK4 sweep: once its running sum overflows, the remaining points are integrated piece by
// piece from the last good point; a point that cannot be is flagged and holds that point's position.
TEST(Polyline, Rk4SweepOverflowFlagsPointsWithoutNan) {
  const LaCurve c(1.0, 1.0);  // ρ = e^θ: positions near 1e307 at θ = 708
  const auto pts = polyline(c, Parameter::theta, 700.0, 709.7, 8, Rk4{.h = 1e-3});
  bool failed = false;
  for (size_t k = 0; k < pts.size(); ++k) {
    const auto& p = pts[k];
    ASSERT_TRUE(std::isfinite(p.point.position.real()) && std::isfinite(p.point.position.imag())) << k;
    if (!usable(p.status)) {
      failed = true;
      EXPECT_TRUE(std::isinf(p.error_estimate));
      EXPECT_EQ(p.point.position, pts[k - 1].point.position);  // the last good point (no good one in between)
    } else {
      EXPECT_FALSE(failed) << "a good point after a failed one is integrated from the last good point";
    }
  }
  EXPECT_TRUE(failed);
}

}  // namespace
}  // namespace lac
