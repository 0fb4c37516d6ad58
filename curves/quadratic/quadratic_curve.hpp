#pragma once
// Quadratic log-aesthetic curve (003; docs/math.md §4 corrects its Eqs. 4.2 and 4.6): the LCG is
// the parabola log(ρ ds/dρ) = γ(log ρ)² + α log ρ − log Λ. In u = log κ (standard form:
// κ = 1, θ = 0, position 0 at s = 0; κ decreases with s):
//   ds/du = −e^(E(u))/Λ,  E(u) = γu² − αu,     s(u) = −F_α(u)/Λ,
//   dθ/du = κ ds/du,                             θ(u) = −F_(α−1)(u)/Λ,
// with F_a(u) = ∫₀^u e^(γt² − a t) dt evaluated in scaled form (Dawson for γ > 0, erfcx for
// γ < 0, the LA curve for γ = 0; detail/exp_quadratic_integral.hpp). No |z| ≤ 5 / ≤ 26 limit
// and no overflow of e^(∓α²/(4γ)) remains; the only limit is a true one: an arc-length bound
// beyond the double range (|α|/(2√−γ) > 26.6) is reported as ±inf.
//
// Domain: s ∈ (s(κ→∞), s(κ→0)). γ < 0 has both ends finite (003 property 3); γ = 0 is the LA
// curve of docs/math.md §1; γ > 0 is unbounded both ways. At a finite s(κ→0) the curvature reaches
// 0 (inflection). With QuadraticOptions::through_inflection the curve continues past it
// point-symmetrically (C(s_i + t) − C(s_i) = C(s_i) − C(s_i − t): θ(s_i + t) = θ(s_i − t),
// signed κ(s_i + t) = −κ(s_i − t), the LCG of |κ| is the same parabola) up to
// 2 s_i − s(κ→∞); otherwise s(κ→0) is an open end.
#include <cmath>
#include <string_view>

#include "lac/common/status.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/curves/quadratic/detail/exp_quadratic_integral.hpp"
#include "lac/special/erf_family.hpp"

namespace lac {

struct QuadraticOptions {
  /// erfi⁻¹ / erf⁻¹ used by κ(s): ours (default; scaled, polished, whole range) or 003's
  /// hybrid bisection–Newton (unscaled, |z| ≤ 26 / ≤ 5, no polishing; for comparison).
  special::ErfInverseMethod inverse = special::ErfInverseMethod::ours;
  /// Continue past κ = 0 by point symmetry (signed curvature). Default false: open end.
  bool through_inflection = false;
  /// Cap on the polishing iterations of κ(s) (default 60; typically 1–2 are used).
  int max_iterations = 60;
  void validate() const;
};

/// κ(s) with its provenance.
struct KappaSolution {
  double log_kappa = 0;   ///< u = log|κ|
  double kappa = 1;       ///< signed curvature (negative past the inflection)
  int iterations = 0;     ///< inverse-function + polishing iterations
  Status status = Status::ok;
};

/// log|κ|(s) where κ itself may exceed the double range (see solve_log_kappa).
struct LogKappaSolution {
  double log_kappa = 0;  ///< u = log|κ| (−inf only at the inflection point itself)
  int sign = 1;          ///< sign of κ (−1 past the inflection)
  int iterations = 0;
  Status status = Status::ok;
};

class QuadraticLaCurve {
 public:
  /// α, γ finite, Λ > 0 finite; InputError otherwise (Λ = 0 would be a circle, which has no
  /// κ(s) to invert).
  QuadraticLaCurve(double alpha, double gamma, double lambda, QuadraticOptions options = {});

  double alpha() const { return alpha_; }
  double gamma() const { return gamma_; }
  double lambda() const { return lambda_; }
  const QuadraticOptions& options() const { return options_; }

  /// Arc length at κ → ∞ (lower end) and at κ → 0 (upper end), docs/math.md §4 (erfcx forms).
  double s_at_infinite_kappa() const { return s_lo_; }
  double s_at_zero_kappa() const { return s_hi_; }
  /// Open s domain of the curve (extended past the inflection when the option is on).
  Interval s_domain() const;
  bool has_inflection() const;  ///< s(κ→0) finite
  /// θ at κ → 0 (finite when has_inflection()).
  double theta_at_zero_kappa() const { return theta_hi_; }

