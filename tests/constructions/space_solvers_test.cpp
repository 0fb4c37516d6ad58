// The generic small solvers used by the space segments: modified downhill simplex, damped Newton
// with a finite-difference Jacobian, Ceres Levenberg–Marquardt (solvers/*.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "lac/common/error.hpp"
#include "lac/solvers/least_squares_2d.hpp"
#include "lac/solvers/newton_2d.hpp"
#include "lac/solvers/simplex.hpp"

namespace lac {
namespace {

using Vec2 = Eigen::Vector2d;

// Rosenbrock, undefined for x < −0.5 (as a curve that never meets the cone is undefined).
std::optional<double> rosenbrock_partial(const Vec2& x) {
  if (x[0] < -0.5) return std::nullopt;
  return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
}

// Roots of (x² + y² − 4, x − y) with x ≥ 0: (√2, √2). Undefined for y > 3.
std::optional<Vec2> circle_line(const Vec2& x) {
  if (x[1] > 3) return std::nullopt;
  return Vec2(x[0] * x[0] + x[1] * x[1] - 4, x[0] - x[1]);
}

TEST(Simplex, MinimizesAcrossAnUndefinedRegion) {
  SimplexOptions o;
  o.x_tolerance = 1e-10;
  o.initial_step = 0.5;
  const auto r = minimize_simplex<2>(rosenbrock_partial, Vec2(-0.4, 1.5), o);  // the simplex starts at the edge
  EXPECT_EQ(r.status, Status::ok) << r.message;
  EXPECT_NEAR(r.x[0], 1, 1e-6);
  EXPECT_NEAR(r.x[1], 1, 1e-6);
  EXPECT_LE(r.value, 1e-12);
  EXPECT_GT(r.evaluations, r.iterations);
}

TEST(Simplex, StopsAtTheTargetAndAtTheCaps) {
  SimplexOptions o;
  o.value_target = 1e-3;
  auto r = minimize_simplex<2>(rosenbrock_partial, Vec2(0, 0), o);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_LE(r.value, 1e-3);
  o.value_target = -1;  // unreachable
  o.x_tolerance = 0;
  o.max_evaluations = 50;
  r = minimize_simplex<2>(rosenbrock_partial, Vec2(0, 0), o);
  EXPECT_EQ(r.status, Status::max_iterations);
  EXPECT_LE(r.evaluations, 50 + 3);  // a move may finish its evaluations (shrink: N more)
  // undefined everywhere near the start
  r = minimize_simplex<2>(rosenbrock_partial, Vec2(-5, 0), SimplexOptions{});
  EXPECT_EQ(r.status, Status::no_solution);
  EXPECT_THROW(minimize_simplex<2>(rosenbrock_partial, Vec2(0, 0), SimplexOptions{.initial_step = 0}), InputError);
}

TEST(Newton, SolvesAndBacktracksOutOfUndefinedPoints) {
  NewtonOptions o;
  o.residual_tolerance = 1e-14;
  const auto r = solve_newton<2>(circle_line, Vec2(0.3, 2.9), o);
  EXPECT_EQ(r.status, Status::ok) << r.message;
  EXPECT_NEAR(r.x[0], std::sqrt(2.0), 1e-13);
  EXPECT_NEAR(r.x[1], std::sqrt(2.0), 1e-13);
  EXPECT_LE(r.residual_norm, 1e-14);
  EXPECT_LE(r.iterations, 12);
}

TEST(Newton, ReportsSingularAndUndefinedStarts) {
  // x² + 1 = 0 has no real root: the Newton direction cannot decrease |r| forever; capped.
  auto no_root = [](const Vec2& x) -> std::optional<Vec2> { return Vec2(x[0] * x[0] + 1, x[1]); };
  const auto r = solve_newton<2>(no_root, Vec2(0.5, 0.5), NewtonOptions{});
  EXPECT_NE(r.status, Status::ok);
  EXPECT_FALSE(r.message.empty());
  const auto u = solve_newton<2>(circle_line, Vec2(0, 5), NewtonOptions{});
  EXPECT_EQ(u.status, Status::no_solution);
  EXPECT_THROW(solve_newton<2>(circle_line, Vec2(0, 0), NewtonOptions{.fd_step = 2}), InputError);
}

TEST(CeresLeastSquares, SolvesTheSameSystemAndReportsCounts) {
  LeastSquaresOptions o;
  o.residual_tolerance = 1e-12;
  const auto r = solve_least_squares<2, 2>(circle_line, Vec2(0.3, 2.5), o);
  EXPECT_EQ(r.status, Status::ok) << r.message;
  EXPECT_NEAR(r.x[0], std::sqrt(2.0), 1e-11);
  EXPECT_NEAR(r.x[1], std::sqrt(2.0), 1e-11);
  EXPECT_GT(r.evaluations, r.iterations);
  const auto u = solve_least_squares<2, 2>(circle_line, Vec2(0, 5), o);
  EXPECT_EQ(u.status, Status::no_solution);
  // least squares with no zero residual: converges elsewhere, status says so
  auto no_root = [](const Vec2& x) -> std::optional<Vec2> { return Vec2(x[0] * x[0] + 1, x[1]); };
  const auto n = solve_least_squares<2, 2>(no_root, Vec2(0.5, 0.5), o);
  EXPECT_NE(n.status, Status::ok);
  EXPECT_GE(n.residual_norm, 1.0 - 1e-12);  // |r| ≥ 1 everywhere
  EXPECT_LE(n.residual_norm, 1.1);
}

}  // namespace
}  // namespace lac
