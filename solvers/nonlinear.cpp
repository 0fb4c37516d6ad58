// Registry, option checks and dispatch of solvers/nonlinear.hpp (the methods: newton.cpp,
// ceres_least_squares.cpp, simplex.cpp).
#include "lac/solvers/nonlinear.hpp"

#include <array>
#include <cmath>

#include "lac/common/error.hpp"
#include "lac/solvers/detail/method_registry.hpp"
#include "lac/solvers/detail/nonlinear_methods.hpp"

namespace lac {
namespace {

constexpr std::array<std::string_view, 1> kCeresAliases = {"levenberg-marquardt"};
constexpr std::array<std::string_view, 1> kSimplexAliases = {"nelder-mead"};
constexpr std::array<NonlinearMethodInfo, 3> kNonlinearMethods = {{
    {NonlinearMethod::newton, "newton", {},
     "damped Newton (M = N): the residual's Jacobian where given, else forward differences; full-pivot LU, step halving until |r| decreases",
     "residual_tolerance, norm, newton.{max_iterations, max_evaluations, fd_step, backward_differences, "
     "reject_singular, max_step, max_trial_change, max_halvings, step_tolerance, stall_factor, stagnation_window}"},
    {NonlinearMethod::ceres, "ceres", kCeresAliases,
     "Ceres Solver Levenberg-Marquardt on min |r|^2/2, central-difference Jacobian",
     "residual_tolerance, norm, ceres.{max_iterations, function_tolerance, gradient_tolerance, parameter_tolerance, "
     "fd_relative_step, initial_trust_region, stop_at_tolerance}"},
    {NonlinearMethod::simplex, "simplex", kSimplexAliases,
     "modified downhill simplex (000's): minimizes |r| or a caller's merit; undefined points rank worst",
     "residual_tolerance (target of the merit), norm, simplex.{initial_step, x_tolerance, f_tolerance, "
     "max_iterations, max_evaluations, restarts, minimum_spread, merit}"},
}};

}  // namespace

std::span<const NonlinearMethodInfo> nonlinear_methods() { return kNonlinearMethods; }

NonlinearMethod parse_nonlinear_method(std::string_view name) {
  return detail::parse_solver_method(nonlinear_methods(), name, "parse_nonlinear_method", "nonlinear solver");
}

std::string_view to_string(NonlinearMethod m) { return detail::solver_method_name(nonlinear_methods(), m); }

void NewtonOptions::validate() const {
  constexpr const char* who = "NewtonOptions";
  if (max_iterations < 1) throw_input_error(who, "max_iterations", max_iterations, "[1, inf)");
  if (max_evaluations < 1) throw_input_error(who, "max_evaluations", static_cast<double>(max_evaluations), "[1, inf)");
  if (!(fd_step > 0 && fd_step < 1)) throw_input_error(who, "fd_step", fd_step, "(0, 1)");
  if (!(max_step > 0)) throw_input_error(who, "max_step", max_step, "(0, inf]");
  for (Eigen::Index j = 0; j < max_trial_change.size(); ++j)
    if (!(max_trial_change[j] > 0)) throw_input_error(who, "max_trial_change", max_trial_change[j], "(0, inf] per component");
  if (max_halvings < 0 || max_halvings > 1000) throw_input_error(who, "max_halvings", max_halvings, "[0, 1000]");
  if (!(step_tolerance >= 0) || !std::isfinite(step_tolerance))
    throw_input_error(who, "step_tolerance", step_tolerance, "[0, inf)");
  if (!(stall_factor >= 1) || !std::isfinite(stall_factor)) throw_input_error(who, "stall_factor", stall_factor, "[1, inf)");
  if (stagnation_window < 0 || stagnation_window > 100000)
    throw_input_error(who, "stagnation_window", stagnation_window, "[0, 100000] (0: never)");
}

void CeresOptions::validate() const {
  constexpr const char* who = "CeresOptions";
  if (max_iterations < 1) throw_input_error(who, "max_iterations", max_iterations, "[1, inf)");
  if (!(function_tolerance >= 0)) throw_input_error(who, "function_tolerance", function_tolerance, "[0, inf)");
  if (!(gradient_tolerance >= 0)) throw_input_error(who, "gradient_tolerance", gradient_tolerance, "[0, inf)");
  if (!(parameter_tolerance >= 0)) throw_input_error(who, "parameter_tolerance", parameter_tolerance, "[0, inf)");
  if (!(fd_relative_step > 0 && fd_relative_step < 1)) throw_input_error(who, "fd_relative_step", fd_relative_step, "(0, 1)");
  if (!(initial_trust_region > 0) || !std::isfinite(initial_trust_region))
    throw_input_error(who, "initial_trust_region", initial_trust_region, "(0, inf)");
}

void SimplexOptions::validate() const {
  constexpr const char* who = "SimplexOptions";
  if (!(initial_step > 0) || !std::isfinite(initial_step)) throw_input_error(who, "initial_step", initial_step, "(0, inf)");
  if (!(x_tolerance >= 0) || !std::isfinite(x_tolerance)) throw_input_error(who, "x_tolerance", x_tolerance, "[0, inf)");
  if (!(f_tolerance >= 0) || !std::isfinite(f_tolerance)) throw_input_error(who, "f_tolerance", f_tolerance, "[0, inf)");
  if (max_iterations < 1) throw_input_error(who, "max_iterations", max_iterations, "[1, inf)");
  if (max_evaluations < 1) throw_input_error(who, "max_evaluations", static_cast<double>(max_evaluations), "[1, inf)");
  if (restarts < 0) throw_input_error(who, "restarts", restarts, "[0, inf)");
  if (!(minimum_spread >= 0 && minimum_spread < 1)) throw_input_error(who, "minimum_spread", minimum_spread, "[0, 1)");
}

void NonlinearOptions::validate() const {
  if (!(residual_tolerance > 0) || !std::isfinite(residual_tolerance))
    throw_input_error("NonlinearOptions", "residual_tolerance", residual_tolerance, "(0, inf)");
  if (norm != ResidualNorm::l2 && norm != ResidualNorm::max)
    throw_input_error("NonlinearOptions", "norm", static_cast<double>(norm), "{l2, max}");
  newton.validate();
  ceres.validate();
  simplex.validate();
}

NonlinearResult solve_nonlinear(NonlinearMethod method, const NonlinearResidual& residual, const Eigen::VectorXd& x0,
                                const NonlinearOptions& options) {
  constexpr const char* who = "solve_nonlinear";
  options.validate();
  if (x0.size() < 1) throw_input_error(who, "x0", "needs at least one unknown");
  if (!x0.allFinite()) throw_input_error(who, "x0", "must be finite");
  if (residual.size < 1) throw_input_error(who, "residual.size", residual.size, "[1, inf)");
  if (!residual.f) throw_input_error(who, "residual.f", "must be set");
  switch (method) {
    case NonlinearMethod::newton:
      if (residual.size != x0.size())
        throw_input_error(who, "residual.size", residual.size, "{" + std::to_string(x0.size()) + "} (newton needs as many residuals as unknowns)");
      if (options.newton.max_trial_change.size() != 0 && options.newton.max_trial_change.size() != x0.size())
        throw_input_error(who, "newton.max_trial_change", "needs 0 or " + std::to_string(x0.size()) + " components");
      return detail::newton_solve(residual, x0, options);
    case NonlinearMethod::ceres: return detail::ceres_solve(residual, x0, options);
    case NonlinearMethod::simplex: return detail::simplex_solve(residual, x0, options);
  }
  throw_input_error(who, "method", static_cast<double>(method), "{newton, ceres, simplex}");
}

}  // namespace lac
