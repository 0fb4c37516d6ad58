#pragma once
// G1 LA space-curve segments by the cone construction (000 §2.2) and compound-rhythm space
// segments (000 §4), docs/math.md §3.
//
// Given P0, v0, P1, v1 (user coordinates), move P0 to the origin, v0 to +x and P1 into the xy
// plane (y > 0). The cone with apex 0, axis +x and half-angle θ = angle(P1 − P0, v0) contains P1.
// For trial unknowns (Λ0, ν0) the standard-form curve is integrated until it meets the cone
// (compound: segment 0 until the inner cone r_θ·θ, segment 1 — parameters from the LCG/LTG
// continuity at the joint — until the outer cone), rotated about x into the xy plane and scaled
// onto P1; so the position constraints hold for every (Λ0, ν0) and only the end tangent is solved:
// two conditions in (log Λ0, log ν0). Solvers by name (solvers/nonlinear.hpp): "simplex" (000's
// modified downhill simplex on the end-tangent angle), "ceres" (Levenberg–Marquardt), "newton"
// (damped Newton); the latter two on the stereographic end-tangent residual
// 2 (t·u1, t·u2)/(1 + t·v̂1), zero only at t = v̂1.
//
// The standard form has positive torsion (right-handed). With allow_mirror the mirror-image
// problem (z → −z in the local frame) is tried as well; the result then has negative torsion.
//
// Every function returns Result<SpaceCurve, SpaceInfo> (common/summary.hpp): the curve
// (curves/space/space_curve.hpp), a Summary (status, counters, end-tangent and end-point errors,
// time, integrator and solver names) and the 000-specific details.
#include <optional>

#include "lac/common/summary.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/solvers/nonlinear.hpp"

