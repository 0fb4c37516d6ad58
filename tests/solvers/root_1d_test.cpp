// solvers/root_1d.hpp: every method on known roots, caps, statuses, option checks and the registry.
#include <gtest/gtest.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "lac/solvers/root_1d.hpp"
#include "tests/support/solver_registry.hpp"

namespace lac {
namespace {

constexpr RootMethod kAll[] = {RootMethod::bisection, RootMethod::secant, RootMethod::toms748, RootMethod::ceres};

struct KnownRoot {
  const char* name;
  double (*f)(double);
  double lo, hi, root;
};

const KnownRoot kCases[] = {
    {"x^2-2", [](double x) { return x * x - 2; }, 0.0, 2.0, std::numbers::sqrt2},
    {"cos(x)-x", [](double x) { return std::cos(x) - x; }, 0.0, 1.0, 0.73908513321516064166},
    {"tanh(50(x-0.3))", [](double x) { return std::tanh(50 * (x - 0.3)); }, -1.0, 2.0, 0.3},
    {"x^3 (triple root)", [](double x) { return x * x * x; }, -1.0, 0.5, 0.0},
};

TEST(Root1d, EveryMethodFindsKnownRoots) {
  RootOptions o;
  o.x_rtol = 1e-15;
  o.x_atol = 1e-16;  // absolute floor for the root at 0
  for (const auto& c : kCases) {
    for (RootMethod m : kAll) {
      const RootResult r = find_root(m, c.f, make_bracket(c.f, c.lo, c.hi), o);
      SCOPED_TRACE(std::string(c.name) + " " + std::string(to_string(m)));
      ASSERT_TRUE(usable(r.status)) << r.message;
      // The triple root is ill-conditioned: |f| ≤ 1e-12 only pins x to ~ 1e-4 (Ceres stops there).
      const double tol = c.root == 0.0 ? 1e-4 : 1e-12;
      EXPECT_NEAR(r.root, c.root, tol);
      EXPECT_LE(std::abs(r.residual), 1e-12);
      EXPECT_GT(r.evaluations, 0);
      EXPECT_LE(r.iterations, o.max_iterations);
      std::printf("  %-18s %-9s root %.17g  iterations %3d  evaluations %3ld\n", c.name, std::string(to_string(m)).c_str(),
                  r.root, r.iterations, r.evaluations);
    }
  }
}

// The same sign at both ends proves nothing about roots inside (x² − 0.25 has two in [−1, 1]).
TEST(Root1d, NoSignChangeIsNotConverged) {
  auto f = [](double x) { return x * x + 1; };
  auto g = [](double x) { return x * x - 0.25; };
  for (RootMethod m : kAll) {
    RootResult r = find_root(m, f, make_bracket(f, -1.0, 1.0));
    EXPECT_EQ(r.status, Status::not_converged) << to_string(m);
    EXPECT_FALSE(r.message.empty());
    EXPECT_EQ(r.evaluations, 0);
    r = find_root(m, g, make_bracket(g, -1.0, 1.0));
    EXPECT_EQ(r.status, Status::not_converged) << to_string(m);
    EXPECT_FALSE(r.message.empty());
    EXPECT_EQ(r.evaluations, 0);
  }
}

TEST(Root1d, IterationCapIsReported) {
  auto f = [](double x) { return x - 1.0 / 3.0; };
  RootOptions o;
  o.max_iterations = 3;
  const RootResult r = bisection(f, make_bracket(f, 0.0, 1.0), o);
  EXPECT_EQ(r.status, Status::max_iterations);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_EQ(r.evaluations, 3);
  EXPECT_LE(r.hi - r.lo, 0.125 + 1e-16);
}

TEST(Root1d, NonFiniteValueIsNumericalFailure) {
  auto f = [](double x) { return x > 0.2 && x < 0.8 ? std::nan("") : x - 0.5; };
  for (RootMethod m : {RootMethod::bisection, RootMethod::secant, RootMethod::toms748}) {
    const RootResult r = find_root(m, f, make_bracket(f, 0.0, 1.0));
    EXPECT_EQ(r.status, Status::numerical_failure) << to_string(m);
  }
}

TEST(Root1d, ResidualToleranceStopsEarly) {
  auto f = [](double x) { return x - 0.3; };
  RootOptions o;
  o.f_atol = 0.05;
  const RootResult r = bisection(f, make_bracket(f, 0.0, 1.0), o);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_LE(std::abs(r.residual), 0.05);
  EXPECT_LE(r.iterations, 4);
}

TEST(Root1d, InvalidInputThrows) {
  auto f = [](double x) { return x; };
  EXPECT_THROW(bisection(f, Bracket{1.0, 0.0, 1.0, 0.0}), InputError);
  EXPECT_THROW(toms748(f, Bracket{std::nan(""), 1.0, -1.0, 1.0}), InputError);
  RootOptions o;
  o.max_iterations = 0;
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.x_rtol = -1;
  EXPECT_THROW(o.validate(), InputError);
  try {
    parse_root_method("regula");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "solver");
  }
}

TEST(Root1d, RegistryListsEveryMethodAndParsesEveryName) {
  test::expect_complete_registry(root_methods(), std::span<const RootMethod>(kAll), parse_root_method, "regula");
  EXPECT_EQ(parse_root_method("newton"), RootMethod::secant);
}

// The bracket tolerance can be Boost.Math's eps_tolerance(50): |a − b| ≤ 2^-49·min(|a|, |b|).
// Same midpoints as tools::bisect, which reports 3 more iterations (2 more when the last midpoint
// is an exact root: it leaves its loop before counting it).
TEST(Root1d, BisectionMatchesBoostBisectWithEpsTolerance) {
  double (*const functions[])(double) = {[](double x) { return std::cos(x) - x; }, [](double x) { return x * x - 2; },
                                         [](double x) { return std::exp(x) - 3; }};
  for (auto f : functions) {
    RootOptions o;
    o.x_rtol = std::ldexp(1.0, -49);
    o.x_atol = 0;
    o.max_iterations = 200 - 3;
    const RootResult r = bisection(f, make_bracket(f, 0.1, 2.0), o);
    boost::uintmax_t iterations = 200;
    const auto ends = boost::math::tools::bisect(f, 0.1, 2.0, boost::math::tools::eps_tolerance<double>(50), iterations);
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.lo, ends.first);
    EXPECT_EQ(r.hi, ends.second);
    const bool exact_root = r.residual == 0;
    EXPECT_EQ(static_cast<boost::uintmax_t>(r.iterations) + (exact_root ? 2 : 3), iterations);
  }
}

TEST(Root1d, CeresCapIsMaxIterations) {
  auto f = [](double x) { return std::tanh(50 * (x - 0.3)); };
  RootOptions o;
  o.max_iterations = 2;
  const RootResult r = ceres_root(f, make_bracket(f, -1.0, 2.0), o);
  EXPECT_EQ(r.status, Status::max_iterations) << r.message;
  EXPECT_EQ(r.message.rfind("ceres: ", 0), 0u) << r.message;
}

}  // namespace
}  // namespace lac
