#pragma once
// One meaning of "usable" for every evaluation and construction (docs/architecture.md, "Accuracy").
// Each has an accuracy target (its tolerance, a documented default, the user's option where it is
// the user's choice) and an accept bound, both relative to the size scale of the result (chord
// of a construction, arc length from the known point of a position):
//   error ≤ target            → ok                 (verified within the target)
//   target < error ≤ accept   → tolerance_not_met  (usable; the report carries the error)
//   error > accept, or NaN    → inaccurate         (not usable, exit 3 on the CLI)
// "error" is the achieved error: a verified residual, or an error estimate that bounds the true
// error (integrators/: every method's estimate is tested to bound it on the reference tables).
#include <cmath>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"

namespace lac {

/// Default accept bound, relative to the size scale: 1e-6 (a user may loosen it knowingly).
inline constexpr double kDefaultAccept = 1e-6;
/// Largest accept bound a user may set (relative): beyond it a "usable" result means nothing.
inline constexpr double kMaxAccept = 1e-1;

/// The status of a result whose achieved relative error is `error` (see above).
constexpr Status grade_error(double error, double target, double accept) {
  if (error <= target) return Status::ok;
  if (error <= accept) return Status::tolerance_not_met;
  return Status::inaccurate;  // also NaN
}

/// A usable status downgraded to inaccurate when `error` exceeds `accept`; others unchanged.
constexpr Status within_accept(Status s, double error, double accept) {
  return usable(s) && !(error <= accept) ? Status::inaccurate : s;
}

/// InputError unless accept ∈ (0, kMaxAccept] (`who`: the construction or command).
inline void validate_accept(const char* who, double accept) {
  if (!(accept > 0 && accept <= kMaxAccept)) throw_input_error(who, "accept", accept, "(0, 0.1]");
}

}  // namespace lac
