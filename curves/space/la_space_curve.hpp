#pragma once
// Log-aesthetic space curve in standard form (000 §2.1, Eqs. (3)–(5); MATH.md §3):
// P(0) = 0, T(0) = e_x, N(0) = e_y, B(0) = e_z, ρ(0) = 1, μ(0) = ν.
//   LCG  log(ρ ds/dρ) = α log ρ − log Λ     ρ(s) = (1 + αΛs)^(1/α)          (α = 0: e^(Λs))
//   LTG  log(μ ds/dμ) = β log μ − log Ω     type 1: μ(s) = (ν^β + Ωβs)^(1/β)  (β = 0: ν e^(Ωs))
//                                            type 2: μ(s) = (ν^β − Ωβs)^(1/β)  (β = 0: ν e^(−Ωs))
// Both laws are one "log-linear graph law" log r(s) = log r0 + c s r0^(−β) g(β c s r0^(−β)),
// g(x) = log1p(x)/x (→ 1 at 0), so α = 0, β = 0, Λ → 0 and Ω → 0 are exact limits, not cases.
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"

namespace lac {

/// Type 1: ρ and μ both increase with s. Type 2: ρ increases, μ decreases (000 §2.1).
enum class TorsionType { type1 = 1, type2 = 2 };

/// Open arc-length interval (lo, hi); infinite ends are ±inf.
struct SRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool contains(double s) const { return s > lo && s < hi; }
};

namespace detail {
inline double log1p_ratio(double x) { return x == 0 ? 1.0 : std::log1p(x) / x; }
inline double expm1_ratio(double y) { return y == 0 ? 1.0 : std::expm1(y) / y; }

/// The law log(r ds/dr) = slope·log r − log|rate| with r(0) = r0 and dr/ds of the sign of rate:
/// log r(s) = log r0 + log(1 + slope·k·s)/slope, k = rate·r0^(−slope) (MATH.md §1, §3).
struct GraphLaw {
  double slope = 0;    ///< α or β
  double rate = 0;     ///< Λ, +Ω (type 1) or −Ω (type 2)
  double log_r0 = 0;   ///< 0 for ρ, log ν for μ
  double k() const { return rate * std::exp(-slope * log_r0); }
  double log_r(double s) const {
    const double ks = k() * s;
    return log_r0 + ks * log1p_ratio(slope * ks);
  }
  /// ∫₀^s du / r(u) = s g(slope·k·s) h((slope − 1)(log r − log r0)) / r0 (MATH.md §1's θ(s)).
  double integral_of_inverse(double s) const {
    const double ks = k() * s;
    const double g = log1p_ratio(slope * ks);
    return s * g * expm1_ratio((slope - 1.0) * ks * g) * std::exp(-log_r0);
  }
  /// The s ≥ 0 where integral_of_inverse reaches phi ≥ 0; +inf when it never does.
  double s_at_integral_of_inverse(double phi) const {
    const double j = phi * std::exp(log_r0), kk = k();
    const double x = (slope - 1.0) * kk * j;
    if (!(1.0 + x > 0)) return std::numeric_limits<double>::infinity();
    const double g = log1p_ratio(x);
    const double s = j * g * expm1_ratio(slope * kk * j * g);
    return std::isfinite(s) && s >= 0 ? s : std::numeric_limits<double>::infinity();
  }
  /// Where 1 + slope·k·s stays positive.
  SRange range() const {
    const double c = slope * k();
    SRange r;
    if (c > 0) r.lo = -1.0 / c;
    if (c < 0) r.hi = -1.0 / c;
    return r;
  }
};
}  // namespace detail

/// Curvature and torsion laws of one LA space curve in standard form.
class LaSpaceCurve {
 public:
  /// α, β finite; Λ ≥ 0, Ω ≥ 0, ν > 0 finite, and both laws representable: α·Λ, ν^(−β) and
  /// Ω·ν^(−β)·max(1, |β|) finite doubles. Throws InputError naming the parameter otherwise.
  LaSpaceCurve(double alpha, double beta, double lambda, double omega, double nu, TorsionType type);

  double alpha() const { return rho_law_.slope; }
  double beta() const { return mu_law_.slope; }
  double lambda() const { return rho_law_.rate; }
  double omega() const { return type_ == TorsionType::type1 ? mu_law_.rate : -mu_law_.rate; }
  double nu() const { return nu_; }
  TorsionType type() const { return type_; }

  /// Open s range where ρ and μ are both positive and finite (intersection of both laws).
  SRange s_range() const;
  bool contains(double s) const { return s_range().contains(s); }

  // Hot-path forms: s must lie in s_range() (not checked).
  double log_rho(double s) const { return rho_law_.log_r(s); }
  double log_mu(double s) const { return mu_law_.log_r(s); }
  double rho(double s) const { return std::exp(log_rho(s)); }
  double mu(double s) const { return std::exp(log_mu(s)); }
  double kappa(double s) const { return std::exp(-log_rho(s)); }
  double tau(double s) const { return std::exp(-log_mu(s)); }

  /// Total turning ∫₀^s κ du of the tangent (the planar θ(s) of MATH.md §1), s in s_range().
  /// InputError naming "s" where the value is not a finite double (extreme laws, e.g. Λ near
  /// DBL_MAX, where k·s overflows): never NaN.
  double turning(double s) const;
  /// The s ≥ 0 at which the turning reaches phi ∈ [0, inf], or +inf when it never does
  /// (the turning is bounded for α < 1). InputError naming "phi" for NaN.
  double s_at_turning(double phi) const;

  /// Total torsion angle ∫₀^s τ du (frame rotation about T) and its inverse, as above.
  double torsion_turning(double s) const;
  double s_at_torsion_turning(double phi) const;

  /// Arc length at which ρ reaches exp(log_rho) (000 Eq. (17); MATH.md §3 s_c). Requires Λ > 0;
  /// InputError naming "log_rho" unless it is finite and the arc length lies in s_range().
  double s_at_log_rho(double log_rho) const;

  /// Throws InputError unless s lies in s_range().
  void check_s(double s, const char* name) const;

 private:
  detail::GraphLaw rho_law_;
  detail::GraphLaw mu_law_;
  double nu_;
  TorsionType type_;
};

/// Parameters of the second segment of a compound curve from the LCG/LTG continuity at the joint
/// (000 Eqs. (11), (16), (17), (18) with the typo of the first ν1 line corrected, MATH.md §3).
struct JointContinuation {
  double lambda1 = 0, omega1 = 0, s_c = 0, nu1 = 0;
  bool valid = false;  ///< false when ν1 has no positive real value (type 1: μc^β1 − Ω1β1 s_c ≤ 0)
};
JointContinuation continue_at_joint(double alpha0, double alpha1, double beta0, double beta1, double lambda0,
                                    double omega0, TorsionType type, double rho_c, double mu_c);

}  // namespace lac
