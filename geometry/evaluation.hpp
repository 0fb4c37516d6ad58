#pragma once
// Everything about a PlanarCurve at one arc length in one call: position (with its error
// estimate), unit tangent T = (cos θ, sin θ), unit normal N = i T (to the left; the centre of
// curvature is at p + N/κ), θ, signed κ and dκ/ds. θ, κ and dκ/ds are closed forms
// (PlanarCurve::frame_at, dkappa_ds_at); the position is integrated from the start of the
// segment holding s (position_at).
//
//   lac::PlanarEvaluation e = lac::evaluate(curve, 0.5 * curve.length());
//   // e.position, e.error_estimate, e.tangent, e.normal, e.kappa, e.dkappa_ds, e.status
#include <complex>
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac {

struct PlanarEvaluation {
  double s = 0;
  std::complex<double> position{};  ///< meaningful only when status is usable
  double error_estimate = 0;        ///< absolute, on the position (+inf when not usable)
  std::complex<double> tangent{1, 0}, normal{0, 1};
  double theta = 0, kappa = 0, dkappa_ds = 0;
  long evaluations = 0;
  Status status = Status::ok;
  std::string message;
};

/// At s ∈ [0, length()] (InputError "s" otherwise).
PlanarEvaluation evaluate(const PlanarCurve& curve, double s, const GaussLegendre& method = {});

}  // namespace lac
