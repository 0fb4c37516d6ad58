// Overflow class of R10 (docs/robustness.md, found by fuzz_hermite): finite inputs whose
// differences, lengths or curvatures leave the double range must give an InputError naming the
// parameter or a non-usable status, never a usable result with inf/NaN in user units.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/s_curve.hpp"
#include "lac/constructions/detail/tangent_integral.hpp"
#include "lac/integrators/registry.hpp"

namespace lac {
namespace {

using Points = std::array<std::complex<double>, 4>;
constexpr double kMax = DBL_MAX;

bool finite(std::complex<double> z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); }

void expect_finite_samples(const std::vector<PositionResult>& pts) {
  for (const auto& p : pts) {
    const CurvePoint& q = p.point;
    EXPECT_TRUE(finite(q.position)) << "s " << q.s;
    EXPECT_TRUE(std::isfinite(q.s)) << "s " << q.s;
    EXPECT_TRUE(std::isfinite(q.theta)) << "s " << q.s;
    EXPECT_TRUE(std::isfinite(q.kappa)) << "s " << q.s;
  }
}

// A residual the result reports is finite (an absent one, of a failed solve, counts as 0).
bool finite_or_absent(const std::optional<double>& v) { return std::isfinite(v.value_or(0)); }

// Every user-unit number of the result is finite; the samples too when the status is usable.
void expect_finite(const SCurveResult& r) {
  EXPECT_TRUE(std::isfinite(r.curve.length()));
  EXPECT_TRUE(std::isfinite(r.info.lambda));
  EXPECT_TRUE(finite_or_absent(r.info.inflection_s));
  EXPECT_TRUE(finite_or_absent(r.summary.residuals.position));
  EXPECT_TRUE(finite_or_absent(r.summary.residuals.angle));
  if (r.usable()) expect_finite_samples(r.curve.sample(33));
}

void expect_finite(const G2Result& r) {
  EXPECT_TRUE(std::isfinite(r.curve.length()));
  EXPECT_TRUE(finite_or_absent(r.summary.residuals.position));
  EXPECT_TRUE(finite_or_absent(r.summary.residuals.angle));
  EXPECT_TRUE(finite_or_absent(r.summary.residuals.curvature));
  if (!r.usable()) return;
  expect_finite_samples(r.curve.sample(33));
  for (const auto& c : r.info.coefficients) {
    EXPECT_TRUE(std::isfinite(c.c0) && std::isfinite(c.c1) && std::isfinite(c.c2));
  }
}

template <class F>
void expect_input_error(F&& f, const std::string& parameter, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << parameter;
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(HermiteRobustness, R10SCurveWithOverflowingLengthIsNotUsable) {
  // The fuzzer's input: finite coordinates, a curve longer than DBL_MAX (was: ok, length = inf).
  const Points P{{{2, 2}, {10, kMax}, {10, 2.2e-308}, {kMax, 2}}};
  for (RootMethod m : {RootMethod::toms748, RootMethod::bisection}) {
    SCurveOptions o;
    o.solver = m;
    const SCurveResult r = solve_s_curve(P, -2.561767578125, o);
    EXPECT_FALSE(r.usable()) << to_string(r.summary.status);
    EXPECT_NE(r.summary.message.find("double range"), std::string::npos) << r.summary.message;
    expect_finite(r);
  }
}

TEST(HermiteRobustness, SCurveWithOverflowingDifferencesThrowsNamingPoints) {
  expect_input_error(
      [] {
        solve_s_curve(Points{{{-kMax, 0}, {0, 1}, {1, 1}, {kMax, 0}}}, -1.0);
      },
      "points", "double range");
  expect_input_error(
      [] {
        solve_s_curve(Points{{{0, 0}, {kMax, -kMax}, {1, 1}, {2, 0}}}, -2.0);
      },
      "points", "double range");
}

TEST(HermiteRobustness, SCurveIsSimilarityInvariantAtExtremeScales) {
  // The same polygon at scale 1, 1e-300 and 1e300 (and shifted): same Λ, length scaled.
  const Points base{{{0, 0}, {1, 0}, {2, 1}, {3, 1}}};
  const SCurveResult ref = solve_s_curve(base, -1.5);
  ASSERT_EQ(ref.summary.status, Status::ok) << ref.summary.message;
  for (double scale : {1e-300, 1e300, 0.2 * kMax}) {
    for (std::complex<double> shift : {std::complex<double>(0, 0), std::complex<double>(1.5, -2) * scale}) {
      Points P;
      for (size_t k = 0; k < 4; ++k) P[k] = base[k] * scale + shift;
      const SCurveResult r = solve_s_curve(P, -1.5);
      ASSERT_EQ(r.summary.status, Status::ok) << "scale " << scale << ": " << r.summary.message;
      EXPECT_NEAR(r.info.lambda, ref.info.lambda, 1e-12 * ref.info.lambda);
      EXPECT_NEAR(r.curve.length() / scale, ref.curve.length(), 1e-12 * ref.curve.length());
      EXPECT_LE(*r.summary.residuals.position / (3 * scale), 1e-10);
      expect_finite(r);
    }
  }
}

TEST(HermiteRobustness, G2WithOverflowingChordThrowsNamingP1) {
  const G2Problem p{{{-kMax, 0}, 0.3, 1}, {{kMax, 0}, -0.3, 1}, -0.5};
  expect_input_error([&] { solve_g2(p); }, "p1", "double range");
}

TEST(HermiteRobustness, G2WithCurvatureTimesChordOverflowingThrowsNamingKappa) {
  expect_input_error([] { solve_g2({{{0, 0}, 0.3, 1e300}, {{1e10, 0}, -0.3, -1}, -0.5}); }, "kappa0", "must be finite");
  expect_input_error(
      [] {
        solve_g2({{{0, 0}, 0.3, 1}, {{0, -1e10}, -0.3, -1e300}, -0.5});
      },
      "kappa1", "must be finite");
  // κ·|p1 − p0| = 1e300 is representable: no curve is found, and nothing non-finite escapes.
  for (G2Solver solver : {G2Solver::newton, G2Solver::paper, G2Solver::ceres, G2Solver::simplex}) {
    G2Options o;
    o.solver = solver;
    o.grid_fallback = false;
    const G2Result r = solve_g2({{{0, 0}, 0.3, 1e300}, {{1, 0}, -0.3, 1e300}, -0.5}, o);
    SCOPED_TRACE(std::string(to_string(solver)));
    expect_finite(r);
  }
}

TEST(HermiteRobustness, G2ReachingBeyondTheDoubleRangeIsNotUsable) {
  // Was: tolerance_not_met (usable) with length = inf and inf / NaN points.
  for (const G2Problem& p : {G2Problem{{{-kMax, 0}, 0.6, 0.5 / kMax}, {{0, 0}, -0.6, -0.3 / kMax}, -0.5},
                             G2Problem{{{0, 0}, 1.5, 0}, {{0.9 * kMax, 0}, -1.5, 0}, -0.5}}) {
    // Winding 0: that turning's own status; the search over windings ends not_converged (incomplete),
    // naming the numerical failure.
    G2Options w0;
    w0.winding = 0;
    const G2Result r = solve_g2(p, w0);
    EXPECT_EQ(r.summary.status, Status::numerical_failure) << r.summary.message;
    EXPECT_NE(r.summary.message.find("double range"), std::string::npos) << r.summary.message;
    expect_finite(r);
    const G2Result searched = solve_g2(p);
    EXPECT_FALSE(searched.usable()) << searched.summary.message;
    EXPECT_NE(searched.summary.status, Status::no_solution) << searched.summary.message;
    EXPECT_NE(searched.summary.message.find("double range"), std::string::npos) << searched.summary.message;
    expect_finite(searched);
    expect_finite(r);
  }
  // The same shape at a representable scale solves, with finite results.
  const G2Result ok = solve_g2({{{0, 0}, 0.6, 0.5e-300}, {{1e300, 0}, -0.6, -0.3e-300}, -0.5});
  EXPECT_EQ(ok.summary.status, Status::ok) << ok.summary.message;
  EXPECT_LE(ok.summary.residuals.position.value_or(HUGE_VAL) / 1e300, 1e-10);
  expect_finite(ok);
}

// Found by the short fuzz run: at α = −1.4e-304 the S-curve solved but its residual check was NaN;
// an unverifiable curve is not usable, and a usable one has finite residuals.
TEST(HermiteRobustness, SCurveWithNonFiniteResidualIsNotUsable) {
  const Points P = {std::complex<double>{2, -3.009033203125}, {-3.04345703125, -21809843929088},
                    {-4.982177734375, 1}, {-0.733154296875, -3641704448}};
  SCurveResult r;
  try {
    r = solve_s_curve(P, -1.381513782954776e-304);
  } catch (const InputError& e) {
    SUCCEED() << "rejected: " << e.what();
    return;
  }
  if (r.usable()) {
    const Residuals& e = r.summary.residuals;
    EXPECT_TRUE(e.position && std::isfinite(*e.position)) << e.position.value_or(NAN);
    EXPECT_TRUE(e.angle && std::isfinite(*e.angle)) << e.angle.value_or(NAN);
  } else {
    EXPECT_FALSE(r.summary.message.empty());
  }
}

// A piece turning more than the 64 Gauss–Legendre panels resolve gives NaN (found by
// fuzz_hermite: a G2 problem with |κ·chord| ~ 1e66 spent ~1 s per Ceres solve on cos/sin of
// huge angles, past the fuzzer's per-call bound). Up to the bound the value is accurate: a
// circle (α = −1, q = κ̃ = const) turning Φ rad has ∫e^{iφ} = (e^{iΦ} − 1)/(iΦ).
TEST(HermiteRobustness, TurningBeyondWhatThePanelsResolveIsNaN) {
  const LaLaw clothoid{-1.0, 1.0};
  for (const double turn : {1.0, 100.0, lac::detail::kMaxResolvedTurning}) {
    long evaluations = 0;
    const auto got = lac::detail::integrate_tangent(clothoid, {0.0, 1.0, turn, turn, 0.0}, evaluations);
    const auto exact = (std::polar(1.0, turn) - 1.0) / std::complex<double>(0.0, turn);
    EXPECT_LE(std::abs(got - exact), 1e-12) << "turning " << turn;
  }
  for (const double turn : {1.01 * lac::detail::kMaxResolvedTurning, 1e66, HUGE_VAL}) {
    long evaluations = 0;
    const auto got = lac::detail::integrate_tangent(clothoid, {0.0, 1.0, turn, turn, 0.0}, evaluations);
    EXPECT_TRUE(std::isnan(got.real()) && std::isnan(got.imag())) << "turning " << turn << ": " << got;
    EXPECT_EQ(evaluations, 0);
  }
}

TEST(HermiteRobustness, G2WithUnresolvableTurningFailsWithoutIntegratingIt) {
  // The fuzz input: p0 far away (chord 1.4e75), so the normalized curvatures are ~2e66.
  const double e = -1.5996874935808592e-09;
  const G2Problem p{{{1.3853946644635051e+75, e}, e, e}, {{e, -1.8325181372347288e-09}, e, e}, -2.9775947041343898e-08};
  for (const G2Solver solver : {G2Solver::newton, G2Solver::paper, G2Solver::ceres, G2Solver::simplex}) {
    G2Options o;
    o.solver = solver;
    o.grid_fallback = false;  // the Bézier-grid start alone scores 10^4 quintics (2e5 evaluations)
    const G2Result r = solve_g2(p, o);
    SCOPED_TRACE(std::string(to_string(solver)));
    EXPECT_FALSE(r.usable()) << r.summary.message;
    EXPECT_FALSE(r.summary.message.empty());
    EXPECT_LT(r.summary.evaluations, 10'000) << r.summary.message;  // was ~5e6 integrand evaluations for ceres
    expect_finite(r);
  }
}

// The same class for the other integrators (found by fuzz_hermite once it chose integrators): with
// |κ·chord| ~ 1e8 the simplex with gk-tanh-sinh spent 2.7 s integrating trial segments turning
// ~1e8 rad. Every method now has the fast path's domain (pieces turning ≤ 1024 rad), so such trial
// curves fail at once whatever the method.
TEST(HermiteRobustness, G2WithUnresolvableTurningFailsFastWithEveryIntegrator) {
  const G2Problem p{{{2.046630859375, 3.141592653589793}, -10, -5.476806640625},
                    {{-1, -5}, -9.09130903892219e-09, -16490496},
                    -1.226318359375};
  for (const MethodInfo& m : quadrature_methods()) {
    for (const auto& s : g2_solvers()) {
      G2Options o;
      o.solver = s.method;
      o.integrator = make_quadrature(m.name);
      o.grid_fallback = false;
      const G2Result r = solve_g2(p, o);
      SCOPED_TRACE(std::string(m.name) + " " + std::string(s.name));
      EXPECT_FALSE(r.usable()) << r.summary.message;
      EXPECT_FALSE(r.summary.message.empty());
      EXPECT_LT(r.summary.evaluations, 10'000) << r.summary.message;
      expect_finite(r);
    }
  }
}

// Found by fuzz_hermite once it chose integrators: at α = −1e-8 every gauss-kronrod trial integral
// exhausts its 20000 intervals (~8e5 evaluations), and newton spent 5 s, the simplex minutes. The
// call's budget max_evaluations now stops the trials: status max_iterations naming it.
TEST(HermiteRobustness, G2AndSCurveStopAtTheEvaluationBudget) {
  const G2Problem p{{{1, 1}, 5e-324, -1}, {{3.141592653589793, 1}, 7.999755859375, 7.999755859375}, -1e-08};
  for (const G2Solver solver : {G2Solver::newton, G2Solver::simplex}) {
    G2Options o;
    o.solver = solver;
    o.integrator = GaussKronrod{};
    o.max_evaluations = 1'000'000;
    const G2Result r = solve_g2(p, o);
    SCOPED_TRACE(std::string(to_string(solver)));
    // Since the offset form (small |α| in log|κ|) the trials no longer exhaust gauss-kronrod here
    // and a solver may stop on its own first; when the budget stops it, the message names it.
    if (r.summary.status == Status::max_iterations) {
      EXPECT_NE(r.summary.message.find("max_evaluations"), std::string::npos) << r.summary.message;
    }
    EXPECT_LT(r.summary.evaluations, 4'000'000);  // the budget plus one trial curve's three integrals
    expect_finite(r);
  }
  SCurveOptions o;
  o.max_evaluations = 100;  // the bracket's ends alone take more
  const SCurveResult s = solve_s_curve(Points{{{0, 0}, {1, 0}, {2, 1}, {3, 1}}}, -0.5, o);
  EXPECT_EQ(s.summary.status, Status::max_iterations) << s.summary.message;
  EXPECT_NE(s.summary.message.find("max_evaluations"), std::string::npos) << s.summary.message;
  expect_finite(s);
  o.max_evaluations = 0;
  expect_input_error([&] { solve_s_curve(Points{{{0, 0}, {1, 0}, {2, 1}, {3, 1}}}, -0.5, o); }, "max_evaluations", "[1");
  G2Options g;
  g.max_evaluations = 0;
  expect_input_error([&] { solve_g2(p, g); }, "max_evaluations", "[1");
}

// Found by the 10^6-execution campaign of fuzz_hermite (R16): κ0 = 5e-324 puts the zero of q
// within rounding of the segment's start; the residual check split off a piece of subnormal
// width, on which Boost tanh-sinh threw (float_next of NaN) out of solve_g2.
TEST(HermiteRobustness, G2WithSubnormalEndCurvatureIsVerified) {
  const G2Problem p{{{2.046630859375, 3.141592653589793}, -1.51708984375, 5e-324},
                    {{-10, -1}, -5, -0.990478515625}, -1};
  for (const G2Solver solver : {G2Solver::newton, G2Solver::paper, G2Solver::ceres, G2Solver::simplex}) {
    G2Options o;
    o.solver = solver;
    SCOPED_TRACE(std::string(to_string(solver)));
    G2Result r;
    EXPECT_NO_THROW(r = solve_g2(p, o));
    expect_finite(r);
    if (solver == G2Solver::paper) {
      EXPECT_EQ(r.summary.status, Status::ok) << r.summary.message;
      EXPECT_LE(r.summary.residuals.position.value_or(HUGE_VAL), 1e-10 * std::abs(p.end.position - p.start.position));
    }
  }
}

// Found while testing every integrator: igf, which integrates each side of a zero of q by its
// standard form, threw on a zero of q within rounding of a segment's end (an empty part) and on a
// subnormal |q| at an anchor (no standard form: ρ overflows), so the G2 problem above failed with
// igf only. Both now go to the graded Gauss–Legendre rule, as the part next to every zero does.
TEST(HermiteRobustness, IgfTrialIntegralsNearAZeroOfQAtAnEnd) {
  const LaLaw clothoid{-1.0, 1.0};
  for (double qa : {5.92879e-323, 1e-300, 1e-200, 1e-100}) {
    for (double qb : {-2.0, 2.0, 1e-300, -1e-300}) {
      const lac::detail::LinearQ seg{0.0, 0.25, qa, qb, 0.1};
      IntegralResult<std::complex<double>> r;
      ASSERT_NO_THROW(r = lac::detail::integrate_tangent_igf(clothoid, seg, Igf{})) << qa << " " << qb;
      long evaluations = 0;
      const auto gl = lac::detail::integrate_tangent(clothoid, seg, evaluations);
      EXPECT_TRUE(usable(r.status)) << r.message;
      EXPECT_LE(std::abs(r.value - gl), 1e-14) << "qa " << qa << " qb " << qb;
    }
  }
  const G2Problem p{{{2.046630859375, 3.141592653589793}, -1.51708984375, 5e-324},
                    {{-10, -1}, -5, -0.990478515625}, -1};
  for (const auto& s : g2_solvers()) {
    G2Options o;
    o.solver = s.method;
    o.integrator = Igf{};
    const G2Result r = solve_g2(p, o);
    EXPECT_EQ(r.summary.status, Status::ok) << s.name << ": " << r.summary.message;
    expect_finite(r);
  }
}

// Found by the campaign (R17b, R18): at α = −5e-324 the law's exponents 1/α, 4(α−1)/α overflow;
// the paper's solver returned tolerance_not_met (usable) with residual_position = NaN (R17b) or,
// unverified, NaN polyline points (R18). Such α are now rejected.
TEST(HermiteRobustness, G2WithSubnormalAlphaThrowsNamingAlpha) {
  const G2Problem p{{{-4.989990234375, -5e-324}, -5e-324, 7.18351701907427e-17},
                    {{7.18351701907427e-17, -5e-324}, -5e-324, -4.98828125}, -5e-324};
  expect_input_error([&] { solve_g2(p); }, "alpha", "1e-300");
  const G2Problem r17b{{{-6.9765625, 1}, 5e-324, 3.141592653589793}, {{-1, 1}, 5e-324, 7.984375}, -5e-324};
  expect_input_error([&] { solve_g2(r17b); }, "alpha", "1e-300");
  G2Problem q = p;
  q.alpha = -1e-300;  // the smallest accepted: no NaN in a usable result
  G2Options o;
  o.solver = G2Solver::paper;
  o.verify = false;
  const G2Result r = solve_g2(q, o);
  expect_finite(r);
}

}  // namespace
}  // namespace lac
