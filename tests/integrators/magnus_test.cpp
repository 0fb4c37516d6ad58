// The order-6 Magnus stepper on SE(3) (integrators/magnus.hpp): exact for a constant generator
// (a helix), order 6 for a varying one, the embedded estimate tracks the error, the frame stays
// orthonormal. Its use in the Frenet integration is tested with the space curves (tests/curves).
#include <gtest/gtest.h>

#include <cmath>

#include "lac/integrators/magnus.hpp"

namespace lac {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

double orthonormality_error(const Matrix3d& r) { return (r.transpose() * r - Matrix3d::Identity()).cwiseAbs().maxCoeff(); }

// Helix: κ, τ constant, ω = (τ, 0, κ), v = e_x. Closed form: rotation about the unit Darboux
// axis u by angle |ω| s; position ((τ² s + κ² sin(ws)/w) / w², κ(1 − cos ws)/w², κτ(s − sin(ws)/w)/w²)
// in the starting frame (a standard result for the Frenet frame of a helix).
TEST(Magnus6Step, IntegratesAHelixExactly) {
  const double kappa = 1.3, tau = 0.4, w = std::hypot(kappa, tau);
  auto xi = [&](double) { return Twist{Vector3d(tau, 0, kappa), Vector3d::UnitX()}; };
  RigidMotion g;
  const double h = 0.37;
  double error = -1;
  for (int k = 0; k < 10; ++k) magnus6_step(xi, k * h, h, g, &error);
  EXPECT_EQ(error, 0.0);  // Ω6 = Ω4 for a constant generator
  const double s = 10 * h, c = std::cos(w * s), sn = std::sin(w * s);
  const Vector3d p((tau * tau * s + kappa * kappa * sn / w) / (w * w), kappa * (1 - c) / (w * w),
                   kappa * tau * (s - sn / w) / (w * w));
  EXPECT_LE((g.position - p).cwiseAbs().maxCoeff(), 1e-14);
  const Vector3d u = Vector3d(tau, 0, kappa) / w;
  const Matrix3d k = (Matrix3d() << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0).finished();
  const Matrix3d r = Matrix3d::Identity() + sn * k + (1 - c) * k * k;
  EXPECT_LE((g.rotation - r).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LE(orthonormality_error(g.rotation), 4e-15);  // rounding of 10 steps
}

// ξ(s) = ((0.5 s, 0, 1 + s), e_x): the error of one step of size h shrinks like h^7 (order 6),
// and the order-4 estimate like h^5, above the true error.
TEST(Magnus6Step, OrderSixWithAnEstimateAboveTheError) {
  auto xi = [](double s) { return Twist{Vector3d(0.5 * s, 0, 1 + s), Vector3d::UnitX()}; };
  auto reference = [&](double h) {  // 2^10 substeps
    RigidMotion g;
    const int n = 1024;
    for (int k = 0; k < n; ++k) magnus6_step(xi, 0.2 + k * h / n, h / n, g);
    return g;
  };
  double prev_err = 0, prev_est = 0;
  for (double h : {0.4, 0.2, 0.1}) {
    RigidMotion g;
    double est = 0;
    magnus6_step(xi, 0.2, h, g, &est);
    const RigidMotion ref = reference(h);
    const double err = std::max((g.position - ref.position).cwiseAbs().maxCoeff(),
                                (g.rotation - ref.rotation).cwiseAbs().maxCoeff());
    EXPECT_LE(err, est) << h;
    if (prev_err > 0) {
      EXPECT_NEAR(std::log2(prev_err / err), 7.0, 0.5) << h;
      EXPECT_NEAR(std::log2(prev_est / est), 5.0, 0.5) << h;
    }
    prev_err = err;
    prev_est = est;
  }
}

TEST(Magnus6Step, RightBracketIsTheTransposedSe3Bracket) {
  const Twist x{Vector3d(1, 2, 3), Vector3d(-1, 0.5, 2)}, y{Vector3d(0.3, -1, 2), Vector3d(4, 1, -2)};
  const Twist b = right_bracket(x, y);
  // se(3) bracket [y, x] = (ω_y × ω_x, ω_y × v_x − ω_x × v_y)
  EXPECT_EQ(b.w, y.w.cross(x.w));
  EXPECT_EQ(b.v, y.w.cross(x.v) - x.w.cross(y.v));
  const Twist zero = right_bracket(x, x);
  EXPECT_EQ(zero.w.norm() + zero.v.norm(), 0.0);
}

}  // namespace
}  // namespace lac
