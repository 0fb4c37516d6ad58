// Planar LA curve: closed forms, positions against the mpmath reference table
// (tests/reference/la_reference.csv), and rejection of invalid input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Documented accuracy of each integrator at its default setting, relative to |C|, on the whole
// reference table (auto form). These are the numbers README.md and results/ quote.
struct Tolerance {
  const char* integrator;
  QuadratureOptions options;
  double max_relative_error;
};
const Tolerance kTolerances[] = {
    {"gauss-kronrod", {}, 1e-13},
    {"rk45", {.h = {}, .tol = 1e-12}, 1e-10},
    {"igf", {}, 1e-12},
};

struct ReferenceCase {
  double alpha, lambda, theta, s, rho;
  std::complex<double> c;
};

std::vector<ReferenceCase> reference_cases() {
  static const std::vector<ReferenceCase> cases = [] {
    auto t = test::read_reference_csv("la_reference.csv");
    std::vector<ReferenceCase> v;
    for (size_t i = 0; i < t.rows.size(); ++i)
      v.push_back({t.number(i, "alpha"), t.number(i, "lambda"), t.number(i, "theta"), t.number(i, "s"),
                   t.number(i, "rho"), {t.number(i, "x"), t.number(i, "y")}});
    return v;
  }();
  return cases;
}

std::string describe_case(const ReferenceCase& rc) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "alpha=%.6g lambda=%.3g theta=%.8g", rc.alpha, rc.lambda, rc.theta);
  return buf;
}

TEST(LaReference, TableSpansTheDomain) {
  const auto cases = reference_cases();
  ASSERT_GE(cases.size(), 200u);
  auto has = [&](auto pred) { return std::any_of(cases.begin(), cases.end(), pred); };
  EXPECT_TRUE(has([](auto& c) { return c.alpha == 0; }));
  EXPECT_TRUE(has([](auto& c) { return c.alpha == 1; }));
  EXPECT_TRUE(has([](auto& c) { return c.alpha <= -100; }));
  EXPECT_TRUE(has([](auto& c) { return c.alpha >= 100; }));
  EXPECT_TRUE(has([](auto& c) { return c.theta < 0; }));
  EXPECT_TRUE(has([](auto& c) { return c.lambda <= 1e-3; }));
  EXPECT_TRUE(has([](auto& c) { return c.lambda >= 100; }));
}

// s and ρ from the closed forms against the 40-digit values, allowing for the rounding of the
// inputs α, Λ, θ to double and for exp() amplifying the absolute error of log ρ:
// tolerance 4 ε (1 + |log ρ| + condition numbers of s and ρ with respect to θ, Λ and α).
// The α condition number is estimated by a central difference of the closed form itself.
double alpha_condition(double alpha, double lambda, double theta, double (LaCurve::*f)(double) const) {
  const double d = 1e-7 * std::max(1.0, std::abs(alpha));
  try {
    const double up = (LaCurve(alpha + d, lambda).*f)(theta), down = (LaCurve(alpha - d, lambda).*f)(theta);
    return std::abs(alpha * (std::log(std::abs(up)) - std::log(std::abs(down))) / (2 * d));
  } catch (const InputError&) {
    return 0;  // θ too close to the bound for the perturbed α: leave the bound to the other terms
  }
}

TEST(LaClosedForms, MatchReferenceToAFewUlp) {
  double worst = 0;
  std::string worst_case;
  for (const auto& rc : reference_cases()) {
    const LaCurve c(rc.alpha, rc.lambda);
    const double s = c.s_at_theta(rc.theta);
    const double rho = c.rho_at_theta(rc.theta);
    const double log_rho = std::abs(std::log(rc.rho));
    const double cond_theta_s = std::abs(rc.theta * rc.rho / rc.s);                            // d log s / d log θ
    const double cond_theta_rho = std::abs(rc.theta * rc.lambda * std::pow(rc.rho, 1.0 - rc.alpha));  // d log ρ / d log θ
    const double bound_s = 1 + log_rho + 2 * cond_theta_s + alpha_condition(rc.alpha, rc.lambda, rc.theta, &LaCurve::s_at_theta);
    const double bound_rho =
        1 + log_rho + 2 * cond_theta_rho + alpha_condition(rc.alpha, rc.lambda, rc.theta, &LaCurve::rho_at_theta);
    const double es = std::abs(s - rc.s) / std::abs(rc.s) / (kEps * bound_s);
    const double er = std::abs(rho - rc.rho) / rc.rho / (kEps * bound_rho);
    EXPECT_LE(es, 4.0) << describe_case(rc) << " s=" << s << " ref " << rc.s;
    EXPECT_LE(er, 4.0) << describe_case(rc) << " rho=" << rho << " ref " << rc.rho;
    if (std::max(es, er) > worst) {
      worst = std::max(es, er);
      worst_case = describe_case(rc);
    }
  }
  std::printf("closed forms: worst %.2f eps*(1 + |log rho| + condition numbers) at %s\n", worst, worst_case.c_str());
}

