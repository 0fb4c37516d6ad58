#include "lac/special/erf_family.hpp"

#include <cerf.h>

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "lac/common/error.hpp"

namespace lac::special {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kSqrtPi = 1.7724538509055160273;                 // √π
constexpr double kLogTwoOverSqrtPi = 0.12078223763524522234551845;  // log(2/√π)
constexpr double kHalfSqrtPi = 0.5 * kSqrtPi;
constexpr double kLog2 = std::numbers::ln2;

// Halley for erfi(x) = a with 0 < a < 1, in the form f/f' = D(x) − (√π/2) a e^(−x²)
// (f = erfi − a, f' = (2/√π) e^(x²), f''/f' = 2x), so that no erfi evaluation can overflow.
InverseResult erfi_inv_small(double a) {
  double lo = 0.0, hi = 0.8;  // erfi(0.8) ≈ 1.08 > a
  const double z = kHalfSqrtPi * a;
  double x = z * (1.0 - z * z / 3.0 + 7.0 * z * z * z * z / 30.0);  // inverse Maclaurin series, 3 terms
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  for (int it = 1; it <= kMaxInverseIterations; ++it) {
    const double ratio = dawson(x) - kHalfSqrtPi * a * std::exp(-x * x);  // f/f'
    if (ratio > 0) hi = x;
    else if (ratio < 0) lo = x;
    else return {x, it, Status::ok};
    const double step = -ratio / (1.0 - ratio * x);
    if (std::abs(step) <= 4.0 * kEps * x) return {x + step, it, Status::ok};
    x = (x + step > lo && x + step < hi) ? x + step : 0.5 * (lo + hi);  // bracket safeguard
    if (hi - lo <= 4.0 * kEps * hi) return {x, it, Status::ok};
  }
  return {x, kMaxInverseIterations, Status::max_iterations};
}

// Halley for log erfi(x) = L with L ≥ 0 (x ≥ erfi⁻¹(1) ≈ 0.75), in the form
// φ(x) = x² + log D(x) + log(2/√π) − L, φ' = 1/D(x), φ'' = −(1 − 2xD)/D²: finite for every L.
InverseResult erfi_inv_large(double L) {
  // Bracket: erfi(0.7) < 1 ≤ e^L, and for x ≥ 1 erfi(x) ≥ e^(x²)/(√π x), which exceeds e^L at
  // x = √(L + 1) + 1.
  double lo = 0.7, hi = std::sqrt(L + 1.0) + 1.0;
  // Asymptotic guess: erfi(x) ≈ e^(x²)/(√π x)  =>  x² ≈ ℓ + log x, ℓ = L + log √π.
  const double ell = L + 0.5 * std::log(std::numbers::pi);
  const double t = std::sqrt(std::max(ell, 1.0));
  double x = std::sqrt(std::max(ell + std::log(t), 0.5));
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  for (int it = 1; it <= kMaxInverseIterations; ++it) {
    const double d = dawson(x);
    const double phi = x * x + std::log(d) + kLogTwoOverSqrtPi - L;
    if (phi > 0) hi = x;
    else if (phi < 0) lo = x;
    else return {x, it, Status::ok};
    const double step = -phi * d / (1.0 + 0.5 * phi * (1.0 - 2.0 * x * d));
    if (std::abs(step) <= 4.0 * kEps * x) return {x + step, it, Status::ok};
    x = (x + step > lo && x + step < hi) ? x + step : 0.5 * (lo + hi);  // bracket safeguard
    if (hi - lo <= 4.0 * kEps * hi) return {x, it, Status::ok};
  }
  return {x, kMaxInverseIterations, Status::max_iterations};
}

InverseResult with_sign(InverseResult r, double sign) {
  r.value = std::copysign(r.value, sign);
  return r;
}

// 003 §4: Newton from 0 near the origin, bisection on [−bound, bound] elsewhere.
template <class F, class Fprime>
InverseResult hybrid_003(double y, double newton_limit, double bound, F f, Fprime fprime) {
  InverseResult r;
  if (std::abs(y) <= newton_limit) {
    double x = 0;
    for (int it = 1; it <= kMaxInverseIterations; ++it) {
      const double step = (f(x) - y) / fprime(x);
      x -= step;
      if (std::abs(step) <= 4.0 * kEps * std::abs(x) || std::abs(step) < std::numeric_limits<double>::min())
        return {x, it, Status::ok};
    }
    return {x, kMaxInverseIterations, Status::max_iterations};
  }
  if (std::abs(y) > f(bound)) return {std::copysign(bound, y), 0, Status::no_solution};
  double lo = -bound, hi = bound;
  for (int it = 1; it <= kMaxInverseIterations; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (f(mid) < y) lo = mid;
    else hi = mid;
    if (hi - lo <= 2.0 * kEps * std::max(std::abs(lo), std::abs(hi))) return {0.5 * (lo + hi), it, Status::ok};
  }
  return {0.5 * (lo + hi), kMaxInverseIterations, Status::max_iterations};
}

}  // namespace

double erf(double x) { return boost::math::erf(x); }
double erfc(double x) { return boost::math::erfc(x); }
double erfi(double x) { return ::erfi(x); }
double dawson(double x) { return ::dawson(x); }
double erfcx(double x) { return ::erfcx(x); }

