#pragma once
// Closed form of the position of a standard-form planar LA curve through the upper incomplete
// gamma function (docs/math.md §1.1; Ziatdinov–Yoshida–Kim as cited by 002 ref. [17]):
//
//   C(θ) = ∫₀^θ ρ(ψ) e^{iψ} dψ = (e^{−i/k}/k) (ik)^a [Γ(a, −i/k) − Γ(a, −iU/k)],
//   k = (α−1)Λ, a = α/(α−1), U = 1 + kθ, ρ(θ) = U^{1/(α−1)};   α = 1: (e^{(Λ+i)θ} − 1)/(Λ + i).
//
// Written on plain numbers so that integrators/ does not depend on curves/. 002 reports that
// the closed form serves some α only; this one serves every α on the whole θ domain by
// choosing, per call, among forms of the same closed form (docs/special_incomplete_gamma.md):
//   elementary      Λ = 0 (unit circle) or α = 1;
//   lower_series    |z| = U/|k| ≤ 1.5 at both ends (large Λ or |α|): the γ(a, ·) difference
//                   as one series in U, any a (also |a| > 10, near α = 1);
//   gamma           |a| ≤ 10: scaled Γ(a, z) at both ends, subtracted as
//                   C(θ1) − C(θ0) = [U0^a e^{iθ0} G(a, z0) − U1^a e^{iθ1} G(a, z1)]/k,
//                   G = e^z z^{−a} Γ(a, z); for a short step the Γ difference is taken by its
//                   segment series instead (no cancellation for small θ);
//   segment_series  |a| > 10 (α near 1) or where the subtraction above would cancel: the
//                   Γ difference as Taylor series of the integrand along short pieces of the
//                   ray (the θ-form integrand (1 + kψ)^{a−1} e^{iψ} expanded per piece).
// Each form reports an error estimate; where none reaches `tol`, the result falls back to
// Gauss–Kronrod on ρ(ψ)e^{iψ} with Status::fell_back and a message saying why.
#include <complex>
#include <string_view>

#include "lac/integrators/quadrature.hpp"

namespace lac {

struct IgfOptions {
  /// Relative accuracy asked of |C(θ1) − C(θ0)|: a form is used only if its error estimate is
  /// at most tol·|result|. Default 1e-12 (the accuracy target; the estimates bound the true error on
  /// every reference case). Valid: [1e-15, 1e-2].
  double tol = 1e-12;
  /// Cap on the pieces of the segment series (e.g. θ spanning thousands of radians); beyond
  /// it the result falls back to Gauss–Kronrod. Default 100000. Valid: ≥ 1.
  long max_pieces = 100'000;

  void validate() const;
};

enum class IgfRegion { elementary, lower_series, gamma, gamma_segment, segment_series, gauss_kronrod };

constexpr std::string_view to_string(IgfRegion r) {
  switch (r) {
    case IgfRegion::elementary: return "elementary";
    case IgfRegion::lower_series: return "lower_series";
    case IgfRegion::gamma: return "gamma";
    case IgfRegion::gamma_segment: return "gamma_segment";
    case IgfRegion::segment_series: return "segment_series";
    case IgfRegion::gauss_kronrod: return "gauss_kronrod";
  }
  return "unknown";
}

struct IgfResult {
  /// value = C(θ1) − C(θ0); evaluations = series terms + continued-fraction steps (or
  /// integrand calls after a fallback); status ok, fell_back or tolerance_not_met.
  IntegralResult<std::complex<double>> integral;
  IgfRegion region = IgfRegion::elementary;
  long pieces = 0;  ///< segment-series pieces (0 in other regions)
};

/// C(θ1) − C(θ0) of the standard-form curve with slope α and Λ ≥ 0. InputError for non-finite
/// input, Λ < 0, or θ outside the open θ domain (docs/math.md §1).
IgfResult igf_position_delta_detailed(double alpha, double lambda, double theta0, double theta1,
                                      const IgfOptions& options = {});

inline IntegralResult<std::complex<double>> igf_position_delta(double alpha, double lambda, double theta0,
                                                               double theta1, const IgfOptions& options = {}) {
  return igf_position_delta_detailed(alpha, lambda, theta0, theta1, options).integral;
}

/// `igf` as a position method (an LaClosedForm, integrators/quadrature.hpp, registered in
/// integrators/registry.hpp): C(θ1) − C(θ0) of the standard-form curve with slope α and Λ.
struct Igf {
  static constexpr std::string_view name = "igf";
  /// Relative accuracy asked of each C(θ1) − C(θ0); see IgfOptions (default 1e-12).
  double tol = IgfOptions{}.tol;
  /// Segment-series piece cap before the Gauss–Kronrod fallback; see IgfOptions.
  long max_pieces = IgfOptions{}.max_pieces;

  IgfOptions options() const { return IgfOptions{tol, max_pieces}; }
  void validate() const { options().validate(); }

  /// InputError for θ0, θ1 outside the θ domain of (α, Λ) (see igf_position_delta_detailed).
  IntegralResult<std::complex<double>> integrate_theta(double alpha, double lambda, double theta0, double theta1) const {
    return igf_position_delta(alpha, lambda, theta0, theta1, options());
  }
};

}  // namespace lac
