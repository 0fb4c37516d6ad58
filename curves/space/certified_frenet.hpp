#pragma once
// Frenet–Serret integration of an LA space curve with a proven error bound (docs/export.md, "End
// data"): Taylor series of the frame F = [T N B] with a majorant remainder.
//
// F' = F K(s), K = [[0, −κ, 0], [κ, 0, −τ], [0, τ, 0]]; over a step F(s + h) = F(s) G(h) with
// G' = G K, G(0) = I, so G's Taylor coefficients follow from K's by G_{j+1} = Σ_{i≤j} G_i K_{j−i} / (j+1),
// and P(s + h) = P(s) + F(s) Σ_j G_j e₁ h^{j+1}/(j+1). K's coefficients are κ^(i)/i! and τ^(i)/i!
// in closed form (000 Eqs. (3)–(5): κ' = −Λκ^{1+α}, τ' = ∓Ωτ^{1+β}, so κ^(i) = (−Λ)^i ∏_{l<i}(1 + lα) κ^{1+iα}).
// Remainder: |κ^(i)|, |τ^(i)| are powers of the monotone ρ, μ, largest on a step at one of its
// ends; the same recursion on those maxima (absolute values) bounds every coefficient of G at every
// point of the step, hence ‖G^(m)/m!‖ there. The exact propagator G(h) is orthogonal, so an error
// of the frame is carried without growth: δ_{k+1} ≤ δ_k + (1 + δ_k)(remainder + rounding).
// Written by hand: no library in Debian integrates an ODE with a proven bound.
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/space/frenet.hpp"
#include "lac/curves/space/la_space_curve.hpp"

namespace lac {

struct CertifiedFrame {
  Frame3 frame;               ///< position and frame at s1
  double position_error = 0;  ///< proven bound on |P − P_exact| (standard-form units)
  double frame_error = 0;     ///< proven bound on ‖F − F_exact‖ (Frobenius; bounds |ΔT|, |ΔN|, |ΔB|)
  long steps = 0;             ///< Taylor steps taken
  Status status = Status::ok;
  std::string message;
};

/// Integrates from (s0, start) to s1 ≥ s0 inside curve.s_range() (InputError otherwise).
/// `start_position_error`, `start_frame_error`: bounds on the start's own errors, carried along.
/// Status max_iterations (no bound) when a step would need to shrink below 2^-60 of the range or
/// more than 10000 steps are needed.
CertifiedFrame integrate_frenet_certified(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1,
                                          double start_position_error = 0, double start_frame_error = 0);

}  // namespace lac
