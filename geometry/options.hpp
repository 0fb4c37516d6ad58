#pragma once
// Options shared by the global geometry queries of geometry/ (closest point, intersections):
// the accuracy target, the accept bound, the work cap and the quadrature of the positions.
#include "lac/common/accuracy.hpp"
#include "lac/common/error.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac {

struct GeometryOptions {
  /// Accuracy target, relative to the curve's length (the size scale): the result is ok when its
  /// error bound (position error estimates plus the gap left by the search) is within it.
  double tolerance = 1e-10;
  double accept = kDefaultAccept;  ///< usable bound, relative to the length (common/accuracy.hpp)
  /// Cap on the spans (pieces of arc length with a position at their centre) the search may
  /// create; past it the result has status max_iterations.
  long max_spans = 200'000;
  /// Cap on the intersections an intersection query reports; past it the result has status
  /// max_iterations (with the points found so far).
  long max_points = 10'000;
  GaussLegendre method{};  ///< positions: ∫ e^{iθ} ds over each span from a known point

  /// InputError naming the option and its valid range (`who`: the calling function).
  void validate(const char* who) const {
    if (!(tolerance >= 1e-15 && tolerance <= 1e-2)) throw_input_error(who, "tolerance", tolerance, "[1e-15, 0.01]");
    validate_accept(who, accept);
    if (!(accept >= tolerance)) throw_input_error(who, "accept", accept, "[tolerance, 0.1]");
    if (max_spans < 16 || max_spans > 100'000'000)
      throw_input_error(who, "max_spans", static_cast<double>(max_spans), "[16, 1e8]");
    if (max_points < 1 || max_points > 100'000'000)
      throw_input_error(who, "max_points", static_cast<double>(max_points), "[1, 1e8]");
    method.validate();
  }
};

}  // namespace lac
