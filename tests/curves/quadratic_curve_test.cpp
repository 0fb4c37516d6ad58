// Quadratic LA curve (003, docs/math.md §4): closed forms and κ(s) against the mpmath reference
// (tests/reference/quadratic.py → quadratic.csv), identities, limits, bad input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Tolerances (one table). Relative errors unless said otherwise.
constexpr double kBoundsTol = 1e-14;         // s(κ→0), s(κ→∞) in erfcx form
constexpr double kForwardTol = 1e-13;        // s(u), θ(u); plus the conditioning term below
constexpr double kInverseTol = 1e-13;        // |Δ log κ| = relative error of κ(s); plus conditioning
constexpr double kRoundTripTol = 1e-13;      // κ(s(κ)) relative; plus conditioning
constexpr double kConditioningFactor = 8.0;  // × eps × (condition number of the problem)

double parse(const std::string& text) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  return std::strtod(text.c_str(), nullptr);
}

// Inherent error of s(u) in double: the terms it is formed from have size ~|s| + |u|/Λ·e^|E|
// at most; for u (given s) the same absolute error in s is multiplied by |du/ds| = Λ e^(−E).
// These are the problem's condition numbers, not the method's.
double s_condition(const QuadraticLaCurve& c, double u) {
  return std::abs(u) * std::abs(c.gamma() * u - c.alpha()) + std::abs(c.gamma()) * u * u + 1.0;
}

// Size of the constant term in the closed form of s (docs/math.md §4), which sets the absolute
// rounding error of s: D(x0)/(√γ Λ) for γ > 0, (√π/2) erfcx(|y0|)/(√−γ Λ) for γ < 0, 1/|αΛ| for γ = 0.
double constant_term_of_s(const QuadraticLaCurve& c) {
  const double a = c.alpha(), g = c.gamma(), l = c.lambda();
  if (g > 0) return std::abs(special::dawson(-a / (2 * std::sqrt(g)))) / (std::sqrt(g) * l);
  if (g < 0) return std::sqrt(M_PI) / 2 * special::erfcx(std::abs(a) / (2 * std::sqrt(-g))) / (std::sqrt(-g) * l);
  return a == 0 ? 0.0 : 1.0 / std::abs(a * l);
}

struct Worst {
  double error = 0;
  std::string where;
  void update(double e, const std::string& w) {
    if (!(e <= error)) {
      error = e;
      where = w;
    }
  }
};

std::string label(double a, double g, double l, double x) {
  return "alpha=" + format_number(a) + " gamma=" + format_number(g) + " lambda=" + format_number(l) + " x=" + format_number(x);
}

