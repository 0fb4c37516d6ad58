// Regression tests for fixed fuzzing findings of docs/robustness.md (R1, R2, R4, R5, R7, R8, R11, R13, R14, R23).
// Inputs are the ones the fuzzers saved (fuzz/findings/fuzz_<target>/), reduced to the call
// that went wrong; each test checks the correct behaviour.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "lac/common/error.hpp"
#include "lac/constructions/chain.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/space_segment.hpp"
#include "lac/constructions/triangle_g1.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/space/frenet.hpp"
#include "lac/curves/space/la_space_curve.hpp"
#include "lac/special/incomplete_gamma.hpp"
#include "tests/support/run_cli.hpp"

namespace {

/// Either a finite value or an InputError naming `parameter`; never NaN.
template <class Call>
void expect_finite_or_input_error(Call call, const std::string& parameter, const std::string& what) {
  try {
    const double v = call();
    EXPECT_TRUE(std::isfinite(v)) << what << " returned " << v << " instead of an InputError naming " << parameter;
  } catch (const lac::InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << what << ": " << e.what();
  }
}

// Finding R1 (fuzz_la_curve): closed-form conversions return NaN instead of rejecting the argument.
TEST(FuzzRegression, LaCurveConversionsNeverReturnNan) {
  const lac::LaCurve big(1e300, 1e300);
  expect_finite_or_input_error([&] { return big.s_at_theta(1e-300); }, "theta",
                               "LaCurve(1e300, 1e300).s_at_theta(1e-300)");
  const lac::LaCurve steep(-DBL_MAX, 5);
  expect_finite_or_input_error([&] { return steep.s_at_theta(-6.9388939039072284e-18); }, "theta",
                               "LaCurve(-DBL_MAX, 5).s_at_theta(-6.9e-18)");
  const lac::LaCurve clothoid_like(0, 7.945556640625);
  expect_finite_or_input_error([&] { return clothoid_like.theta_at_s(DBL_MAX); }, "s",
                               "LaCurve(0, 7.95).theta_at_s(DBL_MAX)");
  const lac::LaCurve spiral(1, DBL_MAX);
  expect_finite_or_input_error([&] { return spiral.rho_at_theta(2); }, "theta", "LaCurve(1, DBL_MAX).rho_at_theta(2)");
}

// Finding R2 (fuzz_la_curve): Gauss–Kronrod returns a usable status with an infinite error estimate.
TEST(FuzzRegression, UsablePositionHasFiniteErrorEstimate) {
  const lac::GaussKronrod gk;
  for (auto [alpha, lambda, p, t] : {std::tuple{1e-300, 0.0, lac::Parameter::theta, 1e300},
                                     std::tuple{0.0, 4.9406564584124654e-324, lac::Parameter::s, DBL_MAX}}) {
    const lac::LaCurve c(alpha, lambda);
    try {
      const lac::PositionResult r = lac::position_at(c, p, t, gk);
      if (lac::usable(r.status)) {
        EXPECT_TRUE(std::isfinite(r.error_estimate)) << "alpha " << alpha << " lambda " << lambda << " t " << t;
        EXPECT_TRUE(std::isfinite(std::abs(r.point.position)));
      }
    } catch (const lac::InputError& e) {
      EXPECT_FALSE(e.parameter().empty());
    }
  }
}

// Finding R7 (fuzz_special): Boost's overflow_error escapes Γ(a, 0) for tiny a > 0.
TEST(FuzzRegression, GammaIncOverflowIsAStatus) {
  for (double a : {5e-324, 1e-310}) {
    lac::special::GammaIncResult r;
    EXPECT_NO_THROW(r = lac::special::gamma_inc(a, {-0.0, -0.0})) << "a = " << a;
    if (r.status == lac::Status::ok) {
      EXPECT_TRUE(std::isfinite(std::abs(r.value)));
    }
    EXPECT_NO_THROW(lac::special::gamma_inc_difference(a, {-0.0, -0.0}, {-5.562744140625, -8})) << "a = " << a;
  }
}

// Finding R13 (fuzz_special): gamma_inc_difference(a > 0, 0, 0) recursed forever (stack overflow).
TEST(FuzzRegression, GammaIncDifferenceOfZeroToZeroIsZero) {
  for (std::complex<double> zero : {std::complex<double>(0, 0), std::complex<double>(-0.0, -0.0)}) {
    const lac::special::GammaIncResult r = lac::special::gamma_inc_difference(0.5, zero, zero);
    EXPECT_EQ(r.status, lac::Status::ok);
    EXPECT_EQ(std::abs(r.value), 0.0);
  }
}

// Finding R4 (fuzz_cli): a point count beyond memory is an internal error (exit 1, std::bad_alloc)
// instead of invalid input naming the option (exit 2).
TEST(FuzzRegression, CliRejectsHugePointCounts) {
  for (const std::string args : {"eval --alpha 0.5 --lambda 1 --theta -0.5 --samples 2147483647",
                                 "g1 --points '0,0 1,0 2,1' --alpha 1 --samples 2147483647"}) {
    const lac::test::CliRun r = lac::test::run_lac(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find("samples = 2147483647"), std::string::npos) << r.out;
  }
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

void expect_finite_samples(const lac::TriangleResult& g, const std::string& what) {
  for (const lac::PositionResult& r : g.curve.sample(50, lac::GkTanhSinh{})) {
    const lac::CurvePoint& q = r.point;
    EXPECT_EQ(r.status, lac::Status::ok) << what << ": sample at s = " << q.s << ": " << r.message;
    ASSERT_TRUE(std::isfinite(q.position.real()) && std::isfinite(q.position.imag()) && std::isfinite(q.s) &&
                std::isfinite(q.theta) && std::isfinite(q.kappa))
        << what << ": sample at s = " << q.s;
  }
}

// Finding R5 (by hand, lac g1): a valid tiny triangle was called collinear because the turning
// angle underflowed (cross product of legs of length 1e-300). The construction is similarity-
// invariant: the scaled triangles must give the unit triangle's segment, scaled.
TEST(FuzzRegression, TinyAndHugeTrianglesSolveLikeTheUnitTriangle) {
  const lac::ControlTriangle unit{{0, 0}, {1, 0}, {2, 1}};
  const lac::TriangleResult ref = lac::solve_g1(unit, 1.0);
  const lac::TriangleResult ref_c = lac::solve_compound(unit, 0.5, 1.5, 0.4);
  ASSERT_EQ(ref.summary.status, lac::Status::ok) << ref.summary.message;
  ASSERT_EQ(ref_c.summary.status, lac::Status::ok) << ref_c.summary.message;
  for (double k : {1e-300, 1e-200, 1e300}) {
    const lac::ControlTriangle t{unit.a0 * k, unit.a1 * k, unit.a2 * k};
    const std::string what = "unit triangle times " + lac::format_number(k);
    const lac::TriangleResult g = lac::solve_g1(t, 1.0);
    ASSERT_EQ(g.summary.status, lac::Status::ok) << what << ": " << g.summary.message;
    EXPECT_NEAR(g.info.turning, std::atan(1.0), 1e-15) << what;
    EXPECT_LE(rel(g.curve.length() / k, ref.curve.length()), 1e-13) << what;
    EXPECT_LE(rel(g.curve.kappa_at(0) * k, ref.curve.kappa_at(0)), 1e-13) << what;
    EXPECT_LE(rel(g.info.pieces[0].lambda_user, ref.info.pieces[0].lambda_user), 1e-13) << what;  // α = 1: scale-free
    expect_finite_samples(g, what);
    const lac::TriangleResult c = lac::solve_compound(t, 0.5, 1.5, 0.4);
    ASSERT_EQ(c.summary.status, lac::Status::ok) << what << ": " << c.summary.message;
    EXPECT_LE(rel(c.curve.length() / k, ref_c.curve.length()), 1e-13) << what;
    EXPECT_LE(rel(c.info.rho_joint / k, ref_c.info.rho_joint), 1e-13) << what;
    EXPECT_LE(rel(c.info.pieces[0].lambda_user, ref_c.info.pieces[0].lambda_user * std::pow(k, -0.5)), 1e-13) << what;
    expect_finite_samples(c, what);
  }
  const lac::test::CliRun r = lac::test::run_lac("g1 --points '0,0 1e-300,0 2e-300,1e-300' --alpha 1");
  EXPECT_EQ(r.status, 0) << r.out;
}

// Finding R8 (fuzz_planar_segments): a triangle with finite coordinates but side lengths beyond
// the double range gave a usable segment of infinite length.
TEST(FuzzRegression, OverflowingTriangleIsRejected) {
  const lac::ControlTriangle saved{{-DBL_MAX, 7.812255859375}, {3.392578125, 1e300}, {-3.437744140625, 7.999755859375}};
  const lac::ControlTriangle overflowing{{-DBL_MAX, 0}, {DBL_MAX, 0}, {DBL_MAX, 1}};  // a1 − a0 = inf
  const lac::ControlTriangle subnormal{{0, 0}, {1e-310, 0}, {2e-310, 1e-310}};
  for (const lac::ControlTriangle& t : {saved, overflowing, subnormal}) {
    for (const lac::RootMethodInfo& method : lac::root_methods()) {
      const std::string_view name = method.name;
      lac::TriangleOptions o;
      o.solver = lac::parse_root_method(name);
      for (bool compound : {false, true}) {
        try {
          const lac::TriangleResult g = compound ? lac::solve_compound(t, 0.0, 1.0, 0.5, o) : lac::solve_g1(t, 0.0, o);
          ADD_FAILURE() << name << ": status " << lac::to_string(g.summary.status) << ", length " << g.curve.length()
                        << " instead of an InputError naming points";
        } catch (const lac::InputError& e) {
          EXPECT_EQ(e.parameter(), "points") << e.what();
          EXPECT_NE(std::string(e.what()).find("double range"), std::string::npos) << e.what();
        }
      }
    }
  }
}

// R8's second half: the standard-form solution is finite but its user-unit image is not
// (Λ_user = Λ k^(α−1) with k = 1e-300, α = −1): a failed status that says so, never inf.
TEST(FuzzRegression, UnrepresentableUserUnitsAreAStatus) {
  const double k = 1e-300;
  const lac::TriangleResult g = lac::solve_g1({{0, 0}, {k, 0}, {2 * k, k}}, -1.0);
  EXPECT_EQ(g.summary.status, lac::Status::numerical_failure) << g.summary.message;
  EXPECT_NE(g.summary.message.find("lambda_user"), std::string::npos) << g.summary.message;
  EXPECT_THROW(g.curve.sample(10), lac::InputError);
  const lac::TriangleResult ok = lac::solve_g1({{0, 0}, {1, 0}, {2, 1}}, -1.0);  // same shape, unit scale
  EXPECT_EQ(ok.summary.status, lac::Status::ok) << ok.summary.message;
}

// Finding R11 (fuzz_space): space-curve laws that overflow gave an empty or NaN s range, NaN
// angles inside the s range, and a usable Frenet integration with a NaN position.
TEST(FuzzRegression, SpaceCurveLawsAreRepresentableOrRejected) {
  using lac::LaSpaceCurve;
  using lac::TorsionType;
  const auto expect_rejected = [](auto make, const std::string& parameter, const std::string& what) {
    try {
      const LaSpaceCurve c = make();
      ADD_FAILURE() << what << ": accepted, s range (" << c.s_range().lo << ", " << c.s_range().hi << ")";
    } catch (const lac::InputError& e) {
      EXPECT_EQ(e.parameter(), parameter) << what << ": " << e.what();
    }
  };
  // The saved input: α·Λ = −inf, and ν^(−β) = inf.
  expect_rejected([] { return LaSpaceCurve(-5.58, DBL_MAX, DBL_MAX, 5e-324, 5e-324, TorsionType::type1); }, "lambda",
                  "LaSpaceCurve(-5.58, DBL_MAX, DBL_MAX, 5e-324, 5e-324, 1)");
  expect_rejected([] { return LaSpaceCurve(1, DBL_MAX, 1, 5e-324, 5e-324, TorsionType::type1); }, "nu",
                  "LaSpaceCurve(1, DBL_MAX, 1, 5e-324, 5e-324, 1)");
  expect_rejected([] { return LaSpaceCurve(7.44, 8.0, 0, 1e300, 5e-324, TorsionType::type2); }, "nu",
                  "LaSpaceCurve(7.44, 8, 0, 1e300, 5e-324, 2)");  // its torsion_turning(-8) was NaN
  expect_rejected([] { return LaSpaceCurve(1, 2, 1, DBL_MAX, 1, TorsionType::type1); }, "omega",
                  "LaSpaceCurve(1, 2, 1, DBL_MAX, 1, 1)");  // β·Ω = inf

  // Accepted laws whose closed-form angle overflows inside the s range: InputError naming s.
  const LaSpaceCurve steep(-5e-324, -5e-324, DBL_MAX, 2.89, 1, TorsionType::type1);
  ASSERT_TRUE(steep.contains(-2.69));
  expect_finite_or_input_error([&] { return steep.turning(-2.69); }, "s", "LaSpaceCurve(-5e-324, ...).turning(-2.69)");
  for (double s : {-2.69, 0.5, 3.0})
    expect_finite_or_input_error([&] { return steep.torsion_turning(s); }, "s", "torsion_turning");

  const LaSpaceCurve plain(1, 1, 1, 1, 1, TorsionType::type1);
  expect_finite_or_input_error([&] { return plain.s_at_log_rho(std::nan("")); }, "log_rho", "s_at_log_rho(NaN)");
  EXPECT_THROW(plain.s_at_log_rho(std::nan("")), lac::InputError);
  EXPECT_THROW(plain.s_at_turning(std::nan("")), lac::InputError);
  EXPECT_THROW(plain.s_at_torsion_turning(std::nan("")), lac::InputError);
  EXPECT_EQ(plain.s_at_log_rho(std::log(2.0)), 1.0);  // ρ = 1 + s
}

TEST(FuzzRegression, FrenetIntegrationNeverReturnsAUsableNan) {
  for (lac::TorsionType type : {lac::TorsionType::type1, lac::TorsionType::type2}) {
    // ρ overflows (κ = 0) and τ = 1/ν = inf on [1, 7]: the fixed-step rk4 state became NaN.
    const lac::LaSpaceCurve c(-5e-324, -2.30, DBL_MAX, 1, 5e-324, type);
    for (lac::OdeMethod m : {lac::OdeMethod::rk4, lac::OdeMethod::rk45, lac::OdeMethod::magnus6}) {
      lac::OdeOptions o;
      o.method = m;
      const lac::FrenetResult r = lac::integrate_frenet(c, lac::Frame3{}, 1, 7, o);
      if (lac::usable(r.status)) {
        EXPECT_TRUE(r.frame.p.allFinite() && r.frame.t.allFinite() && r.frame.n.allFinite() && r.frame.b.allFinite())
            << lac::to_string(m) << ": usable status with position " << r.frame.p.transpose();
      } else {
        EXPECT_EQ(r.status, lac::Status::numerical_failure) << lac::to_string(m) << ": " << r.message;
      }
    }
    if (type == lac::TorsionType::type1) {  // the saved input: rk4 must now fail instead of returning NaN
      lac::OdeOptions o;
      o.method = lac::OdeMethod::rk4;
      EXPECT_EQ(lac::integrate_frenet(c, lac::Frame3{}, 1, 7, o).status, lac::Status::numerical_failure);
    }
  }
  lac::Frame3 bad;
  bad.p.x() = std::nan("");
  EXPECT_THROW(lac::integrate_frenet(lac::LaSpaceCurve(1, 1, 1, 1, 1, lac::TorsionType::type1), bad, 0, 1),
               lac::InputError);
}

// Finding R14 (fuzz_space, short run): a space solver with rk4 ran 1.5e8 Frenet evaluations
// (13 s CPU unsanitized) on awkward input: every trial hit the step cap. The call now stops at
// max_ode_evaluations (default 1e7) with status max_iterations.
TEST(FuzzRegression, SpaceSolverStopsAtItsEvaluationBudget) {
  const double a = -1.403854810178018e-11, b = 7.999755859375;
  const lac::SpaceEndpoints ends{{a, a, a}, {31740, b, b}, {b, b, b}, {b, b, b}};
  const lac::G1SpaceSpec spec{1.000000000000001, 1e300, 0.0, lac::TorsionType::type2};
  lac::SpaceSegmentOptions o;
  o.solver = lac::NonlinearMethod::newton;
  o.integrator.method = lac::OdeMethod::rk4;
  const auto r = lac::solve_g1_space_segment(ends, spec, o);
  EXPECT_EQ(r.summary.status, lac::Status::max_iterations) << r.summary.message;
  EXPECT_NE(r.summary.message.find("max_ode_evaluations"), std::string::npos) << r.summary.message;
  // At most one construction (two pieces of ≤ 20000 rk4 steps, 4 evaluations each, plus the
  // event location) beyond the budget.
  EXPECT_LE(r.summary.evaluations, o.max_ode_evaluations + 200'000);
  o.max_ode_evaluations = 0;
  EXPECT_THROW(lac::solve_g1_space_segment(ends, spec, o), lac::InputError);
}

}  // namespace

// Finding R23 (fuzz_g1_hermite campaign): once tiny chords were accepted (R5's similarity
// invariance), a chord near DBL_MIN with extra windings gave a usable segment with infinite end
// curvature, and coordinates near DBL_MAX a usable one with an infinite position residual. A
// solution that leaves the double range when scaled to the chord is numerical_failure; a chord of
// 1e-300 still solves like the unit chord.
TEST(FuzzRegression, G1HermiteBeyondTheDoubleRangeIsNumericalFailure) {
  const std::complex<double> tiny0{DBL_MIN, -5e-324}, tiny1{-5e-324, DBL_MIN};
  const std::complex<double> huge0{DBL_MAX, 1e300}, huge1{DBL_MAX, -8};
  struct Case {
    lac::G1HermiteProblem problem;
    int winding;
    std::string_view solver;
  };
  const Case cases[] = {
      {{tiny0, 4.4873046875, tiny1, 1, -0.72265625}, -3, "bisection"},
      {{tiny0, 4.4873046875, tiny1, 1, -0.749755859375}, -3, "auto"},
      {{tiny0, 4.4873046875, tiny1, 1.2783203125, 1}, -3, "secant"},
      {{{-5e-324, -5e-324}, 4.7861328125, {DBL_MIN, -5e-324}, -6.9912109375, 1}, -2, "toms748"},
      {{huge0, 26.64, huge1, 4.404296875, 1}, -1, "secant"},
      {{huge0, 26.64, {DBL_MAX, -1}, -26.64, 0.5}, 2, "ceres"},
  };
  for (const Case& c : cases)
    for (bool verify : {false, true}) {
      lac::G1HermiteOptions o;
      o.winding = c.winding;
      o.solver = lac::parse_g1_solver(c.solver);
      o.verify = verify;  // re-integrates the end point from p0: overflows near DBL_MAX
      const lac::G1HermiteResult r = lac::solve_g1_hermite(c.problem, o);
      const std::string what = std::string(c.solver) + " winding " + std::to_string(c.winding) + " verify " +
                               std::to_string(verify) + ": " + std::string(lac::to_string(r.summary.status)) + " " +
                               r.summary.message;
      if (r.usable()) {
        EXPECT_TRUE(std::isfinite(r.curve.length())) << what;
        EXPECT_TRUE(std::isfinite(r.curve.kappa_at(0)) && std::isfinite(r.curve.kappa_at(r.curve.length()))) << what;
        EXPECT_TRUE(std::isfinite(r.summary.residuals.position.value_or(0.0))) << what;
      } else {
        EXPECT_NE(r.summary.status, lac::Status::no_solution) << what;  // nothing is proven here
      }
    }
  // The unit problem scaled by 1e-300 still solves, with curvature scaled by 1e300.
  const lac::G1HermiteResult unit = lac::solve_g1_hermite({{0, 0}, 0.3, {1, 0}, -0.4, -2.0});
  const lac::G1HermiteResult small = lac::solve_g1_hermite({{0, 0}, 0.3, {1e-300, 0}, -0.4, -2.0});
  ASSERT_TRUE(unit.usable() && small.usable()) << small.summary.message;
  EXPECT_NEAR(small.curve.kappa_at(0) * 1e-300 / unit.curve.kappa_at(0), 1.0, 1e-12);
}

// A G1 chain at α = −1.07e-12 through points up to 3e214 apart asked the log-variable kernel for
// 3.9e9 panels of one piece (an int overflow, undefined behaviour): a piece needing more than the
// kernel's panel cap is now "not evaluated", like a piece too steep for its series.
TEST(FuzzRegression, G1PieceBeyondThePanelCapIsNotEvaluated) {
  lac::ChainProblem p;
  p.points = {{-1.9091796875, -0.86083984375},       {-0.08541107177734375, -0.663818359375},
              {-1.03466796875, -19610889393012736.0}, {1.236083984375, -4.80126953125},
              {-1.0700329511337259e-12, -1.0700329511337259e-12}, {-169553489096081408.0, 2.8791116233294963e+214}};
  p.alpha = -1.0700329511337259e-12;
  p.continuity = lac::ChainContinuity::g1;
  const lac::ChainResult r = lac::solve_chain(p);
  const std::string what = std::string(lac::to_string(r.summary.status)) + " " + r.summary.message;
  if (r.usable()) {
    ASSERT_EQ(r.curve.segments().size(), 5u) << what;
    EXPECT_TRUE(std::isfinite(r.curve.length())) << what;
  } else {
    EXPECT_FALSE(r.summary.message.empty()) << what;
  }
}

// R27: a closed G2 chain at α = −3.05e-5 through points from 5e-324 to 8 apart asked the
// small-α kernel for 8.5e9 panels of one piece (the panel count of the near-zero, near-arc and
// α > 1 limit paths overflowed int): such a piece is now "not evaluated" too.
TEST(FuzzRegression, G2ChainPieceBeyondThePanelCapIsNotEvaluated) {
  lac::ChainProblem p;
  p.points = {{7.999755859375, 7.999755859375},        {7.984130859375, 2.058271199775e-312},
              {-1.9091796875, -0.86083984375},         {-0.08541107177734375, -0.736328125},
              {-0.0, -5e-324},                         {-1.9091796875, -0.812744140625}};
  p.alpha = -3.0517578125e-05;
  p.continuity = lac::ChainContinuity::g2;
  p.closed = true;
  const lac::ChainResult r = lac::solve_chain(p);
  const std::string what = std::string(lac::to_string(r.summary.status)) + " " + r.summary.message;
  if (r.usable()) {
    ASSERT_EQ(r.curve.segments().size(), 6u) << what;
    EXPECT_TRUE(std::isfinite(r.curve.length())) << what;
  } else {
    EXPECT_FALSE(r.summary.message.empty()) << what;
  }
}
