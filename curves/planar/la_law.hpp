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
//
// Offset form (`offset`, any α; the α = 0 law is its limit and needs no flag). For small |α| the
// q above is ±(1 − α log|κ|) to first order: a double q then holds log|κ| only to ε/|α| (2e-4 at
// α = 1e-12). The offset form stores the Box–Cox value q = (t − 1)/(−α) instead, with
// t = σ sgn(κ)|κ|^(−α) = 1 − αq the q above times σ (affine in it, so still linear in u):
//   κ = σ sgn(t)|t|^(−1/α) = σ exp(q·log1p(−αq)/(−αq)) where t > 0,   F = σ|t|^p/(1 − α),
// p = 1 − 1/α; q → log|κ| and F → σe^q as α → 0, continuously. Where κ keeps the sign σ (t > 0)
// q carries log|κ| to rounding for every α; t < 0 (κ of sign −σ, past an inflection for α < 0) is
// representable with the precision of the plain form. The mirror image is σ → −σ, q unchanged.
//
// Divided differences, both forms: with t the plain q (σ(1 − αq) in the offset form) and
// z = (t_b − t_a)/t_a > −1 (no zero of t between), F[a, b] = K(a)·E₁(p log1p(z))·log1p(z)/z,
// E₁(y) = expm1(y)/y: no cancellation near a = b, near α = 1 (p → 0, the logarithmic spiral) nor
// near α = 0, and the exact value K(a) at a = b.
#include <cmath>

#include "lac/common/numeric.hpp"

namespace lac {

struct LaLaw {
  double alpha = -1;
  double sigma = 1;     ///< sign of κ for α = 0, and where t > 0 in the offset form (ignored otherwise)
  bool offset = false;  ///< q is the Box–Cox value (|κ|^(−α) − 1)/(−α) (above)

  /// Whether q is log|κ| or its Box–Cox generalization (α = 0 or the offset form): σ gives the sign.
  bool log_form() const { return alpha == 0 || offset; }
  /// t = the plain form's q (σ(1 − αq) in the offset form, σ at α = 0): κ = 0 or ∞ where t = 0.
  double t_of_q(double q) const { return log_form() ? sigma * (1.0 - alpha * q) : q; }
  /// (t(b) − t(a))/t(a) without cancellation.
  double relative_t(double a, double b) const {
    if (!log_form()) return (b - a) / a;
    return -alpha * (b - a) / (1.0 - alpha * a);
  }

  static double expm1_ratio(double y) { return y == 0 ? 1.0 : std::expm1(y) / y; }
  static double log1p_ratio(double z) { return z == 0 ? 1.0 : std::log1p(z) / z; }

