#pragma once
// Space curves shared by the geometry tests.
#include <Eigen/Geometry>

#include "lac/curves/space/frenet.hpp"
#include "lac/curves/space/space_curve.hpp"

namespace lac::test {

/// Two LA space pieces joined at the first one's end frame, placed by a rotation, a scale 2.5 and a
/// translation.
inline SpaceCurve two_pieces() {
  const LaSpaceCurve c0(-1, -1, 0.8, 0.1, 1.5, TorsionType::type1), c1(0.5, 1, 0.7, 0.2, 1.1, TorsionType::type1);
  const Frame3 joint = integrate_frenet(c0, Frame3{}, 0, 0.5, {OdeMethod::rk45, 1e-13, 1e-14}).frame;
  SpacePlacement pl;
  pl.origin = Vec3(1, -2, 3);
  pl.scale = 2.5;
  pl.matrix = pl.scale * Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  return SpaceCurve({{c0, 0, 0.5, Frame3{}}, {c1, 0.1, 0.6, joint}}, pl, {});
}

/// One piece turning several times (a slowly rising spiral), arc length 20.
inline SpaceCurve coil() {
  const LaSpaceCurve c0(2, 1, 0.05, 0.02, 1.0, TorsionType::type1);
  return SpaceCurve({{c0, 0, 20.0, Frame3{}}}, SpacePlacement{}, {});
}

}  // namespace lac::test