namespace lac {

/// Endpoint data in user coordinates; v0, v1 are directions (any nonzero length).
struct SpaceEndpoints {
  Vec3 p0 = Vec3::Zero();
  Vec3 v0 = Vec3::UnitX();
  Vec3 p1 = Vec3::UnitY();
  Vec3 v1 = Vec3::UnitY();
};

/// Monotonic-rhythm segment: α, β any finite; Ω ≥ 0.
struct G1SpaceSpec {
  double alpha = 0, beta = 0, omega = 0.1;
  TorsionType type = TorsionType::type1;
};

/// Compound-rhythm segment (000 §4.1): slopes of both segments, Ω0 ≥ 0, r_θ ∈ (0, 1).
struct CompoundSpaceSpec {
  double alpha0 = 0, alpha1 = 0, beta0 = 0, beta1 = 0, omega0 = 0.1, r_theta = 0.5;
  TorsionType type = TorsionType::type1;
};

struct SpaceSegmentOptions {
  /// Frenet integration, any method of the ODE registry: default order-6 Magnus, rtol 1e-10,
  /// atol 1e-11 (end tangents accurate to ~1e-13 rad, tests/constructions); rk45 / rk4 selectable.
  OdeOptions integrator{OdeMethod::magnus6, 1e-10, 1e-11};
  /// Any method of the N-D registry; newton is the fastest here (see docs/space_curves.md).
  NonlinearMethod solver = NonlinearMethod::newton;
  double tangent_tolerance = 1e-11;  ///< success: end-tangent angle error ≤ this (rad)
  /// Accept bound (common/accuracy.hpp) on summary.error, the larger of the end-point residual
  /// / |P1 − P0| and the end-tangent angle error (rad): a construction beyond it is inaccurate.
  double accept = kDefaultAccept;
  double max_turning = 4 * M_PI;     ///< a trial curve may turn its tangent by at most this (∫κ ds)
  double max_torsion_turning = 40 * M_PI;  ///< and rotate its frame about T by at most this (∫τ ds)
  double max_length = 100;           ///< and be at most this long in standard form (ρ(0) = 1)
  double lambda_start = 0;           ///< first starting point of the solver; 0: automatic (space_segment.cpp)
  double nu_start = 2.0;
  /// Solver runs: first from the start (hand with the smaller end-tangent error); if that fails,
  /// a 7 × 6 grid in (log Λ0, log ν0) around the start is screened (both hands) and the solver is
  /// rerun from the best grid points; newton and ceres then get one simplex run from the closest
  /// stop when it is within 0.05 rad of the end tangent (docs/space_curves.md); a curve found by
  /// that run has summary.solver "simplex" and a message saying so.
  int max_starts = 6;
  bool allow_mirror = true;          ///< also try the mirror-image (negative torsion) problem
  long max_evaluations = 1500;       ///< curve constructions per solver run
  /// Frenet right-hand-side evaluations over the whole call (screening and every run): when spent,
  /// no further trial is integrated and the result is max_iterations. 10^7 is ~1 s of CPU
  /// (unsanitized); the drawable cases need ≤ 10^5 with magnus6/rk45 and ~2·10^6 with rk4 and the
  /// simplex. Without it, rk4 (h = 1e-3) on awkward input ran 1.5·10^8 evaluations (13 s).
  long max_ode_evaluations = 10'000'000;
  void validate() const;
};

/// What a 000 construction adds to its curve. The pieces' α, β, Λ, Ω, ν, type and standard-form
/// arc lengths are the curve's (SpaceCurve::pieces()); the Summary counts constructions (trial
/// curves integrated to the cone) and evaluations (Frenet right-hand sides).
struct SpaceInfo {
  SpaceEndpoints ends;              ///< the endpoint data of the construction (user coordinates)
  Vec3 end_tangent = Vec3::Zero();  ///< unit end tangent of the curve, user coordinates (0: no curve)
  std::optional<Vec3> joint;        ///< compound: joint position, user coordinates
  int torsion_sign = 1;             ///< −1: mirror image (negative torsion)
  int runs = 0;                     ///< solver runs (starts × hands) used
};

/// Solves the G1 segment. InputError for invalid input (zero or non-finite vectors, P1 = P0,
/// v0 parallel to P1 − P0, parameters out of range). Status ok when the end tangent is met within
/// tangent_tolerance (summary.error: the larger of the end-point residual / |P1 − P0| and the
/// end-tangent error in rad, inaccurate beyond options.accept); otherwise the curve is empty and the status says why: max_iterations (the
/// ODE budget was spent, or the solver run that came closest hit its cap), not_converged (the
/// search — the start and the screened grid, both hands — found no curve; one may still exist),
/// or the closest run's own failure status (docs/space_curves.md).
Result<SpaceCurve, SpaceInfo> solve_g1_space_segment(const SpaceEndpoints& ends, const G1SpaceSpec& spec,
                                                     const SpaceSegmentOptions& options = {});
/// Solves the compound-rhythm segment (000 §4.3); statuses as solve_g1_space_segment.
Result<SpaceCurve, SpaceInfo> solve_compound_space_segment(const SpaceEndpoints& ends, const CompoundSpaceSpec& spec,
                                                           const SpaceSegmentOptions& options = {});

/// The construction at given (Λ0, ν0) without solving (v1 only enters the end-tangent residual):
/// the curve that meets P0, v0, P1 for these unknowns, status ok or tolerance_not_met by its
/// end-tangent error (summary.error: the end-point residual / |P1 − P0| only, v1 not being a
/// condition of the construction; inaccurate beyond options.accept). Without a curve: no_solution when these unknowns give none (the curve ends
/// before the cone, no positive ν1 continues the torsion law at the joint), max_iterations when a
/// cap of the options (max_turning, max_torsion_turning, max_length) or the integrator's step cap
/// ends it first, numerical_failure when its laws are not representable in double precision.
Result<SpaceCurve, SpaceInfo> construct_g1_space_segment(const SpaceEndpoints& ends, const G1SpaceSpec& spec,
                                                         double lambda, double nu, bool mirror = false,
                                                         const SpaceSegmentOptions& options = {});
Result<SpaceCurve, SpaceInfo> construct_compound_space_segment(const SpaceEndpoints& ends,
                                                               const CompoundSpaceSpec& spec, double lambda0,
                                                               double nu0, bool mirror = false,
                                                               const SpaceSegmentOptions& options = {});

/// The construction at (Λ0, ν0) (G1 uses alpha0, beta0, omega0, type) for endpoint data where a
/// curve exists by construction: info.ends = P0 = 0, v0 = e_x, P1 = (cos θ, sin θ, 0), θ ∈ (0, π)
/// the cone half-angle, and v1 = the construction's end tangent (status ok, end-tangent residual
/// 0). When the construction fails: its status as construct_*, info.ends.v1 = e_x.
Result<SpaceCurve, SpaceInfo> drawable_endpoints(const CompoundSpaceSpec& spec, bool compound, double lambda0,
                                                 double nu0, double theta, const SpaceSegmentOptions& options = {});

}  // namespace lac
