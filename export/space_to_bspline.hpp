#pragma once
// A space LA curve (a SpaceCurve: the LA space pieces of 000's constructions) as a quintic
// (default) or cubic B-spline in space with a bound on the distance between the two, for CAD
// export (docs/export.md). The planar export (export/to_bspline.hpp) in three dimensions:
//
// Each piece is cut into spans [s0, s1] of arc length; on a span the B-spline is the Hermite
// interpolant in arc length of c(s), with c' = T, c'' = κN at the ends and h the span length:
//   cubic   (c, c'):       P0,  P0 + (h/3)T0,  P1 − (h/3)T1,  P1
//   quintic (c, c', c''):  P0,  P0 + (h/5)T0,  P0 + (2h/5)T0 + (h²/20)κ0N0,  (mirrored at P1)
// The cubic is C1 (G1); the quintic is C2 at every knot where κ is continuous, which is every
// knot of 000's curves (ρ is continuous at a compound joint, 000 Eq. (11)): G2.
//
// Interpolation bound (proven): per span the least over m of C_m h^m M_m with the Peano constants
// C_m of export/detail/hermite_bound.hpp and M_m ≥ |c^(m)| from the Frenet–Serret equations:
// c^(m) = a T + b N + c B with (a, b, c)' = (a' − κb, b' + κa − τc, c' + τb), so majorants
// A, B, C of |a|, |b|, |c| follow by the same rule with κ, τ and their derivatives replaced by
// bounds k_j ≥ |κ^(j)|, t_j ≥ |τ^(j)| and signs dropped, and M_m = √(A² + B² + C²); e.g.
// c''' = −κ²T + κ'N + κτB, M_3 = √(k0⁴ + k1² + k0²t0²). The laws of 000 Eqs. (3)–(5),
// dρ/ds = Λρ^(1−α) and dμ/ds = ±Ωμ^(1−β), give by induction
//   κ^(j) = (−Λ)^j ∏_{i<j}(1 + iα) ρ^−(1+jα),   τ^(j) = (∓Ω)^j ∏_{i<j}(1 + iβ) μ^−(1+jβ),
// powers of ρ and μ, which are monotone in s: each |κ^(j)|, |τ^(j)| is largest at an end of the span.
//
// Positions, tangents and normals at the span ends come from the Frenet–Serret integration
// (curves/space/frenet.hpp), which has no proven error bound: they are integrated twice, by the
// order-6 Magnus stepper at rtol 1e-13 (the values used) and by Dormand–Prince 5(4) at rtol 1e-10,
// and the error of the former is taken as the largest difference of the two so far along the
// piece (an estimate: the coarser run's error, with tolerances 10³ apart far above the finer
// one's; checked against integration at tight tolerance in tests/export/space_export_test.cpp).
// Added: the joint gaps to the next piece's start frame and rounding; a displacement δ of the
// end data moves the B-spline by at most δP + (2h/5)δT + (h²/20)|κ δN| (quintic; partition of
// unity).
//
//   auto r = lac::to_bspline(space_curve, {.tolerance = 1e-6});
//   if (r.usable()) lac::write_file("curve.dxf", lac::ExportFormat::dxf, r.curve);  // export/write3.hpp
#include <string>

#include "lac/common/summary.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/export/bspline3.hpp"
#include "lac/export/to_bspline.hpp"

namespace lac {

struct SpaceExportInfo {
  double tolerance = 0;      ///< the tolerance used (absolute)
  double max_deviation = 0;  ///< proven bound on |c(s) − b(s)| (absolute): interpolation + end data
  double interpolation = 0;  ///< the largest interpolation bound of a span (proven part)
  double positions = 0;      ///< the largest end-data term (proven integration bound, joint gaps, rounding)
  long spans = 0;
  std::string continuity = "G1";  ///< at every knot (C1, or C2 for G2, in the arc-length parameter)
};

using SpaceExportResult = Result<BSpline3, SpaceExportInfo>;

/// The B-spline of a non-empty SpaceCurve within options.tolerance (0: kDefaultExportTolerance ×
/// length); InputError "tolerance" unless ≥ 0 and finite, "max_spans" unless ≥ 1, "degree" unless
/// 3 or 5, "curve" for an empty curve. Status ok when max_deviation ≤ tolerance, inaccurate beyond
/// it (no curve then), max_iterations past max_spans, numerical_failure when an integration failed.
/// summary.error = max_deviation / length, summary.accept = tolerance / length.
SpaceExportResult to_bspline(const SpaceCurve& curve, const ExportOptions& options = {});

}  // namespace lac
