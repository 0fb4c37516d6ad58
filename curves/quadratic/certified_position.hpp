#pragma once
// Positions on a quadratic LA curve (003) with a proven error bound: the Taylor-series frame
// integrator of curves/detail/taylor_frame.hpp (τ = 0) in arc length, with κ's Taylor coefficients
// κ^(i)/i! = (∓Λ)^i P_i(u) e^(φ_i(u))/i! at u = log|κ(s)| (curves/quadratic/detail/kappa_derivatives.hpp)
// and their bounds over a step from max|P_i| and max φ_i on the step's u-interval (u is monotone
// in s on each side of the inflection). The error of u = log|κ(s)| itself (the closed form's
// rounding, and 003's hybrid inverse's residual) enters each coefficient's error through
// d(P_i e^(φ_i))/du = P_(i+1) e^(φ_i).
// At the inflection (through_inflection) κ' is unbounded: a zone |s − s_i| ≤ d with d·max|κ| ≤ ε/16
// is crossed along the tangent at its start, error ≤ (zone length)²·max|κ|, as for LA segments
// (curves/planar/certified_position.hpp).
#include "lac/curves/planar/certified_position.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"

namespace lac {

/// ∫_{s0}^{s1} e^{iθ(s)} ds, s0 and s1 in the curve's domain (either order; InputError otherwise),
/// with a proven bound. Status max_iterations or numerical_failure (error +inf) where the
/// integrator's caps are reached.
CertifiedTangentIntegral integrate_quadratic_certified(const QuadraticLaCurve& curve, double s0, double s1);

}  // namespace lac
