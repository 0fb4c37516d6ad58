#pragma once
// S-shaped G1 input by one LA curve with α < 0 (004 §2.4–2.5).
// Four control points: start P0 with tangent P1 − P0, end P3 with tangent P3 − P2. After moving P0
// to the origin with tangent +x, φD is the end tangent angle and φE the direction of P3. The
// Fig. 2 decision: the curve is S-shaped unless φE lies strictly between 0 and φD (then it fits
// inside the triangle of the end points and the tangents' intersection, Fig. 2(a)). In standard
// form (κ = 1 at the start, 004 Eqs. 9–10) the inflection is at s0 = −1/(Λα) (Eq. 12) and, past
// it, the end angle φD is reached after s1 = −(1 + (α−1)ΛφD)^(α/(α−1))/(Λα) (Eq. 15); Λ is found
// by a root finder of the 1-D registry (solvers/root_1d.hpp) so that the end point's direction
// equals φE, and a similarity maps the curve onto P0 and P3. The non-S (C-shaped) case uses the
// same search without the inflection (s = Eq. 11), oriented so that the curvature decreases from
// the start (the curve is reversed when the chord is closer to the start tangent than to the end
// tangent). The end point of every trial Λ is integrated with SCurveOptions::integrator.
//
//   lac::SCurveOptions o;
//   o.solver = lac::RootMethod::bisection;             // 004's; default toms748
//   auto r = lac::solve_s_curve({{{0, 0}, {1, 0}, {2, 1}, {3, 1}}}, -1.0, o);
//   if (r.usable()) { r.curve.sample(100); r.info.lambda; r.info.inflection_s; }
#include <array>
#include <complex>
#include <optional>
#include <string_view>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac {

struct SCurveOptions {
  RootMethod solver = RootMethod::toms748;  ///< root finder on Λ (004 uses bisection)
  AnyQuadrature integrator = GaussLegendre{};  ///< end point of every trial Λ and of the result
  int max_iterations = 200;                 ///< root-finder iterations on Λ
  int bracket_doublings = 200;              ///< growth steps of Λ's upper end when it is unbounded
  /// Integrand evaluations of the search: once spent, trial Λ fail and the status is max_iterations
  /// (as G2Options::max_evaluations; an S-curve needs far less, ≤ 10^6 with rk4).
  long max_evaluations = 100'000'000;
  /// Residuals from an independent tanh-sinh evaluation of the end point, and the integrator's
  /// deviation from it as summary.error_estimate; without it they come from the integrator (no
  /// error estimate).
  bool verify = true;
  /// Accuracy target (common/accuracy.hpp): largest residual (end point relative to |P3 − P0|, end
  /// angles in rad) for status ok, (0, accept].
  double accuracy = 1e-10;
  /// Accept bound on summary.error (the residuals as above and error_estimate / |P3 − P0|): beyond
  /// it the result is inaccurate (not usable), between accuracy and it tolerance_not_met.
  double accept = kDefaultAccept;
  void validate() const;  ///< InputError naming the option (the integrator's own check included)
};

enum class SCurveShape { s_shaped, c_shaped, straight };
std::string_view to_string(SCurveShape s);  ///< "S", "C", "straight"

/// What is specific to the 004 S-curve.
struct SCurveInfo {
  SCurveShape shape = SCurveShape::s_shaped;
  double lambda = 0;                    ///< Λ of the standard form (κ = 1 at its start)
  std::optional<double> inflection_s;  ///< arc length of the inflection from P0 (S-shaped)
  bool mirrored = false;                ///< y → −y applied in the normalized frame
  bool reversed = false;                ///< the standard form runs from P3 to P0
};

using SCurveResult = Result<PlanarCurve, SCurveInfo>;

/// α ∈ [−5, 0). The curve: one LaSegment, the standard form in s placed onto the points (mirrored,
/// reversed to start at P0). Summary: iterations of the root finder, evaluations (integrand calls),
/// constructions (trial Λ whose end point was integrated), residuals position / angle. Throws
/// InputError for non-finite points, P1 = P0, P3 = P2, P3 = P0, α out of range or invalid options;
/// "no curve" is a status: no_solution where proven (docs/hermite.md), else not_converged.
SCurveResult solve_s_curve(const std::array<std::complex<double>, 4>& control, double alpha,
                           const SCurveOptions& options = {});

}  // namespace lac
