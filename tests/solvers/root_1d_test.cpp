// solvers/root_1d.hpp: every method on known roots, caps, statuses and option checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lac/solvers/root_1d.hpp"

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

TEST(Root1d, NoSignChangeIsNoSolution) {
  auto f = [](double x) { return x * x + 1; };
  for (RootMethod m : kAll) {
    const RootResult r = find_root(m, f, make_bracket(f, -1.0, 1.0));
    EXPECT_EQ(r.status, Status::no_solution) << to_string(m);
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
  EXPECT_EQ(parse_root_method("newton"), RootMethod::secant);
  for (auto name : root_method_names()) EXPECT_EQ(to_string(parse_root_method(name)), name);
}

}  // namespace
}  // namespace lac
