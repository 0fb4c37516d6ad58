#include "lac/curves/quadratic/detail/exp_quadratic_integral.hpp"

#include <array>
#include <cmath>

#include "lac/common/numeric.hpp"

namespace lac::detail {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSqrtPi = 1.7724538509055160273;
constexpr double kLogTwoOverSqrtPi = 0.12078223763524522234551845;
constexpr double kNearRegion = 3.0;  // |γ|u² + |αu| ≤ 3: Gauss–Legendre (see the header)

// sign(m) · e^(E) · |m| without overflowing before the product does.
double scaled(double e, double m) {
  if (m == 0) return 0.0;
  return std::copysign(std::exp(e + std::log(std::abs(m))), m);
}

// x ≥ 0 with log erfi(x) = L, to 7e-10 relative (measured on a 0.001 grid), for L in [kTableLo, kTableHi] (x in [3e-4, 7.5]);
// NaN outside. Quintic Hermite on a table built once per process (513 exact erfi_inv_log calls,
// ~0.1 ms) with dx/dL = D(x) and d²x/dL² = (1 − 2xD(x)) D(x): the start for κ(s) with γ > 0
// costs a lookup instead of 2–4 Halley iterations, each a Dawson and a log.
constexpr double kTableLo = -8.0, kTableHi = 56.0, kTableStep = 0.125;
constexpr int kTableNodes = 513;  // (kTableHi − kTableLo)/kTableStep + 1

struct StartNode {
  double x, d1, d2;  // x, h·dx/dL, h²·d²x/dL²
};
using StartTable = std::array<StartNode, kTableNodes>;

double hermite_start(const StartTable& table, double lo, double log_y) {
  const double pos = (log_y - lo) / kTableStep;
  if (!(pos >= 0.0 && pos < kTableNodes - 1)) return std::numeric_limits<double>::quiet_NaN();
  const int j = static_cast<int>(pos);
  const double t = pos - j, t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  const StartNode& a = table[static_cast<size_t>(j)];
  const StartNode& b = table[static_cast<size_t>(j + 1)];
  const double h0 = 1 - 10 * t3 + 15 * t4 - 6 * t5, h1 = t - 6 * t3 + 8 * t4 - 3 * t5;
  const double h2 = 0.5 * t2 - 1.5 * t3 + 1.5 * t4 - 0.5 * t5, h3 = 10 * t3 - 15 * t4 + 6 * t5;
  const double h4 = -4 * t3 + 7 * t4 - 3 * t5, h5 = 0.5 * t3 - t4 + 0.5 * t5;
  return a.x * h0 + a.d1 * h1 + a.d2 * h2 + b.x * h3 + b.d1 * h4 + b.d2 * h5;
}

double erfi_inv_log_start(double log_y) {
  static const StartTable table = [] {
    StartTable nodes{};
    for (int j = 0; j < kTableNodes; ++j) {
      const double x = special::erfi_inv_log(kTableLo + kTableStep * j, 1).value;
      const double d = special::dawson(x);
      nodes[static_cast<size_t>(j)] = {x, kTableStep * d, kTableStep * kTableStep * (1.0 - 2.0 * x * d) * d};
    }
    return nodes;
  }();
  return hermite_start(table, kTableLo, log_y);
}

// x ≥ 0 with log erfc(x) = L for L in [−64, 0] (x in [0, 7.9]) to 4e-7 relative (2e-8 absolute;
// measured), NaN outside; the γ < 0 start.
// dx/dL = −(√π/2) erfcx(x), d²x/dL² = −(√π/2) erfcx'(x) dx/dL with erfcx' = 2x erfcx − 2/√π.
constexpr double kErfcTableLo = -64.0;
double erfc_inv_log_start(double log_q) {
  static const StartTable table = [] {
    StartTable nodes{};
    for (int j = 0; j < kTableNodes; ++j) {
      const double x = special::erfc_inv_log(std::min(kErfcTableLo + kTableStep * j, 0.0)).value;
      const double e = special::erfcx(x);
      const double d1 = -0.5 * kSqrtPi * e;
      const double d2 = -0.5 * kSqrtPi * (2.0 * x * e - 2.0 / kSqrtPi) * d1;
      nodes[static_cast<size_t>(j)] = {x, kTableStep * d1, kTableStep * kTableStep * d2};
    }
    return nodes;
  }();
  if (log_q == 0.0) return 0.0;
  return hermite_start(table, kErfcTableLo, log_q);
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
    limit_plus_ = c * erfcx_plus_;            // F(+∞), docs/math.md §4.4 bounds in erfcx form
    limit_minus_ = -c * erfcx_minus_;         // F(−∞)
    base_ = center_ >= 0 ? erfcx_plus_ : erfcx_minus_;
  } else {
    if (alpha > 0) limit_plus_ = 1.0 / alpha;
    if (alpha < 0) limit_minus_ = 1.0 / alpha;
  }
}