TEST(QuadraticCurve, MatchesMpmathReference) {
  const auto t = test::read_reference_csv("quadratic.csv");
  const size_t ca = t.column("alpha"), cg = t.column("gamma"), cl = t.column("lambda"), ck = t.column("kind"),
               cx = t.column("x"), c1 = t.column("v1"), c2 = t.column("v2");
  Worst bounds, forward_s, forward_theta, inverse_u, inverse_theta;
  int n_inverse = 0, n_forward = 0, n_ill = 0;
  for (const auto& row : t.rows) {
    const double a = parse(row[ca]), g = parse(row[cg]), l = parse(row[cl]), x = parse(row[cx]);
    const double v1 = parse(row[c1]), v2 = parse(row[c2]);
    const QuadraticLaCurve c(a, g, l);
    const std::string where = label(a, g, l, x);
    if (row[ck] == "bounds") {
      for (auto [ours, ref] : {std::pair{c.s_at_infinite_kappa(), v1}, std::pair{c.s_at_zero_kappa(), v2}}) {
        if (std::isinf(ref)) {
          EXPECT_EQ(ours, ref) << where;
          continue;
        }
        const double e = std::abs(ours - ref) / std::abs(ref);
        bounds.update(e, where);
        // erfcx(−|y0|) ≈ 2e^(y0²) carries the rounding of y0² (condition number 2y0²).
        const double y0_squared = g < 0 ? a * a / (-4.0 * g) : 0.0;
        EXPECT_LE(e, kBoundsTol + 2.0 * kEps * y0_squared) << where;
      }
    } else if (row[ck] == "forward") {
      ++n_forward;
      const double cond = kConditioningFactor * kEps * s_condition(c, x);
      const double es = std::abs(c.s_at_log_kappa(x) - v1) / std::abs(v1);
      const double et = std::abs(c.theta_at_log_kappa(x) - v2) / std::abs(v2);
      forward_s.update(es, where);
      forward_theta.update(et, where);
      EXPECT_LE(es, kForwardTol + cond) << where;
      EXPECT_LE(et, kForwardTol + cond) << where;
    } else if (row[ck] == "inverse") {  // "position" rows: quadratic_position_test.cpp
      ++n_inverse;
      const auto k = c.solve_log_kappa(x);
      ASSERT_EQ(k.status, Status::ok) << where;
      // Condition number of u(s): |s du/ds| = |s| Λ e^(−E(u)), times the relative size of s's terms.
      const double e_u = (g * v1 - a) * v1;
      const double cond = kConditioningFactor * kEps * std::abs(x) * l * std::exp(-e_u) * s_condition(c, v1);
      // Backward error always; forward error where κ is determined by a double s (see the
      // round-trip test: on a plateau of s(u) a whole range of κ maps to the same double s).
      const double back = std::abs(c.s_at_log_kappa(k.log_kappa) - x);
      EXPECT_LE(back, kConditioningFactor * kEps * s_condition(c, v1) * (std::abs(x) + constant_term_of_s(c))) << where;
      if (cond >= kInverseTol) {
        ++n_ill;
        continue;
      }
      const double eu = std::abs(k.log_kappa - v1);
      inverse_u.update(eu, where);
      EXPECT_LE(eu, kInverseTol) << where << " u=" << v1;
      const double et = std::abs(c.theta_at_s(x) - v2) / std::abs(v2);
      inverse_theta.update(et, where);
      EXPECT_LE(et, kInverseTol) << where;
    }
  }
  std::cout << "  bounds: worst relative error " << bounds.error << " (" << bounds.where << ")\n"
            << "  s(u), " << n_forward << " cases: worst " << forward_s.error << " (" << forward_s.where << ")\n"
            << "  theta(u): worst " << forward_theta.error << " (" << forward_theta.where << ")\n"
            << "  log kappa(s), " << n_inverse << " cases (" << n_ill << " ill-conditioned: backward error only): worst |error| " << inverse_u.error << " (" << inverse_u.where
            << ")\n"
            << "  theta(s): worst relative " << inverse_theta.error << " (" << inverse_theta.where << ")\n";
}

const double kSets[][3] = {{-1, -0.5, 1}, {-1, 0.5, 1}, {0, -1, 1}, {3, -1, 1}, {1, -0.5, 1}, {1, 1, 1},
                           {-0.2, -0.5, 0.5}, {1, -30, 0.5}, {1, 30, 0.5}, {2, 1e-6, 1}, {2, -1e-6, 1},
                           {40, -1, 1}, {-60, -1, 1}, {-100, 1, 1}, {100, 1, 1}, {0.5, 2, 1e-3}, {0.5, 2, 1e3}};

TEST(QuadraticCurve, KappaOfSOfKappaRoundTrip) {
  Worst worst;
  int cases = 0, max_iterations = 0, ill_conditioned = 0;
  for (const auto& p : kSets) {
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    for (double u = -40; u <= 40; u += 0.37) {
      const double s = c.s_at_log_kappa(u);
      if (!c.s_domain().contains(s)) continue;  // s rounded onto a bound
      const auto k = c.solve_log_kappa(s);
      ASSERT_EQ(k.status, Status::ok);
      max_iterations = std::max(max_iterations, k.iterations);
      const double e_u = (p[1] * u - p[0]) * u;
      const double cond = kConditioningFactor * kEps * std::abs(s) * p[2] * std::exp(-e_u) * s_condition(c, u);
      const double err = std::abs(k.log_kappa - u);
      ++cases;
      // Backward error, always: s(κ(s)) reproduces s to rounding of its terms.
      const double back = std::abs(c.s_at_log_kappa(k.log_kappa) - s);
      const double s_scale = std::abs(s) + constant_term_of_s(c);
      EXPECT_LE(back, kConditioningFactor * kEps * s_condition(c, u) * s_scale) << label(p[0], p[1], p[2], u);
      // Forward error where the problem is well conditioned (first-order bound < 1e-13). Where
      // s(κ) is flat to rounding (|ds/du| = e^E/Λ tiny: a plateau of s), κ is not determined
      // by a double s at all; those cases are counted, and only the backward error applies.
      if (cond >= kRoundTripTol) {
        ++ill_conditioned;
        continue;
      }
      worst.update(err, label(p[0], p[1], p[2], u));
      EXPECT_LE(err, kRoundTripTol) << label(p[0], p[1], p[2], u);
    }
  }
  std::cout << "  round trip: " << cases << " cases (" << ill_conditioned
            << " ill-conditioned: backward error only), worst |log kappa error| " << worst.error << " (" << worst.where
            << "), max iterations " << max_iterations << "\n";
  EXPECT_LE(max_iterations, 12);
}

