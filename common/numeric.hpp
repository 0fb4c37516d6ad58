#pragma once
// Small numeric helpers shared by the curve models.
//   log1p_ratio(x) = log1p(x)/x,  expm1_ratio(y) = expm1(y)/y   (both = 1 at 0)
// Writing the LA closed forms as products of these makes α = 0, α = 1 and Λ → 0 exact limits
// instead of special cases (curves/planar/la_curve.hpp).
#include <cmath>
#include <limits>
#include <numbers>

namespace lac {

/// g(x) = log1p(x)/x, continuous (= 1) at 0.
inline double log1p_ratio(double x) { return x == 0 ? 1.0 : std::log1p(x) / x; }
/// h(y) = expm1(y)/y, continuous (= 1) at 0.
inline double expm1_ratio(double y) { return y == 0 ? 1.0 : std::expm1(y) / y; }

/// x^e for x ≥ 0 (any x for integer e). Exponents that are multiples of 1/2 with |e| ≤ 4 by
/// products, one sqrt and one division (≤ 4 ulp where x^|e| is a normal number), multiples of 1/3
/// with |e| ≤ 8/3 by cbrt and products (≤ 12 ulp), std::pow otherwise. The LA laws of α = ±1,
/// ±2, ±1/2, ±3, ±1/3 have only such exponents (K = |q|^(−1/α), its derivatives and
/// antiderivative), where this is several times faster than std::pow.
inline double power(double x, double e) {
  const auto by_products = [](double root, int m, bool invert) {
    double r = root;
    for (int i = 1; i < m; ++i) r *= root;
    return invert ? 1.0 / r : r;
  };
  const double twice = 2.0 * e;
  if (std::abs(twice) <= 8 && twice == std::trunc(twice)) {
    const int m = static_cast<int>(std::abs(twice));
    double r = (m & 1) ? std::sqrt(x) : 1.0;
    for (int i = 0; i < m / 2; ++i) r *= x;
    return twice < 0 ? 1.0 / r : r;
  }
  const double thrice = 3.0 * e;
  if (std::abs(thrice) <= 8 && thrice == std::trunc(thrice))
    return by_products(std::cbrt(x), static_cast<int>(std::abs(thrice)), thrice < 0);
  return std::pow(x, e);
}

/// An interval of a curve parameter; infinite ends are ±inf. Open unless an end is marked closed
/// (e.g. the arc-length range [0, L] of a finite curve).
struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_closed = false;
  bool hi_closed = false;
  bool contains(double t) const { return (lo_closed ? t >= lo : t > lo) && (hi_closed ? t <= hi : t < hi); }
};

/// The angle a reduced to (−π, π] (exact: std::remainder, then −π → π). For |a| < 9.42 (< 3π)
/// a − 2πk with k ∈ {−1, 0, 1} is that remainder, exact by Sterbenz's lemma, without the call.
inline double wrap_angle(double a) {
  constexpr double pi = std::numbers::pi, two_pi = 2.0 * std::numbers::pi;
  const double r = a > -9.42 && a < 9.42 ? (a > pi ? a - two_pi : a < -pi ? a + two_pi : a) : std::remainder(a, two_pi);
  return r <= -pi ? r + two_pi : r;
}

}  // namespace lac