double ExpQuadraticIntegral::midpoint_series(double v, double w) const {
  // Taylor series about the midpoint m = (v + w)/2, h = (w − v)/2: E(m + τ) = E(m) + bτ + γτ²,
  // b = E'(m) = 2γm − α,
  //   ∫_v^w e^(E) = e^(E(m)) ∫_{−h}^{h} e^(bτ + γτ²) dτ = e^(E(m)) · 2h Σ_k d_2k/(2k + 1),
  // d_n = c_n h^n with c_n the Taylor coefficients of e^(bτ + γτ²) (c_(n+1) = (b c_n + 2γ c_(n−1))/(n + 1)).
  // Only even terms survive: for γ ≥ 0 all are ≥ 0; for γ < 0 the sum loses at most a factor
  // e^(2|γ|h²) to cancellation (≤ 4.5 in the near region, |γ|h² ≤ 3/4). With |bh| ≤ 3/2 the
  // terms fall below rounding within 40 (cap 60).
  static constexpr auto kInv = [] {
    std::array<double, 64> a{};
    for (size_t i = 1; i < a.size(); ++i) a[i] = 1.0 / static_cast<double>(i);
    return a;
  }();
  const double m = 0.5 * (v + w), h = 0.5 * (w - v);
  const double p = (2.0 * gamma_ * m - alpha_) * h, q = 2.0 * gamma_ * h * h;
  double d_prev = 1.0, d = p, sum = 1.0;  // d_0, d_1; sum of d_2k/(2k + 1)
  for (size_t n = 1; n + 2 < kInv.size(); n += 2) {
    const double even = (p * d + q * d_prev) * kInv[n + 1];  // d_(n+1), n + 1 even
    const double odd = (p * even + q * d) * kInv[n + 2];     // d_(n+2)
    const double term = even * kInv[n + 2];                  // d_(n+1)/(n + 2)
    sum += term;
    if (std::abs(term) + std::abs(odd) <= 0.25 * kEps * std::abs(sum)) break;
    d_prev = even;
    d = odd;
  }
  return std::exp(exponent(m)) * 2.0 * h * sum;
}

double ExpQuadraticIntegral::between(double v, double w) const {
  const double h = 0.5 * (w - v), m = 0.5 * (v + w);
  if (std::abs((2.0 * gamma_ * m - alpha_) * h) <= 1.5 && std::abs(gamma_) * h * h <= 0.75) return midpoint_series(v, w);
  return (*this)(w) - (*this)(v);
}

double ExpQuadraticIntegral::operator()(double u) const {
  if (u == 0) return 0.0;  // the reference point; the series below would form 0·inf for |γ| = DBL_MAX
  if (gamma_ == 0) return u * expm1_ratio(-alpha_ * u);
  if (std::abs(gamma_) * u * u + std::abs(alpha_ * u) <= kNearRegion) return midpoint_series(0.0, u);
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
  const double diff = std::erf(center_) - std::erf(y);  // glibc, < 1 ulp (Boost's promotes to long double)
  return -c * std::copysign(std::exp(center_ * center_ + std::log(std::abs(diff))), diff);
}

