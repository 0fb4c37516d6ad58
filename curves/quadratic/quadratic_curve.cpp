#include "curves/quadratic/quadratic_curve.hpp"

#include <cmath>
#include <limits>

#include "common/error.hpp"

namespace lac {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr const char* kFunction = "quadratic LA curve";
}  // namespace

void QuadraticOptions::validate() const {
  if (max_iterations < 1 || max_iterations > 1000)
    throw_input_error(kFunction, "max_iterations", max_iterations, "[1, 1000]");
}

QuadraticLaCurve::QuadraticLaCurve(double alpha, double gamma, double lambda, QuadraticOptions options)
    : alpha_(alpha),
      gamma_(gamma),
      lambda_(lambda),
      options_(options),
      s_integral_((require_finite(kFunction, "alpha", alpha), require_finite(kFunction, "gamma", gamma), alpha), gamma),
      theta_integral_(alpha - 1.0, gamma) {
  if (!(lambda > 0) || !std::isfinite(lambda)) throw_input_error(kFunction, "lambda", lambda, "(0, inf)");
  options_.validate();
  s_lo_ = -s_integral_.limit_plus() / lambda_;   // κ → ∞
  s_hi_ = -s_integral_.limit_minus() / lambda_;  // κ → 0
  theta_hi_ = -theta_integral_.limit_minus() / lambda_;
}

bool QuadraticLaCurve::has_inflection() const { return std::isfinite(s_hi_); }

Interval QuadraticLaCurve::s_domain() const {
  if (options_.through_inflection && has_inflection()) return {s_lo_, 2.0 * s_hi_ - s_lo_};
  return {s_lo_, s_hi_};
}

void QuadraticLaCurve::check_s(double s, const char* name) const {
  require_finite(kFunction, name, s);
  const Interval d = s_domain();
  if (d.contains(s)) return;
  if (options_.through_inflection && s == s_hi_) return;
  throw_input_error(kFunction, name, s, interval_text(d.lo, d.hi) + " (alpha " + format_number(alpha_) + ", gamma " +
                                            format_number(gamma_) + ", lambda " + format_number(lambda_) + ")");
}

double QuadraticLaCurve::s_at_kappa(double kappa) const {
  if (!(kappa > 0) || !std::isfinite(kappa)) throw_input_error(kFunction, "kappa", kappa, "(0, inf)");
  return s_at_log_kappa(std::log(kappa));
}

double QuadraticLaCurve::ds_dkappa(double kappa) const {
  if (!(kappa > 0) || !std::isfinite(kappa)) throw_input_error(kFunction, "kappa", kappa, "(0, inf)");
  const double u = std::log(kappa);
  return -std::exp(s_integral_.exponent(u) - u) / lambda_;  // MATH.md §4
}

double QuadraticLaCurve::lcg(double log_rho) const {
  return (gamma_ * log_rho + alpha_) * log_rho - std::log(lambda_);
}

KappaSolution QuadraticLaCurve::solve_kappa(double s) const {
  check_s(s, "s");
  if (s == s_hi_) return {-kInf, 0.0, 0, Status::ok};  // the inflection point itself
  const bool mirrored = s > s_hi_;
  const double base_s = mirrored ? 2.0 * s_hi_ - s : s;
  const auto sol = s_integral_.inverse(-lambda_ * base_s, options_.inverse, options_.max_iterations);
  KappaSolution out;
  out.log_kappa = sol.u;
  out.kappa = mirrored ? -std::exp(sol.u) : std::exp(sol.u);
  out.iterations = sol.iterations;
  out.status = sol.status;
  return out;
}

KappaSolution QuadraticLaCurve::solve_kappa_near(double s, double log_kappa_guess) const {
  check_s(s, "s");
  if (s == s_hi_) return {-kInf, 0.0, 0, Status::ok};
  if (options_.inverse != special::ErfInverseMethod::ours || !std::isfinite(log_kappa_guess)) return solve_kappa(s);
  const bool mirrored = s > s_hi_;
  const double base_s = mirrored ? 2.0 * s_hi_ - s : s;
  const auto sol = s_integral_.polish(-lambda_ * base_s, log_kappa_guess, options_.max_iterations);
  return {sol.u, mirrored ? -std::exp(sol.u) : std::exp(sol.u), sol.iterations, sol.status};
}

double QuadraticLaCurve::theta_at_s(double s) const {
  const KappaSolution k = solve_kappa(s);
  if (k.kappa == 0) return theta_hi_;
  return theta_at_log_kappa(k.log_kappa);  // past the inflection θ(s_i + t) = θ(s_i − t)
}

CurvePoint QuadraticLaCurve::frame_at(double s, KappaSolution* solution) const {
  const KappaSolution k = solve_kappa(s);
  if (solution) *solution = k;
  CurvePoint p;
  p.s = s;
  p.kappa = k.kappa;
  p.rho = k.kappa == 0 ? kInf : 1.0 / k.kappa;
  // Point symmetry about the inflection: C(s_i + t) − C(s_i) = −(C(s_i − t) − C(s_i)), so the
  // tangent is even, θ(s_i + t) = θ(s_i − t), and κ = θ' is odd.
  p.theta = k.kappa == 0 ? theta_hi_ : theta_at_log_kappa(k.log_kappa);
  return p;
}

}  // namespace lac
