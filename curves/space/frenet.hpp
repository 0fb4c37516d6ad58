#pragma once
// Frenet–Serret integration of an LA space curve (docs/math.md §3; 000 §2.1):
//   P' = T, T' = κN, N' = −κT + τB, B' = −τN
// with a method of the ODE registry (OdeOptions, integrators/ode_registry.hpp): over a 12-vector
// state (P, T, N, B) with the project's steppers (integrators/ode.hpp), adaptive Dormand–Prince 5(4)
// or fixed-step RK4; or the order-6 Magnus stepper on SE(3) (integrators/magnus.hpp). After every
// accepted step the frame is re-orthonormalized (Gram–Schmidt on T, N; B = T × N), so it stays
// orthonormal to rounding.
// Event location (meeting the cone angle(P, e_x) = θ of 000 §2.2) brackets the first sign change
// over one step and refines it with Boost's TOMS 748 on exact single steps of varying size.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/space/la_space_curve.hpp"
#include "lac/integrators/ode_registry.hpp"

namespace lac {

using Vec3 = Eigen::Vector3d;

/// Position and Frenet frame (tangent, normal, binormal).
struct Frame3 {
  Vec3 p = Vec3::Zero();
  Vec3 t = Vec3::UnitX();
  Vec3 n = Vec3::UnitY();
  Vec3 b = Vec3::UnitZ();
  /// max |F^T F − I| over the frame F = [t n b].
  double orthonormality_error() const;
};


struct FrenetResult {
  Frame3 frame;             ///< state where integration stopped
  double s = 0;             ///< arc length there
  bool met_cone = false;    ///< integrate_to_cone: the event was found (frame is on the cone)
  long steps = 0;           ///< accepted steps
  long evaluations = 0;     ///< right-hand-side evaluations
  double error_estimate = 0;  ///< sum of local error estimates (rk45; 0 for rk4)
  Status status = Status::ok;
  std::string message;
};

/// Integrates from (s0, start) to s1 ≥ s0; [s0, s1] must lie in curve.s_range() (InputError).
FrenetResult integrate_frenet(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1,
                              const OdeOptions& options = {});

/// Integrates from (s0, start) until angle(P, e_x) first reaches cone_angle ∈ (0, π) or s reaches
/// s_limit (met_cone false then). Requires angle(P(s0), e_x) < cone_angle (or P(s0) = 0).
FrenetResult integrate_to_cone(const LaSpaceCurve& curve, const Frame3& start, double s0, double s_limit,
                               double cone_angle, const OdeOptions& options = {});

/// Frames at n ≥ 2 equally spaced arc lengths from s0 to s1 (both included).
std::vector<Frame3> sample_frenet(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1, int n,
                                  const OdeOptions& options = {}, Status* status = nullptr);

/// angle(P, e_x) ∈ [0, π]; 0 at P = 0.
double cone_angle_of(const Vec3& p);

namespace detail {
/// InputError unless start has finite coordinates, s0 lies in curve.s_range() and s0 ≤ s1 below its end.
void check_frenet_input(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1, const char* who);
}  // namespace detail

}  // namespace lac
