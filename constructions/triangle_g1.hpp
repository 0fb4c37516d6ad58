#pragma once
// Planar LA curve segments drawn from three control points, like a quadratic Bézier curve:
// a0 (start), a1 (intersection of the end tangents), a2 (end).
//   solve_g1        monotonic rhythm: one LA segment of slope α (Yoshida–Saito; 001 §2).
//   solve_compound  compound rhythm: segment 0 (α0) then segment 1 (α1), the turning split
//                   θ0 = rθ, θ1 = (1 − r)θ, LCGs joined by Λ1 = Λ0 ρc^(α1−α0) so that the
//                   curve is G3 at the joint (001 §3–4, Eq. (3.5); MATH.md §2).
// Both search Λ (Λ0) with a 1-D root finder (solvers/root_1d.hpp, chosen by name) until the
// triangle (start, tangent intersection, end) of the standard-form curve is similar to
// (a0, a1, a2), then map the curve onto the control points by a similarity.
//
// Any control triangle is accepted: any orientation, any scale max |a_i − a0| in
// [DBL_MIN, DBL_MAX/8] (the angles are computed on the triangle divided by it), mirrored (right
// turn), or swapped (|a1 − a0| > |a2 − a1|: ρ then decreases from a0 to a2). As in 001, segment 0
// is always the segment at the small-ρ end (the end with the shorter control leg).
// Degenerate input (NaN, coincident or collinear points, turning ≥ π, side lengths beyond the
// double range: parameter "points") throws InputError; a triangle outside the drawable region is
// Status::no_solution with the reason; a solution whose user-unit values (length, ρ, κ, Λ_user)
// are not finite doubles is Status::numerical_failure. No NaN or inf in a usable result except
// rho_large = +inf at the end of the last piece (κ underflows to 0 there).
//
//   lac::ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
//   lac::G1Segment g = lac::solve_compound(t, -0.5, 1.5, 0.4);
//   if (lac::usable(g.status)) { g.length; g.kappa0; g.pieces[1].lambda; }
//   auto pts = lac::sample_segment(g, 200);  // positions, s, tangent angle, signed κ
#include <complex>
#include <string>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac {

using Point2 = std::complex<double>;  ///< x + iy

struct ControlTriangle {
  Point2 a0, a1, a2;
};

/// Default position method of the segment solvers (registered as gk-tanh-sinh,
/// integrators/gk_tanh_sinh.hpp): Gauss–Kronrod at relative tolerance 1e-13 (one 21-point panel
/// for most trial curves), tanh-sinh near the singular ends of the LA domain.
GkTanhSinh default_segment_integrator();

struct SegmentOptions {
  RootMethod solver = RootMethod::toms748;  ///< bisection | secant | toms748 | ceres
  /// Root finder settings on f(u) = (angle at p0) − (angle at a0), in radians; u = w/(1+w),
  /// w = Λ0·θ. Defaults: bracket width 2e-15 relative, |f| ≤ 1e-15 rad, 200 iterations.
  RootOptions root{.x_rtol = 2e-15, .x_atol = 0, .f_atol = 1e-15, .max_iterations = 200};
  /// Turnings below this (collinear points) or above π minus this are rejected (InputError).
  double min_turning = 1e-8;
  /// Probes toward the end of the Λ0 range when looking for a sign change (bracket growth):
  /// u = u_max (1 − 0.5·10^−k), k = 0 … max_bracket_probes − 1.
  int max_bracket_probes = 13;
  /// A solution whose end tangents miss the control legs by more than this (rad) is reported
  /// as tolerance_not_met.
  double tangent_tolerance = 1e-11;

  void validate() const;
};

/// One LA piece of the result. Λ values: `lambda` in the units of segment 0's standard form
/// (so pieces[1].lambda = pieces[0].lambda · ρc^(α1−α0), 001 Eq. (3.5)); `lambda_user` in the
/// units of the control points (Λ scales as k^(α−1) under a scaling by k).
struct SegmentPiece {
  double alpha = 0;
  double lambda = 0;
  double lambda_user = 0;
  double turning = 0;    ///< |Δθ| of this piece (rad)
  double length = 0;     ///< user units
  double rho_small = 0;  ///< radius of curvature at the piece's small-ρ end (user units)
  double rho_large = 0;  ///< … and at its large-ρ end
};

