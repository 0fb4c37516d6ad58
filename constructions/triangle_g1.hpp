#pragma once
// Planar LA curve segments drawn from three control points, like a quadratic Bézier curve:
// a0 (start), a1 (intersection of the end tangents), a2 (end).
//   solve_g1        monotonic rhythm: one LA segment of slope α (Yoshida–Saito; 001 §2).
//   solve_compound  compound rhythm: segment 0 (α0) then segment 1 (α1), the turning split
//                   θ0 = rθ, θ1 = (1 − r)θ, LCGs joined by Λ1 = Λ0 ρc^(α1−α0) so that the
//                   curve is G3 at the joint (001 §3–4, Eq. (3.5)).
// Both search Λ (Λ0) with a 1-D root finder (solvers/root_1d.hpp) until the triangle (start,
// tangent intersection, end) of the standard-form curve is similar to (a0, a1, a2), then map the
// curve onto the control points by a similarity and return it as a PlanarCurve running from a0
// to a2 (its segments built exactly from the standard form, curves/planar/standard_form.hpp).
//
// Any control triangle is accepted: any orientation, any scale max |a_i − a0| in
// [DBL_MIN, DBL_MAX/8] (the angles are computed on the triangle divided by it), mirrored (right
// turn), or swapped (|a1 − a0| > |a2 − a1|: ρ then decreases from a0 to a2). As in 001, segment 0
// is always the segment at the small-ρ end (the end with the shorter control leg).
// Degenerate input (NaN, coincident or collinear points, turning ≥ π, side lengths beyond the
// double range: parameter "points") throws InputError. Statuses: no_solution when the triangle is
// proven outside the drawable region (the start angle of the trial curves increases with Λ0, and
// the triangle's angle is at or above its limit at the end of the Λ0 range, docs/planar_segments.md);
// not_converged when no sign change was found and nothing is proven (a curve exists when the
// angle is below the limit: Λ0 closer to the end of its range than double precision resolves;
// solve_g1 with α < 1 then searches again with ρ = 1 at the large-ρ end, which resolves it);
// a root finder's failure as its own status, and so the failure of a trial curve's positions (e.g.
// an integrator's step budget: max_iterations); tolerance_not_met (usable) when the solution's
// positions or end tangents miss their tolerances but summary.error (the end-tangent residual, the
// trial positions' error estimate / chord, and the returned curve's end points verified by two
// quadratures of its segments / chord) is within TriangleOptions::accept, inaccurate beyond it;
// numerical_failure when the solution has no double-precision description in user units.
// summary.residuals.position: the verified miss of a0, of the joint and of a2 (user units).
//
//   lac::ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
//   lac::TriangleResult g = lac::solve_compound(t, -0.5, 1.5, 0.4, {.integrator = lac::Rk45{}});
//   if (g.usable()) { g.curve.length(); g.curve.kappa_at(0); g.info.pieces[1].lambda; g.curve.sample(200); }
#include <complex>
#include <optional>
#include <vector>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac {

using Point2 = std::complex<double>;  ///< x + iy

struct ControlTriangle {
  Point2 a0, a1, a2;
};

struct TriangleOptions {
  /// Position method of the trial curves; any method of the quadrature registry. Default
  /// gk-tanh-sinh: Gauss–Kronrod at relative tolerance 1e-13 (one 21-point panel for most trial
  /// curves), tanh-sinh near the singular ends of the LA domain.
  AnyQuadrature integrator = GkTanhSinh{};
  RootMethod solver = RootMethod::toms748;  ///< any method of root_methods()
  /// Root finder settings on f(u) = (angle at p0) − (angle at a0), in radians; u = w/(1+w),
  /// w = Λ0·θ. Defaults: bracket width 2e-15 relative, |f| ≤ 1e-15 rad, 200 iterations.
  RootOptions root{.x_rtol = 2e-15, .x_atol = 0, .f_atol = 1e-15, .max_iterations = 200};
  /// Turnings below this (collinear points) or above π minus this are rejected (InputError).
  double min_turning = 1e-8;
  /// Probes toward the end of the Λ0 range when looking for a sign change (bracket growth):
  /// u = u_max (1 − 0.5·10^−k), k = 0 … max_bracket_probes − 1 (10^−4k in solve_g1's second
  /// search with ρ = 1 at the large end, docs/planar_segments.md).
  int max_bracket_probes = 13;
  /// Accuracy target: a solution whose end tangents miss the control legs by more than this
  /// (rad), or whose positions' error estimate or verified end-point error exceeds this relative
  /// to the chord, is reported as tolerance_not_met.
  double tangent_tolerance = 1e-11;
  /// Accept bound (common/accuracy.hpp) on summary.error, the largest of the end-tangent residual
  /// (rad), the trial positions' error estimate and the returned curve's verified end-point error,
  /// both relative to the chord |a2 − a0|: beyond it the result is inaccurate (not usable).
  double accept = kDefaultAccept;
  /// Integrand evaluations of the whole call (both searches of solve_g1 counted apart): a trial
  /// curve is not drawn once they are spent, and the search ends max_iterations. One trial may
  /// overshoot by its own method's budget (rk4: max_steps). A fixed-step method on a long trial
  /// curve costs ~10^6 evaluations a trial; [1, 1e12].
  long max_evaluations = 100'000'000;

  void validate() const;
};

/// One LA piece of the result, in 001's order ([0] = segment 0, at the small-ρ end). Λ values:
/// `lambda` in the units of segment 0's standard form (so pieces[1].lambda = pieces[0].lambda ·
/// ρc^(α1−α0), 001 Eq. (3.5)); `lambda_user` in the units of the control points (Λ scales as
/// k^(α−1) under a scaling by k).
struct TrianglePiece {
  double alpha = 0;
  double lambda = 0;
  double lambda_user = 0;
  double turning = 0;    ///< |Δθ| of this piece (rad)
  double rho_small = 0;  ///< radius of curvature at the piece's small-ρ end (user units)
  double rho_large = 0;  ///< … and at its large-ρ end (+inf only at the end of the last piece: κ underflows)
};

/// What is particular to the 001 constructions.
struct TriangleInfo {
  bool compound = false;
  std::vector<TrianglePiece> pieces;  ///< 1 or 2 when a curve was built; empty otherwise
  /// Segment 0 starts at a0 (curve.segments()[k] is piece k); false when the triangle was swapped
  /// (curve.segments()[k] is piece n − 1 − k).
  bool segment0_at_a0 = true;
  Point2 joint{};        ///< user coordinates (compound only)
  double rho_joint = 0;  ///< user units (compound only)
  double turning = 0;    ///< signed total turning a0 → a2 (rad, left turn positive)
  double target_angle = 0;  ///< angle of the control triangle at its short-leg end (rad), the search's target
  double residual = 0;      ///< start-angle mismatch at the solution (rad)
  int bracket_probes = 0;   ///< trial curves spent finding the bracket
  /// Limit of the trial curves' start angle as Λ0 → end of its range (rad; computed only when the
  /// bracket search found no sign change): the triangle is drawable iff target_angle is below it.
  std::optional<double> start_angle_limit;
};

using TriangleResult = Result<PlanarCurve, TriangleInfo>;

/// Monotonic-rhythm G1 segment of slope α (any finite real).
TriangleResult solve_g1(const ControlTriangle& t, double alpha, const TriangleOptions& o = {});

/// Compound-rhythm segment: α0, α1 finite, r ∈ (0, 1) the share of the turning in segment 0.
TriangleResult solve_compound(const ControlTriangle& t, double alpha0, double alpha1, double r,
                              const TriangleOptions& o = {});

}  // namespace lac
