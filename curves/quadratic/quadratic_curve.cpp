#include "lac/curves/quadratic/quadratic_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"

namespace lac {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr const char* kFunction = "quadratic LA curve";
constexpr const char* kNotRepresentable = "(where kappa and theta are representable doubles)";
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
  // Extreme α, γ, Λ can round both bounds to the same value or to NaN (R9 (a)); such a curve
  // has no s to evaluate at. The extended end 2 s_i − s(κ→∞) may overflow to +inf (open end).
  const Interval d = s_domain();
  if (!(d.lo < d.hi) || std::isnan(theta_hi_))
    throw_input_error(kFunction, gamma != 0 ? "gamma" : "lambda",
                      "s domain not representable: (" + format_number(d.lo) + ", " + format_number(d.hi) +
                          ") for alpha " + format_number(alpha) + ", gamma " + format_number(gamma) + ", lambda " +
                          format_number(lambda));
}

double QuadraticLaCurve::s_at_log_kappa(double u) const {
  require_finite(kFunction, "log_kappa", u);
  const double s = -s_integral_(u) / lambda_;
  if (std::isnan(s)) throw_input_error(kFunction, "log_kappa", u, "(where s is a representable double)");
  return s;
}

double QuadraticLaCurve::theta_at_log_kappa(double u) const {
  require_finite(kFunction, "log_kappa", u);
  const double theta = -theta_integral_(u) / lambda_;
  if (std::isnan(theta)) throw_input_error(kFunction, "log_kappa", u, "(where theta is a representable double)");
  return theta;
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
  return -std::exp(s_integral_.exponent(u) - u) / lambda_;  // docs/math.md §4
}

double QuadraticLaCurve::lcg(double log_rho) const {
  return (gamma_ * log_rho + alpha_) * log_rho - std::log(lambda_);
}

KappaSolution QuadraticLaCurve::solve_kappa(double s) const {
  check_s(s, "s");
  if (s == s_hi_) return {-kInf, 0.0, 0, Status::ok};  // the inflection point itself
  const double base_s = mirrored_s(s);
  const auto sol = s_integral_.inverse(-lambda_ * base_s, options_.inverse, options_.max_iterations);
  return finish(s, sol);
}

LogKappaSolution QuadraticLaCurve::solve_log_kappa(double s) const {
  check_s(s, "s");
  if (s == s_hi_) return {-kInf, 1, 0, Status::ok};
  const auto sol = s_integral_.inverse(-lambda_ * mirrored_s(s), options_.inverse, options_.max_iterations);
  if (std::isnan(sol.u) || (std::isinf(sol.u) && sol.status == Status::ok))
    throw_input_error(kFunction, "s", s, "(where log kappa is a representable double)");
  return {sol.u, s > s_hi_ ? -1 : 1, sol.iterations, sol.status};
}

double QuadraticLaCurve::mirrored_s(double s) const {
  if (!(s > s_hi_)) return s;
  // Past the inflection: s_i − (s − s_i), written so that 2 s_i cannot overflow.
  const double base = s_hi_ - (s - s_hi_);
  if (!(base > s_lo_)) throw_input_error(kFunction, "s", s, kNotRepresentable);
  return base;
}

KappaSolution QuadraticLaCurve::finish(double s, const detail::InverseSolution& sol) const {
  KappaSolution out{sol.u, s > s_hi_ ? -std::exp(sol.u) : std::exp(sol.u), sol.iterations, sol.status};
  // Inside the domain κ can still exceed the double range (R9 (b)): an input error, never an inf.
  if (!std::isfinite(out.kappa) || std::isnan(out.log_kappa)) {
    if (sol.status == Status::ok) throw_input_error(kFunction, "s", s, kNotRepresentable);
    out.log_kappa = 0.0;  // a failed hybrid_003 solve: the status says so; no inf handed back
    out.kappa = s > s_hi_ ? -1.0 : 1.0;
  }
  return out;
}

KappaSolution QuadraticLaCurve::solve_kappa_near(double s, double log_kappa_guess) const {
  check_s(s, "s");
  if (s == s_hi_) return {-kInf, 0.0, 0, Status::ok};
  if (options_.inverse != special::ErfInverseMethod::ours || !std::isfinite(log_kappa_guess)) return solve_kappa(s);
  const double base_s = mirrored_s(s);
  return finish(s, s_integral_.polish(-lambda_ * base_s, log_kappa_guess, options_.max_iterations));
}

