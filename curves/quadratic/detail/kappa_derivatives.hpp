#pragma once
// Internal: the derivatives of κ in arc length on a quadratic LA curve (003), used by the certified
// positions (curves/quadratic/certified_position.cpp) and the export's span bounds
// (export/to_bspline_quadratic.cpp).
//
// 003's Eq. (4.3), ds/dκ = −κ^(−α + γ log κ − 1)/Λ, is in u = log κ: ds/du = −e^(E(u))/Λ with
// E(u) = γu² − αu, so d/ds = −Λ e^(−E(u)) d/du and, by induction on j (κ = e^u),
//   κ^(j) = (−Λ)^j P_j(u) e^(φ_j(u)),   φ_j(u) = u − j E(u) = (1 + jα) u − jγ u²,
//   P_0 = 1,   P_(j+1) = P_j' + (1 + jα − 2jγ u) P_j   (φ_j' = 1 + jα − 2jγu).
// Past the inflection the curve is the point-symmetric image (κ(s_i + t) = −κ(s_i − t)), so there
// κ^(j) = −Λ^j P_j(u) e^(φ_j(u)) with u = log|κ|.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

namespace lac::detail {

/// Coefficients (in powers of u, degree j − 1 for j ≥ 1) of P_0 … P_n.
inline std::vector<std::vector<double>> kappa_derivative_polynomials(double alpha, double gamma, int n) {
  std::vector<std::vector<double>> P(static_cast<size_t>(n) + 1);
  P[0] = {1.0};
  for (int j = 0; j < n; ++j) {
    const std::vector<double>& p = P[static_cast<size_t>(j)];
    std::vector<double> q(p.size() + 1, 0.0);
    for (size_t i = 1; i < p.size(); ++i) q[i - 1] += static_cast<double>(i) * p[i];  // P_j'
    for (size_t i = 0; i < p.size(); ++i) {
      q[i] += (1 + j * alpha) * p[i];
      q[i + 1] += -2 * j * gamma * p[i];
    }
    while (q.size() > 1 && q.back() == 0) q.pop_back();
    P[static_cast<size_t>(j) + 1] = std::move(q);
  }
  return P;
}

/// P(u) by Horner, and Σ|a_i||u|^i (which bounds |P| and, times 2·size·ε, Horner's rounding).
inline double evaluate_polynomial(const std::vector<double>& a, double u, double* abs_sum = nullptr) {
  double v = 0, s = 0;
  for (size_t i = a.size(); i-- > 0;) {
    v = v * u + a[i];
    s = s * std::abs(u) + std::abs(a[i]);
  }
  if (abs_sum) *abs_sum = s;
  return v;
}

/// max |P(u)| over [lo, hi] (lo may be −inf: then finite only for a constant), from the Taylor
/// coefficients at the interval's middle, |P(c + t)| ≤ Σ |P^(i)(c)/i!| |t|^i, with a rounding
/// allowance.
inline double max_abs_polynomial(const std::vector<double>& a, double lo, double hi) {
  size_t degree = a.size() - 1;
  while (degree > 0 && a[degree] == 0) --degree;
  if (!std::isfinite(lo)) return degree == 0 ? std::abs(a[0]) : std::numeric_limits<double>::infinity();
  const double c = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
  std::vector<double> t(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(degree) + 1);
  for (size_t k = 0; k <= degree; ++k)  // Taylor shift to c by repeated synthetic division
    for (size_t i = degree; i-- > k;) t[i] += c * t[i + 1];
  double bound = 0, scale = 0, rk = 1, mk = 1;
  const double m = std::max(std::abs(lo), std::abs(hi));
  for (size_t i = 0; i <= degree; ++i, rk *= r, mk *= m) {
    bound += std::abs(t[i]) * rk;
    scale += std::abs(a[i]) * mk;
  }
  // The shift's rounding: 4 (degree + 1)² ε of the coefficients' size at |u| ≤ m, at least 1e-12.
  return bound + std::max(1e-12, 4.0 * static_cast<double>((degree + 1) * (degree + 1)) * DBL_EPSILON) * scale;
}

/// max of φ(u) = b u − c u² over [lo, hi] (lo may be −inf), with a rounding allowance.
inline double max_quadratic(double b, double c, double lo, double hi) {
  const double inf = std::numeric_limits<double>::infinity();
  auto phi = [&](double u) {
    if (std::isfinite(u)) return b * u - c * u * u + 1e-12 * (std::abs(b * u) + std::abs(c * u * u));
    return c < 0 || (c == 0 && b < 0) ? inf : (c == 0 && b == 0 ? 0.0 : -inf);  // u → −∞
  };
  double v = std::max(phi(lo), phi(hi));
  if (c > 0) {
    const double vertex = b / (2 * c);
    if (vertex > lo && vertex < hi) v = std::max(v, phi(vertex));
  }
  return v;
}

}  // namespace lac::detail
