// Regression tests for fixed fuzzing findings of docs/robustness.md (R1, R2, R4, R7, R13).
// Inputs are the ones the fuzzers saved (fuzz/findings/fuzz_<target>/), reduced to the call
// that went wrong; each test checks the correct behaviour.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <sys/wait.h>

#include "common/error.hpp"
#include "tests/support/run_cli.hpp"
#include "curves/planar/la_integrator.hpp"
#include "segments/planar/g1_segment.hpp"
#include "special/incomplete_gamma.hpp"

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
  expect_finite_or_input_error([&] { return big.s_at_theta(1e-300); }, "theta", "LaCurve(1e300, 1e300).s_at_theta(1e-300)");
  const lac::LaCurve steep(-DBL_MAX, 5);
  expect_finite_or_input_error([&] { return steep.s_at_theta(-6.9388939039072284e-18); }, "theta",
                               "LaCurve(-DBL_MAX, 5).s_at_theta(-6.9e-18)");
  const lac::LaCurve clothoid_like(0, 7.945556640625);
  expect_finite_or_input_error([&] { return clothoid_like.theta_at_s(DBL_MAX); }, "s", "LaCurve(0, 7.95).theta_at_s(DBL_MAX)");
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
    if (r.status == lac::Status::ok) EXPECT_TRUE(std::isfinite(std::abs(r.value)));
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

// Finding R3 (fuzz_cli): a point count beyond memory is an internal error (exit 1, std::bad_alloc)
// instead of invalid input naming the option (exit 2).
TEST(FuzzRegression, CliRejectsHugePointCounts) {
  for (const std::string args : {"eval --alpha 0.5 --lambda 1 --theta -0.5 --points 2147483647",
                                 "g1 --points '0,0 1,0 2,1' --alpha 1 --points-out 2147483647"}) {
    const lac::test::CliRun r = lac::test::run_lac(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find("points"), std::string::npos) << r.out;
  }
}

}  // namespace