double QuadraticLaCurve::theta_of(double s, const KappaSolution& k, bool throw_on_failure) const {
  if (k.log_kappa == -kInf) {  // the inflection point, or κ → 0 where θ(κ → 0) is infinite
    if (std::isfinite(theta_hi_)) return theta_hi_;
    if (k.status == Status::ok || throw_on_failure) throw_input_error(kFunction, "s", s, kNotRepresentable);
    return 0.0;  // a failed hybrid_003 solve: the status says so
  }
  const double theta = -theta_integral_(k.log_kappa) / lambda_;  // past the inflection θ(s_i + t) = θ(s_i − t)
  if (k.status == Status::ok) {
    if (!std::isfinite(theta)) throw_input_error(kFunction, "s", s, kNotRepresentable);  // R9 (c)
    return theta;
  }
  // A failed hybrid_003 solve: a plain θ(s) has no status to carry it, a frame has.
  if (throw_on_failure)
    throw_input_error(kFunction, "s", s,
                      "(where 003's hybrid inverse finds kappa; here its status is " +
                          std::string(to_string(k.status)) + "; QuadraticOptions::inverse = ours covers the domain)");
  return std::isfinite(theta) ? theta : 0.0;
}

double QuadraticLaCurve::theta_at_s(double s) const { return theta_of(s, solve_kappa(s), true); }

QuadraticLaCurve::SolutionError QuadraticLaCurve::solution_error(double s, const KappaSolution& k) const {
  if (options_.inverse == special::ErfInverseMethod::ours || !std::isfinite(k.log_kappa) || k.status != Status::ok)
    return {};
  const double residual = std::abs(-s_integral_(k.log_kappa) / lambda_ - mirrored_s(s));
  // ds/du = −e^(E(u))/Λ (docs/math.md §4), so |Δu| = r Λ e^(−E(u)).
  return {std::abs(k.kappa) * residual, residual * lambda_ * std::exp(-s_integral_.exponent(k.log_kappa))};
}

double QuadraticLaCurve::theta_at_s(double s, double& theta_error) const {
  const KappaSolution k = solve_kappa(s);
  theta_error = solution_error(s, k).theta;
  return theta_of(s, k, true);
}

CurvePoint QuadraticLaCurve::frame_at(double s, KappaSolution* solution) const {
  const KappaSolution k = solve_kappa(s);
  if (solution) *solution = k;
  CurvePoint p;
  p.s = s;
  p.kappa = k.kappa;
  p.rho = k.log_kappa == -kInf ? kInf : 1.0 / k.kappa;  // ±inf only at the inflection itself
  if (!std::isfinite(p.rho) && k.log_kappa != -kInf && k.status == Status::ok)
    throw_input_error(kFunction, "s", s, kNotRepresentable);
  // Point symmetry about the inflection: C(s_i + t) − C(s_i) = −(C(s_i − t) − C(s_i)), so the
  // tangent is even, θ(s_i + t) = θ(s_i − t), and κ = θ' is odd.
  p.theta = theta_of(s, k, false);  // a failed solve is flagged by k.status
  return p;
}

namespace {

constexpr double kDefaultTurning = 2 * 3.14159265358979323846;  // rad on each side of s = 0
constexpr double kDefaultLogKappa = 6.907755278982137;           // ln 1e3

// Both curvature and angle are monotone in u = log κ on the base curve, so the end is found in u by
// bisection on the closed forms s(u), θ(u). direction −1: toward κ → ∞ (u > 0, s < 0); +1: toward
// κ → 0 (u < 0, s > 0).
double default_end(const QuadraticLaCurve& c, double direction) {
  auto acceptable = [&](double u) {
    try {
      const double s = c.s_at_log_kappa(u), theta = c.theta_at_log_kappa(u);
      return std::isfinite(s) && std::isfinite(theta) && std::abs(theta) <= kDefaultTurning;
    } catch (const InputError&) {
      return false;
    }
  };
  const double u_far = -direction * kDefaultLogKappa;
  double u;
  if (acceptable(u_far)) {
    u = u_far;
  } else {
    double good = 0.0, bad = u_far;  // acceptable(0): s = θ = 0
    for (int i = 0; i < 200 && std::abs(bad - good) > 1e-12 * std::max(1.0, std::abs(good)); ++i) {
      const double mid = 0.5 * (good + bad);
      (acceptable(mid) ? good : bad) = mid;
    }
    u = good;
  }
  const double s = c.s_at_log_kappa(u);
  const double bound = direction < 0 ? c.s_at_infinite_kappa() : c.s_at_zero_kappa();
  return std::isfinite(bound) && std::abs(s) > 0.999 * std::abs(bound) ? 0.999 * bound : s;
}

}  // namespace

Interval QuadraticLaCurve::default_range() const {
  const double lower = default_end(*this, -1.0);
  const double upper =
      options_.through_inflection && has_inflection() ? 2.0 * s_at_zero_kappa() - lower : default_end(*this, 1.0);
  return {lower, upper, true, true};
}

}  // namespace lac
