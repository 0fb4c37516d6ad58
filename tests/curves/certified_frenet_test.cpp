// The Frenet–Serret integration with a proven bound (curves/space/certified_frenet.hpp) against the
// long-double oracle of fuzz/oracle_check.hpp (Boost.Odeint RKF78 at 1e-17, the law written afresh):
// the distance never exceeds the bound, and the bound stays near rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "fuzz/oracle_check.hpp"
#include "lac/constructions/space_drawable_cases.hpp"
#include "lac/curves/space/certified_frenet.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using oracle::R;

struct Law {
  double a, b, l, o, nu;
  TorsionType ty;
};

// |P − P_ref| and ‖F − F_ref‖ (Frobenius) at s1.
std::pair<double, double> distance_to_oracle(const Law& w, const Frame3& start, double s0, double s1, const Frame3& got) {
  const oracle::SpaceLawL L{w.a, w.b, w.l, w.o, w.nu, w.ty == TorsionType::type1 ? R(1) : R(-1)};
  oracle::FrameL st;
  for (int i = 0; i < 3; ++i) st.p[i] = start.p[i], st.t[i] = start.t[i], st.n[i] = start.n[i], st.b[i] = start.b[i];
  const oracle::FrameL ref = oracle::space_frame(L, st, s0, s1);
  EXPECT_TRUE(ref.ok);
  R dp = 0, df = 0;
  for (int i = 0; i < 3; ++i) {
    dp += (got.p[i] - ref.p[i]) * (got.p[i] - ref.p[i]);
    df += (got.t[i] - ref.t[i]) * (got.t[i] - ref.t[i]) + (got.n[i] - ref.n[i]) * (got.n[i] - ref.n[i]) +
          (got.b[i] - ref.b[i]) * (got.b[i] - ref.b[i]);
  }
  return {static_cast<double>(std::sqrt(dp)), static_cast<double>(std::sqrt(df))};
}

TEST(CertifiedFrenet, TheBoundHoldsAgainstTheLongDoubleOracle) {
  std::mt19937_64 rng(20261128);
  auto u = [&](double a, double b) { return a + (b - a) * (static_cast<double>(rng() >> 11) * 0x1.0p-53); };
  int cases = 0;
  double worst_ratio = 0, worst_bound = 0, worst_position_ratio = 0;
  long steps = 0;
  for (int k = 0; k < 300; ++k) {
    // Laws of the drawable cases (α, β ∈ [−1, 2], Ω ∈ [0.05, 0.6], Λ ∈ [0.2, 3], ν ∈ [0.5, 4]) and wider ones.
    const bool wide = k % 3 == 0;
    const Law w{wide ? u(-3, 4) : u(-1, 2), wide ? u(-3, 4) : u(-1, 2), std::exp(u(std::log(0.2), std::log(3.0))),
                u(0.05, wide ? 3 : 0.6), std::exp(u(std::log(0.5), std::log(4.0))),
                u(0, 1) < 0.5 ? TorsionType::type1 : TorsionType::type2};
    const LaSpaceCurve c(w.a, w.b, w.l, w.o, w.nu, w.ty);
    const Interval range = c.s_range();
    // Up to 6 rad of turning and of torsion turning, and short of a finite end by 1 %.
    double hi = std::min({std::isfinite(range.hi) ? range.hi - 0.01 * std::abs(range.hi) : 50.0, c.s_at_turning(6.0),
                          c.s_at_torsion_turning(6.0), 50.0});
    if (!(hi > 0)) continue;
    const double s0 = u(0, 0.3) * hi, s1 = s0 + u(0.05, 1) * (hi - s0);
    Frame3 start;
    start.p = Vec3(u(-1, 1), u(-1, 1), u(-1, 1));
    const CertifiedFrame r = integrate_frenet_certified(c, start, s0, s1);
    ASSERT_EQ(r.status, Status::ok) << r.message << " alpha " << w.a << " beta " << w.b;
    const auto [dp, df] = distance_to_oracle(w, start, s0, s1, r.frame);
    const double length = s1 - s0;
    // The oracle's own error (RKF78 in long double at 1e-17) is far below a double's rounding.
    EXPECT_LE(dp, r.position_error) << "alpha " << w.a << " beta " << w.b << " s " << s0 << " .. " << s1;
    EXPECT_LE(df, r.frame_error) << "alpha " << w.a << " beta " << w.b << " lambda " << w.l << " omega " << w.o << " nu " << w.nu << " type " << static_cast<int>(w.ty) << " s " << s0 << " .. " << s1;
    // Near rounding: a bound of use for a tolerance of 1e-12 of the length.
    EXPECT_LE(r.position_error, 1e-12 * (1 + length)) << "alpha " << w.a << " beta " << w.b;
    worst_ratio = std::max(worst_ratio, df / r.frame_error);
    worst_position_ratio = std::max(worst_position_ratio, dp / r.position_error);
    worst_bound = std::max(worst_bound, r.position_error / (1 + length));
    steps += r.steps;
    ++cases;
  }
  EXPECT_GE(cases, 250);
  std::printf("%d intervals, %.1f steps each: largest error / bound %.3g (frame), %.3g (position); largest "
              "position bound %.3g of 1 + length\n",
              cases, static_cast<double>(steps) / cases, worst_ratio, worst_position_ratio, worst_bound);
}

TEST(CertifiedFrenet, CarriesTheStartsErrorsAndRejectsBadInput) {
  const LaSpaceCurve c(-1, -1, 0.8, 0.1, 1.5, TorsionType::type1);
  const CertifiedFrame a = integrate_frenet_certified(c, Frame3{}, 0.0, 1.0);
  const CertifiedFrame b = integrate_frenet_certified(c, Frame3{}, 0.0, 1.0, 1e-9, 1e-10);
  ASSERT_EQ(b.status, Status::ok);
  EXPECT_GE(b.position_error, 1e-9 + 1e-10 * 1.0);  // a frame error δ moves P by up to δ·length
  EXPECT_GE(b.frame_error, 1e-10);
  EXPECT_LT(a.frame_error, 1e-13);
  EXPECT_EQ(integrate_frenet_certified(c, Frame3{}, 0.5, 0.5).steps, 0);
  EXPECT_EQ(test::thrown_parameter([&] { integrate_frenet_certified(c, Frame3{}, 1.0, 0.5); }), "s1");
  EXPECT_EQ(test::thrown_parameter([&] { integrate_frenet_certified(c, Frame3{}, 0.0, 1.0, -1.0); }), "start_position_error");
}

}  // namespace
}  // namespace lac
