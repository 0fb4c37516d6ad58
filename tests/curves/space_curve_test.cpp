// LA space curve laws, Frenet–Serret integration and the cone event, and the placed chain of
// pieces SpaceCurve (curves/space).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>

#include "lac/common/error.hpp"
#include "lac/curves/space/frenet.hpp"
#include "lac/curves/space/la_space_curve.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "tests/support/space_tolerances.hpp"
#include "tests/support/reference_csv.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {
namespace tol = test::space_tol;

// docs/math.md §3.1 tables written out case by case (independent of the graph-law form in the library).
double rho_table(double a, double l, double s) { return a == 0 ? std::exp(l * s) : std::pow(1 + a * l * s, 1 / a); }
double mu_table(double b, double o, double nu, TorsionType ty, double s) {
  const double sg = ty == TorsionType::type1 ? 1 : -1;
  return b == 0 ? nu * std::exp(sg * o * s) : std::pow(sg * o * b * s + std::pow(nu, b), 1 / b);
}

struct LawCase {
  double a, b, l, o, nu;
  TorsionType ty;
};
const LawCase kLawCases[] = {{-1, -1, 0.8, 0.1, 1.5, TorsionType::type1}, {0, 2, 1, 0.3, 0.8, TorsionType::type2},
                             {2, 1, 0.5, 0.6, 1, TorsionType::type1},     {1, 0, 0.7, 0.2, 1, TorsionType::type2},
                             {0, 0, 1, 0.5, 2, TorsionType::type1},       {-0.5, 1.5, 2, 0.2, 0.7, TorsionType::type2},
                             {0.5, -1, 0.3, 0.4, 1.2, TorsionType::type1}, {1, -2, 1.5, 0.3, 0.5, TorsionType::type2}};

TEST(SpaceCurveLaws, RhoMuMatchTheTablesOfMathMd) {
  double worst = 0;
  for (const auto& c : kLawCases) {
    const LaSpaceCurve cv(c.a, c.b, c.l, c.o, c.nu, c.ty);
    const Interval r = cv.s_range();
    const double hi = std::isfinite(r.hi) ? r.hi : 5.0;
    for (int i = 0; i <= 20; ++i) {
      const double s = 0.95 * hi * i / 20.0;
      worst = std::max(worst, std::abs(cv.rho(s) / rho_table(c.a, c.l, s) - 1));
      worst = std::max(worst, std::abs(cv.mu(s) / mu_table(c.b, c.o, c.nu, c.ty, s) - 1));
    }
  }
  std::printf("worst relative deviation of rho, mu from the docs/math.md §3.1 tables: %.2e\n", worst);
  EXPECT_LE(worst, tol::kLaw);
}

TEST(SpaceCurveLaws, RangeEndsWhereAFactorVanishes) {
  // α = −0.5, Λ = 2: ρ = (1 − s)^(−2) ends at s = 1; type 2, β = 1.5: μ^β = ν^β − Ωβs ends at ν^β/(Ωβ).
  const LaSpaceCurve a(-0.5, 0, 2, 0.2, 0.7, TorsionType::type2);
  EXPECT_DOUBLE_EQ(a.s_range().hi, 1.0);
  const LaSpaceCurve b(1, 1.5, 0.5, 0.2, 0.7, TorsionType::type2);
  EXPECT_NEAR(b.s_range().hi, std::pow(0.7, 1.5) / (0.2 * 1.5), 1e-15);
  EXPECT_NEAR(b.s_range().lo, -1 / 0.5, 1e-15);  // ρ = 1 + Λs
  const LaSpaceCurve c(0, 0, 1, 0.5, 2, TorsionType::type1);
  EXPECT_TRUE(std::isinf(c.s_range().lo) && std::isinf(c.s_range().hi));
  // type 1 with β < 0: μ^β = ν^β + Ωβs decreases to 0 at s = ν^β/(Ω|β|)
  const LaSpaceCurve d(1, -1, 1, 0.4, 1.2, TorsionType::type1);
  EXPECT_NEAR(d.s_range().hi, std::pow(1.2, -1) / 0.4, 1e-15);
}

