#pragma once
// The G2 triple-LA system in the normalized frame (start at the origin, end at (1, 0);
// lengths in chord units) shared by the solvers and the initial estimates.
#include <array>
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/constructions/g2_hermite.hpp"

namespace lac::hermite::detail {

struct NormalizedG2 {
  LaLaw law;
  double phi_s = 0, phi_e = 0;      ///< end tangent angles relative to the chord
  double kappa_s = 0, kappa_e = 0;  ///< end curvatures in chord units (κ·r)
};

/// Joint curvatures κ̃ = κh at S1, S2 and the length h: what both starts deliver.
struct StartEstimate {
  double h = 1, k1 = 0, k2 = 0;
  long evaluations = 0;
};

struct SolverOutcome {
  Status status = Status::no_solution;
  std::string message;
  double h = 1, q1 = 0, q2 = 0;
  int iterations = 0;
  long evaluations = 0;
};

/// The three segments for length h and joint values q1, q2 (q0, q3 from the end curvatures).
std::array<lac::detail::LinearQ, 3> build_segments(const NormalizedG2& p, double h, double q1, double q2);

/// Normalized residuals: [φ(1) − φe, h∫sin φ dS, h∫cos φ dS − 1]; non-finite when the
/// segments are not representable.
std::array<double, 3> residuals(const NormalizedG2& p, double h, double q1, double q2, long& evaluations);

/// q of a joint curvature estimate, forced onto the sign the law allows (α ≥ 0: sign σ, ≠ 0).
double joint_q(const NormalizedG2& p, double kappa_tilde, double h);

StartEstimate fast_start(const NormalizedG2& p);
StartEstimate bezier_grid_start(const NormalizedG2& p, double alpha);

SolverOutcome solve_newton(const NormalizedG2& p, const StartEstimate& s, const G2Options& o);
SolverOutcome solve_paper(const NormalizedG2& p, const StartEstimate& s, const G2Options& o);
SolverOutcome solve_ceres(const NormalizedG2& p, const StartEstimate& s, const G2Options& o);

}  // namespace lac::hermite::detail
