#include "curves/quadratic/detail/exp_quadratic_integral.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "curves/planar/la_curve.hpp"

namespace lac::detail {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSqrtPi = 1.7724538509055160273;
constexpr double kLogTwoOverSqrtPi = 0.12078223763524522234551845;
constexpr double kNearRegion = 3.0;  // |γ|u² + |αu| ≤ 3: Gauss–Legendre (see the header)

using Gauss20 = boost::math::quadrature::gauss<double, 20>;

// sign(m) · e^(E) · |m| without overflowing before the product does.
double scaled(double e, double m) {
  if (m == 0) return 0.0;
  return std::copysign(std::exp(e + std::log(std::abs(m))), m);
}

}  // namespace

ExpQuadraticIntegral::ExpQuadraticIntegral(double alpha, double gamma) : alpha_(alpha), gamma_(gamma) {
  if (gamma > 0) {
    root_ = std::sqrt(gamma);
    center_ = -alpha / (2.0 * root_);
    base_ = special::dawson(center_);
  } else if (gamma < 0) {
    root_ = std::sqrt(-gamma);
    center_ = alpha / (2.0 * root_);
    const double c = kSqrtPi / (2.0 * root_);
    erfcx_plus_ = special::erfcx(center_);
    erfcx_minus_ = special::erfcx(-center_);  // +inf beyond |y0| ≈ 26.6: a true overflow of F(−∞)
    limit_plus_ = c * erfcx_plus_;            // F(+∞), MATH.md §4 bounds in erfcx form
    limit_minus_ = -c * erfcx_minus_;         // F(−∞)
    base_ = center_ >= 0 ? erfcx_plus_ : erfcx_minus_;
  } else {
    if (alpha > 0) limit_plus_ = 1.0 / alpha;
    if (alpha < 0) limit_minus_ = 1.0 / alpha;
  }
}

double ExpQuadraticIntegral::operator()(double u) const {
  if (gamma_ == 0) return u * LaCurve::expm1_ratio(-alpha_ * u);
  if (std::abs(gamma_) * u * u + std::abs(alpha_ * u) <= kNearRegion) {
    const auto& x = Gauss20::abscissa();
    const auto& w = Gauss20::weights();
    const double half = 0.5 * u;
    double sum = 0;
    for (size_t i = 0; i < x.size(); ++i) {
      const double t1 = half * (1.0 + x[i]), t2 = half * (1.0 - x[i]);
      sum += w[i] * (x[i] == 0 ? std::exp(exponent(t1)) : std::exp(exponent(t1)) + std::exp(exponent(t2)));
    }
    return half * sum;
  }
  const double e = exponent(u);
  if (gamma_ > 0) {
    const double x = center_ + root_ * u;
    return (scaled(e, special::dawson(x)) - base_) / root_;
  }
  const double y = center_ + root_ * u;
  const double c = kSqrtPi / (2.0 * root_);
  if (center_ >= 0 && y >= 0) return -c * (scaled(e, special::erfcx(y)) - base_);
  if (center_ <= 0 && y <= 0) return -c * (base_ - scaled(e, special::erfcx(-y)));
  // Opposite signs: erf(y0) − erf(y) adds magnitudes; e^(y0²) overflows only with the result.
  const double diff = special::erf(center_) - special::erf(y);
  return -c * std::copysign(std::exp(center_ * center_ + std::log(std::abs(diff))), diff);
}

double ExpQuadraticIntegral::start_ours(double target, int& iterations) const {
  if (gamma_ > 0) {
    // e^(x²) D(x) = e^(x0²) R with R = D(x0) + √γ F  ⇔  erfi(x) = (2/√π) e^(x0² + log|R|) sign R.
    const double r = base_ + root_ * target;
    if (r == 0) return -center_ / root_;
    const auto inv = special::erfi_inv_log(center_ * center_ + std::log(std::abs(r)) + kLogTwoOverSqrtPi, r > 0 ? 1 : -1);
    iterations += inv.iterations;
    return (inv.value - center_) / root_;
  }
  // γ < 0: erf y − erf y0 = P e^(−y0²), P = (2√g/√π) F, so with a + b = 2 e^(y0²):
  //   erfc(y) = e^(−y0²) a, a = erfcx(y0) − P;   erfc(−y) = e^(−y0²) b, b = erfcx(−y0) + P.
  // Invert the one that is ≤ 1 (erfc_inv_log is accurate there); an overflowed one is never used.
  const double p = 2.0 * root_ / kSqrtPi * target;
  const double a = erfcx_plus_ - p, b = erfcx_minus_ + p;
  const double y2 = center_ * center_;
  if (a <= b) {
    if (!(a > 0)) return kInf;
    const auto inv = special::erfc_inv_log(std::min(std::log(a) - y2, 0.0));
    iterations += inv.iterations;
    return (inv.value - center_) / root_;
  }
  if (!(b > 0)) return -kInf;
  const auto inv = special::erfc_inv_log(std::min(std::log(b) - y2, 0.0));
  iterations += inv.iterations;
  return (-inv.value - center_) / root_;
}

