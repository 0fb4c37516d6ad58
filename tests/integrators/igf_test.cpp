// The igf closed form (integrators/igf.hpp) against mpmath references:
// tests/reference/igf_reference.csv (generator igf_reference.py: differences C(θ1) − C(θ0),
// small steps, every α incl. near 1) and, when present, the project's la_reference.csv.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <string>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/integrators/igf.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

using cplx = std::complex<double>;

// Tolerances, relative to |C(θ1) − C(θ0)|.
constexpr double kEndpointTolerance = 1e-12;  // target: endpoint relative error ≤ 1e-12 of |C|
// The error estimate must bound the true error, up to this factor (estimates are a-priori
// rounding bounds, not guarantees).
constexpr double kEstimateSlack = 1.0;

struct Worst {
  double error = 0;
  std::string where;
  int count = 0;
  int fell_back = 0;
};

TEST(Igf, ReferenceDifferences) {
  const auto t = test::read_reference_csv("igf_reference.csv");
  ASSERT_GE(t.rows.size(), 300u);
  std::map<std::string, Worst> worst;
  int under_estimated = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const double alpha = t.number(i, "alpha"), lambda = t.number(i, "lambda");
    const double th0 = t.number(i, "theta0"), th1 = t.number(i, "theta1");
    const cplx ref(t.number(i, "re"), t.number(i, "im"));
    const IgfResult r = igf_position_delta_detailed(alpha, lambda, th0, th1);
    const double err = std::abs(r.integral.value - ref) / std::abs(ref);
    char where[200];
    std::snprintf(where, sizeof where, "alpha=%.17g lambda=%g theta %.17g..%.17g (%ld pieces, %ld evals)", alpha, lambda, th0,
                  th1, r.pieces, r.integral.evaluations);
    auto& w = worst[std::string(to_string(r.region))];
    ++w.count;
    if (r.integral.status == Status::fell_back) ++w.fell_back;
    if (!(err <= w.error)) w = Worst{err, where, w.count, w.fell_back};
    EXPECT_TRUE(r.integral.status == Status::ok || r.integral.status == Status::fell_back)
        << where << ": " << to_string(r.integral.status) << " " << r.integral.message;
    if (r.integral.status == Status::fell_back) {
      EXPECT_FALSE(r.integral.message.empty()) << where;
    }
    EXPECT_LE(err, kEndpointTolerance) << where << " value " << r.integral.value << " reference " << ref;
    const double abs_err = std::abs(r.integral.value - ref);
    if (abs_err > kEstimateSlack * r.integral.error_estimate && err > 4e-16) {
      ++under_estimated;
      ADD_FAILURE() << where << ": error " << abs_err << " above its estimate " << r.integral.error_estimate;
    }
  }
  std::printf("igf vs igf_reference.csv: worst relative error per region (%zu cases, %d estimates below the error)\n",
              t.rows.size(), under_estimated);
  for (const auto& [region, w] : worst)
    std::printf("  %-15s %4d cases (%d fell back)  worst %.3e at %s\n", region.c_str(), w.count, w.fell_back, w.error,
                w.where.c_str());
}

TEST(Igf, ProjectReferenceTable) {
  const std::string path = std::string(LAC_REFERENCE_DIR) + "/la_reference.csv";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "la_reference.csv not generated yet (tests/reference/la_reference.py)";
  const auto t = test::read_reference_csv("la_reference.csv");
  double worst = 0;
  std::string where_worst;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const LaCurve curve(t.number(i, "alpha"), t.number(i, "lambda"));
    const double theta = t.number(i, "theta");
    const cplx ref(t.number(i, "x"), t.number(i, "y"));
    const PositionResult r = position_at(curve, Parameter::theta, theta, Igf{}, Form::theta);
    const double err = std::abs(r.point.position - ref) / std::abs(ref);
    const std::string where = "alpha=" + t.rows[i][t.column("alpha")] + " lambda=" + t.rows[i][t.column("lambda")] +
                              " theta=" + t.rows[i][t.column("theta")];
    if (err > worst) worst = err, where_worst = where;
    EXPECT_TRUE(usable(r.status)) << where << " " << r.message;
    EXPECT_LE(err, kEndpointTolerance) << where;
  }
  std::printf("igf vs la_reference.csv: %zu cases, worst relative error %.3e at %s\n", t.rows.size(), worst,
              where_worst.c_str());
}

