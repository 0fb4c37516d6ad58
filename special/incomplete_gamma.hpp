#pragma once
// Upper incomplete gamma function Γ(a, z) = ∫_z^∞ t^(a−1) e^(−t) dt for real order
// a ∈ [−10, 10] (a ≤ 0 included; Γ(0, z) = E₁(z)) and complex z ≠ 0, principal branch
// (arg z ∈ (−π, π]; on the negative real axis the value is the limit from above).
//
// Written here by hand: Boost.Math's incomplete gamma takes real arguments only, and
// libcerf has no incomplete gamma. Needed by the igf closed form of the planar LA curve
// (docs/math.md §1.1), where z is purely imaginary.
//
// Regions (chosen per call; see docs/special_incomplete_gamma.md and detail/):
//   series             |z| ≤ 1.5, or near the negative real axis (|z| + Re z ≤ 1) with |z| < 40:
//                      power series of γ(a, z), with Γ(a) − 1/a and (z^a − 1)/a in
//                      non-cancelling form for |a| ≤ 1/2 (smooth through a = 0) and
//                      downward recurrence in a for a < −1/2 (no Γ(a) at its poles);
//   continued_fraction otherwise for |z| < R(a): Legendre's continued fraction, modified Lentz;
//   asymptotic         |z| ≥ R(a) = 40 + 4·max(0, −a): z^(a−1) e^(−z) Σ (a−1)…(a−n)/z^n,
//                      used only when its smallest term is below the rounding level
//                      (otherwise the continued fraction is used).
// The difference Γ(a, z1) − Γ(a, z2) for nearby points is computed without subtracting
// two large values: Taylor expansion of the integrand along the segment [z1, z2].
#include <complex>
#include <string_view>

#include "lac/common/status.hpp"

namespace lac::special {

enum class GammaIncRegion { series, continued_fraction, asymptotic, segment_series, lower_series, subtraction };

constexpr std::string_view to_string(GammaIncRegion r) {
  switch (r) {
    case GammaIncRegion::series: return "series";
    case GammaIncRegion::continued_fraction: return "continued_fraction";
    case GammaIncRegion::asymptotic: return "asymptotic";
    case GammaIncRegion::segment_series: return "segment_series";
    case GammaIncRegion::lower_series: return "lower_series";
    case GammaIncRegion::subtraction: return "subtraction";
  }
  return "unknown";
}

/// Value with how it was obtained. status is ok, max_iterations (a capped loop ran out; the
/// value is the last iterate) or numerical_failure (overflow of the result, or a non-finite
/// intermediate). A result below the smallest subnormal double is returned as 0 with status ok
/// (the correctly rounded value; gamma_inc_scaled gives its scaled value).
struct GammaIncResult {
  std::complex<double> value{};
  Status status = Status::ok;
  int iterations = 0;  ///< terms summed or continued-fraction steps (total over sub-steps)
  GammaIncRegion region = GammaIncRegion::series;
};

/// Valid order range.
inline constexpr double kGammaIncMinOrder = -10.0;
inline constexpr double kGammaIncMaxOrder = 10.0;

/// Γ(a, z). InputError: a not finite or outside [−10, 10]; z not finite; z = 0 with a ≤ 0
/// (Γ(a, 0) = Γ(a) for a > 0 is returned).
GammaIncResult gamma_inc(double a, std::complex<double> z);

/// e^z z^(−a) Γ(a, z): the same function without the factor that overflows or underflows
/// for large |z| (≈ 1/z there). Same domain as gamma_inc, z ≠ 0.
GammaIncResult gamma_inc_scaled(double a, std::complex<double> z);

/// Γ(a, z1) − Γ(a, z2) = ∫_{z1}^{z2} t^(a−1) e^(−t) dt (principal branch; the segment
/// must not cross the negative real axis). Accurate also when z1 ≈ z2. InputError as for
/// gamma_inc for either point (z = 0 allowed for a > 0), and when the segment crosses
/// the branch cut.
GammaIncResult gamma_inc_difference(double a, std::complex<double> z1, std::complex<double> z2);

/// e^(z1) z1^(−a) (Γ(a, z1) − Γ(a, z2)), z1 ≠ 0: the difference scaled by its start point.
GammaIncResult gamma_inc_difference_scaled(double a, std::complex<double> z1, std::complex<double> z2);

/// e^(z1) z1^(−a) (Γ(a, z1) − Γ(a, z1 + dz)), z1 ≠ 0, with the step dz given exactly: use this
/// when z2 would be rounded (z1 + dz in double loses the low digits of a small dz).
GammaIncResult gamma_inc_step_scaled(double a, std::complex<double> z1, std::complex<double> dz);

}  // namespace lac::special
