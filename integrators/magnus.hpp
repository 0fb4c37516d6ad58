#pragma once
// Order-6 Magnus stepper on SE(3) for g' = g·ξ(s), g = (R, p) a rotation and a position, ξ = (ω, v)
// the body-frame generator (angular and linear velocity). A step is g ← g·exp(Ω) with Ω from ξ at
// the 3 Gauss nodes of the step; constant ξ is integrated exactly and R stays on SO(3) by
// construction. Used by the Frenet integration of LA space curves (curves/space/frenet.hpp: ω the
// Darboux vector (τ, 0, κ), v = e_x). Hand-written: no library offers Lie-group Magnus steppers.
// Ω of order 6 and the embedded order-4 Ω (error estimate) use 3 Gauss nodes (Blanes, Casas, Oteo,
// Ros, Phys. Rep. 470 (2009), §5.2: Ω = α1 + α3/12 + [−20α1 − α3 + C1, α2 + C2]/240 with
// C1 = [α1, α2], C2 = −[α1, 2α3 + C1]/60; order 4: α1 + α3/12 − [α1, α2]/12). Those formulas are
// for Y' = A Y; for g' = g ξ every bracket [X, Y] becomes [Y, X] (transposition).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <concepts>

namespace lac {

/// An element (ω, v) of se(3).
struct Twist {
  Eigen::Vector3d w, v;
  Twist operator+(const Twist& o) const { return {w + o.w, v + o.v}; }
  Twist operator-(const Twist& o) const { return {w - o.w, v - o.v}; }
  Twist operator*(double c) const { return {c * w, c * v}; }
};

/// g = (R, p) ∈ SE(3): R's columns are the body frame's axes, p its origin.
struct RigidMotion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

/// Bracket of the right-multiplied equation g' = g ξ: [X, Y]_right = [Y, X]_se(3).
inline Twist right_bracket(const Twist& x, const Twist& y) {
  return {y.w.cross(x.w), y.w.cross(x.v) - x.w.cross(y.v)};
}

/// g ← g·exp(Ω): rotation R(ω) and translation V(ω) v (Rodrigues; series for |ω|² < 1e-4).
inline void multiply_exp(RigidMotion& g, const Twist& om) {
  const double th2 = om.w.squaredNorm();
  double A, B, C;
  if (th2 < 1e-4) {
    A = 1 - th2 / 6 * (1 - th2 / 20);
    B = 0.5 - th2 / 24 * (1 - th2 / 30);
    C = 1.0 / 6 - th2 / 120 * (1 - th2 / 42);
  } else {
    const double th = std::sqrt(th2), s = std::sin(th), c = std::cos(th);
    A = s / th;
    B = (1 - c) / th2;
    C = (th - s) / (th2 * th);
  }
  const Eigen::Vector3d& w = om.w;
  auto rot = [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(x + A * w.cross(x) + B * w.cross(w.cross(x))); };
  const Eigen::Vector3d d = om.v + B * w.cross(om.v) + C * w.cross(w.cross(om.v));  // body-frame displacement
  // new frame columns F R e_i, new position P + F d
  const Eigen::Matrix3d f = g.rotation;
  g.position += f * d;
  g.rotation.col(0) = f * rot(Eigen::Vector3d::UnitX());
  g.rotation.col(1) = f * rot(Eigen::Vector3d::UnitY());
  g.rotation.col(2) = f * rot(Eigen::Vector3d::UnitZ());
}

/// ξ: s ↦ (ω, v).
template <class G>
concept TwistGenerator = std::invocable<G&, double> && std::convertible_to<std::invoke_result_t<G&, double>, Twist>;

/// One order-6 Magnus step of g' = g·ξ(s) from s to s + h (3 calls of ξ). `error`, when given,
/// receives the step-control estimate max|Ω6 − Ω4| (largest component of the difference from the
/// embedded order-4 Ω).
template <TwistGenerator G>
void magnus6_step(G&& xi, double s, double h, RigidMotion& g, double* error = nullptr) {
  constexpr double kC = 0.3872983346207417;  // √15/10
  const Twist a1 = xi(s + (0.5 - kC) * h), a2 = xi(s + 0.5 * h), a3 = xi(s + (0.5 + kC) * h);
  const Twist al1 = a2 * h, al2 = (a3 - a1) * (h * 1.2909944487358056), al3 = (a3 - a2 * 2.0 + a1) * (h * 10.0 / 3.0);
  const Twist c1 = right_bracket(al1, al2);
  const Twist c2 = right_bracket(al1, al3 * 2.0 + c1) * (-1.0 / 60.0);
  const Twist om6 = al1 + al3 * (1.0 / 12.0) + right_bracket(al1 * -20.0 - al3 + c1, al2 + c2) * (1.0 / 240.0);
  if (error) {
    const Twist om4 = al1 + al3 * (1.0 / 12.0) - c1 * (1.0 / 12.0);
    const Twist d = om6 - om4;
    *error = std::max(d.w.cwiseAbs().maxCoeff(), d.v.cwiseAbs().maxCoeff());
  }
  multiply_exp(g, om6);
}

}  // namespace lac
