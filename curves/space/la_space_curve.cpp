#include "lac/curves/space/la_space_curve.hpp"

#include <algorithm>

namespace lac {

LaSpaceCurve::LaSpaceCurve(double alpha, double beta, double lambda, double omega, double nu, TorsionType type)
    : nu_(nu), type_(type) {
  constexpr const char* who = "LaSpaceCurve";
  require_finite(who, "alpha", alpha);
  require_finite(who, "beta", beta);
  if (!(lambda >= 0) || !std::isfinite(lambda)) throw_input_error(who, "lambda", lambda, "[0, inf)");
  if (!(omega >= 0) || !std::isfinite(omega)) throw_input_error(who, "omega", omega, "[0, inf)");
  if (!(nu > 0) || !std::isfinite(nu)) throw_input_error(who, "nu", nu, "(0, inf)");
  if (type != TorsionType::type1 && type != TorsionType::type2)
    throw_input_error(who, "type", static_cast<double>(type), "{1, 2}");
  rho_law_ = {alpha, lambda, 0.0};
  mu_law_ = {beta, type == TorsionType::type1 ? omega : -omega, std::log(nu)};
  // Both laws need k = rate·r0^(−slope) and slope·k as finite doubles (R11 of docs/robustness.md):
  // otherwise the s range and every law evaluate to NaN or collapse to an empty interval.
  constexpr double kLogMax = 709.782712893384;  // log(DBL_MAX)
  constexpr double kMax = std::numeric_limits<double>::max();
  if (!std::isfinite(alpha * lambda))
    throw_input_error(who, "lambda", lambda,
                      "[0, " + format_number(kMax / std::abs(alpha)) + "] (alpha·lambda must be a finite double; alpha = " +
                          format_number(alpha) + ")");
  const double nu_factor = std::exp(-beta * mu_law_.log_r0);  // ν^(−β)
  if (!std::isfinite(nu_factor))
    throw_input_error(who, "nu", nu,
                      (beta > 0 ? "(" + format_number(std::exp(-kLogMax / beta)) + ", inf)"
                                : "(0, " + format_number(std::exp(kLogMax / -beta)) + ")") +
                          " (nu^(-beta) must be a finite double; beta = " + format_number(beta) + ")");
  const double k = mu_law_.k();
  if (!std::isfinite(k) || !std::isfinite(beta * k))
    throw_input_error(who, "omega", omega,
                      "[0, " + format_number(kMax / (nu_factor * std::max(1.0, std::abs(beta)))) +
                          "] (omega·nu^(-beta)·max(1, |beta|) must be a finite double)");
  const SRange r = s_range();
  if (!(r.lo < r.hi)) throw_input_error(who, "lambda", lambda, "values with a non-empty s range");
}

SRange LaSpaceCurve::s_range() const {
  const SRange a = rho_law_.range(), b = mu_law_.range();
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

namespace {
// The closed forms overflow (k·s beyond DBL_MAX) or divide inf by inf for extreme laws even for
// s inside the s range; the angle there is not a finite double in this form, so such s are
// rejected instead of returning NaN (R11).
double checked_angle(double value, double s, const LaSpaceCurve& c, const char* who) {
  if (!std::isfinite(value)) {
    const SRange r = c.s_range();
    throw_input_error(who, "s", s,
                      "values in the s range " + interval_text(r.lo, r.hi) + " where the angle is a finite double");
  }
  return value;
}

void check_phi(double phi, const char* who) {
  if (std::isnan(phi)) throw_input_error(who, "phi", phi, "[0, inf]");
}
}  // namespace

// θ(s) = ∫κ ds in closed form (MATH.md §1), via the shared graph-law integral.
double LaSpaceCurve::turning(double s) const {
  return checked_angle(rho_law_.integral_of_inverse(s), s, *this, "LaSpaceCurve::turning");
}
double LaSpaceCurve::s_at_turning(double phi) const {
  check_phi(phi, "LaSpaceCurve::s_at_turning");
  return rho_law_.s_at_integral_of_inverse(phi);
}
double LaSpaceCurve::torsion_turning(double s) const {
  return checked_angle(mu_law_.integral_of_inverse(s), s, *this, "LaSpaceCurve::torsion_turning");
}
double LaSpaceCurve::s_at_torsion_turning(double phi) const {
  check_phi(phi, "LaSpaceCurve::s_at_torsion_turning");
  return mu_law_.s_at_integral_of_inverse(phi);
}

double LaSpaceCurve::s_at_log_rho(double log_rho) const {
  constexpr const char* who = "LaSpaceCurve::s_at_log_rho";
  if (!(lambda() > 0)) throw_input_error(who, "lambda", lambda(), "(0, inf)");
  require_finite(who, "log_rho", log_rho);
  const double s = log_rho / lambda() * detail::expm1_ratio(alpha() * log_rho);
  if (!std::isfinite(s) || !contains(s)) throw_input_error(who, "log_rho", log_rho, "values reached inside the s range");
  return s;
}

void LaSpaceCurve::check_s(double s, const char* name) const {
  const SRange r = s_range();
  if (!r.contains(s)) throw_input_error("LaSpaceCurve", name, s, interval_text(r.lo, r.hi));
}

JointContinuation continue_at_joint(double alpha0, double alpha1, double beta0, double beta1, double lambda0,
                                    double omega0, TorsionType type, double rho_c, double mu_c) {
  JointContinuation j;
  const double log_rho_c = std::log(rho_c), log_mu_c = std::log(mu_c);
  j.lambda1 = lambda0 * std::exp((alpha1 - alpha0) * log_rho_c);  // 000 Eq. (11)
  j.omega1 = omega0 * std::exp((beta1 - beta0) * log_mu_c);      // 000 Eq. (16)
  if (!(j.lambda1 > 0) || !std::isfinite(j.lambda1) || !std::isfinite(j.omega1)) return j;
  j.s_c = log_rho_c / j.lambda1 * detail::expm1_ratio(alpha1 * log_rho_c);  // 000 Eq. (17)
  // ν1 from μ(s_c) = μc: ν1^β1 = μc^β1 ∓ Ω1β1 s_c (type 1: −, type 2: +), 000 Eqs. (17)–(18)
  // corrected (MATH.md §3); written as log ν1 = log μc + log(1 + β1 x)/β1, x = ∓Ω1 s_c μc^(−β1).
  const double sign = type == TorsionType::type1 ? -1.0 : 1.0;
  const double x = sign * j.omega1 * j.s_c * std::exp(-beta1 * log_mu_c);
  if (!(1.0 + beta1 * x > 0) || !std::isfinite(x)) return j;
  j.nu1 = std::exp(log_mu_c + x * detail::log1p_ratio(beta1 * x));
  j.valid = std::isfinite(j.s_c) && j.nu1 > 0 && std::isfinite(j.nu1);
  return j;
}

}  // namespace lac