TEST(SpaceCurveLaws, TurningIsTheIntegralOfCurvatureAndInverts) {
  double worst = 0, worst_inv = 0;
  for (const auto& c : kLawCases) {
    const LaSpaceCurve cv(c.a, c.b, c.l, c.o, c.nu, c.ty);
    const double hi = std::isfinite(cv.s_range().hi) ? 0.9 * cv.s_range().hi : 3.0;
    for (double s : {0.1 * hi, 0.5 * hi, hi}) {
      const double q = boost::math::quadrature::gauss_kronrod<double, 31>::integrate([&](double u) { return cv.kappa(u); }, 0, s, 12, 1e-14);
      const double qt = boost::math::quadrature::gauss_kronrod<double, 31>::integrate([&](double u) { return cv.tau(u); }, 0, s, 12, 1e-14);
      worst = std::max({worst, std::abs(cv.turning(s) / q - 1), std::abs(cv.torsion_turning(s) / qt - 1)});
      worst_inv = std::max({worst_inv, std::abs(cv.s_at_turning(cv.turning(s)) / s - 1),
                            std::abs(cv.s_at_torsion_turning(cv.torsion_turning(s)) / s - 1)});
    }
  }
  std::printf("turning vs quadrature: %.2e, inverse round trip: %.2e\n", worst, worst_inv);
  EXPECT_LE(worst, tol::kTurning);
  EXPECT_LE(worst_inv, tol::kTurning);
  // α < 1: the turning is bounded by 1/((1 − α)Λ); beyond it there is no s.
  const LaSpaceCurve b(-1, 0, 0.5, 0.1, 1, TorsionType::type1);
  EXPECT_TRUE(std::isinf(b.s_at_turning(1.01)));
  EXPECT_TRUE(std::isfinite(b.s_at_turning(0.99)));
}

TEST(SpaceCurveLaws, JointContinuationKeepsRhoMuAndTheirSlopes) {
  // docs/math.md §3: ρ, μ and dρ/ds, dμ/ds continuous (LCG, LTG continuous), including α1 = 0, β1 = 0.
  struct J {
    double a0, a1, b0, b1;
    TorsionType ty;
  };
  const J cases[] = {{-1, 1, -1, 1, TorsionType::type1}, {0, -1, 2, 1, TorsionType::type1},
                     {1, 0, 0, 1, TorsionType::type2},   {1, -1, 1, -2, TorsionType::type2},
                     {-1, 0, 2, 0, TorsionType::type1},  {2, 0.5, -1, 0, TorsionType::type2}};
  double worst = 0;
  for (const J& j : cases) {
    const double l0 = 0.7, o0 = 0.3, nu0 = 1.3, s_b = 0.6;
    const LaSpaceCurve c0(j.a0, j.b0, l0, o0, nu0, j.ty);
    const double rc = c0.rho(s_b), mc = c0.mu(s_b);
    const JointContinuation k = continue_at_joint(j.a0, j.a1, j.b0, j.b1, l0, o0, j.ty, rc, mc);
    ASSERT_TRUE(k.valid);
    EXPECT_NEAR(k.lambda1, l0 * std::pow(rc, j.a1 - j.a0), 1e-14 * k.lambda1);  // 000 Eq. (11)
    EXPECT_NEAR(k.omega1, o0 * std::pow(mc, j.b1 - j.b0), 1e-14 * k.omega1);    // 000 Eq. (16)
    const LaSpaceCurve c1(j.a1, j.b1, k.lambda1, k.omega1, k.nu1, j.ty);
    auto d = [](auto f, double s) { return (f(s + 1e-5) - f(s - 1e-5)) / 2e-5; };
    worst = std::max(worst, std::abs(c1.rho(k.s_c) / rc - 1));
    worst = std::max(worst, std::abs(c1.mu(k.s_c) / mc - 1));
    const double dr0 = d([&](double s) { return c0.rho(s); }, s_b), dr1 = d([&](double s) { return c1.rho(s); }, k.s_c);
    const double dm0 = d([&](double s) { return c0.mu(s); }, s_b), dm1 = d([&](double s) { return c1.mu(s); }, k.s_c);
    EXPECT_NEAR(dr1 / dr0, 1, 1e-8);
    EXPECT_NEAR(dm1 / dm0, 1, 1e-8);
  }
  EXPECT_LE(worst, tol::kJointRelative);
}

struct RefRow {
  LaSpaceCurve curve;
  double s_end;
  Frame3 frame;
};