  /// Closed forms in u = log κ (any finite u, InputError "log_kappa" otherwise; ±inf only past
  /// the double range).
  double s_at_log_kappa(double u) const;
  double theta_at_log_kappa(double u) const;
  /// θ(u1) − θ(u0) for finite u0, u1: a local series for nearby u (no cancellation; used when
  /// marching along the curve), the closed forms otherwise.
  double theta_difference(double u0, double u1) const { return -theta_integral_.between(u0, u1) / lambda_; }
  /// s(κ), κ > 0.
  double s_at_kappa(double kappa) const;
  /// ds/dκ = −κ^(−α + γ log κ − 1)/Λ (docs/math.md §4), κ > 0.
  double ds_dkappa(double kappa) const;
  /// The LCG parabola: log(ρ ds/dρ) = γ(log ρ)² + α log ρ − log Λ.
  double lcg(double log_rho) const;

  /// κ(s) for s in s_domain() (InputError otherwise, also where κ exceeds the double range),
  /// with iterations and status (a failed hybrid_003 solve returns κ = ±1 with its status).
  KappaSolution solve_kappa(double s) const;
  /// As solve_kappa, but also where κ = e^u exceeds the double range (e.g. the plateau of s(u)
  /// for small γ > 0): only u = log|κ| is returned.
  LogKappaSolution solve_log_kappa(double s) const;
  double kappa_at_s(double s) const { return solve_kappa(s).kappa; }
  /// κ(s) by Halley from a nearby log κ (e.g. the previous point of a polyline): no erfi⁻¹ start.
  KappaSolution solve_kappa_near(double s, double log_kappa_guess) const;
  /// d(log|κ|)/ds = −Λ e^(−E(u)) at u = log|κ| (sign flips past the inflection).
  double dlog_kappa_ds(double log_kappa) const { return -lambda_ * std::exp(-s_integral_.exponent(log_kappa)); }

  /// θ(s); InputError "s" where θ is not a finite double, or where 003's hybrid inverse (option)
  /// fails (a plain double has no status to carry that).
  double theta_at_s(double s) const;

  /// Error of a κ(s) solution of this curve at s, to first order from its residual in the closed
  /// form: r = |s(u) − s| gives |Δθ| = |κ| r (dθ/ds = κ) and |Δ log κ| = r |du/ds|. Zero for the
  /// default inverse (Halley on the closed form with a bracket, polished to rounding); 003's
  /// hybrid inverse is unpolished, so its error (up to 1e-4 rad) is the residual's.
  struct SolutionError {
    double theta = 0;      ///< rad
    double log_kappa = 0;  ///< relative error of κ
  };
  SolutionError solution_error(double s, const KappaSolution& k) const;
  /// θ(s) with the first-order error of its κ(s) solution (see solution_error).
  double theta_at_s(double s, double& theta_error) const;

  /// s, θ, κ (signed), ρ = 1/κ (±inf at the inflection); position left 0 (see quadratic_position.hpp).
  /// `solution` (optional) receives κ(s)'s iterations and status.
  CurvePoint frame_at(double s, KappaSolution* solution = nullptr) const;

  /// Throws InputError naming `name` unless s is in s_domain() (the inflection point itself is
  /// allowed when through_inflection is on).
  void check_s(double s, const char* name) const;

  /// The default drawing range (docs/quadratic.md): from s = 0 toward each end until the first of
  /// |θ| = 2π, κ = e^(±ln 1e3) (curvature within a factor 1e3 of κ(0) = 1), or 99.9 % of a finite
  /// bound of the domain; with through_inflection and an inflection, the upper end is the
  /// point-symmetric image of the lower one. `lac quadratic` and the Python module draw this range.
  Interval default_range() const;

 private:
  double mirrored_s(double s) const;  // s past the inflection → its mirror image below s(κ→0)
  KappaSolution finish(double s, const detail::InverseSolution& sol) const;
  double theta_of(double s, const KappaSolution& k, bool throw_on_failure) const;

  double alpha_, gamma_, lambda_;
  QuadraticOptions options_;
  detail::ExpQuadraticIntegral s_integral_, theta_integral_;
  double s_lo_, s_hi_, theta_hi_;
};

}  // namespace lac
