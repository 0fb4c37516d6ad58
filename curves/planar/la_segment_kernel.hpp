#pragma once
// The tangent integral of one planar LA segment in the normalized form of the G1 Hermite problem
// (004 §3; docs/g1_hermite.md "Kernel"): u ∈ [0, 1], φ(0) = φ0, φ(1) = φ0 + Δ, q linear in u
// (la_law.hpp), the remaining freedom a shape variable x:
//   α = −1:  x = A, q = κ per unit u = (Δ − A, Δ + A) at u = 0, 1   (φ = φ0 + (Δ − A)u + Au²)
//   α = 0:   x = b = log(κb/κa)                                       (φ = φ0 + Δ expm1(bu)/expm1(b))
//   α > 0:   x = log(qb/qa)                                           (q keeps its sign)
//   α < 0:   x = a, (qa, qb) ∝ (Δ − a, Δ + a)                         (|a| > |Δ|: an inflection)
// evaluate(x) gives I = ∫₀¹ e^{iφ(u)} du and dI/dx (forward-mode derivatives), ≲ 1e-14 relative:
// closed-form series in a logarithmic variable where a piece turns little, Gauss–Legendre panels
// sized by the phase's slope elsewhere, in the offset variables of la_law.hpp for 0 < |α| <
// kLaKernelSmallAlpha (continuous through α = 0). A shape the kernel cannot resolve (a piece past
// its panel cap, a steep piece beyond its series, non-finite data) is "not evaluated" (ok = false),
// never a wrong value.
//
//   lac::LaSegmentKernel k{.alpha = -0.5, .phi0 = 0.3, .delta = -0.8};
//   lac::LaKernelValue v = k.evaluate(0.2);   // v.integral, v.d_integral, v.qa, v.qb
#include <complex>
#include <limits>
#include <optional>

#include "lac/curves/planar/detail/linear_q.hpp"

namespace lac {

/// Below this |α| (α ≠ 0) a shape without a zero of q on [0, 1] is evaluated in the variables of
/// the α = 0 law (la_law.hpp's offset form).
inline constexpr double kLaKernelSmallAlpha = 0.05;

/// The kernel's accuracy: |I − ∫₀¹e^{iφ}| ≤ kLaKernelError (relative to ∫₀¹|e^{iφ}| = 1), measured
/// against long-double references (docs/g1_hermite.md, tests/curves/la_segment_kernel_test.cpp);
/// the rounding of φ itself (ε·max|φ|) comes on top.
inline constexpr double kLaKernelError = 1e-13;

/// One evaluation of the kernel at a shape x.
struct LaKernelValue {
  bool ok = false;  ///< false: not evaluated (see above); the other fields are then meaningless
  /// Im I and Im dI/dx: the G1 end-tangent condition (the chord along the real axis) and its slope.
  double f = std::numeric_limits<double>::quiet_NaN(), df = std::numeric_limits<double>::quiet_NaN();
  std::complex<double> I;   ///< ∫₀¹ e^{iφ(u)} du
  std::complex<double> dI;  ///< dI/dx
  double qa = 0, qb = 0;    ///< the segment's q (α ≠ 0) or log|κ| (α = 0) at u = 0, 1, per unit u
  bool offset = false;      ///< qa, qb in the offset form of la_law.hpp (small |α|), σ = sgn Δ
};

struct LaSegmentKernel {
  double alpha = -1, phi0 = 0, delta = 0;
  long evaluations = 0;    ///< kernel evaluations so far: Gauss–Legendre nodes plus series terms
  long constructions = 0;  ///< shapes evaluated so far
  /// Kernel evaluations allowed for α < 0: once spent, every shape is "not evaluated" (a search
  /// over shapes then ends fast). α ≥ 0 has none (the G1 refusals rest on scans of every shape).
  long budget = std::numeric_limits<long>::max();
  bool exhausted() const { return alpha < 0 && evaluations >= budget; }
  LaKernelValue evaluate(double x);
  /// α < 0, α ≠ −1 (not evaluated otherwise): the segment given by its q (plain form of
  /// la_law.hpp, per unit u) at u = 0 and 1 instead of a shape, with `delta` = F[qa, qb] its
  /// turning; dI is 0. (For α < 0 the shape a is singular where Δ = 0, the antisymmetric S.)
  LaKernelValue evaluate_q(double qa, double qb);
};

/// ∫ e^{iφ(u)} du over a segment in linear-q form with a bound on its error.
struct LaSegmentIntegral {
  std::complex<double> value;
  /// kLaKernelError·(ub − ua), plus, where the segment is handed to the kernel as q values at
  /// α < 0 (evaluate_q), the effect of their rounding (relative ε on q is ε/|α| on κ) over the
  /// turning: 2ε/|α|·(total variation of φ)·(ub − ua). The rounding of φ itself is not included.
  double error = 0;
};

/// That integral over any [ua, ub], either form of the law, by the kernel (normalized to u ∈ [0, 1]);
/// `evaluations` counts its kernel evaluations. nullopt where the kernel does not evaluate it (a
/// piece past its caps, data out of the double range): use a quadrature method there.
std::optional<LaSegmentIntegral> segment_integral(const LaLaw& law, const detail::LinearQ& seg, long& evaluations);

/// Derivatives of a segment's I = ∫_{ua}^{ub} e^{iφ(u)} du and end angle φb with respect to its end
/// values qa, qb (the tangent angle enters as ∂I/∂φa = iI, ∂φb/∂φa = 1): the Jacobian of a
/// construction's end conditions.
struct LaSegmentDerivatives {
  std::complex<double> dI_dqa, dI_dqb;
  double dphib_dqa = 0, dphib_dqb = 0;
};

/// Relative change |qb − qa| (of |q| in the plain form, absolute in the log forms, where q holds
/// log|κ|) below which segment_derivatives declines: its closed form divides by qb − qa.
inline constexpr double kLaDerivativeMinChange = 1e-4;

/// Those derivatives in closed form from I itself (by whatever method I was computed), no further
/// integral: ∂φ/∂qa and ∂φ/∂qb along the segment are combinations of 1, κ, uκ and φ − φa; the
/// integrals of κe^{iφ} and uκe^{iφ} follow by parts, and ∫(φ − φa)e^{iφ}du does too because F(q)
/// is t·K(q)/p times dq/dt (la_law.hpp, p = 1 − 1/α; at α = 0, φ − φa = (κ − κa)/slope)
/// (docs/hermite.md "Jacobian"); at α = 1 (F = log|q|) by its own identity,
/// (m + i)J = qb(φb − φa)e^{iφb} − I. nullopt where the form cancels: |qb − qa| below
/// kLaDerivativeMinChange, 0 < |p| < 0.1 in the plain form (α near but not at 1), non-finite data.
std::optional<LaSegmentDerivatives> segment_derivatives(const LaLaw& law, const detail::LinearQ& seg,
                                                        std::complex<double> integral);

/// ∫₀¹ e^{iΔv^p} dv for 0 < p < 1: the limit shape of α > 1 as the shape variable goes to ±∞
/// (docs/g1_hermite.md "Proofs of no solution"); adds its kernel evaluations to `evaluations`.
/// nullopt where |Δ| is past the kernel's panel cap (not evaluated).
std::optional<std::complex<double>> power_limit_integral(double delta, double p, long& evaluations);

}  // namespace lac