TEST(Igf, PolylineIsConsistentWithPositions) {
  // Running sums of igf pieces reproduce the one-shot endpoint, for α on both sides of 1.
  for (double alpha : {-1.0, 0.5, 0.999, 1.001, 2.0}) {
    const LaCurve curve(alpha, 1.0);
    const double end = curve.theta_domain().hi < 3 ? 0.9 * curve.theta_domain().hi : 3.0;
    const auto pts = polyline(curve, Parameter::theta, 0.0, end, 50, Igf{}, Form::theta);
    const auto one = position_at(curve, Parameter::theta, end, Igf{}, Form::theta);
    EXPECT_LE(std::abs(pts.back().point.position - one.point.position), 1e-12 * std::abs(one.point.position)) << alpha;
  }
}

TEST(Igf, SmallStepsDoNotCancel) {
  // C(θ + h) − C(θ) ≈ ρ(θ) e^{iθ} h for tiny h: relative accuracy is kept (no subtraction
  // of two O(1) closed-form values). Second-order check with ρ'(θ).
  for (double alpha : {-3.0, 0.0, 0.5, 1.5, 2.0, 5.0}) {
    const LaCurve curve(alpha, 0.7);
    const double th = 0.2, th1 = th + 1e-9, h = th1 - th;  // the step the doubles represent
    const auto d = igf_position_delta(alpha, 0.7, th, th1);
    const double rho = curve.rho_at_theta(th);
    const double drho = 0.7 * std::pow(rho, 2.0 - alpha);  // dρ/dθ = Λ ρ^(2−α) (ds/dρ = ρ^(α−1)/Λ, dθ/ds = 1/ρ)
    const cplx expected = std::polar(1.0, th) * (rho * h + 0.5 * h * h * (drho + cplx(0, 1) * rho));
    EXPECT_EQ(d.status, Status::ok);
    EXPECT_LE(std::abs(d.value - expected), 1e-13 * std::abs(expected)) << alpha;
  }
}

TEST(Igf, RandomInputsAgreeWithGaussKronrod) {
  // 20000 random (α, Λ, θ0, θ1) inside the domain: α = 1 ± 10^[−8, 0] (a third) or ±10^[−3, 3],
  // Λ = 10^[−6, 3], θ in the domain clipped to [−50, 50], a fifth of them steps of 10^[−9, −1];
  // rows with |log ρ| > 500 are left out. Never a throw, a non-finite value or an unusable
  // status; agreement with Gauss–Kronrod (tol 1e-13) within their combined error estimates.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  GaussKronrod gk;
  gk.tol = 1e-13;
  gk.max_depth = 25;
  int cases = 0, fell_back = 0;
  double worst = 0;
  for (int it = 0; it < 20000; ++it) {
    const double alpha = u(rng) < 0.3 ? 1 + (u(rng) < 0.5 ? -1 : 1) * std::pow(10, -8 + 8 * u(rng))
                                      : (u(rng) < 0.5 ? -1 : 1) * std::pow(10, -3 + 6 * u(rng));
    const double lambda = std::pow(10, -6 + 9 * u(rng));
    const double k = (alpha - 1) * lambda;
    const double lo = std::max(k > 0 ? -1 / k : -1e3, -50.0), hi = std::min(k < 0 ? -1 / k : 1e3, 50.0);
    const double t0 = u(rng) < 0.5 ? 0.0 : lo + (hi - lo) * (0.02 + 0.96 * u(rng));
    double t1 = lo + (hi - lo) * (0.02 + 0.96 * u(rng));
    if (u(rng) < 0.2) t1 = t0 + std::pow(10, -9 + 8 * u(rng));
    if (!(1 + k * t1 > 0) || !(1 + k * t0 > 0)) continue;
    auto log_rho = [&](double t) { return lambda * t * (k * t == 0 ? 1.0 : std::log1p(k * t) / (k * t)); };
    if (std::max(std::abs(log_rho(t0)), std::abs(log_rho(t1))) > 500) continue;
    ++cases;
    const IgfResult r = igf_position_delta_detailed(alpha, lambda, t0, t1);
    const auto& v = r.integral;
    char where[160];
    std::snprintf(where, sizeof where, "alpha=%.17g lambda=%.17g theta %.17g..%.17g", alpha, lambda, t0, t1);
    ASSERT_TRUE(std::isfinite(v.value.real()) && std::isfinite(v.value.imag())) << where;
    ASSERT_TRUE(v.status == Status::ok || v.status == Status::fell_back) << where << " " << v.message;
    if (v.status == Status::fell_back) ++fell_back;
    const auto q = gk.integrate([&](double psi) { return std::polar(std::exp(log_rho(psi)), psi); }, t0, t1);
    const double diff = std::abs(q.value - v.value);
    worst = std::max(worst, diff / std::abs(q.value));
    EXPECT_LE(diff, std::max(1e-12 * std::abs(q.value), 3 * (q.error_estimate + v.error_estimate))) << where;
  }
  std::printf("igf vs gauss-kronrod on %d random cases: %d fell back, worst relative difference %.3e\n", cases, fell_back,
              worst);
  EXPECT_GE(cases, 15000);
}

