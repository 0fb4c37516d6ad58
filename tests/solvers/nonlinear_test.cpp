// solvers/nonlinear.hpp: every method on small systems (Rosenbrock, circle–line) with undefined
// regions, the registry, the statuses (not_converged, max_iterations, numerical_failure) and option
// checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/solvers/nonlinear.hpp"
#include "tests/support/solver_registry.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using Vec2 = Eigen::Vector2d;
constexpr NonlinearMethod kAll[] = {NonlinearMethod::newton, NonlinearMethod::ceres, NonlinearMethod::simplex};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rosenbrock as residuals (10 (y − x²), 1 − x), root (1, 1); undefined for x < −0.5 (as a curve
// that never meets the cone is undefined).
const NonlinearResidual kRosenbrock{2, [](ConstVectorMap x, VectorMap r) {
                                      if (x[0] < -0.5) return false;
                                      r << 10 * (x[1] - x[0] * x[0]), 1 - x[0];
                                      return true;
                                    }};

// Roots of (x² + y² − 4, x − y) with x ≥ 0: (√2, √2). Undefined for y > 3.
const NonlinearResidual kCircleLine{2, [](ConstVectorMap x, VectorMap r) {
                                      if (x[1] > 3) return false;
                                      r << x[0] * x[0] + x[1] * x[1] - 4, x[0] - x[1];
                                      return true;
                                    }};

// (x² + 1, y): no root; ‖r‖ ≥ 1 with its minimum at (0, 0).
const NonlinearResidual kNoRoot{2, [](ConstVectorMap x, VectorMap r) {
                                  r << x[0] * x[0] + 1, x[1];
                                  return true;
                                }};

NonlinearResult solve(NonlinearMethod m, const NonlinearResidual& r, const Vec2& x0, const NonlinearOptions& o = {}) {
  return solve_nonlinear(m, r, x0, o);
}

TEST(Nonlinear, EveryMethodSolvesRosenbrockAcrossAnUndefinedRegion) {
  NonlinearOptions o;
  o.residual_tolerance = 1e-10;
  o.simplex.initial_step = 0.5;
  for (NonlinearMethod m : kAll) {
    SCOPED_TRACE(std::string(to_string(m)));
    const NonlinearResult r = solve(m, kRosenbrock, Vec2(-0.4, 1.5), o);  // the simplex starts at the edge
    ASSERT_EQ(r.status, Status::ok) << r.message;
    EXPECT_NEAR(r.x[0], 1, 1e-9);
    EXPECT_NEAR(r.x[1], 1, 1e-9);
    EXPECT_LE(r.residual_norm, 1e-10);
    EXPECT_EQ(r.merit, r.residual_norm);
    ASSERT_EQ(r.residual.size(), 2);
    EXPECT_EQ(r.residual.norm(), r.residual_norm);
    EXPECT_GT(r.evaluations, r.iterations);
    EXPECT_TRUE(r.message.empty());
  }
}

TEST(Nonlinear, EveryMethodSolvesTheCircleLineAndBacktracksOutOfUndefinedPoints) {
  NonlinearOptions o;
  o.residual_tolerance = 1e-14;
  o.simplex.x_tolerance = 1e-16;
  for (NonlinearMethod m : kAll) {
    SCOPED_TRACE(std::string(to_string(m)));
    const NonlinearResult r = solve(m, kCircleLine, Vec2(0.3, 2.9), o);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    EXPECT_NEAR(r.x[0], std::sqrt(2.0), 1e-13);
    EXPECT_NEAR(r.x[1], std::sqrt(2.0), 1e-13);
    EXPECT_LE(r.residual_norm, 1e-14);
    if (m == NonlinearMethod::newton) {
      EXPECT_LE(r.iterations, 12);
    }
  }
  // A non-finite residual inside the domain counts as undefined, not as a failure.
  const NonlinearResidual nan_above{2, [](ConstVectorMap x, VectorMap r) {
                                      r << x[0] * x[0] + x[1] * x[1] - 4, x[0] - x[1];
                                      if (x[1] > 3) r[0] = kNaN;
                                      return true;
                                    }};
  for (NonlinearMethod m : kAll) EXPECT_EQ(solve(m, nan_above, Vec2(0.3, 2.9), o).status, Status::ok) << to_string(m);
}

TEST(Nonlinear, MoreResidualsThanUnknowns) {
  // (x − 1, y − 2, x + y − 3): consistent, three residuals for two unknowns.
  const NonlinearResidual over{3, [](ConstVectorMap x, VectorMap r) {
                                 r << x[0] - 1, x[1] - 2, x[0] + x[1] - 3;
                                 return true;
                               }};
  for (NonlinearMethod m : {NonlinearMethod::ceres, NonlinearMethod::simplex}) {
    const NonlinearResult r = solve(m, over, Vec2(0, 0));
    ASSERT_EQ(r.status, Status::ok) << to_string(m) << ": " << r.message;
    EXPECT_EQ(r.residual.size(), 3);
    EXPECT_NEAR(r.x[0], 1, 1e-11);
    EXPECT_NEAR(r.x[1], 2, 1e-11);
  }
  EXPECT_THROW(solve(NonlinearMethod::newton, over, Vec2(0, 0)), InputError);
}

TEST(Nonlinear, DynamicSizeSystem) {
  // x_i² = i + 1 for five unknowns (beyond the fixed-size instantiations).
  const NonlinearResidual squares{5, [](ConstVectorMap x, VectorMap r) {
                                    for (int i = 0; i < 5; ++i) r[i] = x[i] * x[i] - (i + 1);
                                    return true;
                                  }};
  NonlinearOptions o;
  o.residual_tolerance = 1e-9;
  o.simplex.max_evaluations = 20000;
  o.simplex.max_iterations = 20000;
  for (NonlinearMethod m : kAll) {
    const NonlinearResult r = solve_nonlinear(m, squares, Eigen::VectorXd::Ones(5), o);
    ASSERT_EQ(r.status, Status::ok) << to_string(m) << ": " << r.message;
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(r.x[i], std::sqrt(i + 1.0), 1e-9) << to_string(m);
  }
}

TEST(Nonlinear, SimplexMinimizesACallersMeritWithoutEvaluatingTheResidual) {
  long residual_calls = 0;
  const NonlinearResidual counted{2, [&](ConstVectorMap x, VectorMap r) {
                                    ++residual_calls;
                                    r << x[0] - 1, x[1] + 2;
                                    return true;
                                  }};
  NonlinearOptions o;
  o.residual_tolerance = 1e-9;
  // the angle between (cos a, sin a) and (cos 0.7, sin 0.7) at a = x0 + x1
  o.simplex.merit = [](ConstVectorMap x) -> std::optional<double> { return std::abs(std::remainder(x[0] + x[1] - 0.7, 2 * std::numbers::pi)); };
  const NonlinearResult r = solve(NonlinearMethod::simplex, counted, Vec2(0, 0), o);
  EXPECT_EQ(r.status, Status::ok) << r.message;
  EXPECT_LE(r.merit, 1e-9);
  EXPECT_NEAR(r.x[0] + r.x[1], 0.7, 1e-9);
  EXPECT_EQ(residual_calls, 0);
  EXPECT_EQ(r.residual.size(), 0);
  EXPECT_EQ(r.residual_norm, std::numeric_limits<double>::infinity());
}

TEST(Nonlinear, RegistryListsEveryMethodAndParsesEveryName) {
  for (const char* unknown : {"bfgs", "", "Newton"})
    test::expect_complete_registry(nonlinear_methods(), std::span<const NonlinearMethod>(kAll), parse_nonlinear_method, unknown);
  EXPECT_EQ(parse_nonlinear_method("levenberg-marquardt"), NonlinearMethod::ceres);
  EXPECT_EQ(parse_nonlinear_method("nelder-mead"), NonlinearMethod::simplex);
}

TEST(Nonlinear, UndefinedStartIsNotConvergedAndNonFiniteStartIsNumericalFailure) {
  const NonlinearResidual nan_everywhere{2, [](ConstVectorMap, VectorMap r) {
                                           r << kNaN, 0;
                                           return true;
                                         }};
  for (NonlinearMethod m : kAll) {
    SCOPED_TRACE(std::string(to_string(m)));
    const NonlinearResult u = solve(m, kCircleLine, Vec2(0, 5));  // undefined at the start (and the simplex's vertices)
    EXPECT_EQ(u.status, Status::not_converged);
    EXPECT_FALSE(u.message.empty());
    const NonlinearResult n = solve(m, nan_everywhere, Vec2(0, 0));
    // the simplex ranks non-finite merits as undefined
    EXPECT_EQ(n.status, m == NonlinearMethod::simplex ? Status::not_converged : Status::numerical_failure);
    EXPECT_FALSE(n.message.empty());
    EXPECT_EQ(n.x, Vec2(0, 0));
  }
}

TEST(Nonlinear, StallsAreNotConverged) {
  // Newton: the Jacobian of (x + y − 1, 2x + 2y − 2) is singular.
  const NonlinearResidual singular{2, [](ConstVectorMap x, VectorMap r) {
                                     r << x[0] + x[1] - 1, 2 * x[0] + 2 * x[1] - 2;
                                     return true;
                                   }};
  NonlinearResult r = solve(NonlinearMethod::newton, singular, Vec2(0, 0));
  EXPECT_EQ(r.status, Status::not_converged);
  EXPECT_NE(r.message.find("singular"), std::string::npos) << r.message;
  EXPECT_EQ(r.iterations, 1);
  // Newton: no descent along the Newton direction at (1e-20, 0) of (x² + 1, y) (|r| = 1 is a minimum).
  r = solve(NonlinearMethod::newton, kNoRoot, Vec2(1e-20, 0));
  EXPECT_EQ(r.status, Status::not_converged);
  EXPECT_NE(r.message.find("no decrease"), std::string::npos) << r.message;
  EXPECT_EQ(r.residual_norm, 1.0);
  // ... accepted when the stall factor allows |r| = 1
  NonlinearOptions lenient;
  lenient.newton.stall_factor = 2e12;
  EXPECT_EQ(solve(NonlinearMethod::newton, kNoRoot, Vec2(1e-20, 0), lenient).status, Status::ok);
  // Newton: the residual is undefined on both sides of x in one coordinate (no Jacobian).
  const NonlinearResidual isolated{2, [](ConstVectorMap x, VectorMap r) {
                                     if (x[0] != 0.5) return false;
                                     r << x[0] - 1, x[1];
                                     return true;
                                   }};
  r = solve(NonlinearMethod::newton, isolated, Vec2(0.5, 1));
  EXPECT_EQ(r.status, Status::not_converged);
  EXPECT_NE(r.message.find("no Jacobian"), std::string::npos) << r.message;
  // Ceres converges to the least-squares point of an inconsistent system, where |r| = 2.
  const NonlinearResidual inconsistent{3, [](ConstVectorMap x, VectorMap r) {
                                         r << x[0] + x[1] - 1, x[0] + x[1] + 1, x[0] - x[1];
                                         return true;
                                       }};
  r = solve(NonlinearMethod::ceres, inconsistent, Vec2(0.5, 0.5));
  EXPECT_EQ(r.status, Status::not_converged) << r.message;
  EXPECT_NEAR(r.residual_norm, std::sqrt(2.0), 1e-12);
  // ... and creeps toward the minimum |r| = 1 of (x² + 1, y) (J → 0) until its iteration cap.
  r = solve(NonlinearMethod::ceres, kNoRoot, Vec2(0.5, 0.5));
  EXPECT_EQ(r.status, Status::max_iterations) << r.message;
  EXPECT_GE(r.residual_norm, 1.0 - 1e-12);  // |r| ≥ 1 everywhere
  EXPECT_LE(r.residual_norm, 1.1);
  // The simplex collapses onto that minimum (restarts included).
  NonlinearOptions o;
  o.simplex.x_tolerance = 1e-9;
  r = solve(NonlinearMethod::simplex, kNoRoot, Vec2(0.5, 0.5), o);
  EXPECT_EQ(r.status, Status::not_converged) << r.message;
  EXPECT_NE(r.message.find("collapsed"), std::string::npos) << r.message;
  EXPECT_NEAR(r.merit, 1.0, 1e-12);
  EXPECT_LT(r.evaluations, o.simplex.max_evaluations);
}

TEST(Nonlinear, SimplexStopsEarlyAtAPositiveMinimumButNotNearARoot) {
  NonlinearOptions o;
  o.simplex.x_tolerance = 1e-13;
  const NonlinearResult collapsed = solve(NonlinearMethod::simplex, kNoRoot, Vec2(0.5, 0.5), o);
  o.simplex.minimum_spread = 1e-6;
  const NonlinearResult early = solve(NonlinearMethod::simplex, kNoRoot, Vec2(0.5, 0.5), o);
  EXPECT_EQ(early.status, Status::not_converged) << early.message;
  EXPECT_NE(early.message.find("positive local minimum"), std::string::npos) << early.message;
  EXPECT_NEAR(early.merit, 1.0, 1e-9);
  EXPECT_LT(2 * early.evaluations, collapsed.evaluations) << early.evaluations << " vs " << collapsed.evaluations;
  // With a root the merit's spread stays of the order of the merit: the test never fires.
  const NonlinearResult root = solve(NonlinearMethod::simplex, kRosenbrock, Vec2(-0.4, 1.5), o);
  EXPECT_EQ(root.status, Status::ok) << root.message;
  o.simplex.minimum_spread = 1;
  EXPECT_THROW(solve(NonlinearMethod::simplex, kNoRoot, Vec2(0.5, 0.5), o), InputError);
}

TEST(Nonlinear, CapsAreMaxIterations) {
  NonlinearOptions o;
  o.newton.max_iterations = 2;
  o.ceres.max_iterations = 2;
  o.ceres.initial_trust_region = 1e-3;  // small steps: two iterations do not reach the root
  o.simplex.max_iterations = 5;
  for (NonlinearMethod m : kAll) {
    const NonlinearResult r = solve(m, kRosenbrock, Vec2(-0.4, 1.5), o);
    EXPECT_EQ(r.status, Status::max_iterations) << to_string(m) << ": " << r.message;
    EXPECT_FALSE(r.message.empty());
    EXPECT_LE(r.iterations, m == NonlinearMethod::ceres ? 3 : 5);  // Ceres counts its iteration 0
  }
  o = {};
  o.newton.max_evaluations = 4;
  o.simplex.max_evaluations = 20;
  for (NonlinearMethod m : {NonlinearMethod::newton, NonlinearMethod::simplex}) {
    const NonlinearResult r = solve(m, kRosenbrock, Vec2(-0.4, 1.5), o);
    EXPECT_EQ(r.status, Status::max_iterations) << to_string(m);
    EXPECT_LE(r.evaluations, 20 + 2);  // a move finishes its evaluations (shrink: N more)
  }
}

// (e^x − 50, y − 1), counting its calls; and the options the tests below share.
NonlinearResidual exp50_residual(long& calls) {
  return {2, [&calls](ConstVectorMap x, VectorMap r) {
            ++calls;
            r << std::exp(x[0]) - 50, x[1] - 1;
            return true;
          }};
}
NonlinearOptions max_norm_unlimited_steps() {
  NonlinearOptions o;
  o.norm = ResidualNorm::max;
  o.newton.max_step = std::numeric_limits<double>::infinity();
  return o;
}

TEST(Nonlinear, NewtonTrialLimitAndHalvings) {
  // r = e^x − 50 (with y − 1): the first Newton step from 0 is 49; a trial change limit of 2 skips
  // the trials 49, 24.5, …, 3.06 without evaluating them (five halvings) and takes 1.53.
  long calls = 0;
  const NonlinearResidual exp50 = exp50_residual(calls);
  NonlinearOptions o = max_norm_unlimited_steps();
  o.newton.max_trial_change = Eigen::Vector2d(2, std::numeric_limits<double>::infinity());
  o.newton.max_iterations = 1;
  NonlinearResult r = solve(NonlinearMethod::newton, exp50, Vec2(0, 0), o);
  EXPECT_EQ(r.status, Status::max_iterations);
  EXPECT_EQ(calls, 1 + 2 + 1);  // start, Jacobian, one trial
  EXPECT_NEAR(r.x[0], 49.0 / 32, 1e-6);
  EXPECT_NEAR(r.x[1], 1.0 / 32, 1e-9);  // the whole step is scaled
  // With fewer halvings than that the step is never evaluated: no descent.
  o.newton.max_halvings = 4;
  calls = 0;
  r = solve(NonlinearMethod::newton, exp50, Vec2(0, 0), o);
  EXPECT_EQ(r.status, Status::not_converged);
  EXPECT_EQ(calls, 1 + 2);
  o.newton = {};
  r = solve(NonlinearMethod::newton, exp50, Vec2(0, 0), o);
  EXPECT_EQ(r.status, Status::ok) << r.message;
  EXPECT_NEAR(r.x[0], std::log(50.0), 1e-12);
}

TEST(Nonlinear, NewtonSkipsTrialsItsLowerBoundRejectsAndGivesTheSameIterates) {
  // r = (e^x − 50, y − 1) from (0, 0) under the max-norm: the trials x = 49, 24.5, … are rejected
  // by |e^x − 50| alone. The bound |e^x − 50| (exact for that component) skips the shortened ones
  // (a full step is always evaluated): the same iterates, fewer residual calls.
  long calls = 0, bounds = 0;
  NonlinearResidual exp50 = exp50_residual(calls);
  const NonlinearOptions o = max_norm_unlimited_steps();
  const NonlinearResult plain = solve(NonlinearMethod::newton, exp50, Vec2(0, 0), o);
  const long plain_calls = calls;
  exp50.norm_lower_bound = [&](ConstVectorMap x) {
    ++bounds;
    return std::abs(std::exp(x[0]) - 50);
  };
  calls = 0;
  const NonlinearResult bounded = solve(NonlinearMethod::newton, exp50, Vec2(0, 0), o);
  ASSERT_EQ(plain.status, Status::ok) << plain.message;
  EXPECT_EQ(bounded.status, Status::ok) << bounded.message;
  EXPECT_EQ(bounded.x, plain.x);
  EXPECT_EQ(bounded.iterations, plain.iterations);
  EXPECT_GT(bounds, 0);
  EXPECT_EQ(calls, plain_calls - 3);  // the shortened trials x = 24.5, 12.25, 6.125 of the first step
}

TEST(Nonlinear, NewtonStopsWhereItStagnates) {
  // |r| of (x² + 1, y) never falls below 1: from (3, 0) Newton creeps toward x = 0 with halving
  // steps (|r| = x² + 1 falls by ~25 % per step early, then less). With a window of 5 iterations
  // it stops not_converged once 5 iterations gained less than 1 %; without one only the cap stops it.
  NonlinearOptions o;
  o.norm = ResidualNorm::max;
  o.newton.max_iterations = 200;
  o.newton.reject_singular = false;
  o.newton.max_step = std::numeric_limits<double>::infinity();
  NonlinearResult r = solve(NonlinearMethod::newton, kNoRoot, Vec2(3, 0), o);
  const int unbounded = r.iterations;
  EXPECT_NE(r.status, Status::ok);
  o.newton.stagnation_window = 5;
  r = solve(NonlinearMethod::newton, kNoRoot, Vec2(3, 0), o);
  EXPECT_EQ(r.status, Status::not_converged) << r.message;
  EXPECT_NE(r.message.find("stagnated"), std::string::npos) << r.message;
  EXPECT_LT(r.iterations, unbounded);
  EXPECT_GT(r.iterations, 5);
  // A converging solve is not stopped: Rosenbrock needs no more than a few iterations per halving of |r|.
  EXPECT_EQ(solve(NonlinearMethod::newton, kRosenbrock, Vec2(-0.4, 1.5), o).status, Status::ok);
}

TEST(Nonlinear, InvalidInputThrows) {
  const auto param = [](auto&& f) { return test::thrown_parameter(f); };
  NonlinearOptions o;
  o.newton.fd_step = 2;
  EXPECT_EQ(param([&] { solve(NonlinearMethod::newton, kCircleLine, Vec2(0, 0), o); }), "fd_step");
  o = {};
  o.simplex.initial_step = 0;
  EXPECT_EQ(param([&] { solve(NonlinearMethod::simplex, kCircleLine, Vec2(0, 0), o); }), "initial_step");
  o = {};
  o.residual_tolerance = 0;
  EXPECT_EQ(param([&] { solve(NonlinearMethod::ceres, kCircleLine, Vec2(0, 0), o); }), "residual_tolerance");
  o = {};
  o.ceres.max_iterations = 0;
  EXPECT_EQ(param([&] { solve(NonlinearMethod::ceres, kCircleLine, Vec2(0, 0), o); }), "max_iterations");
  o = {};
  o.newton.max_trial_change = Eigen::Vector3d(1, 1, 1);
  EXPECT_EQ(param([&] { solve(NonlinearMethod::newton, kCircleLine, Vec2(0, 0), o); }), "newton.max_trial_change");
  o.newton.max_trial_change = Eigen::Vector2d(1, 0);
  EXPECT_EQ(param([&] { solve(NonlinearMethod::newton, kCircleLine, Vec2(0, 0), o); }), "max_trial_change");
  o = {};
  o.newton.stall_factor = 0.5;
  EXPECT_EQ(param([&] { solve(NonlinearMethod::newton, kCircleLine, Vec2(0, 0), o); }), "stall_factor");
  o.newton = {};
  o.newton.stagnation_window = -1;
  EXPECT_EQ(param([&] { solve(NonlinearMethod::newton, kCircleLine, Vec2(0, 0), o); }), "stagnation_window");
  EXPECT_EQ(param([&] { solve(NonlinearMethod::ceres, kCircleLine, Vec2(kNaN, 0)); }), "x0");
  EXPECT_EQ(param([&] { solve_nonlinear(NonlinearMethod::ceres, kCircleLine, Eigen::VectorXd()); }), "x0");
  EXPECT_EQ(param([&] { solve(NonlinearMethod::newton, NonlinearResidual{0, kCircleLine.f}, Vec2(0, 0)); }),
            "residual.size");
  EXPECT_EQ(param([&] { solve(NonlinearMethod::simplex, NonlinearResidual{2, {}}, Vec2(0, 0)); }), "residual.f");
}

}  // namespace
}  // namespace lac