std::vector<RefRow> reference_rows() {
  const auto t = test::read_reference_csv("space_frenet.csv");
  std::vector<RefRow> rows;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const auto n = [&](const char* c) { return t.number(i, c); };
    const LaSpaceCurve c(n("alpha"), n("beta"), n("lambda"), n("omega"), n("nu"),
                         n("type") == 1 ? TorsionType::type1 : TorsionType::type2);
    Frame3 f{{n("px"), n("py"), n("pz")}, {n("tx"), n("ty"), n("tz")}, {n("nx"), n("ny"), n("nz")}, {n("bx"), n("by"), n("bz")}};
    rows.push_back({c, n("s_end"), f});
  }
  return rows;
}

double frame_distance(const Frame3& a, const Frame3& b) {
  return std::max({(a.p - b.p).cwiseAbs().maxCoeff(), (a.t - b.t).cwiseAbs().maxCoeff(),
                   (a.n - b.n).cwiseAbs().maxCoeff(), (a.b - b.b).cwiseAbs().maxCoeff()});
}

TEST(Frenet, MatchesMpmathReferenceForEveryMethod) {
  const auto rows = reference_rows();
  ASSERT_GE(rows.size(), 8u);
  struct M {
    const char* name;
    OdeOptions opt;
    double tolerance;
  };
  const M methods[] = {{"magnus6 rtol 1e-12", {OdeMethod::magnus6, 1e-12, 1e-13}, tol::kMagnusTight},
                       {"magnus6 rtol 1e-10", {OdeMethod::magnus6, 1e-10, 1e-11}, tol::kMagnusDefault},
                       {"rk45 rtol 1e-12", {OdeMethod::rk45, 1e-12, 1e-13}, tol::kRk45},
                       {"rk4 h 1e-3", {OdeMethod::rk4, 1e-12, 1e-13, 1e-3}, tol::kRk4}};
  for (const M& m : methods) {
    double worst = 0, worst_orth = 0;
    long evals = 0;
    for (const auto& r : rows) {
      const FrenetResult res = integrate_frenet(r.curve, Frame3{}, 0, r.s_end, m.opt);
      ASSERT_EQ(res.status, Status::ok) << m.name << ": " << res.message;
      worst = std::max(worst, frame_distance(res.frame, r.frame));
      worst_orth = std::max(worst_orth, res.frame.orthonormality_error());
      evals += res.evaluations;
    }
    std::printf("%-20s worst |frame - reference| %.2e, orthonormality %.1e, %ld evaluations over %zu curves\n", m.name,
                worst, worst_orth, evals, rows.size());
    EXPECT_LE(worst, m.tolerance) << m.name;
    EXPECT_LE(worst_orth, tol::kOrthonormal) << m.name;
  }
}

TEST(Frenet, ConeEventIsTheFirstMeetingAndIsLocatedAccurately) {
  double worst = 0;
  for (const auto& c : kLawCases) {
    const LaSpaceCurve cv(c.a, c.b, c.l, c.o, c.nu, c.ty);
    const double hi = std::isfinite(cv.s_range().hi) ? cv.s_range().hi * (1 - 1e-9) : 6.0;
    for (double theta : {0.2, 0.5, 0.9}) {
      for (OdeMethod m : {OdeMethod::magnus6, OdeMethod::rk45, OdeMethod::rk4}) {
        OdeOptions o{m, 1e-12, 1e-13, 1e-3};
        const FrenetResult r = integrate_to_cone(cv, Frame3{}, 0, hi, theta, o);
        if (!r.met_cone) continue;
        worst = std::max(worst, std::abs(cone_angle_of(r.frame.p) - theta));
        // first meeting: the angle stays below θ before the event (checked on a dense sample)
        const auto frames = sample_frenet(cv, Frame3{}, 0, r.s, 200, o);
        for (size_t i = 1; i + 1 < frames.size(); ++i) ASSERT_LT(cone_angle_of(frames[i].p), theta + 1e-12);
      }
    }
  }
  std::printf("worst |angle(P_event, e_x) - theta|: %.2e\n", worst);
  EXPECT_LE(worst, tol::kConeAngle);
}

TEST(Frenet, FrameStaysOrthonormalOverLongIntegrations) {
  const LaSpaceCurve cv(2, 1, 0.5, 0.6, 0.3, TorsionType::type1);  // strong torsion, several turns
  double worst = 0;
  for (OdeMethod m : {OdeMethod::magnus6, OdeMethod::rk45, OdeMethod::rk4}) {
    OdeOptions o{m, 1e-10, 1e-11, 1e-2};
    for (const Frame3& f : sample_frenet(cv, Frame3{}, 0, 20, 400, o)) worst = std::max(worst, f.orthonormality_error());
  }
  std::printf("worst orthonormality error over s in [0, 20]: %.2e\n", worst);
  EXPECT_LE(worst, tol::kOrthonormal);
}

