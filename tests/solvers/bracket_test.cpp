// solvers/bracket.hpp: the bracket search (probe order, limits, failed probes, cap, geometric
// sequences) and the safeguarded Newton (quadratic convergence, bisection fallback, back-off, cap).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "lac/solvers/bracket.hpp"

namespace lac {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// f = x − 2.5 from 0 with unit steps: probes 0, 1, −1, 2, −2, 3; the bracket is the nearest pair.
TEST(BracketSearch, FindsNearestPairBothSidesNearestFirst) {
  std::vector<double> xs;
  auto f = [&](double x) {
    xs.push_back(x);
    return x - 2.5;
  };
  const BracketSearchResult r = search_bracket(f, 0.0, BracketSearchOptions{});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, 2.0);
  EXPECT_EQ(r.bracket.hi, 3.0);
  EXPECT_EQ(r.bracket.f_lo, -0.5);
  EXPECT_EQ(r.bracket.f_hi, 0.5);
  EXPECT_EQ(r.probes, 6);
  EXPECT_EQ(xs, (std::vector<double>{0, 1, -1, 2, -2, 3}));
}

// A probe that may not close a bracket (closes = false) is still its side's comparison point:
// f = x − 2.5 with the probe at 3 refused, then the pair [3, 4] is not a sign change and the
// search goes on to the other side's root; the sign change across 2.5 is closed only from 3.
TEST(BracketSearch, ProbeThatMayNotCloseStillMovesTheComparisonPoint) {
  auto f = [](double x) { return x < 3.5 ? x - 2.5 : x - 5.5; };  // roots at 2.5 and 5.5
  const auto closes = [](double x) { return x != 3.0; };
  BracketSearchOptions o;
  o.sides = BracketSides::up;
  const BracketSearchResult r = search_bracket(f, 0.0, o, std::nullopt, closes);
  ASSERT_TRUE(r.found);
  // 1, 2 (f < 0), 3 (f > 0, refused: comparison point 3), 4 (f < 0 against 3: closes [3, 4]).
  EXPECT_EQ(r.bracket.lo, 3.0);
  EXPECT_EQ(r.bracket.hi, 4.0);
  const BracketSearchResult plain = search_bracket(f, 0.0, o);
  ASSERT_TRUE(plain.found);
  EXPECT_EQ(plain.bracket.lo, 2.0);
  EXPECT_EQ(plain.bracket.hi, 3.0);
}

TEST(BracketSearch, FindsOnTheLowerSide) {
  auto f = [](double x) { return x + 1.5; };
  const BracketSearchResult r = search_bracket(f, 0.0, BracketSearchOptions{});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, -2.0);
  EXPECT_EQ(r.bracket.hi, -1.0);
  EXPECT_EQ(r.probes, 5);
}

// from_start: every probe compared with f(x0), the bracket [x0, probe].
TEST(BracketSearch, FromStartBracketsWithTheStart) {
  auto f = [](double x) { return x - 2.5; };
  BracketSearchOptions o;
  o.from_start = true;
  const BracketSearchResult r = search_bracket(f, 0.0, o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, 0.0);
  EXPECT_EQ(r.bracket.hi, 3.0);
}

// growth 2: distances 1, 2, 4, 8 (probes 0, 1, −1, 2, −2, 4, −4, 8).
TEST(BracketSearch, GrowingSteps) {
  auto f = [](double x) { return x - 5; };
  BracketSearchOptions o;
  o.growth = 2;
  const BracketSearchResult r = search_bracket(f, 0.0, o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, 4.0);
  EXPECT_EQ(r.bracket.hi, 8.0);
  EXPECT_EQ(r.probes, 8);
}

TEST(BracketSearch, OneSideOnly) {
  std::vector<double> xs;
  auto f = [&](double x) {
    xs.push_back(x);
    return x + 2.5;
  };
  BracketSearchOptions o;
  o.sides = BracketSides::down;
  o.step = 0.5;
  const BracketSearchResult r = search_bracket(f, 0.0, o, -7.0);  // f(x0) given (wrongly): not evaluated
  EXPECT_EQ(xs, (std::vector<double>{-0.5}));  // −7 vs f(−0.5) = 2: a sign change at once
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.probes, 1);
}

TEST(BracketSearch, NoSignChangeWithinTheCap) {
  auto f = [](double x) { return x * x + 1; };
  BracketSearchOptions o;
  o.max_probes = 7;
  const BracketSearchResult r = search_bracket(f, 0.0, o);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.probes, 7);
  EXPECT_EQ(r.last_x, -3.0);  // 0, 1, −1, 2, −2, 3, −3
}

