#pragma once
// Planar log-aesthetic curve in standard form (MATH.md §1; 001 Table 1; 002 Eqs. 1–6):
// reference point at the origin, tangent +x, ρ = 1 there, ρ increasing with s.
// LCG: log(ρ ds/dρ) = α log ρ − log Λ, so ds/dρ = ρ^(α−1)/Λ. Λ = 0 is the unit circle.
//
// All conversions are written as products of
//   g(x) = log1p(x)/x  and  h(y) = expm1(y)/y   (both → 1 at 0),
// which makes α = 0, α = 1 and Λ → 0 exact limits instead of special cases:
//   log ρ(s) = Λ s g(αΛs),          θ(s) = s g(αΛs) h((α−1) log ρ)
//   log ρ(θ) = Λ θ g((α−1)Λθ),     s(θ) = θ g((α−1)Λθ) h(α log ρ)
#include <cmath>
#include <complex>
#include <limits>

namespace lac {

/// An open interval (lo, hi); infinite ends are ±inf.
struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool contains(double t) const { return t > lo && t < hi; }
};

/// A point of a planar curve with its Frenet data. tangent = (cos θ, sin θ).
struct CurvePoint {
  double s = 0;
  double theta = 0;
  double rho = 1;    ///< radius of curvature (> 0; the curve turns left)
  double kappa = 1;  ///< curvature 1/ρ
  std::complex<double> position{};
};

/// Which parameter a value refers to.
enum class Parameter { theta, s };

class LaCurve {
 public:
  /// α any finite real, Λ ≥ 0 finite. Throws InputError otherwise.
  LaCurve(double alpha, double lambda);

  double alpha() const { return alpha_; }
  double lambda() const { return lambda_; }

  /// Open domains of θ and s (001 Table 1 as restated in MATH.md §1).
  Interval theta_domain() const;
  Interval s_domain() const;
  Interval domain(Parameter p) const { return p == Parameter::theta ? theta_domain() : s_domain(); }

  /// Closed-form conversions. Arguments must lie in the open domain (InputError otherwise).
  double log_rho_at_theta(double theta) const;
  double log_rho_at_s(double s) const;
  double rho_at_theta(double theta) const;
  double rho_at_s(double s) const;
  double kappa_at_theta(double theta) const;
  double kappa_at_s(double s) const;
  double s_at_theta(double theta) const;
  double theta_at_s(double s) const;
  /// Inverse of ρ: requires Λ > 0 (ρ ≡ 1 on the circle); log ρ in the range the domain allows.
  double theta_at_log_rho(double log_rho) const;
  double s_at_log_rho(double log_rho) const;

  /// θ ↔ s for a value of either parameter.
  double to_theta(Parameter p, double t) const { return p == Parameter::theta ? t : theta_at_s(t); }
  double to_s(Parameter p, double t) const { return p == Parameter::s ? t : s_at_theta(t); }

  /// Throws InputError naming `name` and the valid range unless t is inside the domain.
  void check(Parameter p, double t, const char* name) const;

  /// Hot-path forms without the domain check, for integrands (t must be inside the domain).
  double log_rho_at_theta_unchecked(double theta) const {
    const double x = lambda_ * theta;
    return x * log1p_ratio((alpha_ - 1.0) * x);
  }
  double theta_at_s_unchecked(double s) const {
    const double x = lambda_ * s;
    const double log_rho = x * log1p_ratio(alpha_ * x);
    return s * log1p_ratio(alpha_ * x) * expm1_ratio((alpha_ - 1.0) * log_rho);
  }

  /// g(x) = log1p(x)/x and h(y) = expm1(y)/y, both continuous (= 1) at 0.
  static double log1p_ratio(double x) { return x == 0 ? 1.0 : std::log1p(x) / x; }
  static double expm1_ratio(double y) { return y == 0 ? 1.0 : std::expm1(y) / y; }

  /// Everything but the position, at θ or s. Throws InputError when ρ, s or θ is not
  /// representable in double there (overflow near an open end of the domain).
  CurvePoint frame_at(Parameter p, double t) const;

 private:
  double alpha_;
  double lambda_;
};

}  // namespace lac
