#include "lac/geometry/space_transforms.hpp"

#include <cmath>

#include "lac/common/error.hpp"

namespace lac {

namespace {

SpaceCurve placed(const SpaceCurve& curve, const SpacePlacement& placement) {
  curve.check_s(0.0, "curve");
  return SpaceCurve(curve.pieces(), placement, curve.ode_options());
}

void require_vector(const char* who, const char* name, const Vec3& v) {
  if (!v.allFinite()) throw_input_error(who, name, "must have finite coordinates");
}

}  // namespace

SpaceCurve translated(const SpaceCurve& curve, const Vec3& offset) {
  require_vector("translated", "offset", offset);
  SpacePlacement p = curve.placement();
  p.origin += offset;
  return placed(curve, p);
}

SpaceCurve rotated(const SpaceCurve& curve, const Eigen::Matrix3d& rotation, const Vec3& center) {
  require_vector("rotated", "center", center);
  if (!rotation.allFinite() || (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-12 ||
      !(std::abs(rotation.determinant() - 1.0) <= 1e-12))
    throw_input_error("rotated", "rotation", "must be orthogonal with determinant +1 (to 1e-12)");
  SpacePlacement p = curve.placement();
  p.origin = center + rotation * (p.origin - center);
  p.matrix = rotation * p.matrix;
  return placed(curve, p);
}

SpaceCurve scaled(const SpaceCurve& curve, double factor, const Vec3& center) {
  if (!(factor > 0) || !std::isfinite(factor)) throw_input_error("scaled", "factor", factor, "(0, inf)");
  require_vector("scaled", "center", center);
  SpacePlacement p = curve.placement();
  p.origin = center + factor * (p.origin - center);
  p.matrix *= factor;
  p.scale *= factor;
  return placed(curve, p);
}

SpaceCurve mirrored(const SpaceCurve& curve, const Vec3& point, const Vec3& normal) {
  require_vector("mirrored", "point", point);
  if (!normal.allFinite() || !(normal.norm() > 0)) throw_input_error("mirrored", "normal", "a finite nonzero vector is needed");
  const Vec3 n = normal.normalized();
  const Eigen::Matrix3d H = Eigen::Matrix3d::Identity() - 2.0 * n * n.transpose();
  SpacePlacement p = curve.placement();
  p.origin = point + H * (p.origin - point);
  p.matrix = H * p.matrix;
  p.torsion_sign = -p.torsion_sign;
  return placed(curve, p);
}

}  // namespace lac
