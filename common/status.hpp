#pragma once
// Outcome of a numerical algorithm. Non-convergence is reported here, never thrown.
#include <string_view>

namespace lac {

enum class Status {
  ok,                 ///< converged / tolerance met
  tolerance_not_met,  ///< finished within its caps but the error estimate exceeds the tolerance
  max_iterations,     ///< iteration or evaluation cap reached
  fell_back,          ///< primary method unusable here; result from the documented fallback
  no_solution,        ///< no solution exists: proven (the message says why) or a complete search found none
  numerical_failure,  ///< a non-finite intermediate value; result not usable
  /// The solver stopped without converging and without reaching a cap (stalled, singular Jacobian,
  /// no descent, converged to a point where r ≠ 0, no sign change found by a search that is not
  /// complete); a solution may still exist.
  not_converged,
  /// Finished, but the achieved error (verified, or the method's error bound) exceeds the accept
  /// bound (common/accuracy.hpp): the value is not to be used.
  inaccurate,
};

constexpr std::string_view to_string(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::tolerance_not_met: return "tolerance_not_met";
    case Status::max_iterations: return "max_iterations";
    case Status::fell_back: return "fell_back";
    case Status::no_solution: return "no_solution";
    case Status::numerical_failure: return "numerical_failure";
    case Status::not_converged: return "not_converged";
    case Status::inaccurate: return "inaccurate";
  }
  return "unknown";
}

/// True when the value can be used (possibly from a fallback): its achieved error is within the
/// accept bound (common/accuracy.hpp); ok when it is within the accuracy target as well.
constexpr bool usable(Status s) { return s == Status::ok || s == Status::fell_back || s == Status::tolerance_not_met; }

}  // namespace lac
