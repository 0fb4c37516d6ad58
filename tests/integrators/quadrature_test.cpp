// Quadrature methods and ODE steppers on problems with known answers.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/integrators/ode.hpp"
#include "lac/integrators/quadrature.hpp"
#include "lac/integrators/registry.hpp"

namespace lac {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(Rk4Quadrature, ExactForCubicsLikeSimpson) {
  auto cubic = [](double t) { return 1.0 + t - 2.0 * t * t + 3.0 * t * t * t; };
  const double exact = 2.0 + 2.0 - 16.0 / 3.0 + 12.0;  // ∫_0^2
  auto r = Rk4{.h = 0.3}.integrate(cubic, 0.0, 2.0);
  EXPECT_NEAR(r.value, exact, 32 * kEps * std::abs(exact));
  EXPECT_EQ(r.status, Status::ok);
}

TEST(Rk4Quadrature, TwoNewEvaluationsPerStep) {
  auto f = [](double t) { return std::cos(t); };
  auto r = Rk4{.h = 0.001}.integrate(f, 0.0, 1.0);  // 1000 steps, even: no extra evaluation
  EXPECT_EQ(r.evaluations, 2 * 1000 + 1);
}

TEST(Rk4Quadrature, ObservedOrderIsFour) {
  auto f = [](double t) { return std::complex<double>(std::cos(3 * t), std::exp(t)); };
  const std::complex<double> exact(std::sin(6.0) / 3.0, std::exp(2.0) - 1.0);
  double prev = 0;
  for (double h : {0.1, 0.05, 0.025, 0.0125}) {
    const double err = std::abs(Rk4{.h = h}.integrate(f, 0.0, 2.0).value - exact);
    if (prev > 0) { EXPECT_NEAR(std::log2(prev / err), 4.0, 0.1) << "h = " << h; }
    prev = err;
  }
}

TEST(Rk4Quadrature, ErrorEstimateTracksTrueError) {
  auto f = [](double t) { return std::exp(-t) * std::sin(5 * t); };
  const double exact = (5.0 - std::exp(-3.0) * (std::sin(15.0) + 5.0 * std::cos(15.0))) / 26.0;
  for (double h : {0.2, 0.1, 0.01}) {
    for (double b : {3.0}) {
      auto r = Rk4{.h = h}.integrate(f, 0.0, b);
      const double err = std::abs(r.value - exact);
      EXPECT_GE(r.error_estimate, err) << "h = " << h;
      // Step doubling without the factor 1/15, per pair in absolute value: about 15 times the
      // error in the asymptotic regime, more where the pairs' differences change sign. h = 0.2
      // turns sin 5t by 1 rad per step: unresolved, the estimate is width × spread there.
      if (h <= 0.1) EXPECT_LE(r.error_estimate, 100 * err + 1e-15) << "h = " << h << ": estimate far too pessimistic";
    }
  }
}

TEST(Rk4Quadrature, WholeNumberOfStepsDespiteRounding) {
  auto f = [](double t) { return t; };
  // 0.3 / 0.1 is 2.9999999999999996 in double; 0.0010000000000000009 / 0.001 slightly above 1.
  EXPECT_EQ(Rk4{.h = 0.1}.integrate(f, 0.0, 0.3).evaluations, 2 * 3 + 1);  // odd n: no extra evaluation
  EXPECT_EQ(Rk4{.h = 0.001}.integrate(f, 0.0, 0.0010000000000000009).evaluations, 2 * 1 + 1);  // n = 1: f(a) once
}

// Cumulative RK4 (one sweep, shared end values) against independent calls per piece: the same
// steps, so the same values; 2 new evaluations per step instead of 4 for one-step pieces.
TEST(Rk4Quadrature, CumulativeSweepEqualsPerPieceCalls) {
  auto f = [](double t) { return std::complex<double>(std::cos(3 * t), std::exp(t)); };
  std::vector<double> ts;
  for (int k = 0; k <= 1000; ++k) ts.push_back(2.0 * k / 1000.0);  // pieces of ≈ h: one step each
  ts.push_back(2.00037);                                          // a last piece shorter than h
  const Rk4 rk4{.h = 0.002};
  const auto cum = integrate_cumulative(rk4, f, ts);
  std::complex<double> per_piece{};
  long evaluations = 0, per_piece_evaluations = 0;
  for (size_t k = 1; k < ts.size(); ++k) {
    const auto piece = rk4.integrate(f, ts[k - 1], ts[k]);
    per_piece += piece.value;
    per_piece_evaluations += piece.evaluations;
    evaluations += cum[k].evaluations;
    ASSERT_LE(std::abs(cum[k].value - per_piece), 1e-15 * std::abs(per_piece)) << "k = " << k;
    ASSERT_EQ(cum[k].status, Status::ok);
  }
  EXPECT_EQ(evaluations, 2 * static_cast<long>(ts.size() - 1) + 1);
  EXPECT_EQ(per_piece_evaluations, 3 * static_cast<long>(ts.size() - 1));
  // The sweep's estimate bounds the true error at every output point and is far below the
  // per-piece sum (each one-step piece can only estimate by Simpson − trapezoid, O(h^3)).
  double per_piece_estimate = 0;
  for (size_t k = 1; k < ts.size(); ++k) {
    const double t = ts[k];
    const std::complex<double> exact(std::sin(3 * t) / 3.0, std::exp(t) - 1.0);
    per_piece_estimate += rk4.integrate(f, ts[k - 1], ts[k]).error_estimate;
    ASSERT_GE(cum[k].error_estimate, std::abs(cum[k].value - exact)) << "k = " << k;
    ASSERT_LE(cum[k].error_estimate, per_piece_estimate) << "k = " << k;
  }
  const std::complex<double> exact_end(std::sin(3 * ts.back()) / 3.0, std::exp(ts.back()) - 1.0);
  // Pessimism of Σ|fine − coarse| (no 1/15, no cancellation between pairs): measured 160×.
  EXPECT_LE(cum.back().error_estimate, 1000 * std::abs(cum.back().value - exact_end));
}

// R6: default budgets bound the work of hopeless calls by evaluation count; the status says
// which budget stopped it. (A step budget, not a timer: the counts are deterministic.)
TEST(QuadratureBudget, DefaultBudgetsBoundEvaluations) {
  auto wave = [](double t) { return std::sin(t); };
  const auto rk45 = Rk45{}.integrate(wave, 0.0, 1e300);
  EXPECT_EQ(rk45.status, Status::max_iterations);
  EXPECT_LE(rk45.evaluations, 6 * Rk45{}.max_steps + 1);
  EXPECT_NE(rk45.message.find("max_steps = 100000"), std::string::npos) << rk45.message;

  const auto rk4 = Rk4{}.integrate(wave, 0.0, 1e300);  // needs 1e303 steps: not run at all
  EXPECT_EQ(rk4.status, Status::max_iterations);
  EXPECT_EQ(rk4.evaluations, 0);
  EXPECT_NE(rk4.message.find("max_steps = 5000000"), std::string::npos) << rk4.message;
  EXPECT_FALSE(usable(rk4.status));

  const auto gk = GaussKronrod{}.integrate(wave, 0.0, 1e7);
  EXPECT_EQ(gk.status, Status::tolerance_not_met);
  EXPECT_LE(gk.evaluations, 21 * (2 * GaussKronrod{}.max_intervals + 1));
  EXPECT_NE(gk.message.find("max_intervals"), std::string::npos) << gk.message;

  // Larger budgets on request through the options struct.
  const auto rk45_more = Rk45{.max_steps = 200'000}.integrate(wave, 0.0, 1e300);
  EXPECT_GT(rk45_more.evaluations, 6 * Rk45{}.max_steps + 1);
  EXPECT_LE(rk45_more.evaluations, 6 * 200'000 + 1);
}

TEST(Rk4Quadrature, ReversedIntervalNegates) {
  auto f = [](double t) { return t * t; };
  EXPECT_NEAR(Rk4{}.integrate(f, 1.0, 0.0).value, -1.0 / 3.0, 1e-15);
}

// ∫_0^3 e^{(−1+5i)t} dt in closed form: oscillatory, complex-valued.
const std::complex<double> kRate(-1.0, 5.0);
std::complex<double> damped_wave(double t) { return std::exp(kRate * t); }
std::complex<double> damped_wave_integral() { return (std::exp(3.0 * kRate) - 1.0) / kRate; }

TEST(Rk45Quadrature, MeetsToleranceAndEstimateBounds) {
  auto r = Rk45{.tol = 1e-12}.integrate(damped_wave, 0.0, 3.0);
  EXPECT_EQ(r.status, Status::ok);
  const double err = std::abs(r.value - damped_wave_integral());
  EXPECT_LT(err, 1e-10);
  EXPECT_GE(r.error_estimate, err);
}

TEST(GaussKronrodQuadrature, ComplexOscillatoryIntegrand) {
  auto r = GaussKronrod{}.integrate(damped_wave, 0.0, 3.0);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_LT(std::abs(r.value - damped_wave_integral()), 8 * kEps);
  EXPECT_GE(r.error_estimate, std::abs(r.value - damped_wave_integral()));
  EXPECT_GT(r.evaluations, 20);
}

TEST(OdeSteppers, Rk4IsFourthOrderOnAnOscillator) {
  using V = Eigen::Vector2d;
  auto f = [](double, const V& y) -> V { return V(y[1], -y[0]); };
  double prev = 0;
  for (double h : {0.1, 0.05, 0.025}) {
    auto r = rk4_integrate(f, V(1.0, 0.0), 0.0, 2.0, h, NoObserver{});
    const double err = (r.state - V(std::cos(2.0), -std::sin(2.0))).norm();
    if (prev > 0) { EXPECT_NEAR(std::log2(prev / err), 4.0, 0.15); }
    prev = err;
  }
}

TEST(OdeSteppers, DormandPrinceMeetsToleranceAndStopsOnObserver) {
  using V = Eigen::Vector2d;
  auto f = [](double, const V& y) -> V { return V(y[1], -y[0]); };
  AdaptiveOptions o;
  o.rtol = o.atol = 1e-11;
  auto r = DormandPrince45<V>::integrate(f, V(1.0, 0.0), 0.0, 10.0, o, NoObserver{});
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_LT((r.state - V(std::cos(10.0), -std::sin(10.0))).norm(), 1e-9);
  EXPECT_EQ(r.evaluations, 1 + 6 * (r.evaluations - 1) / 6);
  // Stop at the first step end where y0 < 0 (after t = π/2).
  auto stop = DormandPrince45<V>::integrate(f, V(1.0, 0.0), 0.0, 10.0, o, [](double, const V& y) { return y[0] >= 0; });
  EXPECT_TRUE(stop.stopped_by_observer);
  EXPECT_GT(stop.t_end, M_PI / 2);
  EXPECT_LT(stop.t_end, 3.0);
}

TEST(OdeSteppers, DormandPrinceReportsStepCap) {
  auto f = [](double, const double& y) { return -y; };
  AdaptiveOptions o;
  o.max_steps = 3;
  o.rtol = o.atol = 1e-14;
  auto r = DormandPrince45<double>::integrate(f, 1.0, 0.0, 100.0, o, NoObserver{});
  EXPECT_EQ(r.status, Status::max_iterations);
}

TEST(QuadratureOptions, RejectInvalidSettingsNamingTheParameter) {
  auto f = [](double t) { return t; };
  EXPECT_THROW(Rk4{.h = 0}.integrate(f, 0.0, 1.0), InputError);
  EXPECT_THROW(Rk4{.h = std::nan("")}.integrate(f, 0.0, 1.0), InputError);
  EXPECT_THROW((Rk4{.h = 0.1, .max_steps = 0}.integrate(f, 0.0, 1.0)), InputError);
  EXPECT_THROW(GaussKronrod{.tol = -1}.integrate(f, 0.0, 1.0), InputError);
  EXPECT_THROW(Rk45{.tol = 1e-20}.integrate(f, 0.0, 1.0), InputError);
  try {
    make_quadrature("simpson");
    FAIL() << "unknown name accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "integrator");
    EXPECT_NE(std::string(e.what()).find("rk4, rk45, gauss-kronrod"), std::string::npos);
  }
  EXPECT_THROW(make_quadrature("rk45", {.h = 0.1, .tol = {}}), InputError);
  EXPECT_THROW(make_quadrature("rk4", {.h = {}, .tol = 1e-8}), InputError);
  EXPECT_NO_THROW(make_quadrature("gk", {.h = {}, .tol = 1e-10}));
}

}  // namespace
}  // namespace lac