TEST(SpaceCurveInput, InvalidParametersNameTheParameter) {
  const auto param = [](auto&& f) { return test::thrown_parameter(f); };
  EXPECT_EQ(param([] { LaSpaceCurve(NAN, 0, 1, 1, 1, TorsionType::type1); }), "alpha");
  EXPECT_EQ(param([] { LaSpaceCurve(0, INFINITY, 1, 1, 1, TorsionType::type1); }), "beta");
  EXPECT_EQ(param([] { LaSpaceCurve(0, 0, -1, 1, 1, TorsionType::type1); }), "lambda");
  EXPECT_EQ(param([] { LaSpaceCurve(0, 0, 1, -0.1, 1, TorsionType::type1); }), "omega");
  EXPECT_EQ(param([] { LaSpaceCurve(0, 0, 1, 1, 0, TorsionType::type1); }), "nu");
  EXPECT_EQ(param([] { LaSpaceCurve(0, 0, 1, 1, 1, static_cast<TorsionType>(3)); }), "type");
  const LaSpaceCurve c(-1, 0, 1, 0.1, 1, TorsionType::type1);  // s < 1
  EXPECT_EQ(param([&] { integrate_frenet(c, Frame3{}, 0, 1.5); }), "s1");
  EXPECT_EQ(param([&] { integrate_to_cone(c, Frame3{}, 0, 0.5, 0.0); }), "cone_angle");
  EXPECT_EQ(param([&] { integrate_frenet(c, Frame3{}, 0, 0.5, OdeOptions{OdeMethod::rk45, 0}); }), "rtol");
  EXPECT_EQ(param([] { parse_ode_method("euler"); }), "integrator");
}

TEST(Frenet, StepCapGivesAStatusNotAHang) {
  const LaSpaceCurve c(0, 0, 1, 0, 1e-6, TorsionType::type1);  // τ = 1e6: far more steps than the cap
  OdeOptions o{OdeMethod::rk45, 1e-12, 1e-13};
  o.max_steps = 100;
  const FrenetResult r = integrate_frenet(c, Frame3{}, 0, 1, o);
  EXPECT_EQ(r.status, Status::max_iterations);
  EXPECT_FALSE(r.message.empty());
  EXPECT_TRUE(r.frame.p.allFinite());
}

// A two-piece curve built as the compound construction builds it (000 §4): piece 0 of (α, β) =
// (−1, −1) from 0 to 0.5, piece 1 of (1, 1) continuing ρ, μ and their slopes at the joint
// (continue_at_joint) from s_c for 0.7, with the joint frame integrated at rtol 1e-13. Placed by
// a rotation, scale 2.5 and a translation; mirrored (z → −z before the rotation) when asked.
SpaceCurve two_piece_curve(bool mirror, const OdeOptions& ode = {OdeMethod::magnus6, 1e-12, 1e-13}) {
  const TorsionType ty = TorsionType::type1;
  const LaSpaceCurve c0(-1, -1, 0.8, 0.1, 1.5, ty);
  const double s_b = 0.5;
  const FrenetResult joint = integrate_frenet(c0, Frame3{}, 0, s_b, {OdeMethod::rk45, 1e-13, 1e-14});
  const JointContinuation j = continue_at_joint(-1, 1, -1, 1, 0.8, 0.1, ty, c0.rho(s_b), c0.mu(s_b));
  EXPECT_TRUE(j.valid);
  const LaSpaceCurve c1(1, 1, j.lambda1, j.omega1, j.nu1, ty);
  SpacePlacement pl;
  pl.origin = Vec3(1, -2, 3);
  pl.scale = 2.5;
  Eigen::Matrix3d q = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  if (mirror) q.col(2) = -q.col(2);
  pl.matrix = pl.scale * q;
  pl.torsion_sign = mirror ? -1 : 1;
  return SpaceCurve({{c0, 0, s_b, Frame3{}}, {c1, j.s_c, j.s_c + 0.7, joint.frame}}, pl, ode);
}

