#include "lac/curves/space/la_space_curve.hpp"

#include <algorithm>

namespace lac {

LaSpaceCurve::LaSpaceCurve(double alpha, double beta, double lambda, double omega, double nu, TorsionType type)
    : mu_sign_(type == TorsionType::type1 ? 1.0 : -1.0), omega_(omega), nu_(nu), type_(type) {
  constexpr const char* who = "LaSpaceCurve";
  require_finite(who, "alpha", alpha);
  require_finite(who, "beta", beta);
  if (!(lambda >= 0) || !std::isfinite(lambda)) throw_input_error(who, "lambda", lambda, "[0, inf)");
  if (!(omega >= 0) || !std::isfinite(omega)) throw_input_error(who, "omega", omega, "[0, inf)");
  if (!(nu > 0) || !std::isfinite(nu)) throw_input_error(who, "nu", nu, "(0, inf)");
  if (type != TorsionType::type1 && type != TorsionType::type2)
    throw_input_error(who, "type", static_cast<double>(type), "{1, 2}");
  log_nu_ = std::log(nu);
  // Both laws need their rate (Λ; Ω·ν^(−β) for μ) times the slope as finite doubles (R11 of
  // docs/robustness.md): otherwise the s range and every law evaluate to NaN or collapse to an
  // empty interval.
  constexpr double kLogMax = 709.782712893384;  // log(DBL_MAX)
  constexpr double kMax = std::numeric_limits<double>::max();
  if (!std::isfinite(alpha * lambda))
    throw_input_error(who, "lambda", lambda,
                      "[0, " + format_number(kMax / std::abs(alpha)) + "] (alpha·lambda must be a finite double; alpha = " +
                          format_number(alpha) + ")");
  const double nu_factor = std::exp(-beta * log_nu_);  // ν^(−β)
  if (!std::isfinite(nu_factor))
    throw_input_error(who, "nu", nu,
                      (beta > 0 ? "(" + format_number(std::exp(-kLogMax / beta)) + ", inf)"
                                : "(0, " + format_number(std::exp(kLogMax / -beta)) + ")") +
                          " (nu^(-beta) must be a finite double; beta = " + format_number(beta) + ")");
  const double k = omega * nu_factor;
  if (!std::isfinite(k) || !std::isfinite(beta * k))
    throw_input_error(who, "omega", omega,
                      "[0, " + format_number(kMax / (nu_factor * std::max(1.0, std::abs(beta)))) +
                          "] (omega·nu^(-beta)·max(1, |beta|) must be a finite double)");
  rho_law_ = LaCurve(alpha, lambda);
  mu_law_ = LaCurve(beta, k);
  const Interval r = s_range();
  if (!(r.lo < r.hi)) throw_input_error(who, "lambda", lambda, "values with a non-empty s range");
}

Interval LaSpaceCurve::s_range() const {
  const Interval a = rho_law_.s_domain(), mu = mu_law_.s_domain();
  const Interval b = mu_sign_ > 0 ? mu : Interval{-mu.hi, -mu.lo};
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

namespace {
// The closed forms overflow (k·s beyond DBL_MAX) or divide inf by inf for extreme laws even for
// s inside the s range; the angle there is not a finite double in this form, so such s are
// rejected instead of returning NaN (R11).
double checked_angle(double value, double s, const LaSpaceCurve& c, const char* who) {
  if (!std::isfinite(value)) {
    const Interval r = c.s_range();
    throw_input_error(who, "s", s,
                      "values in the s range " + interval_text(r.lo, r.hi) + " where the angle is a finite double");
  }
  return value;
}

void check_phi(double phi, const char* who) {
  if (std::isnan(phi)) throw_input_error(who, "phi", phi, "[0, inf]");
}

// The s ≥ 0 where a standard-form curve's θ reaches phi ≥ 0; +inf when it never does (phi beyond
// the θ domain: the turning of α < 1 is bounded).
double s_at_theta_or_inf(const LaCurve& c, double phi) {
  if (!c.theta_domain().contains(phi)) return std::numeric_limits<double>::infinity();
  const double s = c.s_at_theta_unchecked(phi);
  return std::isfinite(s) && s >= 0 ? s : std::numeric_limits<double>::infinity();
}
}  // namespace

// θ(s) = ∫κ ds in closed form (the standard form's θ(s)); ∫τ ds = ±θ̃(±s)/ν of the μ law.
double LaSpaceCurve::turning(double s) const {
  return checked_angle(rho_law_.theta_at_s_unchecked(s), s, *this, "LaSpaceCurve::turning");
}
double LaSpaceCurve::s_at_turning(double phi) const {
  check_phi(phi, "LaSpaceCurve::s_at_turning");
  return s_at_theta_or_inf(rho_law_, phi);
}
double LaSpaceCurve::torsion_turning(double s) const {
  return checked_angle(mu_sign_ * mu_law_.theta_at_s_unchecked(mu_sign_ * s) * std::exp(-log_nu_), s, *this,
                       "LaSpaceCurve::torsion_turning");
}
double LaSpaceCurve::s_at_torsion_turning(double phi) const {
  check_phi(phi, "LaSpaceCurve::s_at_torsion_turning");
  const double j = phi * std::exp(log_nu_);
  if (mu_sign_ > 0) return s_at_theta_or_inf(mu_law_, j);
  // type 2: −θ̃(−s)/ν = phi, i.e. s = −s̃(−j), s ≥ 0.
  if (!mu_law_.theta_domain().contains(-j)) return std::numeric_limits<double>::infinity();
  const double s = -mu_law_.s_at_theta_unchecked(-j);
  return std::isfinite(s) && s >= 0 ? s : std::numeric_limits<double>::infinity();
}

double LaSpaceCurve::s_at_log_rho(double log_rho) const {
  constexpr const char* who = "LaSpaceCurve::s_at_log_rho";
  if (!(lambda() > 0)) throw_input_error(who, "lambda", lambda(), "(0, inf)");
  require_finite(who, "log_rho", log_rho);
  const double s = rho_law_.s_at_log_rho_unchecked(log_rho);
  if (!std::isfinite(s) || !contains(s)) throw_input_error(who, "log_rho", log_rho, "values reached inside the s range");
  return s;
}

void LaSpaceCurve::check_s(double s, const char* name) const {
  const Interval r = s_range();
  if (!r.contains(s)) throw_input_error("LaSpaceCurve", name, s, interval_text(r.lo, r.hi));
}

JointContinuation continue_at_joint(double alpha0, double alpha1, double beta0, double beta1, double lambda0,
                                    double omega0, TorsionType type, double rho_c, double mu_c) {
  JointContinuation j;
  const double log_rho_c = std::log(rho_c), log_mu_c = std::log(mu_c);
  j.lambda1 = lambda0 * std::exp((alpha1 - alpha0) * log_rho_c);  // 000 Eq. (11)
  j.omega1 = omega0 * std::exp((beta1 - beta0) * log_mu_c);      // 000 Eq. (16)
  if (!(j.lambda1 > 0) || !std::isfinite(j.lambda1) || !std::isfinite(j.omega1)) return j;
  j.s_c = LaCurve(alpha1, j.lambda1).s_at_log_rho_unchecked(log_rho_c);  // 000 Eq. (17)
  // ν1 from μ(s_c) = μc: ν1^β1 = μc^β1 ∓ Ω1β1 s_c (type 1: −, type 2: +), 000 Eqs. (17)–(18)
  // corrected (docs/math.md §3); written as log ν1 = log μc + log(1 + β1 x)/β1, x = ∓Ω1 s_c μc^(−β1).
  const double sign = type == TorsionType::type1 ? -1.0 : 1.0;
  const double x = sign * j.omega1 * j.s_c * std::exp(-beta1 * log_mu_c);
  if (!(1.0 + beta1 * x > 0) || !std::isfinite(x)) return j;
  j.nu1 = std::exp(log_mu_c + x * log1p_ratio(beta1 * x));
  j.valid = std::isfinite(j.s_c) && j.nu1 > 0 && std::isfinite(j.nu1);
  return j;
}

}  // namespace lac
