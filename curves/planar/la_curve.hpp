#pragma once
// Planar log-aesthetic curve in standard form (docs/math.md §1; 001 Table 1; 002 Eqs. 1–6):
// reference point at the origin, tangent +x, ρ = 1 there, ρ increasing with s.
// LCG: log(ρ ds/dρ) = α log ρ − log Λ, so ds/dρ = ρ^(α−1)/Λ. Λ = 0 is the unit circle.
//
// All conversions are written as products of
//   g(x) = log1p(x)/x  and  h(y) = expm1(y)/y   (both → 1 at 0),
// which makes α = 0, α = 1 and Λ → 0 exact limits instead of special cases:
//   log ρ(s) = Λ s g(αΛs),          θ(s) = s g(αΛs) h((α−1) log ρ)
//   log ρ(θ) = Λ θ g((α−1)Λθ),     s(θ) = θ g((α−1)Λθ) h(α log ρ)
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <span>

#include "lac/common/numeric.hpp"
#include "lac/curves/curve.hpp"

namespace lac {

/// Which parameter a value refers to.
enum class Parameter { theta, s };

class LaCurve {
 public:
  /// α any finite real, Λ ≥ 0 finite. Throws InputError otherwise.
  LaCurve(double alpha, double lambda);

  double alpha() const { return alpha_; }
  double lambda() const { return lambda_; }

  /// Open domains of θ and s (001 Table 1 as restated in docs/math.md §1), computed once.
  Interval theta_domain() const { return theta_domain_; }
  Interval s_domain() const { return s_domain_; }
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

  /// Hot-path forms without the domain check, for integrands and for the laws of other curve
  /// models (t must be inside the domain; the result may be non-finite where it is not
  /// representable).
  double log_rho_at_theta_unchecked(double theta) const {
    double g = 0;
    return log_rho_and_g(Parameter::theta, theta, g);
  }
  double log_rho_at_s_unchecked(double s) const {
    double g = 0;
    return log_rho_and_g(Parameter::s, s, g);
  }
  double theta_at_s_unchecked(double s) const {
    double theta = 0;
    log_rho_and_other(Parameter::s, s, theta);
    return theta;
  }
  double s_at_theta_unchecked(double theta) const {
    double s = 0;
    log_rho_and_other(Parameter::theta, theta, s);
    return s;
  }
  /// s where log ρ is reached: (log ρ / Λ) h(α log ρ) (Λ > 0).
  double s_at_log_rho_unchecked(double log_rho) const { return log_rho / lambda_ * expm1_ratio(alpha_ * log_rho); }

  /// Everything but the position, at θ or s. Throws InputError when ρ, s or θ is not
  /// representable in double there (overflow near an open end of the domain).
  CurvePoint frame_at(Parameter p, double t) const;
  /// frame_at(Parameter::s, s): the arc-length form every curve model offers.
  CurvePoint frame_at(double s) const { return frame_at(Parameter::s, s); }

  /// frame_at for a t already known to lie inside the open domain (e.g. between the checked ends
  /// of a polyline): no domain check, but still an InputError where the point is not
  /// representable. One log1p, one expm1 and one exp: log ρ is computed once and ρ, κ and the
  /// other parameter derive from it.
  CurvePoint frame_inside(Parameter p, double t) const {
    CurvePoint c;
    (p == Parameter::theta ? c.theta : c.s) = t;
    double g = 0;
    const double log_rho = log_rho_and_g(p, t, g);
    finish_frame(p, g, log_rho, c);
    return c;
  }

  /// frame_inside for every point of `points`, whose θ (p = theta) or s (p = s) holds the
  /// parameter on entry: the same values bit for bit, computed in two passes (all log1p, then
  /// all expm1 and exp) so that the independent calls of different points overlap in the CPU
  /// (1001 frames: ~30 % less time than one frame after the other).
  void frames_inside(Parameter p, std::span<CurvePoint> points) const;

 private:
  // frame_inside in two stages: log ρ and g (one log1p), then the other parameter, ρ and κ
  // (one expm1, one exp) with the representability check.
  double log_rho_and_g(Parameter p, double t, double& g) const {
    const double x = lambda_ * t, z = (p == Parameter::theta ? alpha_ - 1.0 : alpha_) * x;
    // Toward the end of the domain (z → −1) 1 + z cancels: 1 + cΛt there from exact products (0
    // where a t the domain check let through, e.g. θ_max rounded up, lies beyond the exact end).
    g = z < -0.5 ? std::log(std::max(0.0, one_plus_c_lambda_t(p, t))) / z : log1p_ratio(z);
    return x * g;
  }
  /// 1 + cΛt (c = α, or α − 1 at θ) with the products and sums error-free (fma, two-sum): ~ε
  /// relative however close cΛt is to −1 (where the rounded 1 + z keeps none of its digits).
  double one_plus_c_lambda_t(Parameter p, double t) const;
  void finish_frame(Parameter p, double g, double log_rho, CurvePoint& c) const {
    const bool at_theta = p == Parameter::theta;
    const double t = at_theta ? c.theta : c.s;
    (at_theta ? c.s : c.theta) =
        inside(at_theta ? s_domain_ : theta_domain_, t * (g * expm1_ratio((at_theta ? alpha_ : alpha_ - 1.0) * log_rho)));
    c.rho = std::exp(log_rho);
    // 1/ρ carries ρ's rounding plus one; below DBL_MIN ρ is subnormal (few bits), so take e^(−log ρ).
    c.kappa = c.rho >= std::numeric_limits<double>::min() ? 1.0 / c.rho : std::exp(-log_rho);
    if (!(std::isfinite(c.s) && std::isfinite(c.theta) && c.rho > 0 && c.rho <= std::numeric_limits<double>::max() &&
          c.kappa > 0 && c.kappa <= std::numeric_limits<double>::max()))
      throw_unrepresentable(p, t, log_rho);
  }

  /// log ρ at θ (or s), and the other parameter s (or θ) into `other`, sharing g:
  ///   θ given: x = Λθ, g = g((α−1)x), log ρ = x g, s = θ g h(α log ρ)
  ///   s given: x = Λs, g = g(αx),     log ρ = x g, θ = s g h((α−1) log ρ)
  /// No checks; the results may be non-finite outside the representable range. g·h is formed
  /// first: at extreme α, Λ the two factors compensate (e.g. 7e-298 and 1.4e297 for α = Λ = 1e300,
  /// θ = 1e-300, s = 1e-300), where t·g would underflow to 0.
  double log_rho_and_other(Parameter p, double t, double& other) const {
    double g = 0;
    const double log_rho = log_rho_and_g(p, t, g);
    other = inside(p == Parameter::theta ? s_domain_ : theta_domain_,
                   t * (g * expm1_ratio((p == Parameter::theta ? alpha_ : alpha_ - 1.0) * log_rho)));
    return log_rho;
  }
  /// v, or the nearest double inside an open end of d that v reaches by rounding (θ of an s next
  /// to the end of the s domain rounds onto θ_max, which is outside the θ domain).
  static double inside(const Interval& d, double v) {
    if (!d.hi_closed && v >= d.hi && std::isfinite(d.hi)) return std::nextafter(d.hi, -HUGE_VAL);
    if (!d.lo_closed && v <= d.lo && std::isfinite(d.lo)) return std::nextafter(d.lo, HUGE_VAL);
    return v;
  }
  [[noreturn]] void throw_unrepresentable(Parameter p, double t, double log_rho) const;

  double alpha_;
  double lambda_;
  Interval theta_domain_;
  Interval s_domain_;
};

}  // namespace lac