// Probes outside the open limits are not evaluated; the search ends once both sides are out.
TEST(BracketSearch, RespectsLimits) {
  double widest = 0;
  auto f = [&](double x) {
    widest = std::max(widest, std::abs(x));
    EXPECT_TRUE(x > -3.5 && x < 5.5) << x;
    return x - 10;
  };
  BracketSearchOptions o;
  o.xmin = -3.5;
  o.xmax = 5.5;
  const BracketSearchResult r = search_bracket(f, 0.0, o);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.probes, 9);  // 0, ±1, ±2, ±3, 4, 5
  EXPECT_EQ(widest, 5.0);
  // A limit at a probe excludes it (open interval).
  o.xmax = 3;
  o.xmin = -1e300;
  auto g = [](double x) { return x - 3; };
  o.max_probes = 20;
  EXPECT_FALSE(search_bracket(g, 0.0, o).found);
}

// A failed probe (NaN) is skipped: the side keeps its last finite value.
TEST(BracketSearch, FailedProbesAreSkipped) {
  auto f = [](double x) { return x > 0.5 && x < 2.5 ? kNaN : x - 2.2; };
  const BracketSearchResult r = search_bracket(f, 0.0, BracketSearchOptions{});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, 0.0);  // not 1 or 2, where f failed
  EXPECT_EQ(r.bracket.hi, 3.0);
  EXPECT_EQ(r.probes, 6);  // 0, 1 (failed), −1, 2 (failed), −2, 3
  // A failed start is replaced by each side's first finite probe.
  auto g = [](double x) { return x == 0 ? kNaN : x - 2.5; };
  const BracketSearchResult s = search_bracket(g, 0.0, BracketSearchOptions{});
  ASSERT_TRUE(s.found);
  EXPECT_EQ(s.bracket.lo, 2.0);
  EXPECT_EQ(s.bracket.hi, 3.0);
}

TEST(BracketSearch, FailedProbeCanEndTheSearch) {
  auto f = [](double x) { return x > 0.5 && x < 2.5 ? kNaN : x - 2.2; };
  BracketSearchOptions o;
  o.stop_at_failure = true;
  const BracketSearchResult r = search_bracket(f, 0.0, o);
  EXPECT_FALSE(r.found);
  EXPECT_TRUE(r.stopped_at_failure);
  EXPECT_EQ(r.probes, 2);
  EXPECT_EQ(r.last_x, 1.0);
  EXPECT_TRUE(std::isnan(r.last_f));
  EXPECT_EQ(r.previous_x, 0.0);
}

// Geometric toward a center (001's search toward the end of the range): 1·0.5, ·0.1, ·0.01.
TEST(BracketSearch, GeometricTowardCenter) {
  std::vector<double> xs;
  auto f = [&](double x) {
    xs.push_back(x);
    return 0.01 - x;
  };
  BracketSearchOptions o;
  o.center = 0.0;
  o.step = 0.5;
  o.growth = 0.1;
  const BracketSearchResult r = search_bracket(f, 1.0, o, -1.0);
  ASSERT_TRUE(r.found);
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_EQ(xs[0], 0.5);
  EXPECT_EQ(xs[1], 0.5 * 0.1);
  EXPECT_EQ(xs[2], 0.5 * 0.1 * 0.1);
  EXPECT_EQ(r.bracket.lo, xs[2]);
  EXPECT_EQ(r.bracket.hi, xs[1]);
  EXPECT_EQ(r.probes, 3);
}

// Doubling away from the center (004's upper end of Λ): 2, 4, …, 128.
TEST(BracketSearch, DoublingAwayFromCenter) {
  auto f = [](double x) { return x - 100; };
  BracketSearchOptions o;
  o.center = 0.0;
  o.step = 2;
  o.growth = 2;
  o.max_probes = 10;
  const BracketSearchResult r = search_bracket(f, 1.0, o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, 64.0);
  EXPECT_EQ(r.bracket.hi, 128.0);
  EXPECT_EQ(r.probes, 8);  // x0 and 7 doublings
  o.max_probes = 4;
  const BracketSearchResult s = search_bracket(f, 1.0, o);
  EXPECT_FALSE(s.found);
  EXPECT_EQ(s.last_x, 8.0);
  EXPECT_EQ(s.previous_x, 4.0);
  EXPECT_EQ(s.previous_f, -96.0);
}

TEST(BracketSearch, ExactZeroAtStart) {
  auto f = [](double x) { return x - 1; };
  const BracketSearchResult r = search_bracket(f, 1.0, BracketSearchOptions{});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.bracket.lo, 1.0);
  EXPECT_EQ(r.bracket.hi, 1.0);
  EXPECT_EQ(r.probes, 1);
}