// The frame at standard-form arc length u of piece k, integrated independently (rk45, rtol 1e-13)
// and placed by hand.
Frame3 reference_frame(const SpaceCurve& c, size_t k, double u) {
  const SpacePiece& p = c.pieces()[k];
  const Frame3 f = integrate_frenet(p.law, p.start, p.s_begin, u, {OdeMethod::rk45, 1e-13, 1e-14}).frame;
  const Eigen::Matrix3d& m = c.placement().matrix;
  const Vec3 t = (m * f.t).normalized(), n = (m * f.n).normalized();
  return {c.placement().origin + m * f.p, t, n, t.cross(n)};
}

double point_distance(const SpacePoint& a, const Frame3& b) {
  return std::max({(a.p - b.p).cwiseAbs().maxCoeff(), (a.t - b.t).cwiseAbs().maxCoeff(),
                   (a.n - b.n).cwiseAbs().maxCoeff(), (a.b - b.b).cwiseAbs().maxCoeff()});
}

TEST(SpaceCurve, LengthPiecesAndDomain) {
  const SpaceCurve c = two_piece_curve(false);
  EXPECT_NEAR(c.length(), 2.5 * (0.5 + 0.7), 1e-14);
  EXPECT_NEAR(c.piece_start(1), 2.5 * 0.5, 1e-15);
  EXPECT_EQ(c.piece_at(0), 0u);
  EXPECT_EQ(c.piece_at(c.piece_start(1)), 1u);  // the later piece at a joint
  EXPECT_EQ(c.piece_at(c.length()), 1u);
  EXPECT_DOUBLE_EQ(c.standard_s(1, c.piece_start(1)), c.pieces()[1].s_begin);
  EXPECT_DOUBLE_EQ(c.standard_s(0, 1.0), 0.4);
  EXPECT_EQ(c.s_domain().hi, c.length());
}

TEST(SpaceCurve, PieceEndsMapExactlyToTheirStandardFormEnds) {
  // s = piece_start(k + 1) is the end of piece k: its standard-form arc length is s_end itself,
  // not s_begin + (piece_start(k + 1) − piece_start(k)) / scale, which may miss it by an ulp.
  const LaSpaceCurve law(1, 0.5, 0.7, 0.2, 1.3, TorsionType::type2);
  int checked = 0;
  for (double scale : {0.1, 1.0 / 3, 0.7, 2.5, 7.3, 1e-3, 123.456})
    for (double s_begin : {0.0, 0.1, 0.37})
      for (double len : {0.3, 0.7, 1.1, 2.9}) {
        SpacePlacement pl;
        pl.scale = scale;
        pl.matrix = scale * Eigen::Matrix3d::Identity();
        const SpaceCurve c({{law, s_begin, s_begin + len, Frame3{}}, {law, s_begin + len, s_begin + 2 * len, Frame3{}}},
                           pl, {});
        EXPECT_EQ(c.standard_s(0, 0.0), s_begin);
        EXPECT_EQ(c.standard_s(0, c.piece_start(1)), c.pieces()[0].s_end) << scale << " " << s_begin << " " << len;
        EXPECT_EQ(c.standard_s(1, c.length()), c.pieces()[1].s_end) << scale << " " << s_begin << " " << len;
        ++checked;
      }
  EXPECT_EQ(checked, 84);
}

TEST(SpaceCurve, ClosedFormsFollowTheLawsInUserUnits) {
  // κ, τ against the case-by-case tables of ρ, μ above; τ < 0 on the mirror image; dκ/ds against
  // central differences of κ.
  double worst = 0, worst_d = 0;
  for (bool mirror : {false, true}) {
    const SpaceCurve c = two_piece_curve(mirror);
    const double sign = mirror ? -1 : 1;
    for (int i = 0; i <= 60; ++i) {
      const double s = c.length() * i / 60.0;
      const size_t k = c.piece_at(s);
      const LaSpaceCurve& law = c.pieces()[k].law;
      const double u = c.standard_s(k, s);
      const double rho = rho_table(law.alpha(), law.lambda(), u);
      const double mu = mu_table(law.beta(), law.omega(), law.nu(), law.type(), u);
      worst = std::max({worst, std::abs(c.kappa_at(s) * 2.5 * rho - 1), std::abs(sign * c.tau_at(s) * 2.5 * mu - 1)});
      EXPECT_EQ(c.tau_at(s) < 0, mirror);
      const double h = 1e-5, x = std::clamp(s, c.piece_start(k) + h, c.piece_start(k + 1) - h);  // inside piece k
      auto kappa_on_piece = [&](double y) { return law.kappa(c.standard_s(k, y)) / 2.5; };
      const double fd = (kappa_on_piece(x + h) - kappa_on_piece(x - h)) / (2 * h);
      worst_d = std::max(worst_d, std::abs(c.dkappa_ds_at(x) - fd) / std::abs(c.dkappa_ds_at(x)));
    }
  }
  std::printf("SpaceCurve closed forms: worst relative kappa/tau deviation %.2e, dkappa/ds vs differences %.2e\n", worst,
              worst_d);
  EXPECT_LE(worst, tol::kLaw);
  EXPECT_LE(worst_d, 1e-6);
}

