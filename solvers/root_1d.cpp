// Name registry and the Ceres-based method of solvers/root_1d.hpp.
#include "solvers/root_1d.hpp"

#include <array>
#include <ceres/ceres.h>

namespace lac {

namespace {

constexpr std::array<std::string_view, 4> kRootMethodNames = {"bisection", "secant", "toms748", "ceres"};

/// Residual r(x) = f(x) for Ceres; a non-finite value rejects the step instead of aborting.
struct Residual1d {
  const std::function<double(double)>* f;
  long* evaluations;
  bool operator()(const double* x, double* residual) const {
    ++*evaluations;
    residual[0] = (*f)(x[0]);
    return std::isfinite(residual[0]);
  }
};

}  // namespace

RootMethod parse_root_method(std::string_view name) {
  if (name == "bisection") return RootMethod::bisection;
  if (name == "secant" || name == "newton") return RootMethod::secant;
  if (name == "toms748") return RootMethod::toms748;
  if (name == "ceres") return RootMethod::ceres;
  throw_input_error("parse_root_method", "solver",
                    "unknown root finder '" + std::string(name) + "'; valid: bisection, secant (alias newton), toms748, ceres");
}

std::string_view to_string(RootMethod m) { return kRootMethodNames[static_cast<size_t>(m)]; }

std::span<const std::string_view> root_method_names() { return kRootMethodNames; }

RootResult ceres_root(const std::function<double(double)>& f, const Bracket& b, const RootOptions& o) {
  RootResult r;
  auto plain = [&f](double x) { return f(x); };
  detail::RootTracker<decltype(plain)> t{&plain, o.f_atol};
  if (!detail::start(b, o, t, r, "ceres")) return r;

  long ceres_evaluations = 0;
  double x = b.lo - b.f_lo * (b.hi - b.lo) / (b.f_hi - b.f_lo);  // regula falsi start
  if (!(x > b.lo && x < b.hi)) x = 0.5 * (b.lo + b.hi);
  // Keep the central difference inside the bracket: Ceres' relative step is 1e-6 |x|.
  const std::function<double(double)> tracked = [&](double y) {
    const double v = f(y);
    if (std::isfinite(v) && y >= b.lo && y <= b.hi) t.note(y, v);
    return v;
  };
  ceres::Problem::Options problem_options;
  ceres::Problem problem(problem_options);
  auto* cost = new ceres::NumericDiffCostFunction<Residual1d, ceres::CENTRAL, 1, 1>(
      new Residual1d{&tracked, &ceres_evaluations});
  problem.AddResidualBlock(cost, nullptr, &x);
  problem.SetParameterLowerBound(&x, 0, b.lo);
  problem.SetParameterUpperBound(&x, 0, b.hi);

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = o.max_iterations;
  options.parameter_tolerance = std::max(o.x_rtol, 1e-300);
  options.function_tolerance = 1e-30;  // let the parameter tolerance or |f| decide
  options.gradient_tolerance = 1e-300;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  r.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  r.root = t.best_x;
  r.residual = t.best_f;
  r.evaluations = ceres_evaluations;
  const bool small = std::abs(r.residual) <= o.f_atol;
  if (summary.termination_type == ceres::CONVERGENCE || small) {
    r.status = Status::ok;
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    r.status = Status::max_iterations;
    r.message = "ceres: " + summary.message;
  } else {
    r.status = Status::numerical_failure;
    r.message = "ceres: " + summary.message;
  }
  return r;
}

}  // namespace lac
