#pragma once
// What every construction returns: the curve, a Summary of how it was obtained (in the spirit of
// Ceres' Solver::Summary) and the construction's own details. One type for all constructions, so
// that callers, the command line and the experiments read every result the same way.
#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include "lac/common/accuracy.hpp"
#include "lac/common/status.hpp"

namespace lac {

/// Errors of a construction's end conditions on the returned curve, each where the construction
/// measures it (std::nullopt where it does not apply, e.g. curvature for a G1 construction).
struct Residuals {
  std::optional<double> position;   ///< distance of the end point from its target (user units)
  std::optional<double> angle;      ///< largest end-tangent angle error (rad)
  std::optional<double> curvature;  ///< largest end-curvature error (user units)
};

/// How a result was obtained. Counters add up over every run of the call (starts, fallbacks).
struct Summary {
  Status status = Status::ok;
  std::string message;     ///< why, whenever status is not ok (for no_solution: the proven reason)
  int iterations = 0;      ///< solver iterations
  long evaluations = 0;    ///< integrand or ODE right-hand-side evaluations
  long constructions = 0;  ///< trial curves built (each a full evaluation of the end conditions)
  Residuals residuals;     ///< end-condition errors of the returned curve
  std::optional<double> error_estimate;  ///< of the returned curve's positions, where the method gives one
  /// The achieved error relative to the size scale (common/accuracy.hpp): the largest of the
  /// verified residuals (positions / chord, angles in rad, curvatures × chord) and the error
  /// estimate / chord. Kept when the result is not usable (it says by how much it missed).
  std::optional<double> error;
  double accept = kDefaultAccept;  ///< the accept bound the result was graded against (relative)
  double seconds = 0;      ///< wall time of the whole call
  std::string integrator;  ///< registry name of the integrator used
  std::string solver;      ///< registry name of the solver used

  bool usable() const { return lac::usable(status); }
};

/// No construction-specific details.
struct NoInfo {};

/// A construction's result: `curve` is meaningful only when summary.usable().
template <class Curve, class Info = NoInfo>
struct Result {
  Curve curve{};
  Summary summary;
  Info info{};

  bool usable() const { return summary.usable(); }

  /// Sets the final status and message; a usable status whose summary.error exceeds
  /// summary.accept becomes inaccurate. A result that is not usable keeps no curve, residuals or
  /// error estimate (summary.error stays): nothing of a failed solve reaches the caller as a curve.
  void conclude(Status status, std::string message) {
    if (summary.error && lac::usable(status) && !(*summary.error <= summary.accept)) {
      status = Status::inaccurate;
      message = "achieved error " + format_number(*summary.error) + " exceeds the accept bound " +
                format_number(summary.accept) + (message.empty() ? "" : " (" + message + ")");
    }
    summary.status = status;
    summary.message = std::move(message);
    if (!summary.usable()) {
      curve = Curve{};
      summary.residuals = {};
      summary.error_estimate.reset();
    }
  }
};

/// Wall time since `start` in seconds, for Summary::seconds.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lac