TEST(SpaceCurve, FrameAtIntegratesFromTheStartOfItsPiece) {
  double worst = 0, worst_orth = 0;
  for (bool mirror : {false, true}) {
    const SpaceCurve c = two_piece_curve(mirror);
    for (int i = 0; i <= 24; ++i) {
      const double s = c.length() * i / 24.0;
      const SpacePoint p = c.frame_at(s);
      ASSERT_EQ(p.status, Status::ok) << p.message;
      EXPECT_EQ(p.piece, c.piece_at(s));
      EXPECT_EQ(p.kappa, c.kappa_at(s));
      EXPECT_EQ(p.tau, c.tau_at(s));
      worst = std::max(worst, point_distance(p, reference_frame(c, p.piece, c.standard_s(p.piece, s))));
      Eigen::Matrix3d f;
      f << p.t, p.n, p.b;
      worst_orth = std::max(worst_orth, (f.transpose() * f - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
    }
    EXPECT_EQ(c.frame_at(0).p, c.placement().origin);
    EXPECT_EQ(c.frame_at(0).evaluations, 0);
  }
  std::printf("SpaceCurve::frame_at vs independent rk45 integration: %.2e, orthonormality %.1e\n", worst, worst_orth);
  EXPECT_LE(worst, tol::kMagnusTight);
  EXPECT_LE(worst_orth, tol::kOrthonormal);
}

TEST(SpaceCurve, IsContinuousAtTheJoint) {
  for (bool mirror : {false, true}) {
    const SpaceCurve c = two_piece_curve(mirror);
    const double sj = c.piece_start(1);
    const SpacePoint before = c.sample(0.0, sj, 3).back();  // reaches the joint on piece 0
    const SpacePoint after = c.frame_at(sj);                // piece 1's start
    ASSERT_EQ(before.piece, 0u);
    ASSERT_EQ(after.piece, 1u);
    ASSERT_EQ(before.status, Status::ok);
    EXPECT_LE(point_distance(before, {after.p, after.t, after.n, after.b}), tol::kMagnusTight);
    EXPECT_NEAR(before.kappa / after.kappa, 1, tol::kJointRelative);
    EXPECT_NEAR(before.tau / after.tau, 1, tol::kJointRelative);
    EXPECT_NEAR(before.dkappa_ds / after.dkappa_ds, 1, tol::kJointRelative);  // LCG continuity (000 Eq. (11))
  }
}

TEST(SpaceCurve, SamplesAreUniformAndEqualTheFramesAt) {
  const SpaceCurve c = two_piece_curve(true);
  const auto pts = c.sample(31);
  ASSERT_EQ(pts.size(), 31u);
  double worst = 0;
  long evaluations = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const SpacePoint& p = pts[i];
    ASSERT_EQ(p.status, Status::ok) << p.message;
    EXPECT_NEAR(p.s, c.length() * static_cast<double>(i) / 30, 1e-14);
    EXPECT_GE(p.evaluations, evaluations);  // cumulative
    evaluations = p.evaluations;
    worst = std::max(worst, point_distance(p, reference_frame(c, p.piece, c.standard_s(p.piece, p.s))));
  }
  EXPECT_EQ(pts.back().s, c.length());
  std::printf("SpaceCurve::sample vs independent rk45 integration: %.2e (%ld evaluations)\n", worst, evaluations);
  EXPECT_LE(worst, tol::kMagnusTight);
}

// rk4 (h = 1e-3) with a cap of 150 steps: a sample more than 0.15 (standard form) past its known
// point fails. Samples at user s = 0, 0.75, 1.5, 2.25, 3 (joint at 1.25, scale 2.5): 0.75 is 0.3
// past piece 0's start (fails), 1.5 is 0.1 past the joint (ok), 2.25 and 3 are 0.3 and 0.6 past
// that sample (fail).
TEST(SpaceCurve, AFailedSampleIsFlaggedAndShiftsNoOther) {
  OdeOptions rk4{OdeMethod::rk4, 1e-12, 1e-13, 1e-3};
  rk4.max_steps = 150;
  const SpaceCurve c = two_piece_curve(false, rk4);
  const auto pts = c.sample(5);
  ASSERT_EQ(pts.size(), 5u);
  const Status want[] = {Status::ok, Status::max_iterations, Status::ok, Status::max_iterations, Status::max_iterations};
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(pts[i].status, want[i]) << "sample " << i << ": " << pts[i].message;
    EXPECT_EQ(pts[i].message.empty(), want[i] == Status::ok) << pts[i].message;
    EXPECT_EQ(pts[i].s, c.length() * static_cast<double>(i) / 4);  // its own s and closed forms
    EXPECT_EQ(pts[i].kappa, c.kappa_at(pts[i].s));
    EXPECT_EQ(pts[i].tau, c.tau_at(pts[i].s));
  }
  // A good sample is the one integrated from its known point, unaffected by the failure before it.
  const SpacePoint direct = c.frame_at(pts[2].s);
  ASSERT_EQ(direct.status, Status::ok);
  EXPECT_EQ(pts[2].p, direct.p);
  EXPECT_EQ(pts[2].t, direct.t);
  // A flagged sample holds the frame of the known point it was to be integrated from.
  EXPECT_EQ(pts[1].p, pts[0].p);
  EXPECT_EQ(pts[1].t, pts[0].t);
  EXPECT_EQ(pts[3].p, pts[2].p);
  EXPECT_EQ(pts[4].n, pts[2].n);
  // frame_at flags the same way: from piece 0's start to 0.3 past it.
  const SpacePoint far = c.frame_at(0.75);
  EXPECT_EQ(far.status, Status::max_iterations);
  EXPECT_EQ(far.p, c.placement().origin);
}

