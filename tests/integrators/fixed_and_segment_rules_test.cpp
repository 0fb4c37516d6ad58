// GaussLegendre (composite fixed rule) and GkTanhSinh (the segment solvers' default) on integrals
// with known values: GaussLegendre's estimate bounds its true error on smooth integrands;
// GkTanhSinh keeps the results it had as SegmentQuadrature (evaluations, statuses, values).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include "lac/integrators/gauss_legendre.hpp"
#include "lac/integrators/gk_tanh_sinh.hpp"

namespace lac {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Smooth {
  const char* name;
  std::function<double(double)> f;
  double a, b, exact;
};

TEST(GaussLegendreQuadrature, EstimateBoundsTheTrueErrorOnSmoothIntegrands) {
  const double pi = std::numbers::pi;
  const Smooth cases[] = {
      {"exp", [](double x) { return std::exp(x); }, 0.0, 1.0, std::exp(1.0) - 1.0},
      {"cos 10x", [](double x) { return std::cos(10 * x); }, 0.0, 3.0, std::sin(30.0) / 10},
      {"runge", [](double x) { return 1 / (1 + x * x); }, -5.0, 5.0, 2 * std::atan(5.0)},
      {"gauss", [](double x) { return std::exp(-x * x); }, -3.0, 4.0, std::sqrt(pi) / 2 * (std::erf(4.0) + std::erf(3.0))},
      {"sin^2 reversed", [](double x) { return std::sin(x) * std::sin(x); }, pi, 0.0, -pi / 2},
  };
  for (const Smooth& c : cases) {
    for (int panels : {1, 2, 3, 8, 40}) {
      const auto r = GaussLegendre{.panels = panels, .tol = 1e-6}.integrate(c.f, c.a, c.b);
      const double err = std::abs(r.value - c.exact);
      EXPECT_LE(err, r.error_estimate) << c.name << " panels " << panels;
      // Per panel: the 20-point rule, the 10-point rule and the 20-point rule on both halves.
      EXPECT_EQ(r.evaluations, 70L * panels);
      // The estimate is the larger of the 10-point and halved-panel differences: not wildly
      // pessimistic once those converge.
      if (r.error_estimate > 1e3 * kEps * std::abs(c.exact)) {
        EXPECT_EQ(r.status == Status::ok, r.error_estimate <= 1e-6 * std::abs(r.value)) << c.name << " " << panels;
      }
    }
  }
}

TEST(GaussLegendreQuadrature, ExactForPolynomialsOfDegree39PerPanel) {
  auto p = [](double x) { return std::pow(x, 39) - 3 * std::pow(x, 20) + 1; };
  const double exact = 1.0 / 40 - 3.0 / 21 + 1.0;  // ∫_0^1
  const auto r = GaussLegendre{}.integrate(p, 0.0, 1.0);
  EXPECT_NEAR(r.value, exact, 8 * kEps);
  // The estimate is the 10-point rule's error (exact to degree 19 only): pessimistic here.
  EXPECT_GE(r.error_estimate, 1e-8);
  EXPECT_EQ(r.status, Status::tolerance_not_met);
}

TEST(GaussLegendreQuadrature, RoughIntegrandIsToleranceNotMet) {
  const auto r = GaussLegendre{.panels = 1, .tol = 1e-12}.integrate([](double x) { return std::sqrt(x); }, 0.0, 1.0);
  EXPECT_EQ(r.status, Status::tolerance_not_met);
  EXPECT_LE(std::abs(r.value - 2.0 / 3), r.error_estimate);
  EXPECT_THROW(GaussLegendre{.panels = 0}.validate(), InputError);
  EXPECT_THROW(GaussLegendre{.tol = 0}.validate(), InputError);
}

// Values, estimates, evaluation counts and statuses of SegmentQuadrature before it was renamed
// GkTanhSinh (same compiler and flags): the rename kept its numerics.
TEST(GkTanhSinhQuadrature, BehavesAsTheSegmentQuadratureItReplaces) {
  struct Before {
    const char* name;
    std::function<double(double)> f;
    double a, b, value, exact;
    long evaluations;
    Status status;
  };
  const Before cases[] = {
      {"exp (one Kronrod panel)", [](double x) { return std::exp(x); }, 0, 1, 0x1.b7e151628aed3p+0, std::exp(1.0) - 1, 21,
       Status::ok},
      {"1/sqrt x (tanh-sinh)", [](double x) { return 1 / std::sqrt(x); }, 0, 1, 2.0, 2.0, 263, Status::ok},
      {"1/sqrt x reversed", [](double x) { return 1 / std::sqrt(x); }, 1, 0, -2.0, -2.0, 263, Status::ok},
      {"log x", [](double x) { return std::log(x); }, 0, 1, -1.0, -1.0, 336, Status::ok},
      {"(2 - x)^-3/4", [](double x) { return std::pow(2 - x, -0.75); }, 0, 2, 0x1.306802191313p+2, 4 * std::pow(2.0, 0.25),
       17017, Status::tolerance_not_met},
  };
  for (const Before& c : cases) {
    const auto r = GkTanhSinh{}.integrate(c.f, c.a, c.b);
    EXPECT_EQ(r.evaluations, c.evaluations) << c.name;
    EXPECT_EQ(r.status, c.status) << c.name;
    EXPECT_NEAR(r.value, c.value, 4 * kEps * std::abs(c.value)) << c.name;
    if (r.status == Status::ok) {
      EXPECT_LE(std::abs(r.value - c.exact), std::max(r.error_estimate, 4 * kEps)) << c.name;
    }
  }
  const auto z = GkTanhSinh{}.integrate([](double x) { return std::polar(std::sqrt(1 - x), 10 * x); }, 0.0, 1.0);
  EXPECT_EQ(z.evaluations, 336);
  EXPECT_NEAR(z.value.real(), 0x1.624a92d5223ebp-7, 8 * kEps);
  EXPECT_NEAR(z.value.imag(), 0x1.056d5d300ba79p-3, 8 * kEps);
  EXPECT_EQ(GkTanhSinh{}.integrate([](double x) { return x; }, 2.0, 2.0).evaluations, 0);
}

// ts_max_levels applies to every call, also after a call with other levels in the same thread (the
// rule and its abscissa tables are kept per level count): fewer levels cost fewer evaluations on an
// integrand that needs all of them, and the default comes back unchanged.
TEST(GkTanhSinhQuadrature, LevelsApplyPerCall) {
  const auto f = [](double x) { return std::pow(2 - x, -0.75); };
  const auto full = GkTanhSinh{}.integrate(f, 0.0, 2.0);
  const auto few = GkTanhSinh{.ts_max_levels = 5}.integrate(f, 0.0, 2.0);
  const auto again = GkTanhSinh{}.integrate(f, 0.0, 2.0);
  EXPECT_LT(few.evaluations, full.evaluations / 10);
  EXPECT_EQ(again.evaluations, full.evaluations);
  EXPECT_EQ(again.value, full.value);
}

TEST(GkTanhSinhQuadrature, NonFiniteIntegrandIsANumericalFailure) {
  const auto r = GkTanhSinh{}.integrate([](double x) { return x < 0.5 ? std::nan("") : 1.0; }, 0.0, 1.0);
  EXPECT_EQ(r.status, Status::numerical_failure);
  EXPECT_THROW(GkTanhSinh{.tol = 0}.validate(), InputError);
  EXPECT_THROW(GkTanhSinh{.gk_max_depth = 0}.validate(), InputError);
  EXPECT_THROW(GkTanhSinh{.ts_max_levels = 3}.validate(), InputError);
}

}  // namespace
}  // namespace lac