TEST(LaClosedForms, RoundTripsAndDerivativeIdentity) {
  for (const auto& rc : reference_cases()) {
    const LaCurve c(rc.alpha, rc.lambda);
    const double s = c.s_at_theta(rc.theta);
    if (!c.s_domain().contains(s)) continue;  // s rounded onto an open end
    const double theta_back = c.theta_at_s(s);
    const double cond = std::abs(s / (rc.theta * rc.rho));  // d log θ / d log s
    EXPECT_LE(std::abs(theta_back - rc.theta), 8 * kEps * std::abs(rc.theta) * (1 + cond) * (1 + 1 / std::max(cond, 1e-300)))
        << describe_case(rc);
    if (rc.lambda > 0 && std::abs(std::log(rc.rho)) > 1e-3) {
      const double th_from_rho = c.theta_at_log_rho(c.log_rho_at_theta(rc.theta));
      EXPECT_NEAR(th_from_rho, rc.theta, 16 * kEps * std::abs(rc.theta) * (1 + cond)) << describe_case(rc);
    }
    // ds/dθ = ρ by a Richardson-extrapolated central difference. The step is 1e-3 of the local
    // length scale of ρ (1 / |d log ρ/dθ| = 1 / (Λ ρ^(1−α))) and of the distance to the domain
    // ends; the tolerance adds the rounding of the difference, ε|s| / (h ρ).
    const Interval d = c.theta_domain();
    const double scale = 1.0 / std::max(1.0, rc.lambda * std::pow(rc.rho, 1.0 - rc.alpha));
    const double h = 1e-3 * std::min({scale, std::abs(rc.theta) + 1e-3, (d.hi - rc.theta) / 4, (rc.theta - d.lo) / 4});
    auto ds = [&](double step) { return (c.s_at_theta(rc.theta + step) - c.s_at_theta(rc.theta - step)) / (2 * step); };
    const double derivative = (4 * ds(h / 2) - ds(h)) / 3;
    EXPECT_NEAR(derivative / rc.rho, 1.0, 1e-7 + 10 * kEps * std::abs(rc.s) / (h * rc.rho)) << describe_case(rc);
  }
}

// frame_at computes log ρ once and derives ρ, κ = 1/ρ and s (or θ) from it: it must agree with
// the separate conversions (which check and compute each on its own) to a few ulp, and with the
// reference table within the bound of MatchReferenceToAFewUlp; polyline's frames (domain checked
// at the ends, frame_inside per point) are the same bits.
TEST(LaClosedForms, FrameAgreesWithConversions) {
  double worst = 0;
  for (const auto& rc : reference_cases()) {
    const LaCurve c(rc.alpha, rc.lambda);
    const CurvePoint f = c.frame_at(Parameter::theta, rc.theta);
    EXPECT_EQ(f.theta, rc.theta);
    const double log_rho = std::abs(std::log(rc.rho));
    auto ulp_error = [](double a, double b) { return std::abs(a - b) / (kEps * std::abs(b)); };
    const double e_rho = ulp_error(f.rho, c.rho_at_theta(rc.theta)) / (1 + log_rho);
    const double e_kappa = ulp_error(f.kappa, c.kappa_at_theta(rc.theta)) / (1 + log_rho);
    const double e_s = ulp_error(f.s, c.s_at_theta(rc.theta)) / (1 + log_rho);
    EXPECT_LE(e_rho, 4.0) << describe_case(rc);
    EXPECT_LE(e_kappa, 4.0) << describe_case(rc);
    EXPECT_LE(e_s, 4.0) << describe_case(rc);
    worst = std::max({worst, e_rho, e_kappa, e_s});
    // In s: θ, ρ and κ from one log ρ, against theta_at_s.
    if (c.s_domain().contains(f.s)) {
      const CurvePoint g = c.frame_at(Parameter::s, f.s);
      EXPECT_EQ(g.s, f.s);
      EXPECT_LE(ulp_error(g.theta, c.theta_at_s(f.s)), 4.0 * (1 + log_rho)) << describe_case(rc);
      EXPECT_LE(ulp_error(g.rho * g.kappa, 1.0), 2.0) << describe_case(rc);
    }
  }
  std::printf("frame_at vs separate conversions: worst %.2f eps*(1 + |log rho|)\n", worst);
  for (Parameter p : {Parameter::theta, Parameter::s}) {
    const LaCurve c(4.0 / 3.0, 10.0);
    const auto line = polyline(c, p, -0.01, 0.8, 41, GaussKronrod{});
    for (const auto& r : line) {
      const double t = p == Parameter::theta ? r.point.theta : r.point.s;
      const CurvePoint f = c.frame_at(p, t);
      EXPECT_EQ(r.point.s, f.s);
      EXPECT_EQ(r.point.theta, f.theta);
      EXPECT_EQ(r.point.rho, f.rho);
      EXPECT_EQ(r.point.kappa, f.kappa);
    }
  }
}

