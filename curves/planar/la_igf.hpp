#pragma once
// `igf`: the incomplete-gamma closed form (MATH.md §1.1, integrators/igf.hpp) as a position
// method for la_position.hpp. Satisfies LaClosedForm, so position_at / polyline accept it.
#include <complex>
#include <string_view>

#include "lac/curves/planar/la_curve.hpp"
#include "lac/integrators/igf.hpp"

namespace lac {

struct Igf {
  static constexpr std::string_view name = "igf";
  /// Relative accuracy asked of each C(θ1) − C(θ0); see IgfOptions (default 1e-12).
  double tol = IgfOptions{}.tol;
  /// Segment-series piece cap before the Gauss–Kronrod fallback; see IgfOptions.
  long max_pieces = IgfOptions{}.max_pieces;

  IgfOptions options() const { return IgfOptions{tol, max_pieces}; }
  void validate() const { options().validate(); }

  /// C(θ1) − C(θ0) of the curve (θ0, θ1 in its θ domain; InputError otherwise).
  IntegralResult<std::complex<double>> integrate_theta(const LaCurve& c, double theta0, double theta1) const {
    return igf_position_delta(c.alpha(), c.lambda(), theta0, theta1, options());
  }
};

}  // namespace lac
