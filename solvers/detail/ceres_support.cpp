#include "lac/solvers/detail/ceres_support.hpp"

#include <glog/logging.h>

namespace lac::detail {

ceres::Solver::Options quiet_ceres_options() {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  o.num_threads = 1;
  return o;
}

void solve_quietly(const ceres::Solver::Options& options, ceres::Problem& problem, ceres::Solver::Summary& summary) {
  const int saved = FLAGS_minloglevel;
  FLAGS_minloglevel = google::GLOG_FATAL;
  ceres::Solve(options, &problem, &summary);
  FLAGS_minloglevel = saved;
}

CeresVerdict ceres_verdict(const ceres::Solver::Summary& summary, bool target_met, bool convergence_is_success) {
  if (target_met) return {};
  Status status = Status::not_converged;
  switch (summary.termination_type) {
    case ceres::CONVERGENCE:
      if (convergence_is_success) return {};
      break;
    case ceres::NO_CONVERGENCE: status = Status::max_iterations; break;
    case ceres::USER_SUCCESS:  // stopped by a callback, but the caller's own test failed
    case ceres::FAILURE:
    case ceres::USER_FAILURE: break;
  }
  return {status, "ceres: " + summary.message};
}

}  // namespace lac::detail