TEST(LaClosedForms, CircleWhenLambdaIsZero) {
  const LaCurve c(2.5, 0.0);
  for (double t : {-7.0, -1.0, 0.5, 3.0, 40.0}) {
    EXPECT_EQ(c.rho_at_theta(t), 1.0);
    EXPECT_EQ(c.s_at_theta(t), t);
    EXPECT_EQ(c.theta_at_s(t), t);
    auto r = position_at(c, Parameter::theta, t, GaussKronrod{});
    EXPECT_NEAR(std::abs(r.point.position - std::complex<double>(std::sin(t), 1 - std::cos(t))), 0.0, 1e-13 * (1 + std::abs(t)));
  }
}

// Each integrator at its documented setting meets its documented accuracy on every case,
// and its error estimate bounds the true error.
TEST(LaPositions, IntegratorsMeetDocumentedAccuracy) {
  for (const auto& tol : kTolerances) {
    const AnyQuadrature method = make_quadrature(tol.integrator, tol.options);
    double worst = 0, worst_ratio_est = 1e300;
    std::string worst_case;
    int under_estimated = 0;
    for (const auto& rc : reference_cases()) {
      const LaCurve c(rc.alpha, rc.lambda);
      const auto r = position_at(c, Parameter::theta, rc.theta, method);
      ASSERT_TRUE(usable(r.status)) << tol.integrator << " " << describe_case(rc) << ": " << r.message;
      const double err = std::abs(r.point.position - rc.c);
      const double rel = err / std::abs(rc.c);
      EXPECT_LE(rel, tol.max_relative_error) << tol.integrator << " " << describe_case(rc) << " form "
                                             << to_string(r.form) << " evals " << r.evaluations;
      // Below this level the difference is explained by rounding the inputs α, Λ, θ to double
      // (the reference is exact in them), not by the method: ε|C|(1 + |log ρ| + α-condition).
      const double input_rounding =
          8 * kEps * std::abs(rc.c) * (1 + std::abs(std::log(rc.rho)) + alpha_condition(rc.alpha, rc.lambda, rc.theta, &LaCurve::s_at_theta));
      if (err > input_rounding && r.error_estimate < err) {
        ++under_estimated;
        std::printf("  %s estimate %.3g below true error %.3g at %s\n", tol.integrator, r.error_estimate, err,
                    describe_case(rc).c_str());
      }
      if (rel > worst) {
        worst = rel;
        worst_case = describe_case(rc);
      }
      if (err > 0) worst_ratio_est = std::min(worst_ratio_est, r.error_estimate / err);
    }
    EXPECT_EQ(under_estimated, 0) << tol.integrator << ": error estimate below the true error (above rounding level)";
    std::printf("%s: worst relative error %.3g at %s; min estimate/true error %.3g\n", tol.integrator, worst,
                worst_case.c_str(), worst_ratio_est);
  }
}

