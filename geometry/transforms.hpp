#pragma once
// Transforms of a PlanarCurve, each returning a new curve. The similarities are exact: an LA
// segment is a normalized segment (law, q linear in u, φa) placed by a similarity (la_segment.hpp),
// so a similarity of the plane changes only the placements — start point, scale ℓ, rotation R —
// and the laws (α, the q values) stay bit for bit; a mirror image also flips the normalized
// segment (q → −q, φ → −φ: LaSegment::mirrored), which reverses the sign of κ.
//   translated  start + v
//   rotated     c + e^{iφ}(start − c), R → e^{iφ} R
//   scaled      c + k(start − c), ℓ → k ℓ (k > 0): lengths × k, κ / k, same α
//   mirrored    about the line through P along D: z → P + D² conj(z − P), R → D² conj(R)
// Cutting keeps the laws as well: the part [u0, u1] of a segment is the segment with the same law
// restricted to it (LaSegment::part); its start is the position at u0, integrated (the only
// approximate step, carried as the result's error estimate).
//   split      at 0 < s < length(): the parts [0, s] and [s, length()]
//   trimmed    to [s0, s1]
//   appended   the segments of a then those of b, if b starts at a's end within a tolerance
//   reversed   traversed from the end (PlanarCurve::reversed from the integrated end point)
//
//   auto r = lac::trimmed(curve, 0.2, 0.7);  // r.curve, r.summary.status, r.summary.error_estimate
#include <complex>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/geometry/options.hpp"

namespace lac {

PlanarCurve translated(const PlanarCurve& curve, std::complex<double> offset);
/// About `center` by `angle` (rad, finite).
PlanarCurve rotated(const PlanarCurve& curve, double angle, std::complex<double> center = {});
/// About `center` by factor ∈ (0, inf) (InputError "factor" otherwise).
PlanarCurve scaled(const PlanarCurve& curve, double factor, std::complex<double> center = {});
/// About the line through `point` along `direction` (nonzero; InputError "direction" otherwise).
PlanarCurve mirrored(const PlanarCurve& curve, std::complex<double> point, std::complex<double> direction);

struct CurvePair {
  PlanarCurve first, second;
};

/// Uses options.method for the one position it integrates, options.tolerance and options.accept
/// to grade its error estimate relative to the curve's length. Usable results only hold curves.
/// s ∈ (0, length()) (InputError "s" otherwise).
Result<CurvePair> split(const PlanarCurve& curve, double s, const GeometryOptions& options = {});
/// 0 ≤ s0 < s1 ≤ length() (InputError "s0" / "s1" otherwise).
Result<PlanarCurve> trimmed(const PlanarCurve& curve, double s0, double s1, const GeometryOptions& options = {});
/// InputError "b" when |start of b − end of a| exceeds `gap_tolerance` (absolute, ≥ 0, finite;
/// InputError "gap_tolerance" otherwise). The joint is kept as it is (G0 within the tolerance).
Result<PlanarCurve> appended(const PlanarCurve& a, const PlanarCurve& b, double gap_tolerance,
                             const GeometryOptions& options = {});
Result<PlanarCurve> reversed(const PlanarCurve& curve, const GeometryOptions& options = {});

}  // namespace lac
