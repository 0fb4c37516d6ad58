#pragma once
// F(u) = ∫₀^u e^(γt² − αt) dt and its inverse, the one integral behind the quadratic LA curve
// (docs/math.md §4): s(u) = −F_α(u)/Λ and θ(u) = −F_(α−1)(u)/Λ with u = log κ.
//
// Evaluation (no overflow of e^(∓α²/(4γ)), no cancellation near u = 0):
//   |γ|u² + |αu| ≤ 3   Taylor series of e^(E) about u/2, even terms only (midpoint_series(); |E| ≤ 3 there).
//                      Outside this region every difference below that could cancel has
//                      |E(u)| > 1, so at most one bit is lost.
//   γ > 0  F = (e^(E) D(x) − D(x0)) / √γ,              x = x0 + √γ u, x0 = −α/(2√γ)
//   γ < 0  F = −(√π/(2√g)) e^(y0²) (erf y0 − erf y),   g = −γ, y = y0 + √g u, y0 = α/(2√g)
//          with e^(y0²)(erf y0 − erf y) = e^(E) erfcx(y) − erfcx(y0) (y, y0 ≥ 0),
//          erfcx(−y0) − e^(E) erfcx(−y) (y, y0 ≤ 0), direct otherwise (no cancellation).
//   γ = 0  F = u · expm1(−αu)/(−αu) (the LA curve, la_curve.hpp's ratio helpers).
// e^(E)·D is formed as exp(E + log|D|), so F is finite whenever the result is.
#include <limits>

#include "lac/common/status.hpp"
#include "lac/special/erf_family.hpp"

namespace lac::detail {

struct InverseSolution {
  double u = 0;
  int iterations = 0;  ///< special-inverse iterations + polishing iterations
  Status status = Status::ok;
};

class ExpQuadraticIntegral {
 public:
  ExpQuadraticIntegral(double alpha, double gamma);

  double alpha() const { return alpha_; }
  double gamma() const { return gamma_; }
  /// E(u) = γu² − αu, so that F'(u) = e^(E(u)).
  double exponent(double u) const { return (gamma_ * u - alpha_) * u; }
  /// F(u) for finite u; ±inf only where |F| exceeds the double range.
  double operator()(double u) const;
  /// F(w) − F(v) = ∫_v^w e^(E): the midpoint series when |E'((v+w)/2)|·|w − v| ≤ 3 and
  /// |γ|(w − v)² ≤ 3 (no cancellation, one exp; for marching), the closed forms otherwise.
  double between(double v, double w) const;
  /// F(+∞) and F(−∞) (±inf when unbounded).
  double limit_plus() const { return limit_plus_; }
  double limit_minus() const { return limit_minus_; }

  /// u with F(u) = target, target strictly inside (F(−∞), F(+∞)) (caller checks).
  /// ours: erfi⁻¹ / erfc⁻¹ in log form for the start, then Halley on F with a bracket.
  /// hybrid_003: 003's formula with its hybrid inverses, unscaled, no polishing.
  InverseSolution inverse(double target, special::ErfInverseMethod method, int max_iterations) const;
  /// Safeguarded Halley on F(u) − target from a given start (used by inverse() and by marching
  /// polylines, whose previous point is a good start).
  InverseSolution polish(double target, double u, int max_iterations) const;

 private:
  double midpoint_series(double v, double w) const;
  double start_ours(double target, int& iterations) const;
  InverseSolution inverse_003(double target) const;

  double alpha_, gamma_;
  double root_ = 0;    // √|γ|
  double center_ = 0;  // x0 (γ > 0) or y0 (γ < 0)
  double base_ = 0;    // D(x0) (γ > 0); erfcx(|y0|) (γ < 0)
  double erfcx_plus_ = 0, erfcx_minus_ = 0;  // erfcx(±y0) (γ < 0)
  double limit_plus_ = std::numeric_limits<double>::infinity();
  double limit_minus_ = -std::numeric_limits<double>::infinity();
};

}  // namespace lac::detail
