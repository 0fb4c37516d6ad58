#pragma once
// igf (integrators/igf.hpp, the incomplete-gamma closed form of the standard form, 002) on a
// segment in linear-q form: the tangent integral of LaSegment data and of the constructions' trial
// segments, and PlanarCurve positions by igf (planar_curve.hpp).
#include <complex>

#include "lac/curves/curve.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/integrators/igf.hpp"
#include "lac/integrators/quadrature.hpp"

namespace lac::detail {

/// igf on segment data: each part of the segment on one side of a zero of q is one standard-form
/// piece, C(θ1) − C(θ0) by the closed form. Next to a zero of q (α < 0: an inflection, ρ = ∞) the
/// closed form's variable θ cannot resolve the arc length (U = 1 + (α−1)Λθ → 0 there and
/// s_max − s ∝ U^(α/(α−1)); the zero itself is outside igf's open θ domain), so the part of a
/// piece where U < kIgfMinU is integrated by LaSegment's GaussLegendre path instead (the segment
/// kernel), and so is a part that has no standard form in double
/// precision (|q| at its anchor so small that ρ overflows, e.g. a subnormal end curvature). A zero
/// of q within rounding of an end leaves an empty part, which contributes nothing. InputError for
/// data LaSegment refuses.
IntegralResult<std::complex<double>> integrate_tangent_igf(const LaLaw& law, const LinearQ& seg, const Igf& method);

/// U = 1 + (α−1)Λθ at which an igf piece stops short of a zero of q (above: the θ rounding, ε/U
/// relative in U, moves the arc length by ≲ 50ε of the piece for α ∈ [−5, 0)).
inline constexpr double kIgfMinU = 1e-3;

}  // namespace lac::detail

namespace lac {

class LaSegment;

/// The position at s ∈ [0, seg.length()] by igf from the segment's start: the closed form's cost
/// does not grow with the distance, so no running integral is needed. A failed integral leaves the
/// start point with an infinite estimate (PositionResult).
PositionResult position_at(const LaSegment& seg, double s, const Igf& method);

}  // namespace lac
