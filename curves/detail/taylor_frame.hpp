#pragma once
// The Taylor-series frame integrator with a proven error bound shared by the certified space
// (curves/space/certified_frenet.hpp) and planar (curves/planar/certified_position.hpp) paths.
//
// F' = F K(s), K = [[0, −κ, 0], [κ, 0, −τ], [0, τ, 0]] (τ = 0 for a planar curve); over a step
// F(s + h) = F(s) G(h) with G' = G K, G(0) = I, so G's Taylor coefficients follow from K's by
// G_{j+1} = Σ_{i≤j} G_i K_{j−i} / (j+1), and P(s + h) = P(s) + F(s) Σ_j G_j e₁ h^{j+1}/(j+1).
// Remainder: the caller's coefficient maxima over the step (`majorant`; for LA laws |κ^(i)|, |τ^(i)|
// are largest at an end of the step, powers of a monotone quantity) put through the same recursion bound every
// coefficient of G at every point of the step, hence ‖G^(m)/m!‖ there. The exact propagator G(h)
// is orthogonal, so a frame error is carried without growth:
// δ_{k+1} ≤ δ_k + (1 + δ_k)(remainder + rounding). Rounding: a majorant E_j of the computed G_j's
// error by the recursion's own rule. Written by hand: no library in Debian integrates an ODE with a
// proven bound.
#include <Eigen/Core>
#include <array>
#include <complex>
#include <functional>
#include <optional>
#include <string>

#include "lac/common/status.hpp"

namespace lac {

/// A planar tangent integral ∫ e^{iθ} with a proven bound (curves/planar/certified_position.hpp,
/// curves/quadratic/certified_position.hpp).
struct CertifiedTangentIntegral {
  std::complex<double> value;  ///< ∫ e^{iθ} over the parameter interval
  double error = 0;            ///< proven bound on |value − exact|
  long steps = 0;              ///< Taylor steps taken
  Status status = Status::ok;
  std::string message;
};

}  // namespace lac

namespace lac::detail {

inline constexpr int kTaylorTerms = 24;  ///< G_0 … G_23 are summed; G_24 bounds the remainder

/// Scaled Taylor coefficients of κ and τ over a step of size h from s: κ^(i)(s)/i! · h^(i+1) (and
/// τ's), i = 0 … kTaylorTerms − 1, and bounds on their errors (rounding, and the error of the point
/// on the law they are taken at).
struct FrameSeries {
  std::array<double, kTaylorTerms> kappa{}, tau{};
  std::array<double, kTaylorTerms> kappa_error{}, tau_error{};  ///< absolute
};

/// Bounds on |κ^(i)|/i! · h^(i+1) and |τ^(i)|/i! · h^(i+1) at every point of a step.
struct FrameMajorant {
  std::array<double, kTaylorTerms> kappa{}, tau{};
};

using FrameSeriesFunction = std::function<FrameSeries(double s, double h)>;
/// `majorant(s0, s1, h)`: the bounds on [s0, s1] (s1 = s0 + h up to rounding).
using FrameMajorantFunction = std::function<FrameMajorant(double s0, double s1, double h)>;

/// For the LA laws, whose |κ^(i)|, |τ^(i)| are powers of a monotone quantity: the larger of the
/// coefficients' sizes at the step's two ends.
FrameMajorantFunction end_majorant(FrameSeriesFunction series);

struct TaylorFrame {
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  ///< [T N B] at s1
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double position_error = 0;  ///< proven bound on |P − P_exact|
  double frame_error = 0;     ///< proven bound on ‖F − F_exact‖ (Frobenius)
  long steps = 0;
  Status status = Status::ok;
  std::string message;
};

/// `series(s, h)`: the coefficients at s for a step h; `majorant`: their bounds over a step. Status
/// max_iterations (no bound) when a step would shrink below 2^-60 of [s0, s1] or more than 10000
/// steps are needed; numerical_failure on a non-finite frame or bound. s0 ≤ s1 (the caller checks
/// its input).
TaylorFrame integrate_taylor_frame(const FrameSeriesFunction& series, const FrameMajorantFunction& majorant,
                                   const Eigen::Matrix3d& frame, const Eigen::Vector3d& position, double s0,
                                   double s1, double position_error, double frame_error, const char* who);

/// A zone [a, b] crossed along the tangent at its start, |κ| ≤ kappa on it: the error is at most
/// (length)²·kappa (the turning over the zone times its length). For points where the law's
/// derivatives are unbounded (an inflection of an LA segment with −1/α not an integer, of the
/// quadratic LA curve).
struct TangentZone {
  double a, b, kappa;
};

/// ∫_{t0}^{t1} e^{iθ(t)} dt (t0 ≤ t1, unit speed in t) with a proven bound: the parts outside the
/// zone by the Taylor integrator (τ = 0), each from the tangent angle `angle(t, error)` (closed form,
/// with a bound on its error), so that angle errors do not accumulate; the zone along the tangent.
CertifiedTangentIntegral integrate_plane_tangent(const FrameSeriesFunction& series, const FrameMajorantFunction& majorant,
                                                 const std::function<double(double t, double& error)>& angle,
                                                 double t0, double t1, std::optional<TangentZone> zone, const char* who);

}  // namespace lac::detail
