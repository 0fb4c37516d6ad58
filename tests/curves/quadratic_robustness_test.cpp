// Regression tests for robustness finding R9 (docs/robustness.md, found by fuzz_quadratic):
// empty or NaN s domains, κ and θ beyond the double range inside the domain, NaN log κ.
// The inputs are the ones listed there; each must give an InputError naming the parameter.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

#include "lac/common/error.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"

namespace lac {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

QuadraticOptions hybrid_through() {
  QuadraticOptions o;
  o.inverse = special::ErfInverseMethod::hybrid_003;
  o.through_inflection = true;
  return o;
}

/// `call` must throw an InputError naming `parameter` (and nothing else).
template <class Call>
void expect_input_error(Call call, const std::string& parameter, const std::string& what) {
  try {
    call();
    ADD_FAILURE() << what << " returned instead of throwing an InputError naming " << parameter;
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << what << ": " << e.what();
  }
}

// (a) α, γ, Λ whose s domain rounds to an empty interval or NaN.
TEST(QuadraticRobustness, R9aConstructorRejectsUnrepresentableDomain) {
  expect_input_error([] { QuadraticLaCurve(2.2e-16, -1e300, 1e300); }, "gamma", "QuadraticLaCurve(2.2e-16, -1e300, 1e300)");
  expect_input_error([] { QuadraticLaCurve(1, -DBL_MAX, DBL_MAX, hybrid_through()); }, "gamma",
                     "QuadraticLaCurve(1, -DBL_MAX, DBL_MAX, {hybrid_003, through_inflection})");
  // A nearby ordinary curve is still accepted (the check is not a blanket rejection).
  const QuadraticLaCurve ok(1, -1, 1, hybrid_through());
  EXPECT_LT(ok.s_domain().lo, ok.s_domain().hi);
}

// (b) s inside the domain where κ exceeds the double range: InputError, never κ = inf.
TEST(QuadraticRobustness, R9bKappaBeyondDoubleRangeIsAnInputError) {
  const QuadraticLaCurve c1(1, 1e-300, 1), c2(1, 2.2e-16, 1e300);
  ASSERT_TRUE(c1.s_domain().contains(-7.625));
  ASSERT_TRUE(c2.s_domain().contains(-1e-8));
  expect_input_error([&] { c1.solve_kappa(-7.625); }, "s", "QuadraticLaCurve(1, 1e-300, 1).solve_kappa(-7.625)");
  expect_input_error([&] { c2.solve_kappa(-1e-8); }, "s", "QuadraticLaCurve(1, 2.2e-16, 1e300).solve_kappa(-1e-8)");
  expect_input_error([&] { c1.frame_at(-7.625); }, "s", "frame_at(-7.625)");
  expect_input_error([&] { position_at(c2, -1e-8, GaussKronrod{}); }, "s", "position_at(-1e-8)");
  // Closer to s = 0 the same curves give finite κ (the rejection is only where κ overflows).
  const KappaSolution k = c1.solve_kappa(-0.5);
  EXPECT_TRUE(std::isfinite(k.kappa));
  EXPECT_EQ(k.status, Status::ok);
}

// (c) θ beyond the double range (or 003's hybrid failing) at s inside the domain.
TEST(QuadraticRobustness, R9cThetaBeyondDoubleRangeIsAnInputError) {
  const QuadraticLaCurve c1(-1, 1e-300, 1, hybrid_through()), c2(DBL_MAX, DBL_MAX, 1);
  ASSERT_TRUE(c1.s_domain().contains(-7.375));
  ASSERT_TRUE(c2.s_domain().contains(1.0));
  expect_input_error([&] { c1.theta_at_s(-7.375); }, "s", "QuadraticLaCurve(-1, 1e-300, 1, {hybrid, through}).theta_at_s(-7.375)");
  expect_input_error([&] { c2.theta_at_s(1); }, "s", "QuadraticLaCurve(DBL_MAX, DBL_MAX, 1).theta_at_s(1)");
  expect_input_error([&] { c2.frame_at(1); }, "s", "QuadraticLaCurve(DBL_MAX, DBL_MAX, 1).frame_at(1)");
}

// (d) NaN (or infinite) log κ is an input error, not a NaN result.
TEST(QuadraticRobustness, R9dNanLogKappaIsAnInputError) {
  const QuadraticLaCurve c(-1, -0.5, 1);
  expect_input_error([&] { c.s_at_log_kappa(kNan); }, "log_kappa", "s_at_log_kappa(NaN)");
  expect_input_error([&] { c.theta_at_log_kappa(kNan); }, "log_kappa", "theta_at_log_kappa(NaN)");
  expect_input_error([&] { c.s_at_log_kappa(std::numeric_limits<double>::infinity()); }, "log_kappa",
                     "s_at_log_kappa(inf)");
}

// hermite_polyline over a range where κ underflows (κ = e^(−4660) for s > 0 here) or where one
// step turns the tangent beyond the double range: InputError naming the end, never NaN points
// (found by a random sweep of α, γ, Λ while optimising the march).
TEST(QuadraticRobustness, HermitePolylineRejectsUnrepresentableRanges) {
  const QuadraticLaCurve under(-1.32111, 0.000283721, 0.111627);
  expect_input_error([&] { hermite_polyline(under, -980, 980, 50); }, "s_to", "hermite_polyline(-980, 980)");
  const auto fine = hermite_polyline(under, -980, 0, 50);  // the κ ≥ 1 side is representable
  for (const auto& p : fine) ASSERT_TRUE(std::isfinite(p.point.position.real()) && std::isfinite(p.point.theta));
  const QuadraticLaCurve turning(-0.385347, -0.00015864, 2.66841e-05);
  ASSERT_TRUE(turning.s_domain().contains(-2.2e108));
  expect_input_error([&] { hermite_polyline(turning, -2.2e108, -2.2e106, 50); }, "s_to",
                     "hermite_polyline(-2.2e108, -2.2e106)");
}

// Found by the short fuzz run after the R9 fix: s at the reference point κ = 1 (u = 0) is 0 by
// definition, but the near-region series formed 0·inf for γ = DBL_MAX.
TEST(QuadraticRobustness, ReferencePointIsZeroForHugeGamma) {
  const QuadraticLaCurve c(-2.974609375, DBL_MAX, 1);
  EXPECT_EQ(c.s_at_log_kappa(0.0), 0.0);
  EXPECT_EQ(c.theta_at_log_kappa(0.0), 0.0);
}

// Found by the short fuzz run (a 17 s call): a polyline of n pieces gets one evaluation budget in
// total, not one per piece (R6 for quadratic curves); the points past it carry max_iterations.
TEST(QuadraticRobustness, PolylineSharesOneEvaluationBudget) {
  const QuadraticLaCurve c(-5, 1, 1.000000000000001, hybrid_through());
  GaussKronrod m;
  m.max_intervals = 500;  // the default budget behaves alike, 40 times slower
  const auto points = polyline(c, 5.048828125, 2.8396262443943004e+238, 16, m);
  ASSERT_EQ(points.size(), 16u);
  // At most the budget plus the one piece that crossed it.
  EXPECT_LE(points.back().evaluations, polyline_budget(m, 16) + 21 * (2 * m.max_intervals + 1));
  EXPECT_EQ(points.back().status, Status::max_iterations);
  EXPECT_NE(points.back().message.find("evaluation budget"), std::string::npos) << points.back().message;
  for (const auto& p : points) {
    ASSERT_TRUE(std::isfinite(p.point.position.real()) && std::isfinite(p.point.position.imag()));
  }
}

// Found by the short fuzz run: 003's hybrid inverse gives κ = 0 (log κ = −inf) where the curve has no
// inflection, and θ(κ → 0) = inf was returned as θ(s).
TEST(QuadraticRobustness, ThetaAtVanishingKappaIsAnInputError) {
  QuadraticOptions o;
  o.inverse = special::ErfInverseMethod::hybrid_003;
  const QuadraticLaCurve c(-DBL_MAX, 5e-324, 1, o);
  expect_input_error([&] { (void)c.theta_at_s(-8); }, "s", "theta_at_s(-8)");
}

// Found by the short fuzz run: far out on a curve (θ ~ 1e80 rad) a position call bisected its
// range into 64-rad pieces until the evaluation budget was spent (2.8 s for one gk-tanh-sinh call).
// A turning that needs more pieces than the budget has evaluations now fails at once.
TEST(QuadraticRobustness, TurningBeyondTheBudgetFailsAtOnce) {
  QuadraticOptions h;
  h.inverse = special::ErfInverseMethod::hybrid_003;
  const QuadraticLaCurve c(1, 26.64, 2.220446049250313e-16, h);
  for (const AnyQuadrature& m : {make_quadrature("gk-tanh-sinh"), make_quadrature("gauss-legendre")}) {
    const PositionResult r = position_at(c, -7.845709577152253e+78, m);
    EXPECT_EQ(r.status, Status::max_iterations) << r.message;
    EXPECT_NE(r.message.find("pieces of at most"), std::string::npos) << r.message;
    EXPECT_EQ(r.evaluations, 0) << r.message;
  }
  const QuadraticLaCurve d(1, 5.256633473081384e+83, 5.256633473081384e+83, h);
  const auto points = polyline(d, -0.013072967529296875, 5.256633473081384e+83, 5, GaussLegendre{});
  ASSERT_EQ(points.size(), 5u);
  EXPECT_EQ(points.back().status, Status::max_iterations) << points.back().message;
}

}  // namespace
}  // namespace lac
