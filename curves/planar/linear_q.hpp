#pragma once
// LA segment in "linear q" form (004 Eqs. 2–8; MATH.md §5). Along a segment of one α
// the quantity q = Q(κ) is linear in the length parameter u (normalized S or arc length s):
//   α ≠ 0: q = sgn(κ)|κ|^(−α),  κ = K(q) = sgn(q)|q|^(−1/α)          (004 Eq. 2)
//   α = 0: q = log|κ|,          κ = K(q) = σ e^q, σ = ±1 fixed       (004 Eq. 3)
// The tangent angle is the integral of κ: with F' = K,
//   F(q) = α/(α−1)|q|^((α−1)/α) (α ≠ 0, 1; 004 Eq. 5),  log|q| (α = 1; Eq. 8),  σ e^q (α = 0; Eq. 7)
// and over u ∈ [ua, ub] with q linear: φ(u) = φ(ua) + (u − ua)·F[qa, q(u)], F[·,·] the
// divided difference. Written as a divided difference the arc (c0 = 0, 004 Appendix A) is
// the exact limit F[q, q] = K(q) instead of a 0/0.
#include <array>
#include <cmath>
#include <complex>

namespace lac::hermite::detail {

/// The α-dependent maps Q, K, F and K'' of the linear-q form.
struct LaLaw {
  double alpha = -1;
  double sigma = 1;  ///< sign of κ for α = 0 (ignored otherwise)

  double q_of_kappa(double kappa) const {
    if (alpha == 0) return std::log(std::abs(kappa));
    return std::copysign(std::pow(std::abs(kappa), -alpha), kappa);
  }
  double kappa_of_q(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (alpha == -1) return q;
    if (q == 0) return alpha < 0 ? 0.0 : std::copysign(HUGE_VAL, q);
    return std::copysign(std::pow(std::abs(q), -1.0 / alpha), q);
  }
  /// Antiderivative of K in q.
  double F(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (alpha == 1) return std::log(std::abs(q));
    if (alpha == -1) return 0.5 * q * q;
    return alpha / (alpha - 1.0) * std::pow(std::abs(q), (alpha - 1.0) / alpha);
  }
  /// dK/dq and d²K/dq².
  double dK(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    const double b = -1.0 / alpha;
    return b * std::pow(std::abs(q), b - 1.0);
  }
  double d2K(double q) const {
    if (alpha == 0) return sigma * std::exp(q);
    const double b = -1.0 / alpha;
    return b * (b - 1.0) * std::copysign(std::pow(std::abs(q), b - 2.0), q);
  }

  /// F[a, b] = (F(b) − F(a)) / (b − a), the mean curvature between q = a and q = b.
  /// Near a = b a midpoint Taylor series replaces the cancelling difference.
  double divided_difference(double a, double b) const { return divided_difference(a, F(a), b); }
  /// The same with F(a) supplied (hot loops over one segment).
  double divided_difference(double a, double Fa, double b) const {
    if (a == b) return kappa_of_q(a);
    const double d = b - a, m = 0.5 * (a + b);
    const bool close = alpha == 0 ? std::abs(d) < 1e-4 : std::abs(d) < 1e-4 * std::abs(m);
    if (close) return kappa_of_q(m) + d2K(m) * d * d / 24.0;
    return (F(b) - Fa) / d;
  }
};

/// One segment: q linear from qa at ua to qb at ub, tangent angle phi_a at ua.
struct LinearQSegment {
  double ua = 0, ub = 1;
  double qa = 0, qb = 0;
  double phi_a = 0;

  double length() const { return ub - ua; }
  double slope() const { return (qb - qa) / (ub - ua); }  ///< c0 of 004 Eq. 2
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


/// ∫ e^{iφ(u)} du over the segment by composite Gauss–Legendre. The segment is split
/// where q = 0 (an inflection, α < 0); next to a zero of q (inside or within half a piece
/// length outside) φ − φ* ~ |u − u*|^(1 − 1/α) is not smooth, and the substitution
/// u = u* + (u_end − u*)·t^4 makes the integrand smooth enough for 20 nodes.
/// At least `panels` equal panels of 20 nodes per piece, and one per radian of turning on
/// it, at most 64 panels: a piece turning more than kMaxResolvedTurning cannot be resolved
/// by them and gives NaN (the solvers treat it as a failed evaluation: no curve, fast,
/// instead of seconds of cos/sin of huge angles). `evaluations` is incremented by the
/// number of integrand calls.
std::complex<double> integrate_tangent(const LaLaw& law, const LinearQSegment& seg, long& evaluations, int panels = 1);

/// Default tanh-sinh tolerance of the reference. Its estimate |I_k − I_(k−1)| is pessimistic for this
/// doubly exponential rule: at 1e-13 the value differs from the 1e-15 one by < 1e-14 of the length
/// (test LinearQ.ReferenceToleranceIsNotTheAccuracyLimit) at a third of the evaluations; 1e-15 sits
/// at the rounding floor and refines up to 12 levels near an inflection.
inline constexpr double kReferenceTolerance = 1e-13;

/// The same integral by Boost tanh-sinh in the original variable, split where q = 0: an
/// independent evaluation for residual checks (slower). NaN when tanh-sinh cannot evaluate it.
std::complex<double> integrate_tangent_reference(const LaLaw& law, const LinearQSegment& seg,
                                                 double tolerance = kReferenceTolerance);

}  // namespace lac::hermite::detail
