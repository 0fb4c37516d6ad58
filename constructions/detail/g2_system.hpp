#pragma once
// The G2 triple-LA system in the normalized frame (start at the origin, end at (1, 0), lengths in
// chord units) shared by the solvers and the initial estimates of constructions/g2_hermite.
#include <array>
#include <complex>
#include <optional>
#include <string>

#include "lac/common/status.hpp"
#include "lac/constructions/detail/tangent_integral.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/curves/planar/la_segment_kernel.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/solvers/nonlinear.hpp"

namespace lac::detail {

struct G2System {
  LaLaw law;
  double phi_s = 0, phi_e = 0;      ///< end tangent angles relative to the chord
  double kappa_s = 0, kappa_e = 0;  ///< end curvatures in chord units (κ·r)
  TrialIntegrator integrate;        ///< ∫e^{iφ}dS of trial segments, the construction's method
  double s1 = kG2S1, s2 = kG2S2;    ///< the joints in S (004's 1/4, 3/4 unless freed)
};

/// Below this |α| (α ≠ 0) the G2 triple is held in the offset form of la_law.hpp (q carries log|κ|
/// to rounding); above, in the plain form of 004.
inline constexpr double kOffsetFormMaxAbsAlpha = 0.05;
/// The law of the triple: σ = sgn κ0, the offset form for 0 < |α| < kOffsetFormMaxAbsAlpha.
LaLaw g2_law(double alpha, double sigma);
/// The segments in the plain form (004's q; the identity unless law.offset), for 004's coefficients.
std::array<LinearQ, 3> plain_form(const LaLaw& law, const std::array<LinearQ, 3>& segments);

/// Joint curvatures κ̃ = κh at S1, S2 and the length h: what both starts deliver.
struct G2StartEstimate {
  double h = 1, k1 = 0, k2 = 0;
  long evaluations = 0;
};

struct G2SolverOutcome {
  Status status = Status::not_converged;
  std::string message;
  double h = 1, q1 = 0, q2 = 0;
  int iterations = 0;
  long evaluations = 0;    ///< integrand calls
  long constructions = 0;  ///< trial curves whose end conditions were evaluated
  /// h∫e^{iφ}dS by the integrator at the solution (the normalized end point), when the solver
  /// evaluated it there: what the integrator makes of the returned curve, at no extra cost.
  std::optional<std::complex<double>> end;
  /// The segments' integrals at the solution with the kernel's bounds, where the solver's last
  /// evaluation was the solution and the kernel gave all three (newton with gauss-legendre).
  std::optional<std::array<LaSegmentIntegral, 3>> kernel_parts;
};

/// The three segments for length h and joint values q1, q2 (q0, q3 from the end curvatures).
std::array<LinearQ, 3> g2_segments(const G2System& p, double h, double q1, double q2);

/// Normalized residuals [φ(1) − φe, h∫sin φ dS, h∫cos φ dS − 1] (004 Eqs. 41, 33, 32); non-finite
/// when the segments are not representable or the integrator fails.
std::array<double, 3> g2_residuals(const G2System& p, double h, double q1, double q2, long& evaluations);

/// g2_residuals with their Jacobian with respect to (log h, q1, q2), from each segment's
/// closed-form derivatives (segment_derivatives of curves/planar/la_segment_kernel.hpp) carried
/// along the chain of tangent angles; `jacobian_known` false where a segment has none (Newton then
/// differences).
struct G2Linearization {
  std::array<double, 3> r{};
  /// Each segment's ∫e^{iφ}dS by the trial integrator, and the segment kernel's error bound where
  /// the value is the kernel's (else NaN): the result check reuses them at the solution.
  std::array<std::complex<double>, 3> parts{};
  std::array<double, 3> kernel_bounds{};
  std::array<std::array<double, 3>, 3> jacobian{};  ///< [residual][unknown]
  bool jacobian_known = false;
};
G2Linearization g2_linearize(const G2System& p, double h, double q1, double q2, long& evaluations,
                             bool jacobian = true);  ///< false: the residuals only (jacobian_known false)

/// q of a joint curvature estimate, forced onto the sign the law allows (α ≥ 0: sign σ, ≠ 0).
double g2_joint_q(const G2System& p, double kappa_tilde, double h);

/// The initial estimates integrate with their own rules, not the construction's integrator (part
/// of the estimate, not of the solve): the fast start's clothoid by the segment kernel
/// (curves/planar/la_segment_kernel.hpp), the Bézier grid by a fixed Gauss–Legendre rule.
G2StartEstimate g2_fast_start(const G2System& p);
G2StartEstimate g2_bezier_grid_start(const G2System& p);

/// newton and simplex on (log h, z1, z2), ceres on the ten-unknown system; solvers/nonlinear.hpp.
G2SolverOutcome solve_g2_nonlinear(NonlinearMethod method, const G2System& p, const G2StartEstimate& s,
                                   const G2Options& o);
/// 004 §3.3.
G2SolverOutcome solve_g2_paper(const G2System& p, const G2StartEstimate& s, const G2Options& o);

/// The ten-unknown system for ceres (004 Eqs. 20–23, 28–33): its residual, its starting point from
/// an estimate, and (h, q1, q2) of a solution.
NonlinearResidual g2_ten_unknown_residual(const G2System& p, long& evaluations);
Eigen::VectorXd g2_ten_unknown_start(const G2System& p, const G2StartEstimate& s);
std::array<double, 3> g2_ten_unknown_solution(const G2System& p, const Eigen::VectorXd& x);

}  // namespace lac::detail
