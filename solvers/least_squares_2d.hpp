#pragma once
// Small nonlinear least squares min ½|r(x)|² by Ceres Solver's Levenberg–Marquardt with a
// central-difference Jacobian (ceres::NumericDiffCostFunction). Used with N = 2 unknowns and
// M = 2 residuals for the space-curve end tangent (MATH.md §3), but generic over N, M.
// r may be undefined at some x (return std::nullopt or a non-finite component): the functor then
// reports failure and Ceres rejects the step and shrinks its trust region (Ceres's glog messages
// about it are silenced during the solve: the outcome is in the returned Status).
#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"

namespace lac {

struct LeastSquaresOptions {
  double residual_tolerance = 1e-12;  ///< ok when |r|_2 ≤ this (checked after every iteration)
  int max_iterations = 100;           ///< Ceres max_num_iterations
  double function_tolerance = 1e-16;  ///< Ceres: stop when |Δcost|/cost is below this
  double parameter_tolerance = 1e-15; ///< Ceres: stop when |Δx|/(|x| + tol) is below this
  double fd_relative_step = 1e-6;     ///< central-difference step relative to |x_i|
  double initial_trust_region = 1e4;  ///< Ceres initial_trust_region_radius
  void validate() const {
    constexpr const char* who = "LeastSquaresOptions";
    if (!(residual_tolerance > 0)) throw_input_error(who, "residual_tolerance", residual_tolerance, "(0, inf)");
    if (max_iterations < 1) throw_input_error(who, "max_iterations", max_iterations, "[1, inf)");
    if (!(function_tolerance >= 0)) throw_input_error(who, "function_tolerance", function_tolerance, "[0, inf)");
    if (!(parameter_tolerance >= 0)) throw_input_error(who, "parameter_tolerance", parameter_tolerance, "[0, inf)");
    if (!(fd_relative_step > 0 && fd_relative_step < 1)) throw_input_error(who, "fd_relative_step", fd_relative_step, "(0, 1)");
    if (!(initial_trust_region > 0)) throw_input_error(who, "initial_trust_region", initial_trust_region, "(0, inf)");
  }
};

template <int N, int M>
struct LeastSquaresResult {
  Eigen::Matrix<double, N, 1> x;
  Eigen::Matrix<double, M, 1> residual;
  double residual_norm = std::numeric_limits<double>::infinity();
  int iterations = 0;
  long evaluations = 0;  ///< residual calls, including those of the finite differences
  Status status = Status::ok;
  std::string message;
};

namespace detail {
template <int N, int M, class F>
struct CeresResidual {
  F* f;
  long* count;
  bool operator()(const double* x, double* out) const {
    ++*count;
    const std::optional<Eigen::Matrix<double, M, 1>> r = (*f)(Eigen::Map<const Eigen::Matrix<double, N, 1>>(x));
    if (!r || !r->allFinite()) return false;
    Eigen::Map<Eigen::Matrix<double, M, 1>> dst(out);
    dst = *r;
    return true;
  }
};

struct StopAtCost : ceres::IterationCallback {
  double target;
  explicit StopAtCost(double t) : target(t) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    return s.cost <= target ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
};
}  // namespace detail

/// f: Eigen::Matrix<double, N, 1> → std::optional<Eigen::Matrix<double, M, 1>>.
/// Status: ok (|r| ≤ residual_tolerance), tolerance_not_met (Ceres converged elsewhere, e.g. a
/// local minimum with r ≠ 0), max_iterations, no_solution (r undefined at x0).
template <int N, int M, class F>
LeastSquaresResult<N, M> solve_least_squares(F&& f, const Eigen::Matrix<double, N, 1>& x0,
                                             const LeastSquaresOptions& opt = {}) {
  using Fn = std::remove_reference_t<F>;
  opt.validate();
  LeastSquaresResult<N, M> r;
  r.x = x0;
  {  // Ceres cannot start from an undefined point
    ++r.evaluations;
    const auto r0 = f(x0);
    if (!r0 || !r0->allFinite()) {
      r.status = Status::no_solution;
      r.message = "ceres: residual undefined at the starting point";
      return r;
    }
  }
  double x[N];
  for (int i = 0; i < N; ++i) x[i] = x0[i];
  ceres::NumericDiffOptions nd;
  nd.relative_step_size = opt.fd_relative_step;
  using Functor = detail::CeresResidual<N, M, Fn>;
  auto* cost = new ceres::NumericDiffCostFunction<Functor, ceres::CENTRAL, M, N>(
      new Functor{&f, &r.evaluations}, ceres::TAKE_OWNERSHIP, M, nd);
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, x);
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.max_num_iterations = opt.max_iterations;
  so.function_tolerance = opt.function_tolerance;
  so.gradient_tolerance = 0;
  so.parameter_tolerance = opt.parameter_tolerance;
  so.initial_trust_region_radius = opt.initial_trust_region;
  so.num_threads = 1;
  detail::StopAtCost stop(0.5 * opt.residual_tolerance * opt.residual_tolerance);
  so.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  {  // Ceres logs an undefined residual (which we report as a Status) at glog's ERROR level
    const int saved = FLAGS_minloglevel;
    FLAGS_minloglevel = google::GLOG_FATAL;
    ceres::Solve(so, &problem, &summary);
    FLAGS_minloglevel = saved;
  }
  for (int i = 0; i < N; ++i) r.x[i] = x[i];
  r.iterations = static_cast<int>(summary.iterations.size());
  ++r.evaluations;
  const auto rf = f(r.x);
  if (rf && rf->allFinite()) {
    r.residual = *rf;
    r.residual_norm = rf->norm();
  }
  if (r.residual_norm <= opt.residual_tolerance) {
    r.status = Status::ok;
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    r.status = Status::max_iterations;
    r.message = "ceres: " + summary.message;
  } else {
    r.status = Status::tolerance_not_met;
    r.message = "ceres: " + summary.message;
  }
  return r;
}

}  // namespace lac