TEST(LaPositions, FormsAgreeWhereBothAreSmooth) {
  const LaCurve c(-1.0, 1.0);  // clothoid
  for (double t : {0.1, 0.3, 0.45}) {
    auto a = position_at(c, Parameter::theta, t, GaussKronrod{}, Form::theta);
    auto b = position_at(c, Parameter::theta, t, GaussKronrod{}, Form::s);
    EXPECT_EQ(a.form, Form::theta);
    EXPECT_EQ(b.form, Form::s);
    EXPECT_LT(std::abs(a.point.position - b.point.position), 1e-14);
  }
}

TEST(LaPositions, PolylineIsUniformAndCumulative) {
  const LaCurve c(2.0, 1.0);
  auto pts = polyline(c, Parameter::s, 0.0, 1.5, 31, GaussKronrod{});
  ASSERT_EQ(pts.size(), 31u);
  EXPECT_EQ(pts.front().point.s, 0.0);
  EXPECT_EQ(pts.back().point.s, 1.5);
  for (size_t k = 1; k < pts.size(); ++k) EXPECT_NEAR(pts[k].point.s - pts[k - 1].point.s, 0.05, 1e-15);
  auto end = position_at(c, Parameter::s, 1.5, GaussKronrod{});
  EXPECT_LT(std::abs(pts.back().point.position - end.point.position), 1e-14);
  EXPECT_GE(pts.back().evaluations, pts[1].evaluations);
}

// Rk4 as a generic quadrature (not the Rk4 type), so polyline takes its per-piece path: the
// reference for the cumulative sweep that polyline uses for Rk4 itself.
struct PerPieceRk4 {
  static constexpr std::string_view name = "rk4-per-piece";
  Rk4 rk4;
  void validate() const { rk4.validate(); }
  template <class F>
  auto integrate(F&& f, double a, double b) const {
    return rk4.integrate(f, a, b);
  }
};

// 002's segment as a 1001-point polyline: one RK4 sweep gives the per-piece values (same steps)
// to rounding, 2 new evaluations per step instead of 4, and both agree with Gauss-Kronrod to
// RK4's accuracy; the sweep's estimate bounds the true error at every point. Rounding: the sweep
// takes e^{iθ} from NearbyCis (≤ 0.51 ε against sincos's 0.25 ε), so the two differ by a few ε
// times the arc length swept, not relative to |C| (which is small where the sweep comes back
// toward the reference point). Rows: θ-form, s-form (α ≤ 1/2), a polyline in s (pieces uneven in
// θ), one starting away from the reference point, and an s-form polyline in s.
TEST(LaPositions, Rk4PolylineSweepEqualsPerPiece) {
  struct Case {
    double alpha, lambda;
    Parameter p;
    double t0, t1;
    int n;
    Form form;
  };
  for (const Case& k : {Case{2.0, 1.0, Parameter::theta, 0.0, 1.0, 1001, Form::theta},
                        Case{-1.0, 0.417, Parameter::theta, 0.0, 1.0, 1001, Form::automatic},
                        Case{4.0 / 3.0, 10.0, Parameter::s, 0.0, 1.2, 301, Form::theta},
                        Case{2.0, 1.0, Parameter::theta, -0.5, 0.7, 121, Form::theta},
                        Case{-1.0, 0.417, Parameter::s, 0.0, 1.0, 501, Form::s}}) {
    SCOPED_TRACE("alpha " + std::to_string(k.alpha) + " lambda " + std::to_string(k.lambda));
    const LaCurve c(k.alpha, k.lambda);
    const Rk4 rk4{.h = 1e-3};
    const auto sweep = polyline(c, k.p, k.t0, k.t1, k.n, rk4, k.form);
    const auto per_piece = polyline(c, k.p, k.t0, k.t1, k.n, PerPieceRk4{rk4}, k.form);
    const auto reference = polyline(c, k.p, k.t0, k.t1, k.n, GaussKronrod{}, k.form);
    ASSERT_EQ(sweep.size(), per_piece.size());
    double worst_rounding = 0;
    for (size_t i = 0; i < sweep.size(); ++i) {
      const auto z = sweep[i].point.position, z_old = per_piece[i].point.position, z_ref = reference[i].point.position;
      ASSERT_EQ(sweep[i].status, Status::ok) << i;
      ASSERT_EQ(sweep[i].form, per_piece[i].form);
      const double swept = std::abs(sweep[0].point.s) + std::abs(sweep[i].point.s - sweep[0].point.s);
      worst_rounding = std::max(worst_rounding, std::abs(z - z_old) / (kEps * swept + 1e-300));
      ASSERT_LE(std::abs(z - z_old), 4 * kEps * swept + 1e-300) << i;
      ASSERT_LE(std::abs(z - z_ref), 1e-10 * std::max(1.0, std::abs(z_ref))) << i;
      ASSERT_GE(sweep[i].error_estimate, std::abs(z - z_ref) - reference[i].error_estimate) << i;
    }
    std::printf("sweep vs per piece: worst %.2f eps * arc length swept\n", worst_rounding);
    EXPECT_LT(sweep.back().evaluations, per_piece.back().evaluations);
    if (k.p == Parameter::theta && k.form == Form::theta && k.t0 == 0.0)
      EXPECT_EQ(sweep.back().evaluations, 2 * 1000 + 1);  // one step per piece of width h
  }
}