TEST(Igf, FallbackIsReported) {
  // A piece cap of 1 forbids the segment series on a long interval near α = 1: the result comes
  // from Gauss–Kronrod, says so, and is still accurate.
  IgfOptions o;
  o.max_pieces = 1;
  const IgfResult r = igf_position_delta_detailed(1.001, 1.0, 0.0, 10.0, o);
  EXPECT_EQ(r.integral.status, Status::fell_back);
  EXPECT_EQ(r.region, IgfRegion::gauss_kronrod);
  EXPECT_NE(r.integral.message.find("max_pieces"), std::string::npos) << r.integral.message;
  const IgfResult good = igf_position_delta_detailed(1.001, 1.0, 0.0, 10.0);
  EXPECT_EQ(good.integral.status, Status::ok);
  EXPECT_LE(std::abs(r.integral.value - good.integral.value), 1e-12 * std::abs(good.integral.value));
}

TEST(Igf, InvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(igf_position_delta(nan, 1.0, 0.0, 1.0), InputError);
  EXPECT_THROW(igf_position_delta(2.0, -1.0, 0.0, 1.0), InputError);
  EXPECT_THROW(igf_position_delta(2.0, 1.0, 0.0, nan), InputError);
  EXPECT_THROW(igf_position_delta(2.0, 1.0, -1.0, 0.0), InputError);  // θ > −1/((α−1)Λ) = −1
  EXPECT_THROW(igf_position_delta(0.5, 1.0, 0.0, 2.0), InputError);   // θ < 1/((1−α)Λ) = 2
  try {
    igf_position_delta(0.5, 1.0, 0.0, 2.5);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "theta1");
    EXPECT_NE(std::string(e.what()).find("(-inf, 2)"), std::string::npos) << e.what();
  }
  IgfOptions bad;
  bad.tol = 0;
  EXPECT_THROW(igf_position_delta(2.0, 1.0, 0.0, 1.0, bad), InputError);
}

TEST(Igf, Registry) {
  const AnyQuadrature m = make_quadrature("igf", QuadratureOptions{std::nullopt, 1e-10});
  ASSERT_TRUE(std::holds_alternative<Igf>(m));
  EXPECT_EQ(std::get<Igf>(m).tol, 1e-10);
  EXPECT_EQ(name_of(m), "igf");
  EXPECT_THROW(make_quadrature("igf", QuadratureOptions{1e-3, std::nullopt}), InputError);
  EXPECT_THROW(make_quadrature("igf", QuadratureOptions{std::nullopt, -1.0}), InputError);
  const MethodInfo* info = find_method(quadrature_methods(), "igf");
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->applies_to, "planar LA curves and segments (each piece in standard form); not quadratic curves");
}

}  // namespace
}  // namespace lac
