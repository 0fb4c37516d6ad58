#include "curves/space/la_space_curve.hpp"

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
}

SRange LaSpaceCurve::s_range() const {
  const SRange a = rho_law_.range(), b = mu_law_.range();
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// θ(s) = ∫κ ds in closed form (MATH.md §1), via the shared graph-law integral.
double LaSpaceCurve::turning(double s) const { return rho_law_.integral_of_inverse(s); }
double LaSpaceCurve::s_at_turning(double phi) const { return rho_law_.s_at_integral_of_inverse(phi); }

double LaSpaceCurve::s_at_log_rho(double log_rho) const {
  if (!(lambda() > 0)) throw_input_error("LaSpaceCurve::s_at_log_rho", "lambda", lambda(), "(0, inf)");
  return log_rho / lambda() * detail::expm1_ratio(alpha() * log_rho);
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