double erf_inv(double y) {
  if (!(std::abs(y) < 1.0)) throw_input_error("erf_inv", "y", y, "(-1, 1)");
  return boost::math::erf_inv(y);
}

double erfc_inv(double q) {
  if (!(q > 0.0 && q < 2.0)) throw_input_error("erfc_inv", "q", q, "(0, 2)");
  return boost::math::erfc_inv(q);
}

ErfInverseMethod parse_erf_inverse_method(std::string_view name) {
  if (name == "ours") return ErfInverseMethod::ours;
  if (name == "hybrid-003" || name == "hybrid_003" || name == "003") return ErfInverseMethod::hybrid_003;
  throw_input_error("erf inverse", "method", "unknown name '" + std::string(name) + "' (ours | hybrid-003)");
}

InverseResult erfi_inv_detailed(double y, ErfInverseMethod method) {
  if (std::isnan(y)) throw_input_error("erfi_inv", "y", y, "(-inf, inf)");
  if (method == ErfInverseMethod::hybrid_003) return erfi_inv_hybrid_003(y);
  if (y == 0) return {y, 0, Status::ok};
  if (std::isinf(y)) return {y, 0, Status::ok};
  const double a = std::abs(y);
  return with_sign(a < 1.0 ? erfi_inv_small(a) : erfi_inv_large(std::log(a)), y);
}

double erfi_inv(double y) { return erfi_inv_detailed(y).value; }

InverseResult erfi_inv_log(double log_abs_y, int sign) {
  if (std::isnan(log_abs_y)) throw_input_error("erfi_inv_log", "log_abs_y", log_abs_y, "(-inf, inf]");
  if (sign != 1 && sign != -1) throw_input_error("erfi_inv_log", "sign", sign, "{-1, 1}");
  if (log_abs_y == std::numeric_limits<double>::infinity()) return {sign * log_abs_y, 0, Status::ok};
  if (log_abs_y == -std::numeric_limits<double>::infinity()) return {0.0 * sign, 0, Status::ok};
  const InverseResult r = log_abs_y < 0 ? erfi_inv_small(std::exp(log_abs_y)) : erfi_inv_large(log_abs_y);
  return with_sign(r, sign);
}

InverseResult erfc_inv_log(double log_q) {
  if (!(log_q < kLog2)) throw_input_error("erfc_inv_log", "log_q", log_q, "(-inf, log 2)");
  if (log_q > -0.5) {  // q = e^L near 1: erf⁻¹(1 − q) with 1 − q = −expm1(L) exact to rounding
    const double one_minus_q = std::max(-std::expm1(log_q), std::nextafter(-1.0, 0.0));
    return {boost::math::erf_inv(one_minus_q), 0, Status::ok};
  }
  if (log_q > -700.0) return {boost::math::erfc_inv(std::exp(log_q)), 0, Status::ok};  // Boost.Math
  if (std::isinf(log_q)) return {std::numeric_limits<double>::infinity(), 0, Status::ok};
  // Newton on φ(x) = −x² + log erfcx(x) − L, φ' = −2/(√π erfcx(x)); decreasing in x.
  // Bracket: log erfc(26) ≈ −679 > L, and log erfc(x) < −x² ≤ L at x = √(−L) + 1.
  double lo = 26.0, hi = std::sqrt(-log_q) + 1.0;
  double x = std::sqrt(-log_q);
  x = std::sqrt(-log_q - std::log(kSqrtPi * x));  // erfc(x) ≈ e^(−x²)/(√π x)
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  for (int it = 1; it <= kMaxInverseIterations; ++it) {
    const double e = erfcx(x);
    const double phi = -x * x + std::log(e) - log_q;
    if (phi > 0) lo = x;
    else if (phi < 0) hi = x;
    else return {x, it, Status::ok};
    const double step = phi * kHalfSqrtPi * e;
    if (std::abs(step) <= 4.0 * kEps * x) return {x + step, it, Status::ok};
    x = (x + step > lo && x + step < hi) ? x + step : 0.5 * (lo + hi);  // bracket safeguard
    if (hi - lo <= 4.0 * kEps * hi) return {x, it, Status::ok};
  }
  return {x, kMaxInverseIterations, Status::max_iterations};
}

InverseResult erf_inv_hybrid_003(double y) {
  if (std::isnan(y)) throw_input_error("erf_inv_hybrid_003", "y", y, "(-1, 1)");
  // Newton region |x| ≤ 0.75 (003 gives no number; "near 0 where Newton is reliable").
  // glibc's erf (< 1 ulp) inside the iteration: Boost's promotes to long double, which made the
  // inverse's erf calls most of a quadratic position's time.
  static const double kNewtonLimit = std::erf(0.75);
  return hybrid_003(
      y, kNewtonLimit, 5.0, [](double x) { return std::erf(x); },
      [](double x) { return 2.0 / kSqrtPi * std::exp(-x * x); });
}

InverseResult erfi_inv_hybrid_003(double y) {
  if (std::isnan(y)) throw_input_error("erfi_inv_hybrid_003", "y", y, "(-inf, inf)");
  static const double kNewtonLimit = erfi(0.75);
  return hybrid_003(
      y, kNewtonLimit, 26.0, [](double x) { return erfi(x); },
      [](double x) { return 2.0 / kSqrtPi * std::exp(x * x); });
}

}  // namespace lac::special
