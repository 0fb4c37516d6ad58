#pragma once
// The law of a planar LA segment in "linear q" form (004 Eqs. 2–8). Along a segment of slope α
// the quantity q = Q(κ) is linear in a length parameter u (004 Eqs. 2, 3):
//   α ≠ 0: q = sgn(κ)|κ|^(−α),  κ = K(q) = sgn(q)|q|^(−1/α)
//   α = 0: q = log|κ|,          κ = K(q) = σ e^q, σ = ±1 fixed
// The tangent angle is the integral of κ: with F' = K,
//   F(q) = α/(α−1)|q|^((α−1)/α) (α ≠ 0, 1; 004 Eq. 5),  log|q| (α = 1; Eq. 8),  σ e^q (α = 0; Eq. 7)
// and over u ∈ [ua, ub] with q linear: φ(u) = φ(ua) + (u − ua)·F[q(ua), q(u)], F[·,·] the divided
// difference. Written as a divided difference the arc (004 Appendix A) is the exact limit
// F[q, q] = K(q) instead of a 0/0.
//
// For α < 0, q passes through 0 where κ does (an inflection); for α > 0, q keeps its sign (κ = 0
// and κ = ∞ are out of reach); for α = 0 the sign of κ is σ throughout.
// Link to the standard form (curves/planar/la_curve.hpp): there κ = 1/ρ > 0 and ρ^α = 1 + αΛs
// (α ≠ 0), log ρ = Λs (α = 0), i.e. q = ρ^α (or −log ρ) is linear in s with slope αΛ (or −Λ).
#include <cmath>

namespace lac {

struct LaLaw {
  double alpha = -1;
  double sigma = 1;  ///< sign of κ for α = 0 (ignored otherwise)

  double q_of_kappa(double kappa) const {
    if (alpha == 0) return std::log(std::abs(kappa));
    return std::copysign(std::pow(std::abs(kappa), -alpha), kappa);
  }
  double kappa_of_q(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (alpha == -1) return q;
    if (q == 0) return alpha < 0 ? 0.0 : std::copysign(HUGE_VAL, q);
    return std::copysign(std::pow(std::abs(q), -1.0 / alpha), q);
  }
  /// Antiderivative of K in q (even in q for α ≠ 0).
  double F(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (alpha == 1) return std::log(std::abs(q));
    if (alpha == -1) return 0.5 * q * q;
    return alpha / (alpha - 1.0) * std::pow(std::abs(q), (alpha - 1.0) / alpha);
  }
  /// The q of sign `sign` (ignored for α = 0) with F(q) = y: the inverse of F on one side of 0.
  /// NaN where y is not a value of F.
  double F_inverse(double y, double sign) const {
    if (alpha == 0) return std::log(sigma * y);
    if (alpha == 1) return std::copysign(std::exp(y), sign);
    return std::copysign(std::pow((alpha - 1.0) / alpha * y, alpha / (alpha - 1.0)), sign);
  }
  /// dK/dq and d²K/dq².
  double dK(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    const double b = -1.0 / alpha;
    return b * std::pow(std::abs(q), b - 1.0);
  }
  double d2K(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    const double b = -1.0 / alpha;
    return b * (b - 1.0) * std::copysign(std::pow(std::abs(q), b - 2.0), q);
  }

  /// F[a, b] = (F(b) − F(a)) / (b − a), the mean curvature between q = a and q = b.
  /// Near a = b a midpoint Taylor series replaces the cancelling difference.
  double divided_difference(double a, double b) const { return divided_difference(a, F(a), b); }
  /// The same with F(a) supplied (hot loops over one segment).
  double divided_difference(double a, double Fa, double b) const {
    if (a == b) return kappa_of_q(a);
    const double d = b - a, m = 0.5 * (a + b);
    const bool close = alpha == 0 ? std::abs(d) < 1e-4 : std::abs(d) < 1e-4 * std::abs(m);
    if (close) return kappa_of_q(m) + d2K(m) * d * d / 24.0;
    return (F(b) - Fa) / d;
  }

  /// The mirror image's law (κ → −κ): σ → −σ; q → −q is the segment's part (α ≠ 0).
  LaLaw mirrored() const { return {alpha, alpha == 0 ? -sigma : sigma}; }
};

}  // namespace lac
