#pragma once
// The normalized data of an LA segment (q linear from qa at ua to qb at ub, tangent angle phi_a
// at ua; curves/planar/la_law.hpp) without checks or placement: LaSegment's representation, and
// the trial segments of the G2 and S-curve solvers, which may hold non-finite values (they treat
// a NaN integral as a failed evaluation). The integration kernels of LaSegment work on it.
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include "lac/curves/planar/la_law.hpp"

namespace lac::detail {

struct LinearQ {
  double ua = 0, ub = 1;
  double qa = 0, qb = 0;
  double phi_a = 0;

  double length() const { return ub - ua; }
  double slope() const { return (qb - qa) / (ub - ua); }  ///< c0 of 004 Eq. 2
  /// q(u), interpolated from the nearer end.
  double q_at(double u) const {
    const double t = (u - ua) / (ub - ua);
    return t <= 0.5 ? qa + (qb - qa) * t : qb - (qb - qa) * (1.0 - t);
  }
  double kappa_at(const LaLaw& law, double u) const { return law.kappa_of_q(q_at(u)); }
  double phi_at(const LaLaw& law, double u) const { return phi_a + (u - ua) * law.divided_difference(qa, q_at(u)); }
  double turning(const LaLaw& law) const { return length() * law.divided_difference(qa, qb); }
  double phi_b(const LaLaw& law) const { return phi_a + turning(law); }
};

/// Largest turning |φ(end) − φ(begin)| of one piece that integrate_tangent resolves: 64 panels
/// of 16 rad each, on which 20-node Gauss–Legendre integrates e^{iφ} to ~1e-12.
inline constexpr double kMaxResolvedTurning = 1024.0;

/// ∫ e^{iφ(u)} du over the segment by composite Gauss–Legendre (the fast path). The segment is
/// split where q = 0 (an inflection, α < 0); next to a zero of q (inside or within half a piece
/// length outside) φ − φ* ~ |u − u*|^(1 − 1/α) is not smooth, and the substitution
/// u = u* + (u_end − u*)·t^4 makes the integrand smooth enough for 20 nodes (tangent_plan).
/// At least `panels` equal panels of 20 nodes per piece, and one per radian of turning on
/// it, at most 64 panels: a piece turning more than kMaxResolvedTurning cannot be resolved
/// by them and gives NaN (the solvers treat it as a failed evaluation: no curve, fast,
/// instead of seconds of cos/sin of huge angles). `evaluations` is incremented by the
/// number of integrand calls. With `coarse`, *coarse receives the 10-point rule on twice as many
/// panels (its difference from the result is the error estimate of LaSegment's GaussLegendre
/// path; 20 more evaluations per panel, counted).
std::complex<double> integrate_tangent(const LaLaw& law, const LinearQ& seg, long& evaluations, int panels = 1,
                                       std::complex<double>* coarse = nullptr);

/// Default tanh-sinh tolerance of the reference. Its estimate |I_k − I_(k−1)| is pessimistic for this
/// doubly exponential rule: at 1e-13 the value differs from the 1e-15 one by < 1e-14 of the length
/// (test LinearQ.ReferenceToleranceIsNotTheAccuracyLimit) at a third of the evaluations; 1e-15 sits
/// at the rounding floor and refines up to 12 levels near an inflection.
inline constexpr double kReferenceTolerance = 1e-13;

/// The same integral by Boost tanh-sinh in the original variable, split where q = 0: an
/// independent evaluation for residual checks (slower). NaN when tanh-sinh cannot evaluate it.
std::complex<double> integrate_tangent_reference(const LaLaw& law, const LinearQ& seg,
                                                 double tolerance = kReferenceTolerance);

/// How ∫ e^{iφ} over a segment is cut into smooth pieces, for every quadrature method: one plain
/// piece in u, or up to two graded pieces next to a zero u* of q (α < 0, α ≠ −1), each
/// ∫_{t0}^{1} e^{iφ(t)} 4(e − u*) t³ dt with u = u* + (e − u*) t⁴ and, by 004 Eq. (5) with
/// F(0) = 0, φ(t) = φ* + Δ t^β, β = 4(α−1)/α, φ* = φ(u*), Δ = φ(e) − φ*. A piece integrated
/// toward the zero enters with sign −1.
struct TangentPiece {
  bool graded = false;
  double sign = 1;         ///< +1, or −1 for a graded piece whose end e lies before u*
  double u0 = 0, e = 0;    ///< plain: the u range; graded: u* and the far end e
  double t0 = 0;           ///< graded: the lower end of t
  double beta = 0, phi_zero = 0, delta = 0;  ///< graded: φ(t) = phi_zero + delta·t^beta
  double phi(double t) const { return phi_zero + delta * std::pow(t, beta); }
  double du_dt(double t) const { return 4.0 * t * t * t * (e - u0); }
};
struct TangentPlan {
  std::array<TangentPiece, 2> pieces{};
  int count = 1;
};
TangentPlan tangent_plan(const LaLaw& law, const LinearQ& seg);

/// Boundary layers of small |α| (|p| = |1 − 1/α| large, F ∝ |t|^p; and α = 0 over a long range of
/// q): on [u0, u1], where t keeps its sign (it may vanish at an end), the turning concentrates
/// within a sliver at the end of largest |F| that adaptive rules bisect past (at α = −2e-5 the
/// whole turning of a half S lies within 1e-4 of its end; measured, docs/robustness.md). The u
/// (ascending, inside (u0, u1)) where |F| has fallen from that end's value by e^{-d}, d = 1/4, 1/2,
/// 1, …; empty when |F| changes by less than e^8 over the part, or |p| ≤ 8 outside the log forms
/// (the layer is then not thin), or α = 1.
std::vector<double> layer_cuts(const LaLaw& law, const LinearQ& seg, double u0, double u1);

}  // namespace lac::detail