TEST(BracketSearch, InvalidOptionsThrow) {
  auto f = [](double x) { return x; };
  BracketSearchOptions o;
  o.step = 0;
  EXPECT_THROW(search_bracket(f, 1.0, o), InputError);
  o = {};
  o.growth = 0.5;  // outward steps must not shrink
  EXPECT_THROW(search_bracket(f, 1.0, o), InputError);
  o = {};
  o.max_probes = 0;
  EXPECT_THROW(search_bracket(f, 1.0, o), InputError);
  o = {};
  o.xmin = 2;
  o.xmax = 1;
  EXPECT_THROW(search_bracket(f, 1.0, o), InputError);
  EXPECT_THROW(search_bracket(f, kNaN, BracketSearchOptions{}), InputError);
}

// Newton on x² − 2 from 1: the error squares each step (e_{k+1} ≈ e_k²/(2√2)).
TEST(SafeguardedNewton, ConvergesQuadraticallyOnSmoothRoot) {
  std::vector<double> xs;
  auto fd = [&](double x) {
    xs.push_back(x);
    return Newton1dSample{x * x - 2, 2 * x};
  };
  Newton1dOptions o;
  o.f_atol = 1e-15;
  const Newton1dResult r = safeguarded_newton(fd, 1.0, o);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_NEAR(r.x, std::numbers::sqrt2, 1e-15);
  EXPECT_LE(std::abs(r.f), 1e-15);
  EXPECT_EQ(r.evaluations, static_cast<long>(xs.size()));
  EXPECT_LE(r.iterations, 7);  // bisection would need ~50
  for (size_t k = 1; k + 1 < xs.size(); ++k) {
    const double e0 = std::abs(xs[k] - std::numbers::sqrt2), e1 = std::abs(xs[k + 1] - std::numbers::sqrt2);
    if (e0 > 1e-7) {
      EXPECT_LE(e1, 0.5 * e0 * e0 + 1e-16) << k;
    }
  }
}

// A derivative 1e6 times too small sends every Newton step out of the bracket: bisection keeps
// the iterates inside and still converges.
TEST(SafeguardedNewton, BisectsOnBadDerivative) {
  std::vector<double> xs;
  auto fd = [&](double x) {
    xs.push_back(x);
    return Newton1dSample{x - 0.3, 1e-6};
  };
  Newton1dOptions o;
  o.f_atol = 1e-12;
  o.max_iterations = 100;
  o.bracket = Bracket{0.0, 1.0, -0.3, 0.7};
  const Newton1dResult r = safeguarded_newton(fd, 0.5, o);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_NEAR(r.x, 0.3, 1e-12);
  for (double x : xs) EXPECT_TRUE(x > 0 && x < 1) << x;
  EXPECT_GE(r.iterations, 30);  // halvings of [0, 1] down to 1e-12
  EXPECT_LE(r.iterations, 45);
  // The same with a derivative of the wrong sign: Newton steps go away from the root.
  auto wrong = [](double x) { return Newton1dSample{x - 0.3, -1.0}; };
  const Newton1dResult w = safeguarded_newton(wrong, 0.5, o);
  ASSERT_EQ(w.status, Status::ok);
  EXPECT_NEAR(w.x, 0.3, 1e-12);
}

// Without a bracket given, two iterates of opposite signs form one.
TEST(SafeguardedNewton, FormsBracketFromIterates) {
  auto fd = [](double x) { return Newton1dSample{std::atan(x - 1), 1 / (1 + (x - 1) * (x - 1))}; };
  Newton1dOptions o;
  o.f_atol = 1e-14;
  const Newton1dResult r = safeguarded_newton(fd, 3.0, o);  // plain Newton diverges on atan from |x − 1| > 1.39
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_NEAR(r.x, 1.0, 1e-13);
  EXPECT_TRUE(r.bracketed);
}

TEST(SafeguardedNewton, RespectsTheCap) {
  int calls = 0;
  auto fd = [&](double x) {
    ++calls;
    return Newton1dSample{x - 1.0 / 3.0, 1e-9};
  };
  Newton1dOptions o;
  o.f_atol = 1e-15;
  o.max_iterations = 5;
  o.bracket = Bracket{0.0, 1.0, -1.0 / 3.0, 2.0 / 3.0};
  const Newton1dResult r = safeguarded_newton(fd, 0.5, o);
  EXPECT_EQ(r.status, Status::max_iterations);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_EQ(r.evaluations, 5);
  EXPECT_EQ(calls, 5);
  EXPECT_TRUE(r.bracketed);
  EXPECT_LE(r.hi - r.lo, 1.0 / 8);
}

