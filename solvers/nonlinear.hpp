#pragma once
// Nonlinear systems r(x) = 0 with N unknowns and M residuals, one registry
// (nonlinear_methods(): name, aliases, description, options), selectable by name:
//   newton   damped Newton (M = N): the residual's own Jacobian where it gives one, else forward
//            differences; full-pivot LU, backtracking by halving until ‖r‖ decreases;
//   ceres    Ceres Solver Levenberg–Marquardt on min ½‖r‖₂², central-difference Jacobian;
//   simplex  modified downhill simplex (Nelder–Mead) as 000 §2.2 uses it, minimizing a merit:
//            ‖r‖ by default, or the caller's (e.g. an angle) in SimplexOptions::merit.
// The residual may be undefined at some x (it returns false, or a component is not finite): Newton
// halves the step, Ceres rejects the step, the simplex ranks the point worst. Every loop is capped.
//
// Status: ok (‖r‖ ≤ residual_tolerance; simplex: merit ≤ residual_tolerance), max_iterations (an
// iteration or evaluation cap), not_converged (stalled: no descent, singular or undefined Jacobian,
// a collapsed simplex, Ceres converged where r ≠ 0, undefined at the start), numerical_failure
// (r not finite at the start). Invalid options or sizes throw InputError.
//
// Usage:
//   lac::NonlinearResidual r{2, [](lac::ConstVectorMap x, lac::VectorMap out) {
//     out << x[0] * x[0] + x[1] * x[1] - 4, x[0] - x[1];
//     return true;
//   }};
//   auto res = lac::solve_nonlinear(lac::parse_nonlinear_method("newton"), r, Eigen::Vector2d(1, 0.5));
//   // res.x ≈ (√2, √2), res.status == lac::Status::ok, res.iterations, res.evaluations
#include <Eigen/Core>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "lac/common/status.hpp"
#include "lac/solvers/method_info.hpp"
#include "lac/solvers/nonlinear_method.hpp"

namespace lac {

using ConstVectorMap = Eigen::Map<const Eigen::VectorXd>;
using VectorMap = Eigen::Map<Eigen::VectorXd>;

/// r: R^N → R^M. `f(x, r)` writes the M residuals into r and returns true, or returns false where r
/// is undefined (a trial outside the domain); a non-finite component also counts as undefined.
struct NonlinearResidual {
  using Function = std::function<bool(ConstVectorMap x, VectorMap r)>;
  using FunctionWithJacobian = std::function<bool(ConstVectorMap x, VectorMap r, double* jacobian, bool& jacobian_known)>;
  NonlinearResidual() = default;
  NonlinearResidual(int size, Function f, FunctionWithJacobian f_with_jacobian = {})
      : size(size), f(std::move(f)), f_with_jacobian(std::move(f_with_jacobian)) {}

