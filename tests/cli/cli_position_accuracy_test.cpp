// Positions on the CLI never claim a usable point that is wrong: the reproducers of wrong points
// printed with status ok (quadratic with gauss-legendre, eval with an unresolved integrand, an
// rk4 estimate below the error), the default drawing range of quadratic, its evaluation budget
// option, eval's samples uniform in arc length, and gamma-inc's underflow.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

// The true point (mpmath, tests/reference/quadratic_positions.csv): (−0.29057, 0.69976). It was
// printed as (−2.829, 2.537) with status ok.
TEST(CliPositionAccuracy, QuadraticGaussLegendreIsRightOrNotUsable) {
  for (const char* integrator : {"gauss-legendre", "gk-tanh-sinh", "gauss-kronrod", "rk4", "rk45"}) {
    const std::string args = std::string("quadratic --alpha -1.5 --gamma -0.3 --lambda 0.7 --integrator ") + integrator +
                             " --s-from -14.262385157871448 --s-to 0 --samples 2";
    const auto run = test::run_lac(args);
    const auto j = nlohmann::ordered_json::parse(run.out);
    ASSERT_TRUE(j.contains("points")) << args;
    const auto& p = j["points"][0];
    if (p["x"].is_null()) {
      EXPECT_NE(j["status"], "ok") << args;
      EXPECT_EQ(run.status, 3) << args;
      continue;
    }
    const std::complex<double> got(p["x"].get<double>(), p["y"].get<double>());
    const std::complex<double> ref(-0.29057240284824696117, 0.69975918983315788319);  // quadratic_positions.csv
    EXPECT_LE(std::abs(got - ref), 1e-6 * 14.27) << args << " printed " << got << " with status " << j["status"];
    EXPECT_LE(j["error"].get<double>(), 1e-6) << args;
  }
}

TEST(CliPositionAccuracy, QuadraticDefaultRangeIsBounded) {
  const auto j = test::run_lac_json("quadratic --alpha -2 --gamma -0.01 --lambda 1");
  ASSERT_TRUE(j.contains("points"));
  ASSERT_EQ(j["points"].size(), 100u);
  for (const auto& p : j["points"]) {
    EXPECT_FALSE(p["x"].is_null()) << p.dump();
    EXPECT_LE(std::abs(p["theta"].get<double>()), 2 * M_PI + 1e-9) << p.dump();
    const double kappa = p["kappa"].get<double>();
    EXPECT_TRUE(kappa >= 1e-3 * (1 - 1e-9) && kappa <= 1e3 * (1 + 1e-9)) << p.dump();
  }
  EXPECT_EQ(j["status"], "ok");
}

TEST(CliPositionAccuracy, QuadraticBudgetIsAnOption) {
  EXPECT_EQ(test::run_lac("quadratic --alpha 3 --gamma -0.01 --lambda 1 --samples 9").status, 0);
  const auto low = test::run_lac("quadratic --alpha 3 --gamma -0.01 --lambda 1 --samples 9 --max-evaluations 100");
  EXPECT_EQ(low.status, 3) << low.out;
  EXPECT_NE(low.out.find("--max-evaluations"), std::string::npos) << low.out;
  EXPECT_NE(low.out.find("[1, 1e10]"), std::string::npos) << low.out;
  const auto bad = test::run_lac_stderr("quadratic --alpha 3 --gamma -0.01 --lambda 1 --max-evaluations 0");
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("max-evaluations"), std::string::npos) << bad.out;
}

// True point (−2.213, 6.835) (mpmath); printed (−7.99, 11.72) with exit 0 and estimate 41.
TEST(CliPositionAccuracy, EvalUnresolvedIsNotUsable) {
  const std::string args = "eval --alpha 0.5 --lambda 0.02 --theta 60 --integrator gauss-legendre";
  const auto run = test::run_lac(args);
  const auto j = nlohmann::ordered_json::parse(run.out);
  if (run.status == 0) {
    const std::complex<double> got(j["point"]["x"].get<double>(), j["point"]["y"].get<double>());
    EXPECT_LE(std::abs(got - std::complex<double>(-2.2130, 6.8350)), 1e-3) << run.out;
  } else {
    EXPECT_EQ(run.status, 3) << run.out;
    EXPECT_EQ(j["status"], "inaccurate") << run.out;
    EXPECT_TRUE(j["point"]["x"].is_null()) << run.out;
  }
}

// la_reference.csv: C(0.095) = (5663571820.27772, 536092130.702453) for α = 0.9, Λ = 100. rk4
// reported 4.4e6 while its error was 3.1e7: the estimate must bound the error.
TEST(CliPositionAccuracy, EvalRk4EstimateBoundsItsError) {
  // The estimate is far above any sensible accept bound here: the point is not usable and says so.
  const auto run = test::run_lac("eval --alpha 0.9 --lambda 100 --theta 0.095 --integrator rk4 --accept 0.1");
  EXPECT_EQ(run.status, 3) << run.out;
  const auto j = nlohmann::ordered_json::parse(run.out);
  EXPECT_EQ(j["status"], "inaccurate") << run.out;
  EXPECT_TRUE(j["point"]["x"].is_null()) << run.out;
  // The estimate itself (reported as error, relative to the arc length) bounds the true error.
  const double s = j["point"]["s"].get<double>();
  ASSERT_FALSE(j["error"].is_null()) << run.out;
  EXPECT_GE(j["error"].get<double>() * std::abs(s), 3.1e7) << run.out;
  EXPECT_EQ(test::run_lac("eval --alpha 0.9 --lambda 100 --theta 0.095 --integrator rk4").status, 3);
}

TEST(CliPositionAccuracy, EvalSamplesAreUniformInArcLength) {
  const auto j = test::run_lac_json("eval --alpha -1 --lambda 1 --theta 0.4 --samples 5");
  ASSERT_EQ(j["points"].size(), 5u);
  const double s_end = j["point"]["s"].get<double>();
  for (int k = 0; k < 5; ++k)
    EXPECT_NEAR(j["points"][k]["s"].get<double>(), s_end * k / 4.0, 1e-12 * std::abs(s_end)) << j["points"].dump();
}

TEST(CliPositionAccuracy, GammaIncUnderflowIsTheRoundedValue) {
  const auto j = test::run_lac_json("special gamma-inc --a 2 --z 800,0");
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["re"].get<double>(), 0.0);
}

}  // namespace
}  // namespace lac
