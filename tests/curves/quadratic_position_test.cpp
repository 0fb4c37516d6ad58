// Positions on the quadratic LA curve: every registry method agrees, γ → 0 gives the LA curve's
// positions (independent code: curves/planar), the inflection continuation is point-symmetric,
// and the LCG recomputed from the produced points is the parabola.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/integrators/registry.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

// Tolerances (one table).
constexpr double kMethodAgreement = 1e-9;  // rk4 h = 1e-3 (Simpson, ~h⁴), rk45 1e-12 vs GK 1e-14
constexpr double kGammaZeroTol = 1e-8;     // |C_quadratic(γ = ±1e-10) − C_LA| (O(γ) plus quadrature)
constexpr double kSymmetryTol = 1e-12;     // point symmetry about the inflection, plus the error estimates
constexpr double kHermiteTol = 1e-8;       // hermite_polyline, 1000 points, vs GK at 1e-14
constexpr double kHermiteThetaTol = 1e-13;  // θ accumulated by local series vs closed form (relative, ≥ 1)
constexpr double kGaussKronrodRefTol = 1e-12;  // position_at (G-K, tol 1e-14) vs mpmath
constexpr double kLcgTol = 1e-5;           // LCG from finite differences of positions (h = 0.004, H = 0.001)

TEST(QuadraticPosition, RegistryMethodsAgree) {
  const double sets[][3] = {{-1, -0.5, 1}, {1, 1, 1}, {3, -1, 1}, {0, 0, 1}};
  for (const auto& p : sets) {
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    const auto ref = polyline(c, -0.2, 0.5, 8, make_quadrature("gauss-kronrod", {{}, 1e-14}));
    for (const auto& [name, opts] : {std::pair{"rk4", QuadratureOptions{1e-3, {}}}, std::pair{"rk45", QuadratureOptions{{}, 1e-12}}}) {
      const auto got = polyline(c, -0.2, 0.5, 8, make_quadrature(name, opts));
      for (size_t k = 0; k < got.size(); ++k) {
        EXPECT_LE(std::abs(got[k].point.position - ref[k].point.position), kMethodAgreement) << name << " k=" << k;
        EXPECT_EQ(got[k].status, Status::ok);
      }
    }
    // position_at agrees with the polyline's running integral; the frame is the curve's.
    const auto single = position_at(c, 0.5, GaussKronrod{});
    EXPECT_LE(std::abs(single.point.position - ref.back().point.position), 1e-13);
    EXPECT_DOUBLE_EQ(single.point.kappa, c.kappa_at_s(0.5));
  }
}

// Every method of the quadrature registry at its defaults; igf, a closed form of the planar LA
// curve only, is an InputError naming the integrator.
TEST(QuadraticPosition, EveryRegisteredQuadratureAgreesAndIgfIsRejected) {
  const QuadraticLaCurve c(1, 1, 1);
  const auto ref = polyline(c, -0.2, 0.5, 8, GaussKronrod{});
  for (const MethodInfo& m : quadrature_methods()) {
    const AnyQuadrature method = make_quadrature(m.name);
    if (m.applies_to != kAnyIntegrand) {
      try {
        polyline(c, -0.2, 0.5, 8, method);
        ADD_FAILURE() << m.name << " accepted";
      } catch (const InputError& e) {
        EXPECT_EQ(e.parameter(), "integrator");
        EXPECT_NE(std::string(e.what()).find("planar LA curves in standard form only"), std::string::npos) << e.what();
      }
      EXPECT_THROW(position_at(c, 0.5, method), InputError);
      continue;
    }
    const auto got = polyline(c, -0.2, 0.5, 8, method);
    for (size_t k = 0; k < got.size(); ++k) {
      EXPECT_LE(std::abs(got[k].point.position - ref[k].point.position), kMethodAgreement) << m.name << " k=" << k;
      EXPECT_EQ(got[k].status, Status::ok) << m.name;
    }
  }
}