  int size = 0;  ///< M ≥ 1
  Function f;
  /// Optional, used by newton: r as `f` gives it and, where `jacobian_known` is set true, the M×N
  /// Jacobian at x (column-major in `jacobian`). Newton then calls it instead of `f` and differences
  /// only at points where the Jacobian was not given.
  FunctionWithJacobian f_with_jacobian;
  /// Optional, used by newton's line search: a cheap lower bound on ‖r(x)‖ in the solve's norm
  /// (e.g. the residuals that need no integral). A shortened trial step whose bound is not below
  /// the current ‖r‖ would be rejected anyway: it is not evaluated (the iterates are the same, only
  /// cheaper). The full step is always evaluated.
  std::function<double(ConstVectorMap x)> norm_lower_bound;
};

/// The norm of r for the tolerance test, Newton's descent test and the simplex's default merit.
enum class ResidualNorm { l2, max };

struct NewtonOptions {
  int max_iterations = 50;
  long max_evaluations = 2000;  ///< residual calls (checked before each iteration)
  double fd_step = 1e-7;        ///< forward difference h_j = fd_step·max(1, |x_j|)
  bool backward_differences = true;  ///< where r(x + h_j e_j) is undefined, use r(x − h_j e_j)
  /// Stop (not_converged) when the LU finds the Jacobian rank-deficient; false: solve anyway
  /// (Eigen's FullPivLU gives a step in the range) and stop only on a non-finite step.
  bool reject_singular = true;
  double max_step = 2.0;  ///< cap on the max-norm of the Newton step (scales the whole step; inf: none)
  /// Per component, empty or size N: a trial x_t with |x_t,j − x_j| > max_trial_change_j is not
  /// evaluated and counts as one halving.
  Eigen::VectorXd max_trial_change;
  int max_halvings = 30;         ///< trial steps per iteration: 1, 1/2, …, 2^-max_halvings
  double step_tolerance = 1e-15; ///< stop (not_converged) after an accepted step below this (max-norm; 0: never)
  /// With no descent along the Newton direction, ‖r‖ ≤ stall_factor·residual_tolerance still counts
  /// as ok (1: it does not).
  double stall_factor = 1;
  /// Stagnation: stop (not_converged) when ‖r‖ has not fallen by 1 % over the last
  /// `stagnation_window` iterations (0: never): a search creeping along a kink of the max-norm
  /// with tiny damped steps, not a converging one.
  int stagnation_window = 0;
  void validate() const;
};

struct CeresOptions {
  int max_iterations = 100;            ///< Ceres max_num_iterations
  double function_tolerance = 1e-16;   ///< Ceres: stop when |Δcost|/cost is below this
  double gradient_tolerance = 0;       ///< Ceres: stop when the max-norm of the projected gradient is below this
  double parameter_tolerance = 1e-15;  ///< Ceres: stop when |Δx|/(|x| + tol) is below this
  double fd_relative_step = 1e-6;      ///< central difference step relative to |x_j| (at least √ε)
  double initial_trust_region = 1e4;   ///< Ceres initial_trust_region_radius
  /// Stop as soon as ½‖r‖₂² ≤ ½ residual_tolerance² (an iteration callback); false: only at
  /// Ceres' own tests.
  bool stop_at_tolerance = true;
  void validate() const;
};

struct SimplexOptions {
  double initial_step = 0.25;  ///< edge length of the initial simplex (per coordinate)
  double x_tolerance = 1e-12;  ///< collapsed when every vertex is within this of the best (max-norm)
  double f_tolerance = 0;      ///< ... and the spread of defined merits is ≤ this
  int max_iterations = 2000;   ///< simplex moves
  long max_evaluations = 5000; ///< merit calls
  int restarts = 2;            ///< fresh simplices around the best vertex after a collapse
  /// > 0: a simplex also counts as collapsed at a positive local minimum, once its size is
  /// ≤ 1e-4 × initial_step and its merits' spread is ≤ this × the best merit (> the tolerance).
  /// Near a root the merit changes at the simplex's own scale (spread ~ best), at a minimum above
  /// zero quadratically (spread ~ size²): the test stops such runs long before x_tolerance.
  double minimum_spread = 0;
  /// Minimized instead of ‖r‖ when set (nullopt or non-finite: undefined); the residual is then never
  /// evaluated (the result's residual is empty).
  std::function<std::optional<double>(ConstVectorMap x)> merit;
  void validate() const;
};

struct NonlinearOptions {
  double residual_tolerance = 1e-12;  ///< ok when ‖r‖ ≤ this (simplex: merit ≤ this)
  ResidualNorm norm = ResidualNorm::l2;
  NewtonOptions newton;
  CeresOptions ceres;
  SimplexOptions simplex;
  void validate() const;
};

struct NonlinearResult {
  Eigen::VectorXd x;         ///< last iterate (simplex: best vertex)
  Eigen::VectorXd residual;  ///< r(x), size M; empty when r was not evaluated there
  double residual_norm = std::numeric_limits<double>::infinity();  ///< ‖r(x)‖ (inf: not evaluated)
  double merit = std::numeric_limits<double>::infinity();  ///< the simplex's merit at x; ‖r(x)‖ otherwise
  int iterations = 0;
  long evaluations = 0;  ///< residual (simplex: merit) calls, finite differences included
  Status status = Status::ok;
  std::string message;  ///< empty when ok
};

/// Solves r(x) = 0 from x0 (size N ≥ 1) with the method.
NonlinearResult solve_nonlinear(NonlinearMethod method, const NonlinearResidual& residual, const Eigen::VectorXd& x0,
                                const NonlinearOptions& options = {});

}  // namespace lac