InverseSolution ExpQuadraticIntegral::inverse_003(double target) const {
  // 003 Eq. (4.6) with MATH.md §4's sign correction, unscaled: e^(±α²/(4γ)) and the hybrid
  // inverses bounded to |z| ≤ 26 (erfi) and |z| ≤ 5 (erf), as the paper does.
  InverseSolution out;
  const double lambda_s = -target;  // Λ s = −F
  special::InverseResult z;
  if (gamma_ > 0) {
    const double arg = special::erfi(alpha_ / (2.0 * root_)) +
                       2.0 * root_ * std::exp(alpha_ * alpha_ / (4.0 * gamma_)) * lambda_s / kSqrtPi;
    if (std::isnan(arg)) return {0.0, 0, Status::numerical_failure};
    z = special::erfi_inv_hybrid_003(arg);
  } else {
    const double arg = special::erf(alpha_ / (2.0 * root_)) -
                       2.0 * root_ * std::exp(alpha_ * alpha_ / (4.0 * gamma_)) * lambda_s / kSqrtPi;
    if (std::isnan(arg)) return {0.0, 0, Status::numerical_failure};
    if (std::abs(arg) >= 1.0) return {0.0, 0, Status::no_solution};
    z = special::erf_inv_hybrid_003(arg);
  }
  out.u = (alpha_ - 2.0 * root_ * z.value) / (2.0 * gamma_);
  out.iterations = z.iterations;
  out.status = z.status;
  return out;
}

InverseSolution ExpQuadraticIntegral::inverse(double target, special::ErfInverseMethod method, int max_iterations) const {
  if (gamma_ == 0) {  // LA curve: (1 − e^(−αu))/α = F exactly invertible
    return {target * LaCurve::log1p_ratio(-alpha_ * target), 0, Status::ok};
  }
  if (method == special::ErfInverseMethod::hybrid_003) return inverse_003(target);
  int start_iterations = 0;
  const double u = start_ours(target, start_iterations);
  InverseSolution out = polish(target, std::isfinite(u) ? u : 0.0, max_iterations);
  out.iterations += start_iterations;
  return out;
}

InverseSolution ExpQuadraticIntegral::polish(double target, double u, int max_iterations) const {
  InverseSolution out;
  if (gamma_ == 0) return {target * LaCurve::log1p_ratio(-alpha_ * target), 0, Status::ok};
  // Halley on f(u) = F(u) − target: f' = e^E, f''/f' = E'(u) = 2γu − α. Bracket by sign of f.
  double lo = -kInf, hi = kInf;
  for (int it = 1; it <= max_iterations; ++it) {
    ++out.iterations;
    const double f = (*this)(u)-target;
    if (f > 0) hi = u;
    else if (f < 0) lo = u;
    else return {u, out.iterations, Status::ok};
    const double ratio = f * std::exp(-exponent(u));
    const double step = -ratio / (1.0 - 0.5 * ratio * (2.0 * gamma_ * u - alpha_));
    if (std::isfinite(step) && std::abs(step) <= 2.0 * kEps * std::max(1.0, std::abs(u))) {
      out.u = u + step;
      return out;
    }
    double next = u + step;
    if (!(std::isfinite(next) && next > lo && next < hi)) {  // safeguard
      if (std::isfinite(lo) && std::isfinite(hi)) next = 0.5 * (lo + hi);
      else if (std::isfinite(lo)) next = lo + std::max(1.0, std::abs(lo));
      else next = hi - std::max(1.0, std::abs(hi));
    }
    if (std::isfinite(lo) && std::isfinite(hi) && hi - lo <= 2.0 * kEps * std::max(1.0, std::abs(u))) {
      out.u = 0.5 * (lo + hi);
      return out;
    }
    u = next;
  }
  out.u = u;
  out.status = Status::max_iterations;
  return out;
}

}  // namespace lac::detail
