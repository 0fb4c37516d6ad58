// Name registry and the Ceres-based method of solvers/root_1d.hpp.
#include "lac/solvers/root_1d.hpp"

#include <array>
#include <ceres/ceres.h>

namespace lac {

namespace {

constexpr std::array<std::string_view, 4> kRootMethodNames = {"bisection", "secant", "toms748", "ceres"};

/// Residual r(x) = f(x) for Ceres with a finite-difference derivative that never leaves the
/// bracket (central inside it, one-sided at its ends): f may be undefined outside. A non-finite
/// value rejects the step instead of aborting.
class BracketedResidual : public ceres::SizedCostFunction<1, 1> {
 public:
  BracketedResidual(const std::function<double(double)>* f, long* evaluations, double lo, double hi)
      : f_(f), evaluations_(evaluations), lo_(lo), hi_(hi) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double x = parameters[0][0];
    residuals[0] = call(x);
    if (!std::isfinite(residuals[0])) return false;
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      const double h = 1e-7 * std::max(std::abs(x), hi_ - lo_);
      double d = 0;
      if (x - h >= lo_ && x + h <= hi_) {
        d = (call(x + h) - call(x - h)) / (2 * h);
      } else if (x + h <= hi_) {
        d = (call(x + h) - residuals[0]) / h;
      } else {
        d = (residuals[0] - call(x - h)) / h;
      }
      if (!std::isfinite(d)) return false;
      jacobians[0][0] = d;
    }
    return true;
  }

 private:
  double call(double x) const {
    ++*evaluations_;
    return (*f_)(x);
  }
  const std::function<double(double)>* f_;
  long* evaluations_;
  double lo_, hi_;
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
  const std::function<double(double)> tracked = [&](double y) {
    const double v = f(y);
    if (std::isfinite(v) && y >= b.lo && y <= b.hi) t.note(y, v);
    return v;
  };
  ceres::Problem::Options problem_options;
  ceres::Problem problem(problem_options);
  auto* cost = new BracketedResidual(&tracked, &ceres_evaluations, b.lo, b.hi);
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
