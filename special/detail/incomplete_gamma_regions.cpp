// Region algorithms of the complex upper incomplete gamma function; see the header for the
// formulas. Hand-written: Boost.Math's gamma_q/tgamma(a, x) accept real x only.
#include "lac/special/detail/incomplete_gamma_regions.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <limits>

namespace lac::special::detail {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kTiny = 1e-300;  // Lentz guard against division by zero

bool finite(cplx w) { return std::isfinite(w.real()) && std::isfinite(w.imag()); }

GammaIncResult finish(cplx value, int iterations, GammaIncRegion region, Status status = Status::ok) {
  GammaIncResult r;
  r.value = value;
  r.iterations = iterations;
  r.region = region;
  r.status = finite(value) ? status : Status::numerical_failure;
  return r;
}

/// Σ_{n ≥ 0, n ≠ skip} (−z)^n / (n! (a + n)) until two terms past `skip` are below the rounding
/// level. For z near the negative real axis the terms share their sign: no cancellation.
cplx alternating_sum(double a, cplx z, int skip, int cap, int& terms, bool& converged) {
  cplx term = 1.0, sum = 0.0;
  int small = 0;
  converged = false;
  for (int n = 0; n < cap; ++n) {
    if (n != skip) {
      const cplx add = term / (a + static_cast<double>(n));
      sum += add;
      ++terms;
      if (n > skip && std::abs(add) <= 0.5 * kEps * std::abs(sum)) {
        if (++small == 2) {
          converged = true;
          break;
        }
      } else {
        small = 0;
      }
    }
    term *= -z / static_cast<double>(n + 1);
  }
  return sum;
}

}  // namespace

cplx expm1(cplx w) {
  const double x = w.real(), y = w.imag();
  if (std::abs(x) > 0.5 || std::abs(y) > 0.5) return std::exp(w) - 1.0;
  const double s = std::sin(0.5 * y);
  return {std::expm1(x) * std::cos(y) - 2.0 * s * s, std::exp(x) * std::sin(y)};
}

cplx expm1_ratio(cplx w) {
  if (w == cplx(0.0, 0.0)) return 1.0;
  return expm1(w) / w;
}

cplx log1p(cplx w) {
  const double x = w.real(), y = w.imag();
  if (std::abs(x) > 0.5 || std::abs(y) > 0.5) return std::log(1.0 + w);
  // |1 + w|² − 1 = 2x + x² + y², formed without cancellation.
  return {0.5 * std::log1p(x * (2.0 + x) + y * y), std::atan2(y, 1.0 + x)};
}

GammaIncResult series(double a, cplx z) {
  constexpr int kCap = 600;
  const cplx log_z = std::log(z);
  int terms = 0;
  bool converged = false;
  if (a >= 0.5 && z.real() < 0) {  // Γ(a) − z^a Σ (−z)^n/(n!(a+n)), same-sign terms here
    const cplx sum = alternating_sum(a, z, -1, kCap, terms, converged);
    return finish(boost::math::tgamma(a) - std::exp(a * log_z) * sum, terms, GammaIncRegion::series,
                  converged ? Status::ok : Status::max_iterations);
  }
  if (a >= 0.5) {
    // Γ(a) − γ(a, z), γ(a, z) = z^a e^(−z) Σ_{n≥0} z^n / (a (a+1) … (a+n)) (Kummer's form: its
    // terms shrink from the start while |z| < a + 1, so the sum itself does not cancel).
    cplx term = 1.0 / a, sum = 0.0;
    int small = 0;
    for (int n = 0; n < kCap; ++n) {
      sum += term;
      ++terms;
      if (std::abs(term) <= 0.5 * kEps * std::abs(sum)) {
        if (++small == 2) {
          converged = true;
          break;
        }
      } else {
        small = 0;
      }
      term *= z / (a + static_cast<double>(n + 1));
    }
    const cplx lower = std::exp(a * log_z) * std::exp(-z) * sum;
    return finish(boost::math::tgamma(a) - lower, terms, GammaIncRegion::series,
                  converged ? Status::ok : Status::max_iterations);
  }
  // a = −m + ε, m ≥ 0 integer, ε ∈ [−1/2, 1/2). The n = m term of −z^a Σ (−z)^n/(n!(a+n)) and
  // Γ(a) both blow up as ε → 0; together they are
  //   ((−1)^m / m!) [ (R(ε) − 1)/ε − (z^ε − 1)/ε ],   R(ε) = Γ(1 + ε) Π_{j=1..m} j/(j − ε),
  // smooth through ε = 0 (Γ(0, z) = E₁(z) = −γ_E − log z − …). No recurrence in a is needed.
  const double m_real = -std::floor(a + 0.5);
  const int m = static_cast<int>(m_real);
  const double eps = a + m_real;
  double log_r = std::log1p(boost::math::tgamma1pm1(eps));
  for (int j = 1; j <= m; ++j) log_r -= std::log1p(-eps / j);
  double harmonic = 0;  // H_m: at ε = 0, (R − 1)/ε → R'(0) = −γ_E + H_m
  for (int j = 1; j <= m; ++j) harmonic += 1.0 / j;
  const double r_part = eps == 0 ? harmonic - boost::math::constants::euler<double>() : std::expm1(log_r) / eps;
  const cplx power_part = log_z * expm1_ratio(eps * log_z);  // (z^ε − 1)/ε
  double inv_m_factorial = 1.0;
  for (int j = 2; j <= m; ++j) inv_m_factorial /= j;
  const cplx singular_pair = ((m % 2) ? -inv_m_factorial : inv_m_factorial) * (r_part - power_part);
  const cplx sum = alternating_sum(a, z, m, kCap, terms, converged);
  const cplx value = singular_pair - std::exp(a * log_z) * sum;
  return finish(value, terms, GammaIncRegion::series, converged ? Status::ok : Status::max_iterations);
}