TEST(QuadraticCurve, DsDkappaIdentityAndLcgParabola) {
  for (const auto& p : kSets) {
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    for (double u : {-2.0, -0.5, 0.0, 0.3, 1.7}) {
      const double kappa = std::exp(u);
      const double ds = c.ds_dkappa(kappa);
      // docs/math.md §4: ds/dκ = −κ^(−α + γ log κ − 1)/Λ, here by pow directly.
      const double direct = -std::pow(kappa, -p[0] + p[1] * u - 1.0) / p[2];
      EXPECT_NEAR(ds / direct, 1.0, 1e-13) << label(p[0], p[1], p[2], u);
      // Central difference of the closed form s(κ) (step h κ, h = 1e-5: error ~1e-9 relative).
      // Central difference of the closed form s(κ), step h = 1e-6 κ (truncation ~1e-10 relative);
      // the rounding of s (eps·|s|) over 2h·|ds/dκ| is added: it dominates where s is flat.
      const double h = 1e-6 * kappa;
      const double sp = c.s_at_kappa(kappa + h), sm = c.s_at_kappa(kappa - h);
      const double fd = (sp - sm) / (2 * h);
      const double rounding = 4.0 * kEps * std::max(std::abs(sp), std::abs(sm)) / (2 * h * std::abs(ds));
      EXPECT_NEAR(fd / ds, 1.0, 1e-8 + rounding) << label(p[0], p[1], p[2], u);
      // LCG: log(ρ ds/dρ) = log(−κ ds/dκ) is the parabola at log ρ = −u.
      EXPECT_NEAR(std::log(-kappa * ds), c.lcg(-u), 1e-12 * std::max(1.0, std::abs(c.lcg(-u))));
    }
  }
}

TEST(QuadraticCurve, GammaToZeroConvergesToLaCurve) {
  for (double alpha : {-1.0, 0.0, 0.5, 1.0, 2.0}) {
    const LaCurve la(alpha, 1.0);
    const double s_max = std::min(0.9 * la.s_domain().hi, 2.0);
    const double s_min = std::max(0.9 * la.s_domain().lo, -2.0);
    double previous = std::numeric_limits<double>::infinity();
    for (double g : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      double diff = 0;
      for (double sign : {1.0, -1.0}) {
        const QuadraticLaCurve q(alpha, sign * g, 1.0);
        for (double s = s_min; s <= s_max; s += (s_max - s_min) / 17) {
          if (!q.s_domain().contains(s)) continue;
          diff = std::max(diff, std::abs(q.kappa_at_s(s) / la.kappa_at_s(s) - 1.0));
        }
      }
      EXPECT_LE(diff, 200.0 * g + 1e-13) << "alpha " << alpha << " gamma " << g;  // O(γ)
      EXPECT_LE(diff, previous + 1e-13);
      previous = diff;
    }
  }
  // γ = 0 is the LA curve itself (la_curve.hpp), bounds included.
  const QuadraticLaCurve q0(-1.0, 0.0, 2.0);
  const LaCurve la(-1.0, 2.0);
  EXPECT_DOUBLE_EQ(q0.s_at_zero_kappa(), la.s_domain().hi);
  EXPECT_NEAR(q0.kappa_at_s(0.3), la.kappa_at_s(0.3), 1e-15);
}

