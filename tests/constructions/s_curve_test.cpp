// S-shaped G1 input (004 §2.4–2.5) and the linear-q segment quadrature.
#include "lac/constructions/s_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "lac/common/error.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"

namespace lac {
namespace {

constexpr double kEndTol = 1e-10;         // end position (× chord) and tangent angles
constexpr double kQuadratureTol = 2e-13;  // graded Gauss–Legendre vs tanh-sinh, per segment

using Points = std::array<std::complex<double>, 4>;

double wrap(double a) { return std::remainder(a, 2 * std::numbers::pi); }

// Frame and position at t = s / length ∈ [0, 1] from P0 (positions by Gauss–Legendre).
CurvePoint at(const SCurveResult& r, double t) {
  const PositionResult p = position_at(r.curve, t * r.curve.length());
  EXPECT_TRUE(usable(p.status)) << p.message;
  return p.point;
}

void expect_interpolates(const SCurveResult& r, const Points& P) {
  const double chord = std::abs(P[3] - P[0]);
  const auto a = at(r, 0), b = at(r, 1);
  EXPECT_LE(std::abs(a.position - P[0]) / chord, kEndTol);
  EXPECT_LE(std::abs(b.position - P[3]) / chord, kEndTol);
  EXPECT_LE(std::abs(wrap(a.theta - std::arg(P[1] - P[0]))), kEndTol);
  EXPECT_LE(std::abs(wrap(b.theta - std::arg(P[3] - P[2]))), kEndTol);
  EXPECT_LE(*r.summary.residuals.position / chord, kEndTol);
  EXPECT_LE(*r.summary.residuals.angle, kEndTol);
}

TEST(SCurve, ParallelTangentsGiveAnSCurveWithOneInflection) {
  const Points P{{{0, 0}, {1, 0}, {2, 1}, {3, 1}}};
  for (double alpha : {-0.5, -1.0, -2.0, -4.0}) {
    for (RootMethod m : {RootMethod::toms748, RootMethod::bisection}) {
      SCurveOptions o;
      o.solver = m;
      const auto r = solve_s_curve(P, alpha, o);
      SCOPED_TRACE("alpha " + std::to_string(alpha) + " " + std::string(to_string(m)));
      ASSERT_EQ(r.summary.status, Status::ok) << r.summary.message;
      EXPECT_EQ(r.info.shape, SCurveShape::s_shaped);
      expect_interpolates(r, P);
      ASSERT_TRUE(r.info.inflection_s.has_value());
      const double inflection = *r.info.inflection_s, length = r.curve.length();
      ASSERT_GT(inflection, 0);
      ASSERT_LT(inflection, length);
      // Curvature is zero at the inflection and changes sign there.
      const double t = inflection / length;
      EXPECT_NEAR(at(r, t).kappa * length, 0.0, 1e-9);
      EXPECT_LT(at(r, 0.5 * t).kappa * at(r, 0.5 * (1 + t)).kappa, 0.0);
    }
  }
}

// The accuracy contract (common/accuracy.hpp): summary.error is the largest verified residual
// (and the integrator's deviation from the tanh-sinh check) relative to the chord; ok within the
// target `accuracy`; beyond `accept` inaccurate, without a curve.
TEST(SCurve, AchievedErrorIsGradedAgainstAccuracyAndAccept) {
  const Points P{{{0, 0}, {1, 0}, {2, 1}, {3, 1}}};
  const SCurveResult r = solve_s_curve(P, -1.0);
  ASSERT_EQ(r.summary.status, Status::ok) << r.summary.message;
  ASSERT_TRUE(r.summary.error.has_value());
  const double chord = std::abs(P[3] - P[0]);
  EXPECT_GE(*r.summary.error, *r.summary.residuals.position / chord);
  EXPECT_GE(*r.summary.error, *r.summary.residuals.angle);
  EXPECT_LE(*r.summary.error, SCurveOptions{}.accuracy);
  EXPECT_EQ(r.summary.accept, kDefaultAccept);
  // rk4 with one step of 10 over the curve: the end point, checked by tanh-sinh, far off.
  SCurveOptions coarse;
  coarse.integrator = Rk4{.h = 10};
  const SCurveResult c = solve_s_curve(P, -1.0, coarse);
  EXPECT_EQ(c.summary.status, Status::inaccurate) << c.summary.message;
  ASSERT_TRUE(c.summary.error.has_value());
  EXPECT_GT(*c.summary.error, kDefaultAccept);
  EXPECT_TRUE(c.curve.segments().empty());
  EXPECT_FALSE(c.info.inflection_s.has_value());
  // The same error within a loosened accept bound: usable, tolerance_not_met.
  coarse.accept = 0.1;
  const SCurveResult loose = solve_s_curve(P, -1.0, coarse);
  if (*c.summary.error <= 0.1) {
    EXPECT_EQ(loose.summary.status, Status::tolerance_not_met) << loose.summary.message;
    EXPECT_FALSE(loose.curve.segments().empty());
  }
  for (double bad : {0.0, 0.2, std::nan("")}) {
    SCurveOptions o;
    o.accept = bad;
    EXPECT_THROW(solve_s_curve(P, -1.0, o), InputError) << bad;
  }
  SCurveOptions above;
  above.accuracy = 1e-3;  // a target above the accept bound
  EXPECT_THROW(solve_s_curve(P, -1.0, above), InputError);
}

TEST(SCurve, RootMethodsAgree) {
  const Points P{{{0, 0}, {1, 0}, {2, 1.5}, {3, 1}}};
  SCurveOptions bis;
  bis.solver = RootMethod::bisection;
  const auto a = solve_s_curve(P, -1.0), b = solve_s_curve(P, -1.0, bis);
  ASSERT_EQ(a.summary.status, Status::ok) << a.summary.message;
  ASSERT_EQ(b.summary.status, Status::ok) << b.summary.message;
  EXPECT_NEAR(a.info.lambda, b.info.lambda, 1e-12 * a.info.lambda);
  EXPECT_LT(a.summary.iterations, b.summary.iterations);  // toms748 needs fewer evaluations than bisection
}

TEST(SCurve, MirroredAndCShapedInputs) {
  // Mirror image of an S: still S-shaped; mirrored flag set.
  const Points S_down{{{0, 0}, {1, 0}, {2, -1}, {3, -1}}};
  const auto s = solve_s_curve(S_down, -1.0);
  ASSERT_EQ(s.summary.status, Status::ok) << s.summary.message;
  EXPECT_EQ(s.info.shape, SCurveShape::s_shaped);
  EXPECT_TRUE(s.info.mirrored);
  expect_interpolates(s, S_down);
  // C-shaped (Fig. 2(a)): the curve stays inside the tangent triangle, no inflection.
  for (const Points& P :
       {Points{{{0, 0}, {1, 0}, {2, 0.5}, {2.5, 1.5}}}, Points{{{0, 0}, {1, 1}, {2.5, 1.2}, {3, 0}}}}) {
    const auto c = solve_s_curve(P, -1.0);
    ASSERT_EQ(c.summary.status, Status::ok) << c.summary.message;
    EXPECT_EQ(c.info.shape, SCurveShape::c_shaped);
    EXPECT_FALSE(c.info.inflection_s.has_value());
    expect_interpolates(c, P);
    for (double t : {0.1, 0.5, 0.9}) EXPECT_GT(at(c, t).kappa * at(c, 0.5).kappa, 0) << t;
  }
}

TEST(SCurve, BadInput) {
  const Points good{{{0, 0}, {1, 0}, {2, 1}, {3, 1}}};
  auto expect_param = [](const Points& P, double alpha, const std::string& name) {
    try {
      solve_s_curve(P, alpha);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  };
  expect_param(good, 0.0, "alpha");
  expect_param(good, 1.5, "alpha");
  expect_param(good, NAN, "alpha");
  expect_param(good, -7, "alpha");
  expect_param(Points{{{0, 0}, {0, 0}, {2, 1}, {3, 1}}}, -1, "p1");
  expect_param(Points{{{0, 0}, {1, 0}, {3, 1}, {3, 1}}}, -1, "p2");
  expect_param(Points{{{0, 0}, {1, 0}, {1, 1}, {0, 0}}}, -1, "p3");
  expect_param(Points{{{0, 0}, {1, NAN}, {2, 1}, {3, 1}}}, -1, "p1.y");
  // Straight line: a status, not a NaN curve.
  const auto line = solve_s_curve(Points{{{0, 0}, {1, 0}, {2, 0}, {3, 0}}}, -1.0);
  EXPECT_EQ(line.summary.status, Status::no_solution);
  EXPECT_EQ(line.info.shape, SCurveShape::straight);
}

// Every quadrature method of the registry (the end point of every trial Λ and of the result) ×
// every root finder of the 1-D registry: each solves (residuals ≤ accuracy = 1e-10 by tanh-sinh) and
// gives the curve of the default (gauss-legendre, toms748). kAgreeTol = accuracy: the end direction
// as a function of Λ has a slope of order 1, so Λ and the length follow the integrator's error of
// the end point (rk4, h = 1e-3: ~1e-11); the printed worst deviation is the measured margin.
constexpr double kAgreeTol = 1e-10;

TEST(SCurve, EveryIntegratorAndRootFinderGiveTheSameCurve) {
  struct Input {
    Points P;
    double alpha;
  };
  const Points S{{{0, 0}, {1, 0}, {2, 1.5}, {3, 1}}};
  const std::vector<Input> inputs{{S, -0.5},
                                  {S, -1.0},
                                  {S, -2.0},
                                  {S, -4.0},
                                  {Points{{{0, 0}, {1, 0}, {2, -1}, {3, -1}}}, -1.0},           // mirrored
                                  {Points{{{0, 0}, {1, 0}, {2, 0.5}, {2.5, 1.5}}}, -0.5},       // C-shaped
                                  {Points{{{0, 0}, {1, 1}, {2.5, 1.2}, {3, 0}}}, -2.0}};        // C-shaped, reversed
  double worst = 0;
  std::string worst_what;
  for (const Input& in : inputs) {
    const SCurveResult base = solve_s_curve(in.P, in.alpha);
    ASSERT_EQ(base.summary.status, Status::ok) << base.summary.message;
    const double chord = std::abs(in.P[3] - in.P[0]);
    for (const MethodInfo& m : quadrature_methods()) {
      for (const RootMethodInfo& root : root_methods()) {
        SCurveOptions o;
        o.integrator = make_quadrature(m.name);
        o.solver = root.method;
        const SCurveResult r = solve_s_curve(in.P, in.alpha, o);
        const std::string what =
            "alpha " + std::to_string(in.alpha) + " " + std::string(m.name) + " " + std::string(root.name);
        SCOPED_TRACE(what);
        ASSERT_EQ(r.summary.status, Status::ok) << r.summary.message;
        EXPECT_EQ(r.summary.integrator, m.name);
        EXPECT_EQ(r.summary.solver, root.name);
        EXPECT_EQ(r.info.shape, base.info.shape);
        EXPECT_EQ(r.info.mirrored, base.info.mirrored);
        EXPECT_EQ(r.info.reversed, base.info.reversed);
        expect_interpolates(r, in.P);
        const double d = std::max({std::abs(r.info.lambda - base.info.lambda) / base.info.lambda,
                                   std::abs(r.curve.length() - base.curve.length()) / chord,
                                   std::abs(at(r, 0.5).position - at(base, 0.5).position) / chord,
                                   std::abs(r.info.inflection_s.value_or(0) - base.info.inflection_s.value_or(0)) / chord});
        if (d > worst) worst = d, worst_what = what;
        EXPECT_LE(d, kAgreeTol);
      }
    }
  }
  std::printf("worst deviation from gauss-legendre + toms748: %.3e (%s)\n", worst, worst_what.c_str());
}

TEST(LinearQ, GradedGaussLegendreMatchesTanhSinh) {
  // Segments with an inflection inside, at an end, just outside, and none.
  struct Seg {
    double alpha, qa, qb;
  };
  double worst = 0;
  for (const Seg& s : {Seg{-1, 1, -2}, Seg{-0.5, 2, -1}, Seg{-2, 1, -1}, Seg{-5, 3, -0.2}, Seg{-0.9, 0, 2},
                       Seg{-3, 0.05, 4}, Seg{-2, -3, -0.1}, Seg{0.5, 1, 3}, Seg{2, 0.3, 4}, Seg{1, 0.5, 2}}) {
    for (double len : {0.25, 0.5, 2.0}) {
      const LaLaw law{s.alpha, 1.0};
      const lac::detail::LinearQ seg{0.1, 0.1 + len, s.qa, s.qb, 0.3};
      const auto b = lac::detail::integrate_tangent_reference(law, seg);
      for (int panels : {1, 2}) {
        long evals = 0;
        const auto a = lac::detail::integrate_tangent(law, seg, evals, panels);
        const double e = std::abs(a - b) / len;
        worst = std::max(worst, e);
        EXPECT_LE(e, kQuadratureTol) << "alpha " << s.alpha << " q " << s.qa << ".." << s.qb << " len " << len
                                     << " panels " << panels;
      }
    }
  }
  std::printf("worst graded Gauss-Legendre vs tanh-sinh (relative to length): %.3e\n", worst);
}

TEST(LinearQ, ReferenceToleranceIsNotTheAccuracyLimit) {
  // The residual check's tanh-sinh at its default tolerance against the same rule at 1e-15, on the
  // segments of solved G2 problems (random end data as bench_hermite; zeros of q inside, at and
  // near segment ends) and S-curves: the default tolerance must not cost accuracy above 1e-14.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-std::numbers::pi / 2, std::numbers::pi / 2), curvature(-3, 3);
  double worst = 0;
  int segments = 0;
  auto compare = [&](const LaLaw& law, const lac::detail::LinearQ& seg) {
    const auto a = lac::detail::integrate_tangent_reference(law, seg);
    const auto b = lac::detail::integrate_tangent_reference(law, seg, 1e-15);
    const double e = std::abs(a - b) / seg.length();
    worst = std::max(worst, e);
    ++segments;
    EXPECT_LE(e, 1e-14) << "alpha " << law.alpha << " q " << seg.qa << ".." << seg.qb;
  };
  for (double alpha : {-0.5, -2.0, -4.0}) {
    for (int i = 0; i < 40; ++i) {
      const double t0 = angle(rng), k0 = curvature(rng), t1 = angle(rng), k1 = curvature(rng);
      const G2Result r = solve_g2({{{0, 0}, t0, k0}, {{1, 0}, t1, k1}, alpha});
      if (r.usable())
        for (const LaSegment& seg : r.curve.segments()) compare(seg.law(), seg.normalized());
      const Points P{std::complex<double>(0, 0), std::polar(1.0 / 3, t0),
                     std::complex<double>(1, 0) - std::polar(1.0 / 3, t1), std::complex<double>(1, 0)};
      const SCurveResult c = solve_s_curve(P, alpha);
      if (c.usable()) compare(c.curve.segments().front().law(), c.curve.segments().front().normalized());
    }
  }
  EXPECT_GT(segments, 300);
  std::printf("worst tanh-sinh at tolerance %g vs 1e-15 (relative to length, %d segments): %.3e\n",
              lac::detail::kReferenceTolerance, segments, worst);
}

TEST(LinearQ, DividedDifferenceIsTheArcLimit) {
  for (double alpha : {-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 3.0}) {
    const LaLaw law{alpha, 1.0};
    const double q = 1.7;
    EXPECT_DOUBLE_EQ(law.divided_difference(q, q), law.kappa_of_q(q));
    // Near-equal arguments: continuous with the exact value (no cancellation blow-up).
    const double d = law.divided_difference(q, q * (1 + 1e-9));
    EXPECT_NEAR(d, law.kappa_of_q(q * (1 + 0.5e-9)), 1e-14 * std::abs(d)) << alpha;
  }
}

}  // namespace
}  // namespace lac