GammaIncResult continued_fraction_scaled(double a, cplx z, int max_steps) {
  // Modified Lentz: f = b0 + a1/(b1 + a2/(b2 + …)) with f = 1/G here, b0 = z + 1 − a,
  // a_n = −n (n − a), b_n = z + 2n + 1 − a.
  cplx b = z + 1.0 - a;
  cplx c = 1.0 / kTiny;
  cplx d = 1.0 / b;
  cplx h = d;
  int n = 1;
  bool converged = false;
  for (; n <= max_steps; ++n) {
    const double an = -static_cast<double>(n) * (static_cast<double>(n) - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const cplx delta = c * d;
    h *= delta;
    if (std::abs(delta - 1.0) <= kEps) {
      converged = true;
      break;
    }
  }
  return finish(h, n, GammaIncRegion::continued_fraction, converged ? Status::ok : Status::max_iterations);
}

GammaIncResult asymptotic_scaled(double a, cplx z, int max_terms) {
  cplx term = 1.0, sum = 1.0;
  double previous = 1.0;
  int n = 1;
  Status status = Status::tolerance_not_met;
  for (; n <= max_terms; ++n) {
    term *= (a - static_cast<double>(n)) / z;
    const double size = std::abs(term);
    if (size > previous) break;  // divergent tail reached before the rounding level
    sum += term;
    if (size <= 0.5 * kEps * std::abs(sum)) {
      status = Status::ok;
      break;
    }
    previous = size;
  }
  return finish(sum / z, n, GammaIncRegion::asymptotic, status);
}

GammaIncResult segment_series_scaled(double a, cplx z1, cplx dz, int max_terms) {
  const cplx delta = dz / z1;
  cplx c_prev = 0.0, c = 1.0;
  cplx power = delta;  // δ^(n+1)
  cplx sum = 0.0;
  int small = 0, n = 0;
  bool converged = false;
  for (; n < max_terms; ++n) {
    const cplx add = c * power / static_cast<double>(n + 1);
    sum += add;
    if (std::abs(add) <= 0.5 * kEps * std::abs(sum)) {
      if (++small == 3) {
        converged = true;
        break;
      }
    } else {
      small = 0;
    }
    const cplx c_next = ((a - 1.0 - static_cast<double>(n) - z1) * c - z1 * c_prev) / static_cast<double>(n + 1);
    c_prev = c;
    c = c_next;
    power *= delta;
  }
  return finish(sum, n + 1, GammaIncRegion::segment_series, converged ? Status::ok : Status::max_iterations);
}

GammaIncResult lower_series_difference_scaled(double a, cplx z1, cplx dz, int max_terms) {
  const cplx z2 = z1 + dz;
  const bool to_zero = z2 == cplx(0.0, 0.0);  // a > 0: z1^(−a) (0 − γ(a, z1)) term by term
  const cplx ratio = dz / z1;
  const cplx L = to_zero ? 0.0 : std::abs(ratio) < 0.5 ? log1p(ratio) : std::log(z2) - std::log(z1);
  cplx term = 1.0;  // (−z1)^n / n!
  cplx sum = 0.0;
  int small = 0, n = 0;
  bool converged = false;
  for (; n < max_terms; ++n) {
    const double b = a + static_cast<double>(n);
    const cplx add = to_zero ? -term / b : term * L * expm1_ratio(b * L);
    sum += add;
    if (std::abs(add) <= 0.5 * kEps * std::abs(sum)) {
      if (++small == 2) {
        converged = true;
        break;
      }
    } else {
      small = 0;
    }
    term *= -z1 / static_cast<double>(n + 1);
  }
  return finish(std::exp(z1) * sum, n + 1, GammaIncRegion::lower_series,
                converged ? Status::ok : Status::max_iterations);
}

}  // namespace lac::special::detail
