// geometry/evaluation, geometry/transforms: evaluate() against the independent long-double model
// (reference_curve.hpp); similarities keep α and the normalized segments and map positions as the
// similarity does; split, trim, append and reverse agree with the original curve within the
// error estimates.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "curves.hpp"
#include "lac/geometry/evaluation.hpp"
#include "lac/geometry/transforms.hpp"
#include "reference_curve.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using test::cld;
using test::ld;

std::complex<double> to_double(cld z) { return {double(z.real()), double(z.imag())}; }

TEST(GeometryEvaluate, MatchesTheLongDoubleModel) {
  double worst = 0, worst_estimate = 0;
  for (const PlanarCurve& c : test::test_curves()) {
    const test::RefCurve ref(c, 200);
    const double L = c.length();
    for (int i = 0; i <= 40; ++i) {
      const double s = L * i / 40.0;
      const PlanarEvaluation e = evaluate(c, s);
      ASSERT_EQ(e.status, Status::ok) << e.message;
      const size_t k = c.segment_at(s);
      const ld u = ref.segs[k].u_of(ld(c.local_s(k, s)));
      const std::complex<double> p = to_double(ref.position(k, u));
      EXPECT_LE(std::abs(e.position - p), 1e-13 * L + e.error_estimate) << "s = " << s;
      worst = std::max(worst, std::abs(e.position - p) / L);
      worst_estimate = std::max(worst_estimate, e.error_estimate / L);
      EXPECT_LE(e.error_estimate, 1e-9 * L);
      EXPECT_NEAR(e.kappa, double(ref.segs[k].kappa(u)), 1e-12 * std::abs(e.kappa) + 1e-14);
      EXPECT_NEAR(std::remainder(e.theta - double(ref.segs[k].theta(u)), 2 * std::numbers::pi), 0.0, 1e-12);
      EXPECT_NEAR(std::abs(e.tangent - std::polar(1.0, double(ref.segs[k].theta(u)))), 0.0, 1e-12);
      EXPECT_EQ(e.normal, std::complex<double>(0, 1) * e.tangent);
      // dκ/ds by a central difference of the model's κ(s) (away from the ends and joints).
      const double h = 1e-5 * L;
      if (s - h > c.segment_start(k) && s + h < c.segment_start(k + 1)) {
        const ld up = ref.segs[k].u_of(ld(c.local_s(k, s + h))), um = ref.segs[k].u_of(ld(c.local_s(k, s - h)));
        const double fd = double((ref.segs[k].kappa(up) - ref.segs[k].kappa(um)) / (2 * ld(h)));
        EXPECT_NEAR(e.dkappa_ds, fd, 1e-6 * (std::abs(fd) + 1)) << "s = " << s;
      }
    }
  }
  std::printf("evaluate: worst |position − model|/length = %.2e, largest error estimate/length = %.2e\n", worst, worst_estimate);
  EXPECT_EQ(test::thrown_parameter([] { evaluate(test::log_spiral(), -1.0); }), "s");
}

// A similarity applied to positions.
template <class F>
void expect_maps_positions(const PlanarCurve& c, const PlanarCurve& t, F&& map, double length_factor) {
  ASSERT_EQ(t.segments().size(), c.segments().size());
  EXPECT_NEAR(t.length(), length_factor * c.length(), 1e-14 * t.length());
  for (size_t k = 0; k < c.segments().size(); ++k) {
    EXPECT_EQ(t.segments()[k].law().alpha, c.segments()[k].law().alpha);
    EXPECT_EQ(t.segments()[k].ua(), c.segments()[k].ua());
    EXPECT_EQ(t.segments()[k].ub(), c.segments()[k].ub());
  }
  for (int i = 0; i <= 20; ++i) {
    const double s = c.length() * i / 20.0, st = std::min(t.length(), s * length_factor);
    const PositionResult p = position_at(c, s), q = position_at(t, st);
    ASSERT_EQ(q.status, Status::ok);
    EXPECT_LE(std::abs(q.point.position - map(p.point.position)), 1e-13 * t.length() + p.error_estimate * length_factor + q.error_estimate);
  }
}

