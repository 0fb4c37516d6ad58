// LA chains (constructions/chain.hpp): the three-point frame estimate, G1 and G2 chains through
// points on a circle (exactly the circle), closed chains, failure propagation, bad input.
#include "lac/constructions/chain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using std::numbers::pi;
using P = std::complex<double>;

double wrap(double a) { return std::remainder(a, 2 * pi); }

// n points on the circle of radius R about c, counter-clockwise from angle a0 by step da.
std::vector<P> on_circle(int n, double R, P c, double a0, double da) {
  std::vector<P> v;
  for (int k = 0; k < n; ++k) v.push_back(c + std::polar(R, a0 + k * da));
  return v;
}

// Eight points around an irregular closed loop (the figure's input).
std::vector<P> loop8() { return {{0, 0}, {2, -0.5}, {4, 0.3}, {5, 2}, {4, 4}, {2, 4.6}, {0.2, 3.8}, {-0.8, 2}}; }

TEST(ChainFrames, ExactOnACircle) {
  const auto pts = on_circle(5, 2.0, {1, -1}, 0.3, 0.4);
  const auto f = estimate_frames(pts, false);
  ASSERT_EQ(f.size(), pts.size());
  for (size_t k = 0; k < pts.size(); ++k) {
    EXPECT_NEAR(wrap(f[k].theta - (0.3 + 0.4 * k + pi / 2)), 0.0, 1e-14) << k;
    EXPECT_NEAR(f[k].kappa, 0.5, 1e-14) << k;
  }
  // Clockwise: curvature −1/R, tangent reversed.
  std::vector<P> cw(pts.rbegin(), pts.rend());
  const auto g = estimate_frames(cw, false);
  for (size_t k = 0; k < cw.size(); ++k) EXPECT_NEAR(g[k].kappa, -0.5, 1e-14) << k;
  EXPECT_NEAR(wrap(g[0].theta - (0.3 + 0.4 * 4 - pi / 2)), 0.0, 1e-14);
}

TEST(ChainFrames, LineAndTwoPoints) {
  const std::vector<P> line{{0, 0}, {1, 1}, {3, 3}, {4, 4}};
  for (const auto& f : estimate_frames(line, false)) {
    EXPECT_NEAR(f.theta, pi / 4, 1e-15);
    EXPECT_EQ(f.kappa, 0.0);
  }
  const std::vector<P> two{{1, 1}, {1, 3}};
  const auto f = estimate_frames(two, false);
  EXPECT_NEAR(f[0].theta, pi / 2, 1e-15);
  EXPECT_NEAR(f[1].theta, pi / 2, 1e-15);
}

// Points on a circle with the circle's tangents: every pair's least-turning LA segment is the
// circular arc (κ constant is an LA curve of every α), so the chain is the circle.
TEST(Chain, G1OnACircleIsTheCircle) {
  for (double alpha : {-1.0, -0.5, 0.0, 1.0, 2.0}) {
    ChainProblem p{.points = on_circle(6, 1.5, {0, 0}, 0.0, 0.5), .alpha = alpha};
    const ChainResult r = solve_chain(p);
    ASSERT_TRUE(r.usable()) << alpha << ": " << r.summary.message;
    EXPECT_TRUE(r.info.estimated_thetas);
    EXPECT_EQ(r.curve.segments().size(), 5u);
    EXPECT_NEAR(r.curve.length(), 1.5 * 0.5 * 5, 1e-10) << alpha;
    for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) EXPECT_NEAR(r.curve.kappa_at(t * r.curve.length()), 1 / 1.5, 1e-9) << alpha;
  }
}

TEST(Chain, ClosedG1ChainIsG1AndTurnsOnce) {
  for (double alpha : {-1.0, -0.3}) {
    ChainProblem p{.points = loop8(), .alpha = alpha, .closed = true};
    const ChainResult r = solve_chain(p);
    ASSERT_TRUE(r.usable()) << alpha << ": " << r.summary.message;
    ASSERT_EQ(r.info.pairs.size(), 8u);
    EXPECT_EQ(r.curve.segments().size(), 8u);
    for (const Joint& j : r.curve.joints()) {
      EXPECT_LT(j.position_gap, 1e-10 * 5);
      EXPECT_LT(std::abs(j.angle_gap), 1e-10);
    }
    // Back at the start, in the start direction, one full turn.
    const PositionResult end = position_at(r.curve, r.curve.length());
    EXPECT_LT(std::abs(end.point.position - loop8()[0]), 1e-10 * 5);
    EXPECT_NEAR(r.curve.theta_at(r.curve.length()) - r.curve.theta_at(0), 2 * pi, 1e-10);
  }
}

TEST(Chain, GivenTangentsAreMet) {
  const std::vector<P> pts{{0, 0}, {1, 0.5}, {2, 0}, {3, 0.4}};
  const std::vector<double> th{0.2, -0.3, 0.1, 0.6};
  ChainProblem p{.points = pts, .thetas = th, .alpha = -1};
  const ChainResult r = solve_chain(p);
  ASSERT_TRUE(r.usable()) << r.summary.message;
  EXPECT_FALSE(r.info.estimated_thetas);
  for (size_t k = 0; k < pts.size(); ++k) {
    const double s = r.curve.segment_start(k);
    EXPECT_NEAR(wrap(r.curve.theta_at(s) - th[k]), 0.0, 1e-10) << k;
    EXPECT_LT(std::abs(position_at(r.curve, s).point.position - pts[k]), 1e-10) << k;
  }
}