  double q_of_kappa(double kappa) const {
    if (alpha == 0) return std::log(std::abs(kappa));
    if (offset) {
      if (kappa * sigma > 0) {
        const double l = std::log(std::abs(kappa));
        return l * expm1_ratio(-alpha * l);
      }
      return (1.0 + power(std::abs(kappa), -alpha)) / alpha;  // t = −|κ|^(−α) (κ = 0: t = 0)
    }
    return std::copysign(power(std::abs(kappa), -alpha), kappa);
  }
  double kappa_of_q(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (offset) {
      const double z = -alpha * q;
      if (z > -1) return sigma * std::exp(q * log1p_ratio(z));
      if (z == -1) return alpha < 0 ? 0.0 : sigma * HUGE_VAL;
      return -sigma * power(-(1.0 + z), -1.0 / alpha);
    }
    if (alpha == -1) return q;
    if (q == 0) return alpha < 0 ? 0.0 : std::copysign(HUGE_VAL, q);
    return std::copysign(power(std::abs(q), -1.0 / alpha), q);
  }
  /// Antiderivative of K in q (even in t for α ≠ 0).
  double F(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (offset) {
      const double z = -alpha * q;
      if (alpha == 1) return z > -1 ? sigma * q * log1p_ratio(z) : -sigma * std::log(std::abs(1.0 + z));
      if (z > -1) return sigma * std::exp((1.0 - alpha) * q * log1p_ratio(z)) / (1.0 - alpha);
      return sigma * power(std::abs(1.0 + z), 1.0 - 1.0 / alpha) / (1.0 - alpha);
    }
    if (alpha == 1) return std::log(std::abs(q));
    if (alpha == -1) return 0.5 * q * q;
    return alpha / (alpha - 1.0) * power(std::abs(q), (alpha - 1.0) / alpha);
  }
  /// The q on the side `sign` of the zero of t (the sign of t; ignored for α = 0) with F(q) = y:
  /// the inverse of F on that side. NaN where y is not a value of F.
  double F_inverse(double y, double sign) const {
    if (alpha == 0) return std::log(sigma * y);
    if (offset) {
      if (alpha == 1) return sign > 0 ? -std::expm1(-sigma * y) : 1.0 + std::exp(-sigma * y);
      const double v = y * (1.0 - alpha) * sigma;  // |t|^p
      if (sign > 0) {
        const double l = std::log(v) / (1.0 - alpha);  // log|κ|
        return l * expm1_ratio(-alpha * l);
      }
      return (1.0 + power(v, alpha / (alpha - 1.0))) / alpha;
    }
    if (alpha == 1) return std::copysign(std::exp(y), sign);
    return std::copysign(power((alpha - 1.0) / alpha * y, alpha / (alpha - 1.0)), sign);
  }
  /// dK/dq and d²K/dq².
  double dK(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (offset) return kappa_of_q(q) / (1.0 - alpha * q);
    const double b = -1.0 / alpha;
    return b * power(std::abs(q), b - 1.0);
  }
  double d2K(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (offset) {
      const double t = 1.0 - alpha * q;
      return kappa_of_q(q) * (1.0 + alpha) / (t * t);
    }
    const double b = -1.0 / alpha;
    return b * (b - 1.0) * std::copysign(power(std::abs(q), b - 2.0), q);
  }

  /// F[a, b] = (F(b) − F(a)) / (b − a), the mean curvature between q = a and q = b.
  double divided_difference(double a, double b) const { return divided(a, kappa_of_q(a), F(a), b); }
  /// The same with F(a) supplied.
  double divided_difference(double a, double Fa, double b) const { return divided(a, kappa_of_q(a), Fa, b); }
  /// The same with K(a) and F(a) supplied (hot loops over one segment). Where F(b)/F(a) = e^(pL)
  /// is within a factor e of 1 (or t has a zero between a and b) the plain difference quotient
  /// cancels: K(a)·E₁(pL)·log1p(z)/z instead (above).
  double divided(double a, double Ka, double Fa, double b) const {
    if (a == b) return Ka;
    const double z = relative_t(a, b);
    if (z > -1 && std::isfinite(z)) {
      // log(t_b/t_a): from the ratio itself where z is not small (z = −1 + t_b/t_a would lose
      // t_b/t_a's digits when it is tiny), log1p(z) near 1.
      const double R = std::abs(z) > 0.5 && !log_form() ? std::log(b / a) / z : log1p_ratio(z);
      // p·log(t_b/t_a), p = 1 − 1/α: in the offset form (1 − α)(b − a)R/t_a (finite at α = 0).
      const double pL = log_form() ? (1.0 - alpha) * (b - a) * R / (1.0 - alpha * a)
                                   : (1.0 - 1.0 / alpha) * (z * R);
      if (std::abs(pL) < 1) return Ka * expm1_ratio(pL) * R;
    }
    return (F(b) - Fa) / (b - a);  // no cancellation, a zero of t between a and b (α < 0), or t(a) = 0
  }

  /// The mirror image's law (κ → −κ): σ → −σ in the log forms; q → −q is the segment's part
  /// in the plain form (α ≠ 0).
  LaLaw mirrored() const { return {alpha, log_form() ? -sigma : sigma, offset}; }
};

}  // namespace lac