// A failed evaluation (outside f's domain x ≤ 1) backs off halfway to the previous iterate.
TEST(SafeguardedNewton, BacksOffFromFailedEvaluations) {
  int failed = 0;
  auto fd = [&](double x) {
    if (x > 1) {
      ++failed;
      return Newton1dSample{};
    }
    return Newton1dSample{x * x - 0.81, 2 * x};
  };
  Newton1dOptions o;
  o.f_atol = 1e-15;
  const Newton1dResult r = safeguarded_newton(fd, 0.1, o);  // first step to 4.1, then 2.1, 1.1, 0.6
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_NEAR(r.x, 0.9, 1e-15);
  EXPECT_EQ(failed, 3);
  // A failed start has nowhere to back off to.
  const Newton1dResult s = safeguarded_newton(fd, 2.0, o);
  EXPECT_EQ(s.status, Status::not_converged);
  EXPECT_EQ(s.iterations, 1);
  EXPECT_TRUE(std::isnan(s.x));
  // The domain given as a limit instead: the step goes halfway to it, nothing fails.
  failed = 0;
  o.xmax = 1;
  const Newton1dResult t = safeguarded_newton(fd, 0.1, o);
  ASSERT_EQ(t.status, Status::ok);
  EXPECT_NEAR(t.x, 0.9, 1e-15);
  EXPECT_EQ(failed, 0);
}

// stop_at_failure: a failed evaluation ends the iteration instead of backing off.
TEST(SafeguardedNewton, FailureCanEndTheIteration) {
  int calls = 0;
  auto fd = [&](double x) {
    ++calls;
    return x > 1 ? Newton1dSample{} : Newton1dSample{x * x - 0.81, 2 * x};
  };
  Newton1dOptions o;
  o.f_atol = 1e-15;
  o.stop_at_failure = true;
  const Newton1dResult r = safeguarded_newton(fd, 0.1, o);  // the first step lands at 4.1
  EXPECT_EQ(r.status, Status::not_converged);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_EQ(r.x, 0.1);  // the best point evaluated
}

// form_bracket = false: iterates of opposite signs do not confine the next steps.
TEST(SafeguardedNewton, IteratesNeedNotFormBracket) {
  std::vector<double> xs;
  auto fd = [&](double x) {
    xs.push_back(x);
    return Newton1dSample{x - 3, 1.0};
  };
  // A step rule that first jumps from 0 past the root to 5 (f > 0) and then to −1 (f < 0).
  const auto rule = [&](double x, const Newton1dSample& s, bool) {
    if (xs.size() == 1) return 5.0;
    if (xs.size() == 2) return -1.0;
    return x - s.f / s.df;
  };
  Newton1dOptions o;
  o.f_atol = 1e-15;
  const Newton1dResult with = safeguarded_newton(fd, 0.0, o, rule);
  ASSERT_EQ(with.status, Status::ok);
  EXPECT_EQ(xs[2], 2.5);  // −1 leaves the bracket [0, 5]: its midpoint instead
  EXPECT_TRUE(with.bracketed);
  xs.clear();
  o.form_bracket = false;
  const Newton1dResult without = safeguarded_newton(fd, 0.0, o, rule);
  ASSERT_EQ(without.status, Status::ok);
  EXPECT_EQ(xs[2], -1.0);
  EXPECT_FALSE(without.bracketed);
}

// A custom step rule (here: half Newton steps) still converges, and a point that is not
// acceptable is not a root even with f = 0.
TEST(SafeguardedNewton, StepRuleAndAcceptability) {
  auto fd = [](double x) { return Newton1dSample{x - 2, 1.0, x > 0}; };
  Newton1dOptions o;
  o.f_atol = 1e-12;
  o.max_iterations = 100;
  const auto half = [](double x, const Newton1dSample& s, bool) { return x - 0.5 * s.f / s.df; };
  const Newton1dResult r = safeguarded_newton(fd, 0.0, o, half);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_NEAR(r.x, 2.0, 1e-12);
  EXPECT_GE(r.iterations, 30);  // linear: the error halves per step
  auto never = [](double x) { return Newton1dSample{x - 2, 1.0, false}; };
  const Newton1dResult n = safeguarded_newton(never, 0.0, o);
  EXPECT_NE(n.status, Status::ok);
  EXPECT_TRUE(std::isnan(n.x));
}

// Convergence by the step: x tolerance max(x_atol, x_rtol·|x|).
TEST(SafeguardedNewton, StepTolerance) {
  auto fd = [](double x) { return Newton1dSample{std::exp(x) - 10, std::exp(x)}; };
  Newton1dOptions o;
  o.x_rtol = 1e-10;
  const Newton1dResult r = safeguarded_newton(fd, 0.0, o);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_NEAR(r.x, std::log(10.0), 1e-12);
  Newton1dOptions bad;
  bad.max_iterations = 0;
  EXPECT_THROW(safeguarded_newton(fd, 0.0, bad), InputError);
}

}  // namespace
}  // namespace lac