TEST(QuadraticCurve, BoundsAreTheLimitsOfS) {
  for (const auto& p : kSets) {
    const QuadraticLaCurve c(p[0], p[1], p[2]);
    if (p[1] >= 0) {
      EXPECT_TRUE(std::isinf(c.s_at_zero_kappa()) || p[1] == 0);
      continue;
    }
    // For γ < 0, e^(γu²) makes s(u) reach its limits to double precision by |u| ~ 40/√−γ + |α|/|γ|.
    const double far = 40.0 / std::sqrt(-p[1]) + std::abs(p[0] / p[1]);
    if (std::isfinite(c.s_at_infinite_kappa()))
      EXPECT_NEAR(c.s_at_log_kappa(far), c.s_at_infinite_kappa(), 1e-14 * std::abs(c.s_at_infinite_kappa()));
    if (std::isfinite(c.s_at_zero_kappa()))
      EXPECT_NEAR(c.s_at_log_kappa(-far), c.s_at_zero_kappa(), 1e-14 * std::abs(c.s_at_zero_kappa()));
  }
}

TEST(QuadraticCurve, InflectionContinuationIsPointSymmetric) {
  QuadraticOptions o;
  o.through_inflection = true;
  const QuadraticLaCurve c(-0.2, -0.5, 1.0, o);
  const double si = c.s_at_zero_kappa();
  ASSERT_TRUE(c.has_inflection());
  EXPECT_EQ(c.kappa_at_s(si), 0.0);
  for (double t : {1e-6, 0.01, 0.3, 1.0}) {
    EXPECT_NEAR(c.kappa_at_s(si + t), -c.kappa_at_s(si - t), 1e-13 * std::abs(c.kappa_at_s(si - t)));
    EXPECT_NEAR(c.theta_at_s(si + t), c.theta_at_s(si - t), 1e-13);  // tangent even about s_i
  }
  const QuadraticLaCurve open(-0.2, -0.5, 1.0);
  EXPECT_THROW(open.kappa_at_s(si), InputError);
  EXPECT_THROW(open.kappa_at_s(si + 0.1), InputError);
}

TEST(QuadraticCurve, Hybrid003MatchesInsideItsRangeAndFailsOutside) {
  QuadraticOptions h;
  h.inverse = special::ErfInverseMethod::hybrid_003;
  for (const auto& p : {std::array{-1.0, -0.5, 1.0}, std::array{1.0, 1.0, 1.0}, std::array{0.0, -1.0, 1.0}}) {
    const QuadraticLaCurve ours(p[0], p[1], p[2]), hybrid(p[0], p[1], p[2], h);
    for (double u : {-1.0, -0.3, 0.2, 1.0}) {
      const double s = ours.s_at_log_kappa(u);
      const auto k = hybrid.solve_kappa(s);
      EXPECT_EQ(k.status, Status::ok);
      EXPECT_NEAR(k.log_kappa, u, 1e-9) << label(p[0], p[1], p[2], u);
    }
  }
  // α = −100, γ = 1: e^(α²/(4γ)) = e^2500 overflows in 003's unscaled formula; ours is fine.
  const QuadraticLaCurve ours(-100, 1, 1), hybrid(-100, 1, 1, h);
  const double s = ours.s_at_log_kappa(0.2);  // ds/du = −e^(u² + 100u): well conditioned for u ≳ −0.1
  EXPECT_NEAR(ours.solve_kappa(s).log_kappa, 0.2, 1e-13);
  EXPECT_NE(hybrid.solve_kappa(s).status, Status::ok);
}

TEST(QuadraticCurve, BadInputIsAnInputError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(QuadraticLaCurve(1, 1, 0), InputError);
  EXPECT_THROW(QuadraticLaCurve(1, 1, -1), InputError);
  EXPECT_THROW(QuadraticLaCurve(nan, 1, 1), InputError);
  EXPECT_THROW(QuadraticLaCurve(1, nan, 1), InputError);
  EXPECT_THROW(QuadraticLaCurve(1, 1, std::numeric_limits<double>::infinity()), InputError);
  QuadraticOptions bad;
  bad.max_iterations = 0;
  EXPECT_THROW(QuadraticLaCurve(1, 1, 1, bad), InputError);
  const QuadraticLaCurve c(-1, -1, 1);
  EXPECT_THROW(c.kappa_at_s(nan), InputError);
  EXPECT_THROW(c.kappa_at_s(c.s_at_zero_kappa()), InputError);
  EXPECT_THROW(c.kappa_at_s(c.s_at_infinite_kappa() - 1e-3), InputError);
  EXPECT_THROW(c.s_at_kappa(0.0), InputError);
  EXPECT_THROW(c.s_at_kappa(-1.0), InputError);
  try {
    c.kappa_at_s(10.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "s");
    EXPECT_NE(std::string(e.what()).find("outside its valid range ("), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lac
