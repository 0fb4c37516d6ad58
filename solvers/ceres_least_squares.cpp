// The `ceres` method of solvers/nonlinear.hpp: Ceres Solver's Levenberg–Marquardt on
// min ½‖r(x)‖₂² with a central-difference Jacobian (ceres::NumericDiffCostFunction).
#include <Eigen/Core>
#include <array>
#include <utility>

#include "lac/solvers/detail/ceres_support.hpp"
#include "lac/solvers/detail/nonlinear_methods.hpp"

namespace lac::detail {
namespace {

// The caller's residual for Ceres: counts calls; an undefined or non-finite r rejects the point.
struct CeresResidual {
  const NonlinearResidual* residual;
  long* evaluations;
  int n;
  mutable Eigen::VectorXd scratch;  // r is written to Ceres only when defined (single-threaded solve)

  bool operator()(double const* const* x, double* out) const { return evaluate(x[0], out); }
  bool operator()(const double* x, double* out) const { return evaluate(x, out); }
  bool evaluate(const double* x, double* out) const {
    ++*evaluations;
    if (!residual->f(ConstVectorMap(x, n), VectorMap(scratch.data(), scratch.size())) || !scratch.allFinite()) return false;
    VectorMap(out, scratch.size()) = scratch;
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

// Ceres 2.1's NumericDiffCostFunction (compile-time N) keeps the Jacobian columns it could not
// difference when a point beside x is undefined; DynamicNumericDiffCostFunction instead fails the
// evaluation. The constructions rely on the former (their iterates are pinned by the result tables),
// so N ≤ kMaxFixedN uses it and only larger N the dynamic one.
constexpr int kMaxFixedN = 16;

template <int N>
ceres::CostFunction* fixed_cost(CeresResidual* functor, int m, const ceres::NumericDiffOptions& nd) {
  return new ceres::NumericDiffCostFunction<CeresResidual, ceres::CENTRAL, ceres::DYNAMIC, N>(functor, ceres::TAKE_OWNERSHIP,
                                                                                            m, nd);
}

template <int... Ns>
ceres::CostFunction* make_cost(CeresResidual* functor, int n, int m, const ceres::NumericDiffOptions& nd,
                               std::integer_sequence<int, Ns...>) {
  using Maker = ceres::CostFunction* (*)(CeresResidual*, int, const ceres::NumericDiffOptions&);
  static constexpr std::array<Maker, sizeof...(Ns)> makers = {&fixed_cost<Ns + 1>...};
  if (n <= kMaxFixedN) return makers[static_cast<size_t>(n - 1)](functor, m, nd);
  auto* cost = new ceres::DynamicNumericDiffCostFunction<CeresResidual, ceres::CENTRAL>(functor, ceres::TAKE_OWNERSHIP, nd);
  cost->AddParameterBlock(n);
  cost->SetNumResiduals(m);
  return cost;
}

}  // namespace

NonlinearResult ceres_solve(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o) {
  const CeresOptions& co = o.ceres;
  const int n = static_cast<int>(x0.size()), m = residual.size;
  NonlinearResult r;
  r.x = x0;
  Eigen::VectorXd rv(m);
  auto evaluate = [&](const Eigen::VectorXd& x) {
    ++r.evaluations;
    return residual.f(ConstVectorMap(x.data(), n), VectorMap(rv.data(), m));
  };
  // Ceres cannot start from an undefined point.
  if (const bool defined = evaluate(x0); !defined || !rv.allFinite()) {
    r.status = defined ? Status::numerical_failure : Status::not_converged;
    r.message = defined ? "ceres: residual not finite at the starting point" : "ceres: residual undefined at the starting point";
    return r;
  }
  Eigen::VectorXd x = x0;
  ceres::NumericDiffOptions nd;
  nd.relative_step_size = co.fd_relative_step;
  auto* functor = new CeresResidual{&residual, &r.evaluations, n, Eigen::VectorXd(m)};
  ceres::Problem problem;
  problem.AddResidualBlock(make_cost(functor, n, m, nd, std::make_integer_sequence<int, kMaxFixedN>{}), nullptr, x.data());
  ceres::Solver::Options so = quiet_ceres_options();
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.max_num_iterations = co.max_iterations;
  so.function_tolerance = co.function_tolerance;
  so.gradient_tolerance = co.gradient_tolerance;
  so.parameter_tolerance = co.parameter_tolerance;
  so.initial_trust_region_radius = co.initial_trust_region;
  StopAtCost stop(0.5 * o.residual_tolerance * o.residual_tolerance);
  if (co.stop_at_tolerance) so.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  solve_quietly(so, problem, summary);
  r.x = x;
  r.iterations = static_cast<int>(summary.iterations.size());
  if (evaluate(x) && rv.allFinite()) {
    r.residual = rv;
    r.residual_norm = r.merit = residual_norm(rv, o.norm);
  }
  CeresVerdict verdict = ceres_verdict(summary, r.residual_norm <= o.residual_tolerance, false);
  r.status = verdict.status;
  r.message = std::move(verdict.message);
  return r;
}

}  // namespace lac::detail