TEST(QuadraticPosition, GammaToZeroGivesTheLaCurvesPositions) {
  GaussKronrod gk;
  for (double alpha : {-1.0, 0.0, 2.0}) {
    const LaCurve la(alpha, 1.0);
    const auto la_pts = polyline(la, Parameter::s, -0.4, 0.8, 6, gk, Form::s);
    for (double g : {1e-10, -1e-10}) {
      const QuadraticLaCurve q(alpha, g, 1.0);
      const auto q_pts = polyline(q, -0.4, 0.8, 6, gk);
      for (size_t k = 0; k < q_pts.size(); ++k)
        EXPECT_LE(std::abs(q_pts[k].point.position - la_pts[k].point.position), kGammaZeroTol) << alpha << " " << g;
    }
  }
}

TEST(QuadraticPosition, InflectionContinuationIsPointSymmetric) {
  QuadraticOptions o;
  o.through_inflection = true;
  for (const auto& p : {std::array{-0.2, -0.5, 1.0}, std::array{-1.0, 0.0, 1.0}, std::array{3.0, -1.0, 1.0}}) {
    const QuadraticLaCurve c(p[0], p[1], p[2], o);
    ASSERT_TRUE(c.has_inflection());
    const double si = c.s_at_zero_kappa();
    // Toward κ → 0 the s-form integrand is smooth but not analytic (γ < 0: κ vanishes faster
    // than any power), and Boost's G10K21 cannot reach 1e-14 there; tol 1e-11 keeps this fast.
    GaussKronrod gk;
    gk.tol = 1e-11;
    gk.max_depth = 10;
    const auto mid = position_at(c, si, gk);
    for (double t : {0.05, 0.2}) {
      const auto before = position_at(c, si - t, gk);
      const auto after = position_at(c, si + t, gk);
      // Within the quadrature's own error estimates (which must bound the true error).
      const double bound = kSymmetryTol + after.error_estimate + 2 * mid.error_estimate + before.error_estimate;
      EXPECT_LE(std::abs(after.point.position - (2.0 * mid.point.position - before.point.position)), bound)
          << p[0] << " " << p[1] << " t=" << t;
      EXPECT_LT(after.point.kappa, 0.0);
    }
  }
}

TEST(QuadraticPosition, LcgFromProducedPointsIsTheParabola) {
  GaussKronrod gk;
  double worst = 0;
  const double sets[][3] = {{-1, -0.5, 1}, {1, 1, 1}, {3, -1, 1}, {0, -1, 2}};
  for (const auto& p : sets) {
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    for (double s : {-0.1, 0.0, 0.2}) {
      // Curvature from positions only: |C''| by a 5-point stencil (h = 0.004) with the sign of C' × C''.
      auto kappa_from_points = [&](double sc) {
        const double h = 0.004;
        std::complex<double> q[5];
        for (int j = 0; j < 5; ++j) q[j] = position_at(c, sc + (j - 2) * h, gk).point.position;
        const auto d1 = (q[0] - 8.0 * q[1] + 8.0 * q[3] - q[4]) / (12 * h);
        const auto d2 = (-q[0] + 16.0 * q[1] - 30.0 * q[2] + 16.0 * q[3] - q[4]) / (12 * h * h);
        return (d1.real() * d2.imag() - d1.imag() * d2.real()) / std::pow(std::abs(d1), 3);
      };
      const double H = 0.001;
      const double k0 = kappa_from_points(s), km = kappa_from_points(s - H), kp = kappa_from_points(s + H);
      const double dlog_rho_ds = (std::log(km) - std::log(kp)) / (2 * H);
      const double log_rho = -std::log(k0);
      const double lcg = -std::log(std::abs(dlog_rho_ds));  // log(ρ ds/dρ)
      const double err = std::abs(lcg - c.lcg(log_rho));
      worst = std::max(worst, err);
      EXPECT_LE(err, kLcgTol) << p[0] << " " << p[1] << " s=" << s;
      EXPECT_NEAR(k0, c.kappa_at_s(s), 1e-6 * k0);
    }
  }
  std::cout << "  LCG from the produced points vs the parabola: worst deviation " << worst << "\n";
}

}  // namespace
}  // namespace lac

