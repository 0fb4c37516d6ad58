#include "lac/geometry/evaluation.hpp"

namespace lac {

PlanarEvaluation evaluate(const PlanarCurve& curve, double s, const GaussLegendre& method) {
  const PositionResult p = position_at(curve, s, method);
  PlanarEvaluation e;
  e.s = s;
  e.position = p.point.position;
  e.error_estimate = p.error_estimate;
  e.theta = p.point.theta;
  e.kappa = p.point.kappa;
  e.dkappa_ds = curve.dkappa_ds_at(s);
  e.tangent = std::polar(1.0, e.theta);
  e.normal = std::complex<double>(0, 1) * e.tangent;
  e.evaluations = p.evaluations;
  e.status = p.status;
  e.message = p.message;
  return e;
}

}  // namespace lac
