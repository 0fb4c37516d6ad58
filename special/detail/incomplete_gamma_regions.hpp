#pragma once
// Region algorithms behind special/incomplete_gamma.hpp, without argument checks (any finite
// real a unless noted, z ≠ 0). Exposed for the tests that probe each region on its own.
#include <complex>

#include "lac/special/incomplete_gamma.hpp"

namespace lac::special::detail {

using cplx = std::complex<double>;

/// e^w − 1 for complex w without cancellation for small |w|.
cplx expm1(cplx w);
/// (e^w − 1)/w, continuous (= 1) at w = 0.
cplx expm1_ratio(cplx w);
/// log(1 + w) for complex w without cancellation for small |w|.
cplx log1p(cplx w);

/// Γ(a, z) by power series (region `series`); meant for small |z|, |z| < a + 1, or z near
/// the negative real axis, where the terms do not cancel. a ≥ 1/2: Γ(a) − γ(a, z) with
/// Kummer's series of γ. a < 1/2: Γ(a) − z^a Σ (−z)^n/(n!(a+n)) with the two parts that are
/// singular at non-positive integer a (Γ(a) and the n = −round(a) term) combined analytically,
/// so a = 0 (E₁), a = −1, −2, … and orders near them need no special case or recurrence.
GammaIncResult series(double a, cplx z);

/// e^z z^(−a) Γ(a, z) by Legendre's continued fraction
///   1/(z + 1 − a − 1(1 − a)/(z + 3 − a − 2(2 − a)/(z + 5 − a − …)))
/// evaluated forward by the modified Lentz method (Numerical Recipes §5.2, 6.2). Converges
/// for z off the negative real axis, fast for large |z|. Capped at `max_steps`.
GammaIncResult continued_fraction_scaled(double a, cplx z, int max_steps = 20000);

/// e^z z^(−a) Γ(a, z) by the asymptotic series (1/z) Σ_n (a − 1)…(a − n)/z^n, valid for
/// |arg z| < 3π/2 as |z| → ∞. Summation stops at the rounding level; if the terms start to
/// grow first, status is tolerance_not_met (the caller then uses another region).
GammaIncResult asymptotic_scaled(double a, cplx z, int max_terms = 500);

/// e^(z1) z1^(−a) ∫_{z1}^{z2} t^(a−1) e^(−t) dt, z2 = z1 + dz, by the Taylor series of the integrand
/// along the segment: with t = z1 (1 + x), x ∈ [0, δ], δ = dz/z1,
///   ∫_0^δ (1 + x)^(a−1) e^(−z1 x) dx = Σ_n c_n δ^(n+1)/(n + 1),
///   c_0 = 1, c_1 = a − 1 − z1, c_(n+1) = ((a − 1 − n − z1) c_n − z1 c_(n−1)) / (n + 1).
/// Needs |δ| < 1 (radius of convergence); fast for |δ| ≤ 1/2 and |z2 − z1| ≤ 4.
GammaIncResult segment_series_scaled(double a, cplx z1, cplx dz, int max_terms = 400);

/// e^(z1) z1^(−a) (γ(a, z2) − γ(a, z1)) = e^(z1) Σ_n (−z1)^n/n! · L · expm1_ratio((a + n) L),
/// z2 = z1 + dz, L = log z2 − log z1 (log1p(dz/z1) for small steps): the lower-gamma series of both points combined term by term, so no
/// Γ(a) appears (any real a, including non-positive integers). For max(|z1|, |z2|) ≲ 1.5.
GammaIncResult lower_series_difference_scaled(double a, cplx z1, cplx dz, int max_terms = 400);

}  // namespace lac::special::detail
