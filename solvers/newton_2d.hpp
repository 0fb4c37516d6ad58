#pragma once
// Damped Newton for a small square system r(x) = 0 (N = 2 for the space-curve end tangent,
// MATH.md §3) with a forward-difference Jacobian and a backtracking line search on |r|.
// r may be undefined at some x (std::nullopt or a non-finite component): the line search then
// halves the step, exactly as for a step that does not decrease |r|. Every loop is capped.
// Hand-written because the residual is a black box (an ODE integration with an event) and
// Eigen's unsupported HybridNonLinearSolver cannot be told that a point is undefined.
#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"

namespace lac {

struct NewtonOptions {
  double residual_tolerance = 1e-12;  ///< ok when |r|_2 ≤ this
  double fd_step = 1e-7;              ///< forward-difference step, relative to max(1, |x_i|)
  double step_tolerance = 1e-15;      ///< stop (tolerance_not_met) when the accepted step is below this
  int max_iterations = 50;            ///< Newton iterations (status max_iterations)
  int max_halvings = 30;              ///< line-search halvings per iteration
  long max_evaluations = 2000;        ///< residual calls (status max_iterations)
  double max_step = 2.0;              ///< cap on the max-norm of a Newton step (trust radius in x)
  void validate() const {
    constexpr const char* who = "NewtonOptions";
    if (!(residual_tolerance > 0)) throw_input_error(who, "residual_tolerance", residual_tolerance, "(0, inf)");
    if (!(fd_step > 0 && fd_step < 1)) throw_input_error(who, "fd_step", fd_step, "(0, 1)");
    if (!(step_tolerance >= 0)) throw_input_error(who, "step_tolerance", step_tolerance, "[0, inf)");
    if (max_iterations < 1) throw_input_error(who, "max_iterations", max_iterations, "[1, inf)");
    if (max_halvings < 0) throw_input_error(who, "max_halvings", max_halvings, "[0, inf)");
    if (max_evaluations < 1) throw_input_error(who, "max_evaluations", static_cast<double>(max_evaluations), "[1, inf)");
    if (!(max_step > 0)) throw_input_error(who, "max_step", max_step, "(0, inf]");
  }
};

template <int N>
struct NewtonResult {
  Eigen::Matrix<double, N, 1> x;
  Eigen::Matrix<double, N, 1> residual;  ///< r(x)
  double residual_norm = std::numeric_limits<double>::infinity();
  int iterations = 0;
  long evaluations = 0;
  Status status = Status::ok;
  std::string message;
};

/// Solves r(x) = 0 from x0. r: Eigen::Matrix<double, N, 1> → std::optional<Eigen::Matrix<double, N, 1>>.
/// Status: ok, max_iterations (a cap), tolerance_not_met (stalled: singular Jacobian or no descent),
/// no_solution (r undefined at x0).
template <int N, class F>
NewtonResult<N> solve_newton(F&& residual, const Eigen::Matrix<double, N, 1>& x0, const NewtonOptions& opt = {}) {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  opt.validate();
  NewtonResult<N> r;
  auto eval = [&](const Vec& x) -> std::optional<Vec> {
    ++r.evaluations;
    std::optional<Vec> v = residual(x);
    if (v && !v->allFinite()) v.reset();
    return v;
  };
  Vec x = x0;
  std::optional<Vec> fx = eval(x);
  r.x = x;
  if (!fx) {
    r.status = Status::no_solution;
    r.message = "newton: residual undefined at the starting point";
    return r;
  }
  double norm = fx->norm();
  auto finish = [&](Status s, std::string msg) {
    r.x = x;
    r.residual = *fx;
    r.residual_norm = norm;
    r.status = s;
    r.message = std::move(msg);
    return r;
  };
  while (true) {
    if (norm <= opt.residual_tolerance) return finish(Status::ok, "");
    if (r.iterations >= opt.max_iterations || r.evaluations >= opt.max_evaluations)
      return finish(Status::max_iterations, "newton: cap reached after " + std::to_string(r.iterations) + " iterations");
    ++r.iterations;
    Mat jac;
    bool jac_ok = true;
    for (int j = 0; j < N && jac_ok; ++j) {
      Vec xp = x;
      double h = opt.fd_step * std::max(1.0, std::abs(x[j]));
      std::optional<Vec> fp = eval(xp += Vec::Unit(j) * h);
      if (!fp) {  // undefined ahead: difference backwards
        h = -h;
        xp = x + Vec::Unit(j) * h;
        fp = eval(xp);
      }
      if (!fp) jac_ok = false;
      else jac.col(j) = (*fp - *fx) / h;
    }
    if (!jac_ok) return finish(Status::tolerance_not_met, "newton: residual undefined around x (no Jacobian)");
    const auto lu = jac.fullPivLu();
    if (!lu.isInvertible()) return finish(Status::tolerance_not_met, "newton: singular Jacobian");
    Vec dx = -lu.solve(*fx);
    const double dmax = dx.cwiseAbs().maxCoeff();
    if (!std::isfinite(dmax)) return finish(Status::tolerance_not_met, "newton: non-finite step");
    if (dmax > opt.max_step) dx *= opt.max_step / dmax;
    bool accepted = false;
    double t = 1.0;
    for (int k = 0; k <= opt.max_halvings; ++k, t *= 0.5) {
      const Vec xn = x + t * dx;
      std::optional<Vec> fn = eval(xn);
      if (fn && fn->norm() < norm) {
        x = xn;
        fx = fn;
        norm = fn->norm();
        accepted = true;
        break;
      }
    }
    if (!accepted) return finish(Status::tolerance_not_met, "newton: no decrease of |r| along the Newton direction");
    if (t * dx.cwiseAbs().maxCoeff() <= opt.step_tolerance && norm > opt.residual_tolerance)
      return finish(Status::tolerance_not_met, "newton: step below step_tolerance");
  }
}

}  // namespace lac
