// geometry/space_transforms: similarities of a SpaceCurve keep its pieces and map its frames as
// the similarity does (each frame integrated by the curve itself); κ scales by 1/k, a mirror
// image negates τ.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "lac/geometry/space_transforms.hpp"
#include "tests/support/space_curves.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using test::two_pieces;

// Frames of t at s·factor against the similarity applied to c's frames at s.
template <class F, class G>
void expect_maps(const SpaceCurve& c, const SpaceCurve& t, double factor, F&& point, G&& vector, double tau_sign) {
  EXPECT_NEAR(t.length(), factor * c.length(), 1e-14 * t.length());
  for (int i = 0; i <= 10; ++i) {
    const double s = c.length() * i / 10.0;
    const SpacePoint a = c.frame_at(s), b = t.frame_at(std::min(t.length(), factor * s));
    ASSERT_EQ(b.status, Status::ok);
    EXPECT_LE((b.p - point(a.p)).norm(), 1e-9 * t.length());
    EXPECT_LE((b.t - vector(a.t)).norm(), 1e-9);
    EXPECT_LE((b.n - vector(a.n)).norm(), 1e-9);
    EXPECT_LE((b.b - b.t.cross(b.n)).norm(), 1e-12);
    EXPECT_NEAR(b.kappa, a.kappa / factor, 1e-12 * std::abs(a.kappa));
    EXPECT_NEAR(b.tau, tau_sign * a.tau / factor, 1e-12 * std::abs(a.tau) + 1e-15);
  }
}

TEST(GeometrySpaceTransforms, SimilaritiesMapFrames) {
  const SpaceCurve c = two_pieces();
  const Vec3 v(0.5, -1, 2), center(1, 1, 0);
  expect_maps(c, translated(c, v), 1.0, [&](const Vec3& p) { return Vec3(p + v); }, [](const Vec3& u) { return u; }, 1.0);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 0.2).normalized()).toRotationMatrix();
  expect_maps(c, rotated(c, Q, center), 1.0, [&](const Vec3& p) { return Vec3(center + Q * (p - center)); },
              [&](const Vec3& u) { return Vec3(Q * u); }, 1.0);
  expect_maps(c, scaled(c, 3.0, center), 3.0, [&](const Vec3& p) { return Vec3(center + 3.0 * (p - center)); },
              [](const Vec3& u) { return u; }, 1.0);
  const Vec3 P(0, 1, 2), n = Vec3(1, 1, -0.5).normalized();
  const Eigen::Matrix3d H = Eigen::Matrix3d::Identity() - 2.0 * n * n.transpose();
  const SpaceCurve m = mirrored(c, P, 4.0 * n);
  EXPECT_EQ(m.placement().torsion_sign, -1);
  expect_maps(c, m, 1.0, [&](const Vec3& p) { return Vec3(P + H * (p - P)); }, [&](const Vec3& u) { return Vec3(H * u); }, -1.0);
  // Mirroring twice gives back the curve's placement.
  const SpaceCurve mm = mirrored(m, P, n);
  EXPECT_EQ(mm.placement().torsion_sign, 1);
  EXPECT_LE((mm.placement().matrix - c.placement().matrix).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(test::thrown_parameter([&] { scaled(c, 0.0); }), "factor");
  EXPECT_EQ(test::thrown_parameter([&] { rotated(c, H); }), "rotation");  // a reflection
  EXPECT_EQ(test::thrown_parameter([&] { mirrored(c, P, Vec3::Zero()); }), "normal");
}

}  // namespace
}  // namespace lac
