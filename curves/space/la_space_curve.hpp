#pragma once
// Log-aesthetic space curve in standard form (000 §2.1, Eqs. (3)–(5); docs/math.md §3):
// P(0) = 0, T(0) = e_x, N(0) = e_y, B(0) = e_z, ρ(0) = 1, μ(0) = ν.
//   LCG  log(ρ ds/dρ) = α log ρ − log Λ     ρ(s) = (1 + αΛs)^(1/α)          (α = 0: e^(Λs))
//   LTG  log(μ ds/dμ) = β log μ − log Ω     type 1: μ(s) = (ν^β + Ωβs)^(1/β)  (β = 0: ν e^(Ωs))
//                                            type 2: μ(s) = (ν^β − Ωβs)^(1/β)  (β = 0: ν e^(−Ωs))
// Both laws are the standard-form law of the planar LA curve (curves/planar/la_curve.hpp):
// ρ(s) is LaCurve(α, Λ)'s, and μ(s) = ν ρ̃(±s) with ρ̃ the ρ of LaCurve(β, Ω ν^(−β)) (+ for type
// 1, − for type 2), so α = 0, β = 0, Λ → 0 and Ω → 0 are exact limits, not cases; the turning
// angles ∫κ ds and ∫τ ds are that curve's θ(s).
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/common/numeric.hpp"
#include "lac/curves/planar/la_curve.hpp"

namespace lac {

/// Type 1: ρ and μ both increase with s. Type 2: ρ increases, μ decreases (000 §2.1).
enum class TorsionType { type1 = 1, type2 = 2 };

/// Curvature and torsion laws of one LA space curve in standard form.
class LaSpaceCurve {
 public:
  /// α, β finite; Λ ≥ 0, Ω ≥ 0, ν > 0 finite, and both laws representable: α·Λ, ν^(−β) and
  /// Ω·ν^(−β)·max(1, |β|) finite doubles. Throws InputError naming the parameter otherwise.
  LaSpaceCurve(double alpha, double beta, double lambda, double omega, double nu, TorsionType type);

  double alpha() const { return rho_law_.alpha(); }
  double beta() const { return mu_law_.alpha(); }
  double lambda() const { return rho_law_.lambda(); }
  double omega() const { return omega_; }
  double nu() const { return nu_; }
  TorsionType type() const { return type_; }

  /// Open s range where ρ and μ are both positive and finite (intersection of both laws).
  Interval s_range() const;
  bool contains(double s) const { return s_range().contains(s); }

  // Hot-path forms: s must lie in s_range() (not checked).
  double log_rho(double s) const { return rho_law_.log_rho_at_s_unchecked(s); }
  double log_mu(double s) const { return log_nu_ + mu_law_.log_rho_at_s_unchecked(mu_sign_ * s); }
  double rho(double s) const { return std::exp(log_rho(s)); }
  double mu(double s) const { return std::exp(log_mu(s)); }
  double kappa(double s) const { return std::exp(-log_rho(s)); }
  double tau(double s) const { return std::exp(-log_mu(s)); }
  /// dκ/ds = −Λ ρ^(−1−α), since dρ/ds = Λ ρ^(1−α) (000 Eqs. (1), (3)).
  double dkappa_ds(double s) const { return -lambda() * std::exp(-(1.0 + alpha()) * log_rho(s)); }

  /// Total turning ∫₀^s κ du of the tangent (the planar θ(s) of docs/math.md §1), s in s_range().
  /// InputError naming "s" where the value is not a finite double (extreme laws, e.g. Λ near
  /// DBL_MAX, where k·s overflows): never NaN.
  double turning(double s) const;
  /// The s ≥ 0 at which the turning reaches phi ∈ [0, inf], or +inf when it never does
  /// (the turning is bounded for α < 1). InputError naming "phi" for NaN.
  double s_at_turning(double phi) const;

  /// Total torsion angle ∫₀^s τ du (frame rotation about T) and its inverse, as above.
  double torsion_turning(double s) const;
  double s_at_torsion_turning(double phi) const;

  /// Arc length at which ρ reaches exp(log_rho) (000 Eq. (17); docs/math.md §3.3 s_c). Requires Λ > 0;
  /// InputError naming "log_rho" unless it is finite and the arc length lies in s_range().
  double s_at_log_rho(double log_rho) const;

  /// Throws InputError unless s lies in s_range().
  void check_s(double s, const char* name) const;

 private:
  LaCurve rho_law_{0, 0};  ///< ρ(s)
  LaCurve mu_law_{0, 0};   ///< μ(s)/ν at ±s (mu_sign_)
  double mu_sign_ = 1;     ///< +1 type 1, −1 type 2
  double omega_;
  double nu_, log_nu_;
  TorsionType type_;
};

/// Parameters of the second segment of a compound curve from the LCG/LTG continuity at the joint
/// (000 Eqs. (11), (16), (17), (18) with the typo of the first ν1 line corrected, docs/math.md §3).
struct JointContinuation {
  double lambda1 = 0, omega1 = 0, s_c = 0, nu1 = 0;
  bool valid = false;  ///< false when ν1 has no positive real value (type 1: μc^β1 − Ω1β1 s_c ≤ 0)
};
JointContinuation continue_at_joint(double alpha0, double alpha1, double beta0, double beta1, double lambda0,
                                    double omega0, TorsionType type, double rho_c, double mu_c);

}  // namespace lac