TEST(GeometryTransforms, SimilaritiesKeepTheLawsAndMapPositions) {
  for (const PlanarCurve& c : test::test_curves()) {
    const std::complex<double> v{0.3, -1.7}, center{2.0, 1.0};
    expect_maps_positions(c, translated(c, v), [&](auto z) { return z + v; }, 1.0);
    const double a = 2.1;
    const PlanarCurve r = rotated(c, a, center);
    expect_maps_positions(c, r, [&](auto z) { return center + std::polar(1.0, a) * (z - center); }, 1.0);
    EXPECT_NEAR(r.theta_at(0.3 * r.length()) - c.theta_at(0.3 * c.length()), a, 1e-12);
    const double k = 2.5;
    const PlanarCurve sc = scaled(c, k, center);
    expect_maps_positions(c, sc, [&](auto z) { return center + k * (z - center); }, k);
    for (size_t j = 0; j < c.segments().size(); ++j) {  // same α, same q: κ / k
      EXPECT_EQ(sc.segments()[j].qa(), c.segments()[j].qa());
      EXPECT_EQ(sc.segments()[j].qb(), c.segments()[j].qb());
    }
    EXPECT_NEAR(sc.kappa_at(0.4 * sc.length()), c.kappa_at(0.4 * c.length()) / k, 1e-12 * std::abs(c.kappa_at(0.4 * c.length())));
    const std::complex<double> P{0.5, 0.5}, D{std::cos(0.3), std::sin(0.3)};
    const PlanarCurve m = mirrored(c, P, 3.0 * D);
    expect_maps_positions(c, m, [&](auto z) { return P + D * D * std::conj(z - P); }, 1.0);
    for (double f : {0.1, 0.5, 0.9}) {
      EXPECT_NEAR(m.kappa_at(f * m.length()), -c.kappa_at(f * c.length()), 1e-12 * std::abs(c.kappa_at(f * c.length())));
      EXPECT_NEAR(m.dkappa_ds_at(f * m.length()), -c.dkappa_ds_at(f * c.length()), 1e-10 * std::abs(c.dkappa_ds_at(f * c.length())) + 1e-14);
    }
  }
  const PlanarCurve c = test::log_spiral();
  EXPECT_EQ(test::thrown_parameter([&] { scaled(c, 0.0); }), "factor");
  EXPECT_EQ(test::thrown_parameter([&] { scaled(c, -1.0); }), "factor");
  EXPECT_EQ(test::thrown_parameter([&] { rotated(c, NAN); }), "angle");
  EXPECT_EQ(test::thrown_parameter([&] { mirrored(c, {0, 0}, {0, 0}); }), "direction");
  EXPECT_EQ(test::thrown_parameter([&] { translated(c, {INFINITY, 0}); }), "offset");
}

TEST(GeometryTransforms, SplitTrimAppendReverseAgreeWithTheCurve) {
  for (const PlanarCurve& c : test::test_curves()) {
    const double L = c.length();
    for (double f : {0.013, 0.37, 0.5, 0.81}) {
      const double s = f * L;
      const Result<CurvePair> sp = split(c, s);
      ASSERT_EQ(sp.summary.status, Status::ok) << sp.summary.message;
      EXPECT_NEAR(sp.curve.first.length(), s, 1e-13 * L);
      EXPECT_NEAR(sp.curve.second.length(), L - s, 1e-13 * L);
      const double e0 = *sp.summary.error_estimate;
      for (double g : {0.0, 0.3, 1.0}) {
        const double t = g * sp.curve.second.length();
        const PositionResult a = position_at(sp.curve.second, t), b = position_at(c, std::min(L, s + t));
        EXPECT_LE(std::abs(a.point.position - b.point.position), e0 + a.error_estimate + b.error_estimate + 1e-14 * L);
        EXPECT_NEAR(a.point.kappa, b.point.kappa, 1e-9 * std::abs(b.point.kappa));
      }
      // Appending the parts gives back the curve (one more segment at the cut).
      const Result<PlanarCurve> ap = appended(sp.curve.first, sp.curve.second, 1e-9 * L);
      ASSERT_EQ(ap.summary.status, Status::ok) << ap.summary.message;
      EXPECT_NEAR(ap.curve.length(), L, 1e-13 * L);
      for (double g : {0.05, 0.5, 0.95}) {
        const PositionResult a = position_at(ap.curve, g * L), b = position_at(c, g * L);
        EXPECT_LE(std::abs(a.point.position - b.point.position), e0 + a.error_estimate + b.error_estimate + 1e-13 * L);
      }
    }
    const Result<PlanarCurve> tr = trimmed(c, 0.2 * L, 0.75 * L);
    ASSERT_EQ(tr.summary.status, Status::ok);
    EXPECT_NEAR(tr.curve.length(), 0.55 * L, 1e-13 * L);
    for (double g : {0.0, 0.5, 1.0}) {
      const double t = g * tr.curve.length();
      const PositionResult a = position_at(tr.curve, t), b = position_at(c, 0.2 * L + t);
      EXPECT_LE(std::abs(a.point.position - b.point.position), *tr.summary.error_estimate + a.error_estimate + b.error_estimate + 1e-14 * L);
      EXPECT_NEAR(a.point.theta, b.point.theta, 1e-12 * (1 + std::abs(b.point.theta)));
    }
    const Result<PlanarCurve> rv = reversed(c);
    ASSERT_EQ(rv.summary.status, Status::ok);
    for (double g : {0.1, 0.65}) {  // not at the joint of compound() (s = 3 of 7.5), where κ jumps
      const PositionResult a = position_at(rv.curve, g * L), b = position_at(c, (1 - g) * L);
      EXPECT_LE(std::abs(a.point.position - b.point.position), *rv.summary.error_estimate + a.error_estimate + b.error_estimate + 1e-13 * L);
      EXPECT_NEAR(a.point.kappa, -b.point.kappa, 1e-9 * std::abs(b.point.kappa));
    }
    EXPECT_EQ(test::thrown_parameter([&] { split(c, 0.0); }), "s");
    EXPECT_EQ(test::thrown_parameter([&] { split(c, L); }), "s");
    EXPECT_EQ(test::thrown_parameter([&] { trimmed(c, 0.5 * L, 0.4 * L); }), "s1");
    EXPECT_EQ(test::thrown_parameter([&] { trimmed(c, -1.0, 0.4 * L); }), "s0");
    // A gap beyond the tolerance is bad input naming b; a negative tolerance names itself.
    EXPECT_EQ(test::thrown_parameter([&] { appended(c, translated(c, {1, 0}), 1e-6); }), "b");
    EXPECT_EQ(test::thrown_parameter([&] { appended(c, c, -1.0); }), "gap_tolerance");
  }
}

}  // namespace
}  // namespace lac
