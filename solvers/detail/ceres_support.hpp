#pragma once
// Ceres Solver glue shared by the solvers (the 1-D `ceres` root finder, the N-D `ceres` method):
// the one mapping of a Ceres outcome to Status, and a quiet solve. Included by .cpp files only,
// so no Ceres header reaches a public solver header.
#include <ceres/ceres.h>

#include <string>

#include "lac/common/status.hpp"

namespace lac::detail {

/// Options every solver here shares: dense QR, single thread, no logging or progress output.
ceres::Solver::Options quiet_ceres_options();

/// ceres::Solve with glog's messages silenced (Ceres logs an undefined residual at ERROR level;
/// the outcome is reported as a Status instead).
void solve_quietly(const ceres::Solver::Options& options, ceres::Problem& problem, ceres::Solver::Summary& summary);

struct CeresVerdict {
  Status status = Status::ok;
  std::string message;  ///< empty when ok; else "ceres: " and Ceres' own message
};

/// The Status of a Ceres solve. `target_met`: the caller's success test passed at the returned
/// point (e.g. ‖r‖ ≤ tolerance); `convergence_is_success`: Ceres' own convergence tests count as
/// success (the 1-D finder, whose parameter tolerance is its x tolerance). Otherwise a Ceres
/// convergence (a point where r ≠ 0, or a trust region that collapsed) and a Ceres failure
/// (too many invalid steps, a Jacobian undefined after a step) are not_converged, and the
/// iteration or time cap is max_iterations.
CeresVerdict ceres_verdict(const ceres::Solver::Summary& summary, bool target_met, bool convergence_is_success);

}  // namespace lac::detail