// e^{iψ} of the RK4 sweeps: one sincos per base angle, a Taylor turn within 1/64 of it. Against
// long double sin/cos (64-bit significand) on nearby runs of angles, ascending and descending,
// small and large: within one ε absolute (documented 0.51 ε; sincos itself ~0.25 ε).
TEST(LaPositions, NearbyCisMatchesSincos) {
  double worst = 0;
  for (double start : {0.0, -0.5, 1.0, 3e3, -1e6}) {
    for (double step : {5e-4, -5e-4, 0.01, 1.0 / 64, 0.02, 0.3}) {
      detail::NearbyCis cis;
      for (int k = 0; k < 500; ++k) {
        const double psi = start + step * k;
        const std::complex<double> z = cis(psi);
        const long double x = psi;
        const double err = std::max(std::abs(static_cast<double>(z.real() - std::cos(x))),
                                    std::abs(static_cast<double>(z.imag() - std::sin(x))));
        worst = std::max(worst, err / kEps);
        ASSERT_LE(err, kEps) << "psi " << psi << " step " << step;
      }
    }
  }
  std::printf("NearbyCis: worst %.2f eps absolute\n", worst);
}

// R6: a position far along the curve within the turning limit used to run each of its up to 10^6
// pieces with a full budget (rk45: 6·10^6 evaluations, 1.6 s). Now one position call has the
// method's budget: the evaluation count is bounded and the status names the budget.
TEST(LaInvalidInput, DefaultBudgetsBoundPositionWork) {
  const LaCurve c(0.5, 1e-300);  // 002-style curve that is a circle to double precision: s = θ
  const auto rk45 = position_at(c, Parameter::theta, 6e7, Rk45{});
  EXPECT_EQ(rk45.status, Status::max_iterations);
  EXPECT_LE(rk45.evaluations, 2 * (6 * Rk45{}.max_steps + 1));
  const auto gk = position_at(c, Parameter::theta, 6e7, GaussKronrod{});
  EXPECT_FALSE(gk.status == Status::ok);
  EXPECT_LE(gk.evaluations, 2 * 21 * (2 * GaussKronrod{}.max_intervals + 1));
  const auto rk4 = position_at(c, Parameter::theta, 6e7, Rk4{});  // 6e10 steps needed: refused at once
  EXPECT_EQ(rk4.status, Status::max_iterations);
  EXPECT_EQ(rk4.evaluations, 0);
  EXPECT_NE(rk4.message.find("max_steps"), std::string::npos) << rk4.message;
  const auto line = polyline(c, Parameter::theta, 0.0, 6e7, 11, Rk4{});
  EXPECT_EQ(line.back().status, Status::max_iterations);
  EXPECT_EQ(line.back().evaluations, 0);
}

