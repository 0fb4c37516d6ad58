#pragma once
// A planar LA curve (a PlanarCurve: LA segments joined G1 or G2) as a quintic (default) or cubic
// B-spline with a certified bound on the distance between the two, for CAD export (docs/export.md).
//
// Each LA segment is cut into spans [s0, s1] (the joints and an inflection are span ends); on a
// span the B-spline is the Hermite interpolant in arc length of the curve c(s), with T = e^{iθ},
// N = c'' = iκT at the ends and h the span length:
//   cubic   (c, c'):       P0,  P0 + (h/3)T0,  P1 − (h/3)T1,  P1
//   quintic (c, c', c''):  P0,  P0 + (h/5)T0,  P0 + (2h/5)T0 + (h²/20)N0,  (mirrored at P1)
// Consecutive spans share these end data, so with the arc length as parameter the cubic is C1
// (G1; interior knots double, 2N + 2 control points for N spans; its curvature matches κ only to
// O(h²) at a knot) and the quintic is C2 inside each LA segment and at G2 joints (knots triple,
// 3N + 3 points; curvature continuous, G2), C1 at a joint where the curve's curvature jumps.
//
// The interpolation bound is proven: per span the least over m of C_m h^m M_m, C_m the Peano
// constant of the interpolant for the m-th derivative and M_m ≥ |c^(m)| a polynomial in bounds
// of |κ^(j)| on the span (c⁗ = (iκ'' − 3κκ' − iκ³) e^{iθ}, M₄ = |κ''| + 3|κ||κ'| + |κ|³; cubic:
// h⁴/384 M₄, h³/96 M₃, h²/16 |κ|; quintic: h⁶/46080 M₆ … 0.0062 h³ M₃). On a span without an
// inflection each |κ^(j)| is a monotone function of s (a power of the LA law's t), so its largest
// value is at an end; where κ' is unbounded (α < −1 at an inflection) a quintic span is the cubic
// one raised to degree 5. Added: the end positions' proven integration bounds, the chain's joint
// gaps (position, tangent, curvature) and rounding. The B-spline is within max_deviation of the
// curve at the same arc length, hence in Hausdorff distance.
//
// An arc of a quadratic LA curve (003) is exported by the same spans (export/detail/hermite_bound.hpp);
// its |κ^(j)| come from closed forms in u = log κ bounded on each span (to_bspline_quadratic.cpp).
//
//   auto r = lac::to_bspline(curve, {.tolerance = 1e-6});
//   if (r.usable()) lac::write_file("curve.dxf", lac::ExportFormat::dxf, r.curve);  // export/write.hpp
#include <string>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/export/bspline.hpp"

namespace lac {

/// The default export tolerance relative to the curve's length: T = kDefaultExportTolerance × length.
inline constexpr double kDefaultExportTolerance = 1e-6;

struct ExportOptions {
  /// Bound on the deviation, absolute in the curve's units (> 0); 0: kDefaultExportTolerance × length.
  double tolerance = 0;
  /// Cap on the number of spans (≥ 1): status max_iterations beyond it.
  long max_spans = 1'000'000;
  /// 5: quintic Hermite spans (c, c', c'' at the ends), C2 in arc length inside each LA segment and
  /// at G2 joints, so the curvature is continuous (G2); 3: cubic Hermite spans, C1 (G1).
  int degree = 5;
  /// Remove knots inside each LA segment within the tolerance (export/detail/hermite_bound.hpp,
  /// remove_knots_within): the Hermite spans are then built to 1/10 of the tolerance and the knots
  /// they do not need are removed with a certified bound, leaving a smoother B-spline (C4 for the
  /// quintic, C2 for the cubic, at the remaining interior knots) with fewer control points. The
  /// joints between segments stay knots of their multiplicity. false: the Hermite spans' knots.
  bool remove_knots = true;
  /// With remove_knots: also try a least-squares fit with simple knots and a proven distance
  /// (export/detail/bspline_fit.hpp), taken where it needs fewer points. Fewest control points, but
  /// its curvature follows the LA curve's less closely (its LCG is less straight:
  /// results/export_lcg.md), so it is not the default. Joints and end data as above.
  bool fit = false;
  /// With fit: fits of every degree from 3 up to this are tried, and the one with the fewest
  /// control points kept (a higher degree carries more of a smooth segment per span, as
  /// OpenCASCADE's approximation chooses its degree from 3 to 8; a lower one needs fewer points
  /// around the joints). Inside each LA segment the fit of degree q is C^(q−1); at the joints and the
  /// ends it keeps the continuity and end data of `degree` (G2 for 5: the cubic fit is then C2 at a
  /// G2 joint). 0: the fit has the degree `degree`; else [3, kMaxFitDegree].
  int fit_max_degree = 0;
};

/// The highest degree ExportOptions::fit_max_degree allows.
inline constexpr int kMaxFitDegree = 9;

struct ExportInfo {
  double tolerance = 0;        ///< the tolerance used (absolute)
  double max_deviation = 0;    ///< certified bound on |c(s) − b(s)| (absolute), see above
  double interpolation = 0;    ///< the largest interpolation bound of a span (proven part)
  double positions = 0;        ///< the largest end-position term (proven integration bounds, joint gaps, rounding)
  long spans = 0;
  /// Whether the B-spline's curvature is monotone, in the LA curvature's direction, on every LA
  /// segment whose curvature changes (by more than 1e-9 of its scale): proven, with a slack of
  /// 1e-9 of the curvature's scale for rounding, inside each span from the Bernstein coefficients
  /// of the numerator of dκ/dt (subdivided where needed) and across the knots inside the segment.
  /// A segment of constant curvature (an arc) is not checked: no polynomial has constant curvature.
  bool curvature_monotone = false;
  long monotone_segments = 0;            ///< LA segments on which it is
  long constant_curvature_segments = 0;  ///< arcs, not checked
  double max_curvature_jump = 0;  ///< largest jump of the B-spline's curvature at a knot
  std::string continuity = "G1";  ///< at every knot (C1 in the arc-length parameter)
};

using ExportResult = Result<BSpline, ExportInfo>;

/// The certified cubic B-spline of a usable curve (InputError "tolerance" unless ≥ 0 and finite,
/// "max_spans" unless ≥ 1, "curve" for an empty curve). Status ok when max_deviation ≤
/// tolerance, inaccurate beyond it (no curve then; info keeps the bound), max_iterations past
/// max_spans, numerical_failure if a position failed. summary.error = max_deviation / length and
/// summary.accept = tolerance / length.
ExportResult to_bspline(const PlanarCurve& curve, const ExportOptions& options = {});

/// The arc [s0, s1] of a quadratic LA curve (both in s_domain(), InputError "s0" / "s1" otherwise
/// and unless s0 < s1; `lac quadratic` draws curve.default_range()) as the certified B-spline, as
/// for a PlanarCurve: one smooth part, split at the inflection when the arc passes it
/// (through_inflection); its end positions by quadrature from s = 0 (the standard form's origin).
/// The curvature check has one segment (κ decreases along the whole curve).
ExportResult to_bspline(const QuadraticLaCurve& curve, double s0, double s1, const ExportOptions& options = {});

/// The curvature check of ExportInfo on a B-spline made by to_bspline, on its Bézier pieces
/// (export/write.hpp bezier_pieces): segment k's spans are those between its joints' knots.
bool curvature_monotone(const BSpline& b, const PlanarCurve& curve, long* monotone_segments = nullptr,
                        double* max_jump = nullptr, long* constant_segments = nullptr);

}  // namespace lac
