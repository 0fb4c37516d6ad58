#pragma once
// The methods behind solve_nonlinear (solvers/nonlinear.hpp); options and sizes already checked.
#include "lac/solvers/nonlinear.hpp"

namespace lac::detail {

NonlinearResult newton_solve(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o);
NonlinearResult ceres_solve(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o);
NonlinearResult simplex_solve(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o);

/// f.template operator()<N>() with N = n for the small systems the constructions solve (2, 3:
/// fixed-size Eigen vectors), N = Eigen::Dynamic otherwise.
template <class F>
auto with_static_size(Eigen::Index n, F&& f) {
  switch (n) {
    case 2: return f.template operator()<2>();
    case 3: return f.template operator()<3>();
    default: return f.template operator()<Eigen::Dynamic>();
  }
}

/// ‖r‖ in the chosen norm.
template <class V>
double residual_norm(const V& r, ResidualNorm norm) {
  return norm == ResidualNorm::l2 ? r.norm() : r.template lpNorm<Eigen::Infinity>();
}

}  // namespace lac::detail
