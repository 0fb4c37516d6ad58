// Complex upper incomplete gamma function: argument checks and the choice of region.
// Thresholds were set from the worst relative error against tests/reference/gamma_inc.csv
// (see docs/special_incomplete_gamma.md).
#include "lac/special/incomplete_gamma.hpp"

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>

#include "lac/common/error.hpp"
#include "lac/special/detail/incomplete_gamma_regions.hpp"

namespace lac::special {
namespace {

using detail::cplx;

constexpr double kSeriesRadius = 1.5;     // |z| up to which the power series is used
constexpr double kNegativeAxisBand = 1.0;  // series also where |z| + Re z ≤ this (near arg z = π), |z| < R(a)
constexpr double kKummerFraction = 0.5;    // a ≥ 1/2: series also for |z| ≤ this · (a + 1)
constexpr double kSegmentMaxRatio = 0.5;   // segment series: |z2 − z1| ≤ 0.5 |z1| …
constexpr double kSegmentMaxLength = 4.0;  // … and |z2 − z1| ≤ 4


/// |z| from which the asymptotic series is tried: its smallest term ~ Π (|a| + n)/|z| must
/// reach the rounding level, which needs |z| well above |a| for negative a.
double asymptotic_radius(double a) { return 40.0 + 4.0 * std::max(0.0, -a); }

void check_order(const char* function, double a) {
  require_finite(function, "a", a);
  if (a < kGammaIncMinOrder || a > kGammaIncMaxOrder)
    throw_input_error(function, "a", a, interval_text(kGammaIncMinOrder, kGammaIncMaxOrder, true, true));
}

cplx check_argument(const char* function, const char* name, double a, cplx z, bool allow_zero) {
  require_finite(function, std::string(name) + ".re", z.real());
  require_finite(function, std::string(name) + ".im", z.imag());
  if (z == cplx(0.0, 0.0) && !(allow_zero && a > 0))
    throw_input_error(function, name,
                      a > 0 ? "must be nonzero here" : "must be nonzero for a <= 0 (Gamma(a, z) has a pole at z = 0)");
  if (z.imag() == 0.0) z.imag(0.0);  // −0 → +0: the negative real axis is approached from above
  return z;
}

/// e^(w) z^c. The factors are formed separately: for large |Im w| the phase of e^w is then
/// exact to rounding (summing w + c log z first would cost |w| ulps of phase). Only when a
/// factor over- or underflows on its own is the product formed in the exponent.
cplx exp_times_power(cplx w, double c, cplx z) {
  const cplx e = std::exp(w), p = std::exp(c * std::log(z));
  const cplx product = e * p;
  const double m = std::abs(product);
  if (std::isfinite(m) && m > 0 && std::abs(e) > 1e-300 && std::abs(p) > 1e-300) return product;
  return std::exp(w + c * std::log(z));
}

/// e^(−z) z^a.
cplx prefactor(double a, cplx z) { return exp_times_power(-z, a, z); }

bool use_series(double a, cplx z) {
  const double r = std::abs(z);
  return r <= kSeriesRadius || (a >= 0.5 && r <= kKummerFraction * (a + 1)) ||
         (z.real() < 0 && r + z.real() <= kNegativeAxisBand && r < asymptotic_radius(a));
}

/// Scaled value by the continued fraction or the asymptotic series (|z| > 1.5).
GammaIncResult scaled_large(double a, cplx z) {
  if (std::abs(z) >= asymptotic_radius(a)) {
    GammaIncResult r = detail::asymptotic_scaled(a, z);
    if (r.status == Status::ok) return r;
  }
  return detail::continued_fraction_scaled(a, z);
}

GammaIncResult rescale(GammaIncResult r, cplx factor) {
  const cplx scaled = r.value;
  r.value *= factor;
  if (r.status == Status::ok && !(std::isfinite(r.value.real()) && std::isfinite(r.value.imag())))
    r.status = Status::numerical_failure;
  // A zero from a nonzero scaled value is the true value rounded to the double range (|Γ| below
  // the smallest subnormal, e.g. Γ(2, 800) ≈ 1e-345): the correctly rounded result, status ok.
  // A zero scaled value cannot be right (the scaled function has no zeros there): a failure.
  if (r.status == Status::ok && r.value == cplx(0.0, 0.0) && scaled == cplx(0.0, 0.0)) r.status = Status::numerical_failure;
  return r;
}

bool crosses_branch_cut(cplx z1, cplx z2) {
  const bool upper1 = z1.imag() >= 0, upper2 = z2.imag() >= 0;
  if (upper1 == upper2) return false;
  const double t = z1.imag() / (z1.imag() - z2.imag());
  return z1.real() + t * (z2.real() - z1.real()) < 0;
}

// Γ(a) with overflow returned as inf (checked by the callers) instead of Boost's exception.
double gamma_function(double a) {
  using namespace boost::math::policies;
  return boost::math::tgamma(a, policy<overflow_error<ignore_error>>());
}

}  // namespace

GammaIncResult gamma_inc(double a, std::complex<double> z) {
  check_order("gamma_inc", a);
  z = check_argument("gamma_inc", "z", a, z, true);
  if (z == cplx(0.0, 0.0)) {  // Γ(a, 0) = Γ(a) overflows for 0 < a < ~5.6e-309: a status, not an exception
    const double g = gamma_function(a);
    return GammaIncResult{g, std::isfinite(g) ? Status::ok : Status::numerical_failure, 0, GammaIncRegion::series};
  }
  if (use_series(a, z)) return rescale(detail::series(a, z), 1.0);
  return rescale(scaled_large(a, z), prefactor(a, z));
}

GammaIncResult gamma_inc_scaled(double a, std::complex<double> z) {
  check_order("gamma_inc_scaled", a);
  z = check_argument("gamma_inc_scaled", "z", a, z, false);
  if (use_series(a, z)) return rescale(detail::series(a, z), exp_times_power(z, -a, z));
  return rescale(scaled_large(a, z), 1.0);
}

GammaIncResult gamma_inc_step_scaled(double a, std::complex<double> z1, std::complex<double> dz) {
  constexpr const char* kName = "gamma_inc_step_scaled";
  check_order(kName, a);
  z1 = check_argument(kName, "z1", a, z1, false);
  require_finite(kName, "dz.re", dz.real());
  require_finite(kName, "dz.im", dz.imag());
  const cplx z2 = check_argument(kName, "z2", a, z1 + dz, true);
  if (crosses_branch_cut(z1, z2))
    throw_input_error(kName, "z2", "the segment from z1 to z2 crosses the branch cut (negative real axis)");
  if (dz == cplx(0.0, 0.0)) return GammaIncResult{0.0, Status::ok, 0, GammaIncRegion::segment_series};
  const double gap = std::abs(dz);
  if (gap <= kSegmentMaxRatio * std::abs(z1) && gap <= kSegmentMaxLength) return detail::segment_series_scaled(a, z1, dz);
  if (std::max(std::abs(z1), std::abs(z2)) <= kSeriesRadius) return detail::lower_series_difference_scaled(a, z1, dz);
  // Far apart: the two values differ by O(1) of themselves, so subtracting them is safe.
  GammaIncResult g1 = gamma_inc_scaled(a, z1);
  GammaIncResult out = g1;
  out.region = GammaIncRegion::subtraction;
  if (z2 == cplx(0.0, 0.0)) {  // a > 0: Γ(a, 0) = Γ(a)
    out.value = g1.value - gamma_function(a) * exp_times_power(z1, -a, z1);
  } else {
    const GammaIncResult g2 = gamma_inc_scaled(a, z2);
    out.value = g1.value - g2.value * std::exp(-dz) * std::exp(a * (std::log(z2) - std::log(z1)));
    out.iterations += g2.iterations;
    if (out.status == Status::ok) out.status = g2.status;
  }
  if (!(std::isfinite(out.value.real()) && std::isfinite(out.value.imag()))) out.status = Status::numerical_failure;
  return out;
}

GammaIncResult gamma_inc_difference_scaled(double a, std::complex<double> z1, std::complex<double> z2) {
  check_order("gamma_inc_difference_scaled", a);
  z1 = check_argument("gamma_inc_difference_scaled", "z1", a, z1, false);
  z2 = check_argument("gamma_inc_difference_scaled", "z2", a, z2, true);
  return gamma_inc_step_scaled(a, z1, z2 - z1);
}

GammaIncResult gamma_inc_difference(double a, std::complex<double> z1, std::complex<double> z2) {
  check_order("gamma_inc_difference", a);
  z1 = check_argument("gamma_inc_difference", "z1", a, z1, true);
  z2 = check_argument("gamma_inc_difference", "z2", a, z2, true);
  if (z1 == z2) return GammaIncResult{0.0, Status::ok, 0, GammaIncRegion::segment_series};  // also 0 − 0 (no recursion)
  if (z1 == cplx(0.0, 0.0)) {  // a > 0: Γ(a) − Γ(a, z2) = γ(a, z2) = −(Γ(a, z2) − Γ(a, 0))
    GammaIncResult r = gamma_inc_difference(a, z2, z1);
    r.value = -r.value;
    return r;
  }
  if (z1 == z2) return GammaIncResult{0.0, Status::ok, 0, GammaIncRegion::segment_series};
  return rescale(gamma_inc_difference_scaled(a, z1, z2), prefactor(a, z1));
}

}  // namespace lac::special