double ExpQuadraticIntegral::start_ours(double target, int& iterations) const {
  if (gamma_ > 0) {
    // e^(x²) D(x) = e^(x0²) R with R = D(x0) + √γ F  ⇔  erfi(x) = (2/√π) e^(x0² + log|R|) sign R.
    const double r = base_ + root_ * target;
    if (r == 0) return -center_ / root_;
    const double log_y = center_ * center_ + std::log(std::abs(r)) + kLogTwoOverSqrtPi;
    const double x = erfi_inv_log_start(log_y);  // polish() takes it from 7e-10 to rounding
    if (!std::isnan(x)) return ((r > 0 ? x : -x) - center_) / root_;
    const auto inv = special::erfi_inv_log(log_y, r > 0 ? 1 : -1);
    iterations += inv.iterations;
    return (inv.value - center_) / root_;
  }
  // γ < 0: erf y − erf y0 = P e^(−y0²), P = (2√g/√π) F, so with a + b = 2 e^(y0²):
  //   erfc(y) = e^(−y0²) a, a = erfcx(y0) − P;   erfc(−y) = e^(−y0²) b, b = erfcx(−y0) + P.
  // Invert the one that is ≤ 1 (erfc_inv_log is accurate there); an overflowed one is never used.
  const double p = 2.0 * root_ / kSqrtPi * target;
  const double a = erfcx_plus_ - p, b = erfcx_minus_ + p;
  const double y2 = center_ * center_;
  // A table start (erfc_inv_log_start, 4e-7 relative, measured) where it covers the argument.
  auto erfc_inverse = [&](double log_q) {
    const double x = erfc_inv_log_start(log_q);
    if (!std::isnan(x)) return x;
    const auto inv = special::erfc_inv_log(log_q);
    iterations += inv.iterations;
    return inv.value;
  };
  if (a <= b) {
    if (!(a > 0)) return kInf;
    return (erfc_inverse(std::min(std::log(a) - y2, 0.0)) - center_) / root_;
  }
  if (!(b > 0)) return -kInf;
  return (-erfc_inverse(std::min(std::log(b) - y2, 0.0)) - center_) / root_;
}

InverseSolution ExpQuadraticIntegral::inverse_003(double target) const {
  // 003 Eq. (4.6) with docs/math.md §4's sign correction, unscaled: e^(±α²/(4γ)) and the hybrid
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
    return {target * log1p_ratio(-alpha_ * target), 0, Status::ok};
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
  if (gamma_ == 0) return {target * log1p_ratio(-alpha_ * target), 0, Status::ok};
  // Halley on f(u) = F(u) − target: f' = e^E, f''/f' = E'(u) = 2γu − α. Bracket by sign of f.
  double lo = -kInf, hi = kInf;
  for (int it = 1; it <= max_iterations; ++it) {
    ++out.iterations;
    const double f = (*this)(u)-target;
    if (f > 0) hi = u;
    else if (f < 0) lo = u;
    else return {u, out.iterations, Status::ok};
    const double ratio = f * std::exp(-exponent(u));
    const double slope = 2.0 * gamma_ * u - alpha_;  // E'(u)
    const double step = -ratio / (1.0 - 0.5 * ratio * slope);
    // Halley's error after this step is K step³ + O(step⁴) with K = (f2/2f1)² − f3/6f1 = E'²/12 − γ/3
    // (f1 = e^E, f2 = E' e^E, f3 = (2γ + E'²) e^E), |K| ≤ σ², σ = |E'| + √|γ|. Accept when that is
    // below a tenth of the rounding of u (σ|step| ≤ 1e-3 keeps the step⁴ term smaller still): this
    // saves the confirming evaluation after a good start.
    const double sigma = std::abs(slope) + std::sqrt(std::abs(gamma_));
    const double scaled_step = sigma * std::abs(step);
    const double rounding = kEps * std::max(1.0, std::abs(u));
    if (std::isfinite(step) && (std::abs(step) <= 2.0 * rounding ||
                                (scaled_step <= 1e-3 && scaled_step * scaled_step * std::abs(step) <= 0.1 * rounding))) {
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
