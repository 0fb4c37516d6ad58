// geometry/offset: offset positions p + dN against the long-double model, the offset's curvature
// against a finite difference of offset positions, and the first cusp (1 − dκ = 0) against
// bisection on the model's closed-form κ — with a cusp inside a segment, at a G1 joint where κ
// jumps, at the start, and none.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "curves.hpp"
#include "lac/geometry/offset.hpp"
#include "lac/geometry/transforms.hpp"
#include "reference_curve.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using test::cld;
using test::ld;

TEST(GeometryOffset, PositionsAndCurvatureMatchTheModel) {
  for (const PlanarCurve& c : test::test_curves()) {
    const test::RefCurve ref(c, 200);
    const double L = c.length();
    for (double d : {-0.3, 0.05, 0.2}) {
      for (int i = 1; i < 20; ++i) {
        const double s = L * i / 20.0;
        const OffsetPoint o = offset_at(c, s, d);
        ASSERT_EQ(o.status, Status::ok);
        const size_t k = c.segment_at(s);
        const ld u = ref.segs[k].u_of(ld(c.local_s(k, s)));
        const cld e = ref.position(k, u) + ld(d) * cld(0, 1) * ref.tangent(k, u);
        EXPECT_LE(std::abs(o.position - std::complex<double>(double(e.real()), double(e.imag()))), 1e-13 * L + o.error_estimate);
        EXPECT_NEAR(o.factor, 1 - d * double(ref.segs[k].kappa(u)), 1e-12);
        // κ of the offset: turning of its tangent over its arc length, by central differences.
        const double h = 1e-4 * L;
        if (s - h > c.segment_start(k) && s + h < c.segment_start(k + 1) && std::abs(o.factor) > 0.1) {
          const OffsetPoint a = offset_at(c, s - h, d), b = offset_at(c, s + h, d);
          const double turn = c.theta_at(s + h) - c.theta_at(s - h);
          const double length = std::abs(b.position - a.position);  // chord ≈ arc of the offset
          EXPECT_NEAR(o.kappa, (o.factor > 0 ? turn : -turn) / length, 1e-5 * std::abs(o.kappa) + 1e-9);
        }
      }
    }
  }
}

// First s where 1 − dκ(s) vanishes or loses the sign it has at s = 0, by bisection on the
// model's κ along each segment.
double reference_cusp(const test::RefCurve& ref, double d) {
  const ld sign = 1 - ld(d) * ref.segs[0].kappa(ref.segs[0].ua) > 0 ? 1 : -1;
  for (const test::RefSegment& g : ref.segs) {
    const auto f = [&](ld u) { return sign * (1 - ld(d) * g.kappa(u)); };
    if (f(g.ua) <= 0) return double(g.s_begin);
    if (f(g.ub) > 0) continue;
    const ld u = test::bisect(f, g.ua, g.ub);
    return double(g.s_begin + g.scale * (u - g.ua));
  }
  return NAN;
}

TEST(GeometryOffset, FirstCuspMatchesTheModel) {
  struct Case {
    PlanarCurve curve;
    double d;
    bool cusp, at_joint, backwards;
  };
  const PlanarCurve spiral = test::clothoid_spiral(), comp = test::compound();
  // compound() reversed: κ from −10/3 to −2/3, then −4/3 to 1/2; at d = −0.5, 1 − dκ starts at −2/3
  // (the offset runs backwards) and turns positive where κ = −2.
  const Result<PlanarCurve> rev = reversed(comp);
  ASSERT_TRUE(rev.usable());
  const PlanarCurve back = rev.curve;
  // κ from 2/3 to 5/6 (α = 2), then from 4/3 to 5/3 (α = −1) after a G1 joint at s = 3.
  const PlanarCurve jump = test::chain({{LaLaw{2.0}, 0.0, 1.0, 0.25, 0.16, 3.0}, {LaLaw{-1.0}, 0.0, 1.0, 4.0, 5.0, 3.0}}, 0.0, {0, 0}, 0.3);
  // spiral: κ from 0.2 to 6; compound: κ from −0.5 through 0 to 4/3, then 2/3 to 10/3 (G1 joint at s = 3).
  const std::vector<Case> cases{{spiral, 1.0, true, false, false},  {spiral, 0.1, false, false, false},
                                {spiral, -1.0, false, false, false}, {spiral, 0.05, false, false, false},
                                {spiral, 5.0, true, false, false},   {comp, -2.5, true, false, true} ,
                                {comp, 0.9, true, false, false},     {comp, 1.2, true, false, false},
                                {comp, 0.25, false, false, false},   {spiral, 10.0, false, false, true},
                                {jump, 1.0, true, true, false},      {jump, 1.25, true, false, false},
                                {back, -0.5, true, false, true}};
  for (const Case& t : cases) {
    const test::RefCurve ref(t.curve, 10);
    const OffsetCusp r = first_offset_cusp(t.curve, t.d);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    const double e = reference_cusp(ref, t.d);
    EXPECT_EQ(r.s.has_value(), t.cusp) << "d = " << t.d;
    EXPECT_EQ(std::isfinite(e), t.cusp) << "d = " << t.d;
    EXPECT_EQ(r.at_joint, t.at_joint) << "d = " << t.d;
    EXPECT_EQ(r.backwards_at_start, t.backwards) << "d = " << t.d;
    if (r.s && std::isfinite(e)) {
      EXPECT_NEAR(*r.s, e, 1e-12 * t.curve.length()) << "d = " << t.d;
      // Beyond the cusp the offset runs backwards.
      // The offset's direction flips there: 1 − dκ has the start's sign before, the other after.
      const double sign = t.backwards ? -1.0 : 1.0;
      if (*r.s + 1e-6 < t.curve.length()) {
        EXPECT_LT(sign * offset_at(t.curve, *r.s + 1e-6, t.d).factor, 0.0);
      }
      if (*r.s > 1e-6 && !r.at_joint) {
        EXPECT_GT(sign * offset_at(t.curve, *r.s - 1e-6, t.d).factor, 0.0);
      }
    }
  }
  // d = 10: 1 − dκ(0) = 1 − 10·0.2 < 0 and κ increases: the offset runs backwards from the start
  // and never turns (no cusp).
  EXPECT_TRUE(first_offset_cusp(spiral, 10.0).backwards_at_start);
  EXPECT_FALSE(first_offset_cusp(spiral, 10.0).s.has_value());
  EXPECT_FALSE(first_offset_cusp(spiral, 0.0).s.has_value());
  EXPECT_EQ(test::thrown_parameter([&] { first_offset_cusp(spiral, NAN); }), "d");
  EXPECT_EQ(test::thrown_parameter([&] { offset_at(spiral, 1.0, INFINITY); }), "d");
  EXPECT_EQ(test::thrown_parameter([&] { offset_at(spiral, -1.0, 0.1); }), "s");
}

}  // namespace
}  // namespace lac
