#pragma once
// Frenet–Serret integration of an LA space curve with a proven error bound (docs/export.md, "End
// data"): the Taylor-series frame integrator of curves/detail/taylor_frame.hpp (majorant
// remainder, rounding majorant, orthogonal propagation) on the law's coefficients κ^(i)/i!,
// τ^(i)/i! in closed form (000 Eqs. (3)–(5): κ' = −Λκ^{1+α}, τ' = ∓Ωτ^{1+β}, so
// κ^(i) = (−Λ)^i ∏_{l<i}(1 + lα) κ^{1+iα}); |κ^(i)|, |τ^(i)| are powers of the monotone ρ, μ,
// largest on a step at one of its ends.
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
