// The `newton` method of solvers/nonlinear.hpp: damped Newton with the residual's Jacobian or a
// forward-difference one, and backtracking on ‖r‖. Hand-written because the residual is a black box that may be undefined
// at a trial point (an ODE integration with an event, a curve that is not representable), which
// Eigen's unsupported HybridNonLinearSolver and Ceres' line search cannot be told.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lac/common/error.hpp"

#include "lac/solvers/detail/nonlinear_methods.hpp"

namespace lac::detail {
namespace {

enum class Eval { defined, undefined, non_finite };

// The stagnation test's required fall of ‖r‖ over NewtonOptions::stagnation_window iterations.
constexpr double kStagnationFactor = 0.99;

template <int N>
NonlinearResult newton(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o) {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  const NewtonOptions& no = o.newton;
  const auto n = x0.size();
  NonlinearResult r;
  // With f_with_jacobian, every point but the differencing ones is evaluated with its Jacobian
  // (known: whether the residual gave one there).
  auto eval = [&](const Vec& x, Vec& out, Mat* jac = nullptr, bool* known = nullptr) {
    ++r.evaluations;
    bool defined;
    if (jac && residual.f_with_jacobian) {
      defined = residual.f_with_jacobian(ConstVectorMap(x.data(), n), VectorMap(out.data(), n), jac->data(), *known);
      *known = *known && defined && jac->allFinite();
    } else {
      if (known) *known = false;
      defined = residual.f(ConstVectorMap(x.data(), n), VectorMap(out.data(), n));
    }
    if (!defined) return Eval::undefined;
    return out.allFinite() ? Eval::defined : Eval::non_finite;
  };
  auto too_far = [&](const Vec& trial, const Vec& x) {
    if (no.max_trial_change.size() == 0) return false;
    for (Eigen::Index j = 0; j < n; ++j)
      if (std::abs(trial[j] - x[j]) > no.max_trial_change[j]) return true;
    return false;
  };
  Vec x = x0;
  Vec fx(n);
  Mat jac(n, n), jac_trial(n, n);
  bool jac_known = false, trial_known = false;
  r.x = x0;
  if (const Eval e = eval(x, fx, &jac, &jac_known); e != Eval::defined) {
    r.status = e == Eval::undefined ? Status::not_converged : Status::numerical_failure;
    r.message = e == Eval::undefined ? "newton: residual undefined at the starting point"
                                     : "newton: residual not finite at the starting point";
    return r;
  }
  double norm = residual_norm(fx, o.norm);
  auto finish = [&](Status s, std::string msg) {
    r.x = x;
    r.residual = fx;
    r.residual_norm = r.merit = norm;
    r.status = s;
    r.message = std::move(msg);
    return r;
  };
  Vec xp(n), fp(n), xn(n), fn(n);
  std::vector<double> history;  // ‖r‖ after each iteration, for the stagnation test
  while (true) {
    if (norm <= o.residual_tolerance) return finish(Status::ok, "");
    if (r.iterations >= no.max_iterations || r.evaluations >= no.max_evaluations)
      return finish(Status::max_iterations, "newton: cap reached after " + std::to_string(r.iterations) + " iterations");
    ++r.iterations;
    for (Eigen::Index j = 0; j < n && !jac_known; ++j) {
      double h = no.fd_step * std::max(1.0, std::abs(x[j]));
      xp = x;
      xp[j] += h;
      Eval e = eval(xp, fp);
      if (e != Eval::defined && no.backward_differences) {  // undefined ahead: difference backwards
        h = -h;
        xp[j] = x[j] + h;
        e = eval(xp, fp);
      }
      if (e != Eval::defined) return finish(Status::not_converged, "newton: residual undefined around x (no Jacobian)");
      jac.col(j) = (fp - fx) / h;
    }
    const Eigen::FullPivLU<Mat> lu(jac);
    if (no.reject_singular && !lu.isInvertible()) return finish(Status::not_converged, "newton: singular Jacobian");
    Vec dx = -lu.solve(fx);
    if (!dx.allFinite()) return finish(Status::not_converged, "newton: non-finite step (singular Jacobian)");
    const double dmax = dx.cwiseAbs().maxCoeff();
    if (dmax > no.max_step) dx *= no.max_step / dmax;
    bool accepted = false;
    double t = 1.0;
    for (int k = 0; k <= no.max_halvings; ++k, t *= 0.5) {
      xn = x + t * dx;
      if (too_far(xn, x)) continue;
      // After a rejected full step: a converging run takes the full step, which is evaluated anyway.
      if (k > 0 && residual.norm_lower_bound && !(residual.norm_lower_bound(ConstVectorMap(xn.data(), n)) < norm)) continue;
      if (eval(xn, fn, &jac_trial, &trial_known) != Eval::defined) continue;
      const double trial_norm = residual_norm(fn, o.norm);
      if (trial_norm < norm) {
        x = xn;
        fx = fn;
        jac_known = trial_known;
        if (jac_known) jac = jac_trial;
        norm = trial_norm;
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      if (norm <= no.stall_factor * o.residual_tolerance) return finish(Status::ok, "");
      return finish(Status::not_converged, "newton: no decrease of |r| along the Newton direction");
    }
    if (t * dx.cwiseAbs().maxCoeff() <= no.step_tolerance && norm > o.residual_tolerance)
      return finish(Status::not_converged, "newton: step below step_tolerance");
    if (no.stagnation_window > 0) {
      history.push_back(norm);
      const auto w = static_cast<size_t>(no.stagnation_window);
      if (history.size() > w && norm > o.residual_tolerance && !(norm < kStagnationFactor * history[history.size() - 1 - w]))
        return finish(Status::not_converged, "newton: stagnated (|r| = " + format_number(norm) + " fell by less than 1 % in " +
                                                 std::to_string(w) + " iterations)");
    }
  }
}

}  // namespace

NonlinearResult newton_solve(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o) {
  return with_static_size(x0.size(), [&]<int N>() { return newton<N>(residual, x0, o); });
}

}  // namespace lac::detail
