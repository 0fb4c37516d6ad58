#include "lac/curves/planar/la_curve.hpp"

#include <cmath>

#include "lac/common/error.hpp"

namespace lac {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Inside the open domain a result can still leave the double range (e.g. ρ = e^800): that is
// an input error naming the argument, never an inf or NaN handed back.
double representable(double value, bool positive, const LaCurve& c, const char* name, double t) {
  if (std::isfinite(value) && (!positive || value > 0)) return value;
  throw_input_error("LaCurve(alpha=" + format_number(c.alpha()) + ", lambda=" + format_number(c.lambda()) + ")", name, t,
                    "where rho, kappa, s and theta are representable doubles");
}

}  // namespace

LaCurve::LaCurve(double alpha, double lambda) : alpha_(alpha), lambda_(lambda) {
  require_finite("LaCurve", "alpha", alpha);
  if (!(lambda >= 0) || !std::isfinite(lambda)) throw_input_error("LaCurve", "lambda", lambda, "[0, inf)");
  if (lambda_ > 0 && alpha_ < 1) theta_domain_ = {-kInf, 1.0 / ((1.0 - alpha_) * lambda_)};
  if (lambda_ > 0 && alpha_ > 1) theta_domain_ = {-1.0 / ((alpha_ - 1.0) * lambda_), kInf};
  if (lambda_ > 0 && alpha_ < 0) s_domain_ = {-kInf, -1.0 / (alpha_ * lambda_)};
  if (lambda_ > 0 && alpha_ > 0) s_domain_ = {-1.0 / (alpha_ * lambda_), kInf};
}

void LaCurve::check(Parameter p, double t, const char* name) const {
  const Interval d = domain(p);
  if (!d.contains(t)) {
    throw_input_error("LaCurve(alpha=" + format_number(alpha_) + ", lambda=" + format_number(lambda_) + ")", name, t,
                      interval_text(d.lo, d.hi));
  }
}

double LaCurve::log_rho_at_theta(double theta) const {
  check(Parameter::theta, theta, "theta");
  return representable(log_rho_at_theta_unchecked(theta), false, *this, "theta", theta);
}

double LaCurve::log_rho_at_s(double s) const {
  check(Parameter::s, s, "s");
  return representable(log_rho_at_s_unchecked(s), false, *this, "s", s);
}

double LaCurve::rho_at_theta(double theta) const {
  return representable(std::exp(log_rho_at_theta(theta)), true, *this, "theta", theta);
}
double LaCurve::rho_at_s(double s) const { return representable(std::exp(log_rho_at_s(s)), true, *this, "s", s); }
double LaCurve::kappa_at_theta(double theta) const {
  return representable(std::exp(-log_rho_at_theta(theta)), true, *this, "theta", theta);
}
double LaCurve::kappa_at_s(double s) const { return representable(std::exp(-log_rho_at_s(s)), true, *this, "s", s); }

// One domain check and one log ρ (it used to be computed by log_rho_at_theta and again here).
double LaCurve::s_at_theta(double theta) const {
  check(Parameter::theta, theta, "theta");
  double s = 0;
  representable(log_rho_and_other(Parameter::theta, theta, s), false, *this, "theta", theta);
  return representable(s, false, *this, "theta", theta);
}

double LaCurve::theta_at_s(double s) const {
  check(Parameter::s, s, "s");
  return representable(theta_at_s_unchecked(s), false, *this, "s", s);
}

// From log ρ = Λ θ g((α−1)Λθ): θ = (log ρ / Λ) h((α−1) log ρ); likewise s with α.
double LaCurve::theta_at_log_rho(double log_rho) const {
  if (!(lambda_ > 0)) throw_input_error("LaCurve::theta_at_log_rho", "lambda", lambda_, "(0, inf) (rho is constant when lambda = 0)");
  require_finite("LaCurve::theta_at_log_rho", "log_rho", log_rho);
  const double theta = log_rho / lambda_ * expm1_ratio((alpha_ - 1.0) * log_rho);
  if (!std::isfinite(theta) || !theta_domain().contains(theta))
    throw_input_error("LaCurve::theta_at_log_rho", "log_rho", log_rho, "values reached inside the theta domain");
  return theta;
}

double LaCurve::s_at_log_rho(double log_rho) const {
  if (!(lambda_ > 0)) throw_input_error("LaCurve::s_at_log_rho", "lambda", lambda_, "(0, inf) (rho is constant when lambda = 0)");
  require_finite("LaCurve::s_at_log_rho", "log_rho", log_rho);
  const double s = s_at_log_rho_unchecked(log_rho);
  if (!std::isfinite(s) || !s_domain().contains(s))
    throw_input_error("LaCurve::s_at_log_rho", "log_rho", log_rho, "values reached inside the s domain");
  return s;
}

double LaCurve::one_plus_c_lambda_t(Parameter p, double t) const {
  const auto two_sum = [](double a, double b, double& err) {
    const double s = a + b, bb = s - a;
    err = (a - (s - bb)) + (b - bb);
    return s;
  };
  const double pr = lambda_ * t, pr_err = std::fma(lambda_, t, -pr);  // Λt = pr + pr_err exactly
  const double q = alpha_ * pr;
  double q_err = std::fma(alpha_, pr, -q) + alpha_ * pr_err;  // αΛt = q + q_err to ~ε²
  double r = q;
  if (p == Parameter::theta) {  // (α − 1)Λt = αΛt − Λt
    double e = 0;
    r = two_sum(q, -pr, e);
    q_err += e - pr_err;
  }
  double e = 0;
  const double one_plus_r = two_sum(1.0, r, e);
  return one_plus_r + (e + q_err);
}

CurvePoint LaCurve::frame_at(Parameter p, double t) const {
  check(p, t, p == Parameter::theta ? "theta" : "s");
  return frame_inside(p, t);
}

void LaCurve::frames_inside(Parameter p, std::span<CurvePoint> points) const {
  for (CurvePoint& q : points) q.rho = log_rho_and_g(p, p == Parameter::theta ? q.theta : q.s, q.kappa);  // κ holds g
  for (CurvePoint& q : points) finish_frame(p, q.kappa, q.rho, q);
}

void LaCurve::throw_unrepresentable(Parameter p, double t, double log_rho) const {
  throw_input_error("LaCurve(alpha=" + format_number(alpha_) + ", lambda=" + format_number(lambda_) + ")",
                    p == Parameter::theta ? "theta" : "s", t,
                    "where rho, s and theta are representable doubles (log rho = " + format_number(log_rho) + " here)");
}

}  // namespace lac