/// Standard-form description of the solved curve (what sample_segment draws). Segment 0 is
/// LaCurve(α0, Λ0) over θ ∈ [0, θ0] (configuration a, α0 ≤ 1) or [−θ0, 0] (configuration b,
/// α0 > 1). Segment 1 is drawn from the joint J in its own standard form scaled by ρc:
/// LaCurve(α1, Λ0 ρc^(1−α0)) over [0, θ1] (equivalent to 001's θs … θs + θ1 on LaCurve(α1, Λ1),
/// without the cancellation of C(θs + θ1) − C(θs)). User point = A·m(z) + B with m the
/// identity, or complex conjugation when mirrored.
struct StandardForm {
  double alpha0 = 0, alpha1 = 0, theta0 = 0, theta1 = 0;
  bool configuration_b = false;
  double lambda0 = 0;
  double log_rho_joint = 0;  ///< log ρc in standard units (0 in configuration b)
  Point2 start{}, joint{}, end{};
  double start_tangent = 0;  ///< θ at the start point
  Point2 scale_rotation{1, 0}, offset{};  ///< A and B
  bool mirrored = false;     ///< canonical triangle turns right in user coordinates
  bool swapped = false;      ///< canonical start is the user's a2
};

struct G1Segment {
  Status status = Status::ok;
  std::string message;
  bool compound = false;
  std::vector<SegmentPiece> pieces;  ///< 1 (monotonic) or 2 (compound); [0] at the small-ρ end
  bool segment0_at_a0 = true;        ///< false when the triangle was swapped
  Point2 joint{};                    ///< user coordinates (compound only)
  double rho_joint = 0;              ///< user units (compound only)
  double length = 0;                 ///< user units
  double kappa0 = 0, kappa1 = 0;     ///< signed curvature at a0 and a2 (left turn positive)
  double turning = 0;                ///< signed total turning a0 → a2 (rad)
  double tangent_error = 0;          ///< max angle between end tangents and control legs (rad)
  double residual = 0;               ///< root finder residual (rad)
  int iterations = 0;                ///< root-finder iterations
  int bracket_probes = 0;            ///< trial curves spent finding the bracket
  long trials = 0;                   ///< trial curves drawn in total
  long evaluations = 0;              ///< integrand evaluations in total
  StandardForm form;
};

/// Monotonic-rhythm G1 segment of slope α (any finite real).
G1Segment solve_g1(const ControlTriangle& t, double alpha, const SegmentOptions& o = {});
G1Segment solve_g1(const ControlTriangle& t, double alpha, const SegmentOptions& o, const AnyQuadrature& method);

/// Compound-rhythm segment: α0, α1 finite, r ∈ (0, 1) the share of the turning in segment 0.
G1Segment solve_compound(const ControlTriangle& t, double alpha0, double alpha1, double r, const SegmentOptions& o = {});
G1Segment solve_compound(const ControlTriangle& t, double alpha0, double alpha1, double r, const SegmentOptions& o,
                         const AnyQuadrature& method);

/// A point of a solved segment in user coordinates, ordered from a0 to a2.
struct SegmentSample {
  Point2 position{};
  double s = 0;      ///< arc length from a0
  double theta = 0;  ///< tangent angle (rad, continuous along the curve)
  double kappa = 0;  ///< signed curvature (left turn positive)
  int piece = 0;     ///< 0 or 1
};

/// About n points (≥ 2 per piece, uniform in arc length within each piece, the joint once)
/// of a usable segment, from a0 to a2. InputError if the segment is not usable or n < 2.
std::vector<SegmentSample> sample_segment(const G1Segment& g, int n);
std::vector<SegmentSample> sample_segment(const G1Segment& g, int n, const AnyQuadrature& method);

}  // namespace lac
