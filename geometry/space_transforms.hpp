#pragma once
// Similarities of a SpaceCurve (curves/space/space_curve.hpp), each returning a new curve. The
// pieces (their laws, standard-form ranges and start frames) stay bit for bit: only the placement
// user point = origin + matrix · standard-form point changes, so κ, τ and dκ/ds keep their closed
// forms (scaled by 1/k for a scale k; τ negated by a mirror image, whose placement has
// torsion_sign = −1).
//   translated  origin + v
//   rotated     c + Q(origin − c), matrix → Q · matrix (Q a rotation: orthogonal, det +1)
//   scaled      c + k(origin − c), matrix → k · matrix, scale → k · scale (k > 0)
//   mirrored    about the plane through P with normal n: H = I − 2nnᵀ, origin → P + H(origin − P),
//               matrix → H · matrix, torsion_sign → −torsion_sign
#include <Eigen/Core>

#include "lac/curves/space/space_curve.hpp"

namespace lac {

SpaceCurve translated(const SpaceCurve& curve, const Vec3& offset);
/// `rotation` orthogonal with determinant +1 to 1e-12 (InputError "rotation" otherwise).
SpaceCurve rotated(const SpaceCurve& curve, const Eigen::Matrix3d& rotation, const Vec3& center = Vec3::Zero());
/// factor ∈ (0, inf) (InputError "factor").
SpaceCurve scaled(const SpaceCurve& curve, double factor, const Vec3& center = Vec3::Zero());
/// normal nonzero and finite (InputError "normal"); point finite (InputError "point").
SpaceCurve mirrored(const SpaceCurve& curve, const Vec3& point, const Vec3& normal);

}  // namespace lac