// The α < 0 G2 start solves two 1-D equations for the joint q (constructions/detail/g2_system.cpp);
// on this chain (oracle campaign, chain problem 106) one of them is met exactly by a bracket
// probe, which once reached TOMS 748 as the empty bracket [x, x] and threw InputError.
TEST(Chain, G2StartWhoseRootIsProbedExactly) {
  const std::vector<P> pts{{-7.6777448467952851, 6.2291612833796748}, {-9.4414625659794851, 4.512981376105679},
                           {-8.8432154320288507, 3.6432442019774021}, {-8.3680449932263077, 4.0651800896234391},
                           {-8.4916984025500071, 6.2680854851132173}, {-8.4122308560110195, 6.3966867526617435}};
  ChainProblem p{.points = pts, .alpha = -0.3, .continuity = ChainContinuity::g2};
  ChainResult r;
  ASSERT_NO_THROW(r = solve_chain(p));
  ASSERT_TRUE(r.usable()) << r.summary.message;
  for (const Joint& j : r.curve.joints()) EXPECT_LT(std::abs(j.curvature_gap), 1e-8);
}

TEST(Chain, G2ChainIsCurvatureContinuous) {
  ChainProblem p{.points = loop8(), .alpha = -0.5, .continuity = ChainContinuity::g2, .closed = true};
  const ChainResult r = solve_chain(p);
  ASSERT_TRUE(r.usable()) << r.summary.message;
  EXPECT_EQ(r.curve.segments().size(), 3u * 8u);
  for (const Joint& j : r.curve.joints()) {
    EXPECT_LT(j.position_gap, 1e-9);
    EXPECT_LT(std::abs(j.angle_gap), 1e-9);
    EXPECT_LT(std::abs(j.curvature_gap), 1e-8);
  }
  for (size_t k = 0; k < 8; ++k) EXPECT_NEAR(r.curve.kappa_at(r.curve.segment_start(3 * k)), r.info.kappas[k], 1e-8) << k;
}

// α > 0: κ cannot change sign, so an S-shaped pair has no curve turning at most π (winding 0);
// the chain names the pair and the scope of the proof.
TEST(Chain, APairWithoutCurveFailsTheChain) {
  ChainProblem p{.points = {{0, 0}, {1, 0}, {2, 0}}, .thetas = {0.2, -0.2, -0.4}, .alpha = 1.0};
  ChainOptions o;
  o.g1.winding = 0;
  const ChainResult r = solve_chain(p, o);
  EXPECT_FALSE(r.usable());
  EXPECT_EQ(r.summary.status, Status::no_solution);
  EXPECT_EQ(r.info.failed_pair, 1);
  EXPECT_NE(r.summary.message.find("pair 1"), std::string::npos) << r.summary.message;
  EXPECT_NE(r.summary.message.find("winding 0"), std::string::npos) << r.summary.message;
  EXPECT_TRUE(r.curve.segments().empty());
}

// Without a winding each pair takes its least-turning curve: the S-shaped pair above turns further.
TEST(Chain, EachPairSearchesItsWindings) {
  ChainProblem p{.points = {{0, 0}, {1, 0}, {2, 0}}, .thetas = {0.2, -0.2, -0.4}, .alpha = 1.0};
  const ChainResult r = solve_chain(p);
  ASSERT_TRUE(r.usable()) << r.summary.message;
  ASSERT_EQ(r.info.windings.size(), 2u);
  ASSERT_EQ(r.info.turnings.size(), 2u);
  EXPECT_EQ(r.info.windings[0], 0);
  EXPECT_NEAR(r.info.turnings[0], -0.4, 1e-12);
  EXPECT_NE(r.info.windings[1], 0);
  EXPECT_GT(std::abs(r.info.turnings[1]), std::numbers::pi);
  const auto& segs = r.curve.segments();
  ASSERT_EQ(segs.size(), 2u);
  EXPECT_NEAR(segs[1].turning(), r.info.turnings[1], 1e-10);
  const PositionResult end = position_at(r.curve, r.curve.length());
  ASSERT_TRUE(usable(end.status)) << end.message;
  EXPECT_LE(std::abs(end.point.position - std::complex<double>(2, 0)), 1e-9);
  ASSERT_TRUE(r.summary.error);
  EXPECT_LE(*r.summary.error, 1e-10);
  // The G2 chain: the pairs' windings are reported as well.
  ChainProblem q{.points = {{0, 0}, {1, 1}, {2, 0}, {3, 1}}, .alpha = -1, .continuity = ChainContinuity::g2};
  const ChainResult g2 = solve_chain(q);
  ASSERT_TRUE(g2.usable()) << g2.summary.message;
  EXPECT_EQ(g2.info.windings.size(), 3u);
}

TEST(Chain, BadInputNamesTheParameter) {
  using test::thrown_parameter;
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}}}); }), "points");
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}, {1, 0}}, .closed = true}); }), "points");
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}, {0, 0}, {1, 0}}}); }), "points");
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}, {NAN, 0}}}); }), "points");
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}, {1, 0}}, .thetas = {0.0}}); }), "thetas");
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}, {1, 0}}, .kappas = {0.0, 1.0}}); }), "kappas");
  EXPECT_EQ(thrown_parameter([] { solve_chain({.points = {{0, 0}, {1, 0}}, .alpha = INFINITY}); }), "alpha");
  EXPECT_EQ(thrown_parameter([] { parse_chain_continuity("g3"); }), "continuity");
}

}  // namespace
}  // namespace lac