TEST(SpaceCurve, InvalidInputNamesTheParameter) {
  const auto param = [](auto&& f) { return test::thrown_parameter(f); };
  const SpaceCurve c = two_piece_curve(false);
  EXPECT_EQ(param([&] { c.frame_at(-0.1); }), "s");
  EXPECT_EQ(param([&] { c.kappa_at(c.length() * 1.01); }), "s");
  EXPECT_EQ(param([&] { c.sample(1); }), "points");
  EXPECT_EQ(param([&] { c.sample(2'000'000); }), "points");
  EXPECT_EQ(param([&] { c.sample(1.0, 0.5, 3); }), "s1");
  EXPECT_EQ(param([] { SpaceCurve().sample(3); }), "s");
  EXPECT_EQ(param([] { SpaceCurve().frame_at(0); }), "s");
  const LaSpaceCurve law(-1, 0, 1, 0.1, 1, TorsionType::type1);  // s < 1
  EXPECT_EQ(param([&] { SpaceCurve({}, {}, {}); }), "pieces");
  EXPECT_EQ(param([&] { SpaceCurve({{law, 0, 1.5, Frame3{}}}, {}, {}); }), "pieces[0].s_end");
  EXPECT_EQ(param([&] { SpaceCurve({{law, NAN, 0.5, Frame3{}}}, {}, {}); }), "pieces[0].s_begin");
  SpacePlacement skew;
  skew.matrix(0, 1) = 0.5;
  EXPECT_EQ(param([&] { SpaceCurve({{law, 0, 0.5, Frame3{}}}, skew, {}); }), "placement.matrix");
  SpacePlacement mirrored_sign;
  mirrored_sign.torsion_sign = -1;  // det of the identity is +1
  EXPECT_EQ(param([&] { SpaceCurve({{law, 0, 0.5, Frame3{}}}, mirrored_sign, {}); }), "placement.matrix");
  SpacePlacement zero;
  zero.scale = 0;
  EXPECT_EQ(param([&] { SpaceCurve({{law, 0, 0.5, Frame3{}}}, zero, {}); }), "placement.scale");
  EXPECT_EQ(param([&] { SpaceCurve({{law, 0, 0.5, Frame3{}}}, {}, OdeOptions{OdeMethod::rk45, 0}); }), "rtol");
}

}  // namespace
}  // namespace lac
