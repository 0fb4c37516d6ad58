// Name registry and the Ceres-based method of solvers/root_1d.hpp.
#include "lac/solvers/root_1d.hpp"

#include <array>

#include "lac/solvers/detail/ceres_support.hpp"
#include "lac/solvers/detail/method_registry.hpp"

namespace lac {

namespace {

constexpr std::array<std::string_view, 1> kSecantAliases = {"newton"};
constexpr std::array<RootMethodInfo, 4> kRootMethods = {{
    {RootMethod::bisection, "bisection", {}, "halves the bracket (001's method)", "x_rtol, x_atol, f_atol, max_iterations"},
    {RootMethod::secant, "secant", kSecantAliases,
     "secant steps kept inside the bracket, bisection when a step leaves it or the bracket stops shrinking",
     "x_rtol, x_atol, f_atol, max_iterations"},
    {RootMethod::toms748, "toms748", {}, "Boost.Math TOMS 748 (Alefeld-Potra-Shi)", "x_rtol, x_atol, f_atol, max_iterations"},
    {RootMethod::ceres, "ceres", {},
     "Ceres Solver Levenberg-Marquardt on f(x), bounded by the bracket, derivative by differences inside it",
     "x_rtol (Ceres parameter tolerance), f_atol, max_iterations"},
}};

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

std::span<const RootMethodInfo> root_methods() { return kRootMethods; }

RootMethod parse_root_method(std::string_view name) {
  return detail::parse_solver_method(root_methods(), name, "parse_root_method", "root finder");
}

std::string_view to_string(RootMethod m) { return detail::solver_method_name(root_methods(), m); }

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

  ceres::Solver::Options options = detail::quiet_ceres_options();
  options.max_num_iterations = o.max_iterations;
  options.parameter_tolerance = std::max(o.x_rtol, 1e-300);
  options.function_tolerance = 1e-30;  // let the parameter tolerance or |f| decide
  options.gradient_tolerance = 1e-300;
  ceres::Solver::Summary summary;
  detail::solve_quietly(options, problem, summary);

  r.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  r.root = t.best_x;
  r.residual = t.best_f;
  r.evaluations = ceres_evaluations;
  // Ceres' convergence is its parameter tolerance x_rtol: the x tolerance of the other methods.
  auto verdict = detail::ceres_verdict(summary, std::abs(r.residual) <= o.f_atol, true);
  r.status = verdict.status;
  r.message = std::move(verdict.message);
  return r;
}

}  // namespace lac
