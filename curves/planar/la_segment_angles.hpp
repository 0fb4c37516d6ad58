#pragma once
// Where the tangent of an LA segment takes given directions: the u values with θ ≡ beta (mod
// period), in closed form (φ is monotonic between inflections and F is invertible there, 004
// Eq. 5), polished by Newton on φ(u) = target. PlanarCurve's bounding box (θ ≡ 0 mod π/2) and the
// geometry layer's line crossings and spans (geometry/) cut segments there.
#include <cstddef>
#include <vector>

#include "lac/curves/planar/la_segment.hpp"

namespace lac::detail {

/// The u values in [ua, ub] of `seg` where θ ≡ beta (mod period), ascending and distinct, with
/// the ends and the inflection: between two consecutive values sin(π(θ − beta)/period) keeps its
/// sign. Empty (with *capped set) when a monotonic piece holds `cap` values or more.
std::vector<double> angle_cuts(const LaSegment& seg, double beta, double period, size_t cap, bool* capped);

}  // namespace lac::detail