namespace lac {
namespace {

TEST(QuadraticPosition, HermitePolylineMatchesGaussKronrod) {
  const double sets[][3] = {{-1, -0.5, 1}, {1, 1, 1}, {3, -1, 1}, {1, -30, 0.5}, {0, 0, 1}, {-1, 0.5, 1}};
  double worst = 0;
  for (const auto& p : sets) {
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    const auto d = c.s_domain();
    const double s0 = std::isfinite(d.lo) ? 0.99 * d.lo : -3.0, s1 = std::isfinite(d.hi) ? 0.99 * d.hi : 3.0;
    const auto fast = hermite_polyline(c, s0, s1, 1000);
    for (int k = 0; k < 11; ++k) {
      const auto& f = fast[static_cast<size_t>(k * 999 / 10)];
      const auto ref_point = position_at(c, f.point.s, GaussKronrod{});
      const double err = std::abs(f.point.position - ref_point.point.position);
      worst = std::max(worst, err);
      EXPECT_LE(err, f.error_estimate + 1e-12) << p[0] << " " << p[1] << " k=" << k;  // the bound holds
      EXPECT_LE(err, kHermiteTol) << p[0] << " " << p[1] << " k=" << k;
      EXPECT_NEAR(f.point.kappa, ref_point.point.kappa, 1e-13 * f.point.kappa);
      EXPECT_EQ(f.status, Status::ok);
    }
  }
  std::cout << "  hermite_polyline (1000 points) vs Gauss-Kronrod: worst position error " << worst << "\n";
}

// Positions against mpmath (tests/reference/quadratic.py, kind = position: C(s) integrated in
// u = log κ at 40 digits). Three s per set: s_a, s_m, s_b. hermite_polyline's θ is accumulated by
// local series, so its θ is also checked against the closed form.
TEST(QuadraticPosition, PositionsMatchMpmathReference) {
  const auto t = test::read_reference_csv("quadratic.csv");
  struct Ref {
    double s;
    std::complex<double> c;
  };
  std::map<std::array<double, 3>, std::vector<Ref>> sets;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r][t.column("kind")] != "position") continue;
    sets[{t.number(r, "alpha"), t.number(r, "gamma"), t.number(r, "lambda")}].push_back(
        {t.number(r, "x"), {t.number(r, "v1"), t.number(r, "v2")}});
  }
  ASSERT_EQ(sets.size(), 6u);
  double worst_fast = 0, worst_gk = 0, worst_theta = 0;
  for (const auto& [p, refs] : sets) {
    ASSERT_EQ(refs.size(), 3u);
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    const std::string where = "alpha=" + format_number(p[0]) + " gamma=" + format_number(p[1]);
    // The s values are exact end points of these polylines.
    const auto ab = hermite_polyline(c, refs[0].s, refs[2].s, 1000);
    const auto mb = hermite_polyline(c, refs[1].s, refs[2].s, 1000);
    for (const auto& [point, ref] : {std::pair{ab.front(), refs[0]}, std::pair{mb.front(), refs[1]}, std::pair{ab.back(), refs[2]}}) {
      ASSERT_EQ(point.point.s, ref.s);
      const double err = std::abs(point.point.position - ref.c);
      worst_fast = std::max(worst_fast, err);
      EXPECT_LE(err, point.error_estimate + 1e-12) << where << " s=" << ref.s;  // the bound holds
      EXPECT_LE(err, kHermiteTol) << where << " s=" << ref.s;
      const double theta = c.theta_at_s(ref.s);
      worst_theta = std::max(worst_theta, std::abs(point.point.theta - theta) / std::max(1.0, std::abs(theta)));
      EXPECT_LE(std::abs(point.point.theta - theta), kHermiteThetaTol * std::max(1.0, std::abs(theta))) << where;
      const auto gk = position_at(c, ref.s, GaussKronrod{});
      const double err_gk = std::abs(gk.point.position - ref.c);
      worst_gk = std::max(worst_gk, err_gk);
      EXPECT_LE(err_gk, kGaussKronrodRefTol) << where << " s=" << ref.s;
    }
  }
  std::cout << "  positions vs mpmath (18 points): hermite_polyline worst " << worst_fast << ", gauss-kronrod worst "
            << worst_gk << "; hermite theta vs closed form: worst relative " << worst_theta << "\n";
}

}  // namespace
}  // namespace lac
