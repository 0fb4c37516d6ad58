// G1 and compound-rhythm LA space segments (constructions/space_segment; 000 §2.2, §4; MATH.md §3).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>

#include "lac/common/error.hpp"
#include "lac/constructions/space_drawable_cases.hpp"
#include "lac/constructions/space_segment.hpp"
#include "tests/support/space_tolerances.hpp"

namespace lac {
namespace {
namespace tol = test::space_tol;

SpaceSegmentResult solve_case(const DrawableCase& c, const SpaceSegmentOptions& o) {
  return c.compound ? solve_compound_space_segment(c.ends, c.spec, o) : solve_g1_space_segment(c.ends, c.g1(), o);
}

std::vector<DrawableCase> cases(bool compound, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<DrawableCase> out;
  for (int i = 0; i < n; ++i) {
    bool ok = false;
    out.push_back(random_drawable_case(rng, compound, &ok));
    EXPECT_TRUE(ok);
  }
  return out;
}

// The end tangent of the produced curve, re-integrated with an independent method (rk45 at
// rtol 1e-13 instead of the solver's Magnus steps), in user coordinates.
Vec3 reintegrated_end_tangent(const SpaceSegmentResult& r) {
  Frame3 f;
  for (size_t i = 0; i < r.pieces.size(); ++i) {
    const SpacePiece& p = r.pieces[i];
    const LaSpaceCurve c(p.alpha, p.beta, p.lambda, p.omega, p.nu, p.type);
    const FrenetResult fr = integrate_frenet(c, f, p.s_begin, p.s_end, OdeOptions{OdeMethod::rk45, 1e-13, 1e-14});
    EXPECT_EQ(fr.status, Status::ok);
    f = fr.frame;
  }
  return (r.placement * f.t).normalized();
}

double angle(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// LCG and LTG slopes of one piece recomputed from the produced curve's frames alone: κ = |T'|,
// |τ| = |B'| by central differences of the sampled frames; then log(r |ds/dr|) against log r.
std::pair<double, double> graph_slopes(const std::vector<SpaceSample>& pts) {
  std::vector<double> ls, lr, lm;
  for (size_t i = 1; i + 1 < pts.size(); ++i) {
    const double ds = pts[i + 1].s - pts[i - 1].s;
    const double kappa = 2 * std::asin(0.5 * (pts[i + 1].t - pts[i - 1].t).norm()) / ds;  // chord angle
    const double tau = 2 * std::asin(0.5 * (pts[i + 1].b - pts[i - 1].b).norm()) / ds;
    ls.push_back(pts[i].s);
    lr.push_back(-std::log(kappa));
    lm.push_back(-std::log(tau));
  }
  std::vector<double> xr, yr, xm, ym;
  constexpr size_t kStride = 8;  // differentiate log r over 2·kStride samples
  for (size_t i = kStride; i + kStride < ls.size(); ++i) {
    const double ds = ls[i + kStride] - ls[i - kStride];
    const double dlr = (lr[i + kStride] - lr[i - kStride]) / ds;  // d log ρ / ds = ρ'/ρ
    const double dlm = (lm[i + kStride] - lm[i - kStride]) / ds;
    xr.push_back(lr[i]);
    yr.push_back(-std::log(std::abs(dlr)));  // log(ρ ds/dρ) = −log(d log ρ/ds)
    xm.push_back(lm[i]);
    ym.push_back(-std::log(std::abs(dlm)));
  }
  return {slope(xr, yr), slope(xm, ym)};
}

TEST(SpaceSegment, EverySolverMeetsTheEndConditionsOnDrawableCases) {
  for (bool compound : {false, true}) {
    const auto cs = cases(compound, 12, compound ? 11 : 7);
    for (NonlinearMethod solver : {NonlinearMethod::newton, NonlinearMethod::ceres, NonlinearMethod::simplex}) {
      SpaceSegmentOptions o;
      o.solver = solver;
      int ok = 0;
      double worst_tangent = 0, worst_reint = 0, worst_pos = 0, worst_start = 0;
      for (const auto& c : cs) {
        const SpaceSegmentResult r = solve_case(c, o);
        if (r.status != Status::ok) {
          std::printf("  %s %s: %s\n", compound ? "compound" : "G1", std::string(to_string(solver)).c_str(), r.message.c_str());
          continue;
        }
        ++ok;
        const double chord = (c.ends.p1 - c.ends.p0).norm();
        worst_tangent = std::max(worst_tangent, r.tangent_error);
        worst_reint = std::max(worst_reint, angle(reintegrated_end_tangent(r), c.ends.v1.normalized()));
        worst_pos = std::max(worst_pos, r.position_error / chord);
        const auto pts = space_segment_points(r, 20);
        worst_start = std::max({worst_start, (pts.front().p - c.ends.p0).norm() / chord,
                                angle(pts.front().t, c.ends.v0.normalized()),
                                (pts.back().p - c.ends.p1).norm() / chord});
        EXPECT_EQ(r.pieces.size(), compound ? 2u : 1u);
        EXPECT_GT(r.evaluations, 0);
        EXPECT_GT(r.length, chord * (1 - 1e-12));
      }
      std::printf("%-8s %-7s: %d/%zu ok; worst tangent error %.2e (re-integrated with rk45 %.2e), end position %.2e, "
                  "start/end of polyline %.2e\n",
                  compound ? "compound" : "G1", std::string(to_string(solver)).c_str(), ok, cs.size(), worst_tangent,
                  worst_reint, worst_pos, worst_start);
      EXPECT_GE(ok, static_cast<int>(cs.size()) - 1) << "success rate on drawable cases";
      EXPECT_LE(worst_tangent, tol::kTangent);
      EXPECT_LE(worst_reint, tol::kTangent);
      EXPECT_LE(worst_pos, tol::kPosition);
      EXPECT_LE(worst_start, tol::kPosition);
    }
  }
}

TEST(SpaceSegment, CompoundJointIsContinuousAndFollowsTheContinuityConditions) {
  const auto cs = cases(true, 10, 23);
  double worst = 0, worst_frame = 0;
  int checked = 0;
  for (const auto& c : cs) {
    const SpaceSegmentResult r = solve_compound_space_segment(c.ends, c.spec);
    if (r.status != Status::ok) continue;
    ++checked;
    const SpacePiece &p0 = r.pieces[0], &p1 = r.pieces[1];
    const LaSpaceCurve c0(p0.alpha, p0.beta, p0.lambda, p0.omega, p0.nu, p0.type);
    const LaSpaceCurve c1(p1.alpha, p1.beta, p1.lambda, p1.omega, p1.nu, p1.type);
    const double rc = c0.rho(p0.s_end), mc = c0.mu(p0.s_end);
    worst = std::max({worst, std::abs(c1.rho(p1.s_begin) / rc - 1), std::abs(c1.mu(p1.s_begin) / mc - 1),
                      std::abs(p1.lambda / (p0.lambda * std::pow(rc, c.spec.alpha1 - c.spec.alpha0)) - 1),
                      std::abs(p1.omega / (p0.omega * std::pow(mc, c.spec.beta1 - c.spec.beta0)) - 1)});
    // dρ/ds = Λ ρ^(1−α) and dμ/ds = ±Ω μ^(1−β) match on both sides (G3 and LTG continuity)
    worst = std::max(worst, std::abs(p1.lambda * std::pow(rc, 1 - p1.alpha) / (p0.lambda * std::pow(rc, 1 - p0.alpha)) - 1));
    worst = std::max(worst, std::abs(p1.omega * std::pow(mc, 1 - p1.beta) / (p0.omega * std::pow(mc, 1 - p0.beta)) - 1));
    // joint position and frame: last sample of piece 0 = first of piece 1 = reported joint
    const auto pts = space_segment_points(r, 60);
    size_t k = 0;
    while (pts[k + 1].piece == 0) ++k;
    const double chord = (c.ends.p1 - c.ends.p0).norm();
    worst_frame = std::max({worst_frame, (pts[k].p - pts[k + 1].p).norm() / chord, (pts[k].p - r.joint).norm() / chord,
                            (pts[k].t - pts[k + 1].t).norm(), (pts[k].n - pts[k + 1].n).norm(),
                            (pts[k].b - pts[k + 1].b).norm(), std::abs(pts[k].kappa / pts[k + 1].kappa - 1),
                            std::abs(pts[k].tau / pts[k + 1].tau - 1)});
  }
  std::printf("compound joints (%d solved): worst law mismatch %.2e, worst position/frame/kappa/tau jump %.2e\n", checked,
              worst, worst_frame);
  EXPECT_GE(checked, 8);
  EXPECT_LE(worst, tol::kJointRelative);
  EXPECT_LE(worst_frame, tol::kJointRelative);
}

TEST(SpaceSegment, LcgAndLtgOfTheProducedCurveAreLinesWithTheRequestedSlopes) {
  double worst = 0;
  int checked = 0;
  for (bool compound : {false, true}) {
    for (const auto& c : cases(compound, 4, compound ? 31 : 37)) {
      const SpaceSegmentResult r = c.compound ? solve_compound_space_segment(c.ends, c.spec) : solve_g1_space_segment(c.ends, c.g1());
      if (r.status != Status::ok) continue;
      const auto pts = space_segment_points(r, 3000);
      for (int piece = 0; piece < static_cast<int>(r.pieces.size()); ++piece) {
        std::vector<SpaceSample> mine;
        for (const auto& p : pts)
          if (p.piece == piece) mine.push_back(p);
        if (mine.size() < 200) continue;  // a very short piece: too few samples for differences
        const auto [a, b] = graph_slopes(mine);
        const double want_a = piece == 0 ? c.spec.alpha0 : c.spec.alpha1;
        const double want_b = piece == 0 ? c.spec.beta0 : c.spec.beta1;
        worst = std::max({worst, std::abs(a - want_a), std::abs(b - want_b)});
        ++checked;
      }
    }
  }
  std::printf("LCG/LTG slopes from finite differences of the frames (%d pieces): worst |slope - requested| %.2e\n", checked, worst);
  EXPECT_GE(checked, 8);
  EXPECT_LE(worst, tol::kSlope);
}

TEST(SpaceSegment, SamplesHaveOrthonormalRightHandedFrames) {
  for (const auto& c : cases(true, 3, 41)) {
    const SpaceSegmentResult r = solve_compound_space_segment(c.ends, c.spec);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    for (const auto& p : space_segment_points(r, 100)) {
      Eigen::Matrix3d f;
      f << p.t, p.n, p.b;
      EXPECT_LE((f.transpose() * f - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), tol::kOrthonormal);
      EXPECT_NEAR(f.determinant(), 1.0, 1e-12);
    }
  }
}

TEST(SpaceSegment, CompoundWithEqualSlopesIsTheMonotonicSegment) {
  // α0 = α1, β0 = β1 makes Λ1 = Λ0, Ω1 = Ω0, s_c = s_b, ν1 = ν0 (000 §4.1): the same curve.
  for (const auto& c : cases(false, 4, 53)) {
    const SpaceSegmentResult g = solve_g1_space_segment(c.ends, c.g1());
    ASSERT_EQ(g.status, Status::ok) << g.message;
    CompoundSpaceSpec sp = c.spec;
    sp.alpha1 = sp.alpha0;
    sp.beta1 = sp.beta0;
    sp.r_theta = 0.4;
    const SpaceSegmentResult k = construct_compound_space_segment(c.ends, sp, g.pieces[0].lambda, g.pieces[0].nu,
                                                                  g.torsion_sign < 0);
    ASSERT_EQ(k.pieces.size(), 2u);
    EXPECT_NEAR(k.pieces[1].lambda, g.pieces[0].lambda, 1e-13 * g.pieces[0].lambda);
    EXPECT_NEAR(k.pieces[1].nu, g.pieces[0].nu, 1e-12 * g.pieces[0].nu);
    EXPECT_NEAR(k.pieces[1].s_begin, k.pieces[0].s_end, 1e-12);
    EXPECT_NEAR(k.length, g.length, 1e-9 * g.length);
    EXPECT_LE(k.tangent_error, 1e-9);
  }
}

TEST(SpaceSegment, UndrawableConfigurationGivesAStatusNotAnException) {
  // Planar data (v1 in the plane of v0 and P1 − P0) would need zero torsion: ν → ∞, outside the
  // solver's box. Expect a Status other than ok, no NaN, and a message.
  SpaceEndpoints e{Vec3::Zero(), Vec3::UnitX(), Vec3(1, 1, 0), Vec3(-1, 0.2, 0)};
  for (NonlinearMethod s : {NonlinearMethod::newton, NonlinearMethod::ceres, NonlinearMethod::simplex}) {
    SpaceSegmentOptions o;
    o.solver = s;
    o.max_starts = 3;
    const SpaceSegmentResult r = solve_g1_space_segment(e, {-1, 0, 0.1, TorsionType::type1}, o);
    EXPECT_NE(r.status, Status::ok) << to_string(s) << " tangent error " << r.tangent_error;
    EXPECT_FALSE(r.message.empty());
    EXPECT_FALSE(std::isnan(r.tangent_error));
    EXPECT_GT(r.evaluations, 0);
  }
}

TEST(SpaceSegment, BadInputNamesTheParameter) {
  auto param = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.parameter();
    }
    return std::string("<no error>");
  };
  const G1SpaceSpec g{0, 0, 0.1, TorsionType::type1};
  const CompoundSpaceSpec k{-1, 1, -1, 1, 0.1, 0.5, TorsionType::type1};
  const SpaceEndpoints good{Vec3::Zero(), Vec3::UnitX(), Vec3(1, 1, 0.2), Vec3(0, 1, 0.3)};
  auto with = [&](auto change) {
    SpaceEndpoints e = good;
    change(e);
    return e;
  };
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.v0 = Vec3(2, 2, 0); e.p1 = Vec3(1, 1, 0); }), g); }), "v0");
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.v0 = Vec3(-1, -1, 0); e.p1 = Vec3(1, 1, 0); }), g); }), "v0");
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.v0 = Vec3::Zero(); }), g); }), "v0");
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.v1 = Vec3::Zero(); }), g); }), "v1");
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.p0.x() = NAN; }), g); }), "p0");
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.p1 = e.p0; }), g); }), "p1");
  EXPECT_EQ(param([&] { solve_g1_space_segment(with([](auto& e) { e.v1.z() = INFINITY; }), g); }), "v1");
  EXPECT_EQ(param([&] { solve_g1_space_segment(good, {NAN, 0, 0.1, TorsionType::type1}); }), "alpha");
  EXPECT_EQ(param([&] { solve_g1_space_segment(good, {0, NAN, 0.1, TorsionType::type1}); }), "beta");
  EXPECT_EQ(param([&] { solve_g1_space_segment(good, {0, 0, -0.1, TorsionType::type1}); }), "omega");
  EXPECT_EQ(param([&] { solve_g1_space_segment(good, {0, 0, 0.1, static_cast<TorsionType>(0)}); }), "type");
  for (double r : {0.0, 1.0, -0.2, std::nan("")}) {
    CompoundSpaceSpec bad = k;
    bad.r_theta = r;
    EXPECT_EQ(param([&] { solve_compound_space_segment(good, bad); }), "r_theta");
  }
  CompoundSpaceSpec bad = k;
  bad.alpha1 = INFINITY;
  EXPECT_EQ(param([&] { solve_compound_space_segment(good, bad); }), "alpha1");
  bad = k;
  bad.omega0 = NAN;
  EXPECT_EQ(param([&] { solve_compound_space_segment(good, bad); }), "omega0");
  EXPECT_EQ(param([] { parse_nonlinear_method("bfgs"); }), "solver");
  SpaceSegmentOptions o;
  o.tangent_tolerance = 0;
  EXPECT_EQ(param([&] { solve_g1_space_segment(good, g, o); }), "tangent_tolerance");
}

}  // namespace
}  // namespace lac