// Found by the short fuzz run (6.6 s under the sanitizers): the pieces of a polyline share one
// evaluation budget instead of spending one each; the points past it carry max_iterations.
TEST(LaInvalidInput, PolylineSharesOneEvaluationBudget) {
  GaussKronrod gk;
  gk.max_intervals = 500;  // the default budget behaves alike, 40 times slower
  const long budget = 21 * (2 * gk.max_intervals + 1) + 64 * 21 * 35;
  const auto line = polyline(LaCurve(0, 5e-324), Parameter::theta, 16776704, -4.61181640625, 35, gk);
  EXPECT_EQ(line.back().status, Status::max_iterations);
  EXPECT_NE(line.back().message.find("evaluation budget"), std::string::npos) << line.back().message;
  EXPECT_LE(line.back().evaluations, 2 * budget);  // the budget plus the piece that crossed it
  for (const auto& p : line) ASSERT_TRUE(std::isfinite(std::abs(p.point.position)));
  // The closed form counts series terms against its own budget (fuzz: 6.7 s under the sanitizers).
  Igf igf;
  igf.max_pieces = 1000;
  const auto closed = polyline(LaCurve(0, 2.2250738585072014e-308), Parameter::theta, 850526208, 0, 23, igf);
  EXPECT_EQ(closed.back().status, Status::max_iterations);
  EXPECT_LT(closed.back().evaluations, 2 * detail::polyline_budget(igf, 23) + 21 * (2 * GaussKronrod{}.max_intervals + 1));
  // A dense polyline of a well-behaved curve is not limited by the shared budget.
  const auto dense = polyline(LaCurve(2, 1), Parameter::theta, 0, 1, 100'000, GaussKronrod{});
  EXPECT_EQ(dense.back().status, Status::ok);
}

// RK4's observed order is 4 where the integrand is smooth (002's rows, θ ∈ [0, 1]).
TEST(LaPositions, Rk4ObservedOrderIsFour) {
  for (double alpha : {2.0, 4.0 / 3.0, -1.0}) {
    const LaCurve c(alpha, 1.0);
    const auto exact = position_at(c, Parameter::theta, 0.4, GaussKronrod{}).point.position;
    double prev = 0;
    for (double h : {0.04, 0.02, 0.01}) {
      const double err = std::abs(position_at(c, Parameter::theta, 0.4, Rk4{.h = h}, Form::theta).point.position - exact);
      if (prev > 0) {
        EXPECT_NEAR(std::log2(prev / err), 4.0, 0.15) << "alpha " << alpha << " h " << h;
      }
      prev = err;
    }
  }
}

// ---- invalid input -------------------------------------------------------------------------

template <class Fn>
void expect_input_error(Fn&& fn, const std::string& parameter, const std::string& range_text) {
  try {
    fn();
    ADD_FAILURE() << "no InputError for " << parameter;
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
    EXPECT_NE(std::string(e.what()).find(range_text), std::string::npos) << e.what();
  }
}

TEST(LaInvalidInput, ParametersOutsideTheirRanges) {
  const double nan = std::nan("");
  expect_input_error([] { LaCurve(1.0, -0.5); }, "lambda", "[0, inf)");
  expect_input_error([&] { LaCurve(1.0, nan); }, "lambda", "[0, inf)");
  expect_input_error([&] { LaCurve(nan, 1.0); }, "alpha", "finite");
  expect_input_error([] { LaCurve(std::numeric_limits<double>::infinity(), 1.0); }, "alpha", "finite");
  expect_input_error([] { LaCurve(0.5, 1.0).s_at_theta(2.0); }, "theta", "(-inf, 2)");
  expect_input_error([] { LaCurve(3.0, 1.0).rho_at_theta(-0.5); }, "theta", "(-0.5, inf)");
  expect_input_error([] { LaCurve(-1.0, 2.0).theta_at_s(0.5); }, "s", "(-inf, 0.5)");
  expect_input_error([] { LaCurve(2.0, 1.0).theta_at_s(-0.5); }, "s", "(-0.5, inf)");
  expect_input_error([&] { LaCurve(2.0, 1.0).theta_at_s(nan); }, "s", "(-0.5, inf)");
  expect_input_error([] { polyline(LaCurve(2.0, 1.0), Parameter::s, 0.0, 1.0, 1, GaussKronrod{}); }, "points", "[2, 1000000]");
  expect_input_error([] { polyline(LaCurve(2.0, 1.0), Parameter::s, 0.0, 1.0, 2'000'000, GaussKronrod{}); }, "points", "[2, 1000000]");
  // polyline checks the domain at both ends only (every point lies between them).
  expect_input_error([] { polyline(LaCurve(0.5, 1.0), Parameter::theta, 0.0, 2.0, 11, Rk4{}); }, "theta", "(-inf, 2)");
  expect_input_error([] { polyline(LaCurve(2.0, 1.0), Parameter::s, -0.5, 1.0, 11, Rk4{}); }, "s", "(-0.5, inf)");
  // ... but still rejects a point inside the domain whose ρ overflows (R1), on either integrator path.
  expect_input_error([] { polyline(LaCurve(1.0, 1.0), Parameter::theta, 0.0, 1000.0, 3, Rk4{}); }, "theta", "representable");
  expect_input_error([] { polyline(LaCurve(1.0, 1.0), Parameter::theta, 1000.0, 0.0, 3, GaussKronrod{}); }, "theta", "representable");
  // Found by fuzz_la_curve: results outside the double range inside the open domain.
  // s = (ρ^α − 1)/(αΛ) = 1.00000000000000002506e-300 (mpmath, 50 digits) is representable; the
  // old evaluation order overflowed an intermediate ((α − 1)Λ = inf) and threw, the product
  // θ·g·h underflows to 0: either would be wrong. ρ^α = e^690.8 amplifies rounding ×690.
  EXPECT_NEAR(LaCurve(1e300, 1e300).s_at_theta(1e-300) / 1.00000000000000002506e-300, 1.0, 4e-13);
  expect_input_error([] { LaCurve(0, 7.95).theta_at_s(std::numeric_limits<double>::max()); }, "s", "representable");
  expect_input_error([] { LaCurve(1, std::numeric_limits<double>::max()).rho_at_theta(2); }, "theta", "representable");
  // Turning beyond what the quadrature pieces can resolve (was: status ok, |C| wrong by 1e150).
  expect_input_error([] { position_at(LaCurve(2.0, 1.0), Parameter::s, 1e300, GaussKronrod{}); }, "theta", "turning");
  expect_input_error([] { position_at(LaCurve(0.5, 1.0), Parameter::theta, 5.0, GaussKronrod{}); }, "theta", "(-inf, 2)");
  // ρ overflows although θ is inside the domain: an error, never inf/NaN.
  expect_input_error([] { LaCurve(1.0, 1.0).frame_at(Parameter::theta, 800.0); }, "theta", "representable");
  expect_input_error([] { parse_form("arc"); }, "form", "theta, s, auto");
  expect_input_error([] { make_quadrature("euler"); }, "integrator", "valid:");
}

TEST(LaInvalidInput, NoNanAtTheEdgesOfTheDomain) {
  for (double alpha : {-100.0, -1.0, 0.0, 0.5, 0.99, 1.0, 1.01, 2.0, 100.0}) {
    const LaCurve c(alpha, 10.0);
    const Interval d = c.theta_domain();
    for (double t : {std::nextafter(d.hi, 0.0), std::nextafter(d.lo, 0.0), 1e3, -1e3}) {
      if (!d.contains(t)) continue;
      try {
        const CurvePoint p = c.frame_at(Parameter::theta, t);
        EXPECT_TRUE(std::isfinite(p.s) && std::isfinite(p.rho) && p.rho > 0 && std::isfinite(p.kappa)) << alpha << " " << t;
      } catch (const InputError& e) {
        EXPECT_EQ(e.parameter(), "theta");
      }
    }
  }
}

// Within 1e-16 .. 1e-11 of the open end of the s domain (α > 0, s → −1/(αΛ)) 1 + αΛs cancels: the
// campaign found κ off by 35 % and θ by 0.4 rad with status ok. Against mpmath with exact products.
TEST(LaCurve, FramesNearTheOpenEndOfTheDomainMatchExactProducts) {
  const auto t = test::read_reference_csv("la_curve_edge.csv");
  ASSERT_EQ(t.rows.size(), 5u);
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const LaCurve c(t.number(i, "alpha"), t.number(i, "lambda"));
    const double s = t.number(i, "s");
    SCOPED_TRACE("row " + std::to_string(i));
    const CurvePoint f = c.frame_at(s);
    EXPECT_NEAR(f.kappa, t.number(i, "kappa"), 1e-13 * t.number(i, "kappa"));
    EXPECT_NEAR(f.rho, t.number(i, "rho"), 1e-13 * t.number(i, "rho"));
    EXPECT_NEAR(f.theta, t.number(i, "theta"), 1e-13 * std::abs(t.number(i, "theta")));
    EXPECT_NEAR(c.kappa_at_s(s), f.kappa, 1e-15 * f.kappa);
    EXPECT_NEAR(c.theta_at_s(s), f.theta, 1e-15 * std::abs(f.theta));
  }
}

}  // namespace
}  // namespace lac
