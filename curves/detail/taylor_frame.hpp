#pragma once
// The Taylor-series frame integrator with a proven error bound shared by the certified space
// (curves/space/certified_frenet.hpp) and planar (curves/planar/certified_position.hpp) paths.
//
// F' = F K(s), K = [[0, −κ, 0], [κ, 0, −τ], [0, τ, 0]] (τ = 0 for a planar curve); over a step
// F(s + h) = F(s) G(h) with G' = G K, G(0) = I, so G's Taylor coefficients follow from K's by
// G_{j+1} = Σ_{i≤j} G_i K_{j−i} / (j+1), and P(s + h) = P(s) + F(s) Σ_j G_j e₁ h^{j+1}/(j+1).
// Remainder: the caller's coefficient maxima over the step (|κ^(i)|, |τ^(i)| largest at an end of
// the step for LA laws, powers of a monotone quantity) put through the same recursion bound every
// coefficient of G at every point of the step, hence ‖G^(m)/m!‖ there. The exact propagator G(h)
// is orthogonal, so a frame error is carried without growth:
// δ_{k+1} ≤ δ_k + (1 + δ_k)(remainder + rounding). Rounding: a majorant E_j of the computed G_j's
// error by the recursion's own rule. Written by hand: no library in Debian integrates an ODE with a
// proven bound.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>

#include "lac/common/status.hpp"

namespace lac::detail {

inline constexpr int kTaylorTerms = 24;  ///< G_0 … G_23 are summed; G_24 bounds the remainder

/// Scaled Taylor coefficients of κ and τ over a step of size h from s: κ^(i)(s)/i! · h^(i+1) (and
/// τ's), i = 0 … kTaylorTerms − 1, and a bound on their relative rounding.
struct FrameSeries {
  std::array<double, kTaylorTerms> kappa{}, tau{};
  std::array<double, kTaylorTerms> relative_error{};  ///< of κ_i and τ_i (the larger)
};

struct TaylorFrame {
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  ///< [T N B] at s1
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double position_error = 0;  ///< proven bound on |P − P_exact|
  double frame_error = 0;     ///< proven bound on ‖F − F_exact‖ (Frobenius)
  long steps = 0;
  Status status = Status::ok;
  std::string message;
};

/// `series(s, h)`: the coefficients at s for a step h. Status max_iterations (no bound) when a step
/// would shrink below 2^-60 of [s0, s1] or more than 10000 steps are needed; numerical_failure on
/// a non-finite frame. s0 ≤ s1 (the caller checks its input).
TaylorFrame integrate_taylor_frame(const std::function<FrameSeries(double s, double h)>& series,
                                   const Eigen::Matrix3d& frame, const Eigen::Vector3d& position, double s0,
                                   double s1, double position_error, double frame_error, const char* who);

}  // namespace lac::detail
