#pragma once
// Exact conversions between an LA segment (la_segment.hpp) and pieces of the standard form
// (la_curve.hpp: κ = 1, θ = 0, position 0 at s = 0, ρ increasing, ρ^α = 1 + αΛs), so that the
// closed forms (θ(s), s(θ), igf positions) apply to segments and the 001 construction, which
// works on the standard form, can return segments.
//
// The link: on a piece where q keeps its sign, ρ̃ = 1/|K(q)| per unit of u satisfies
// ρ̃^α = |q| linear in u; scaling the standard form by k = ρ̃(u*) at a point u* maps ρ^α = 1 + αΛs
// onto it with u − u* = ±k s and Λ = |dρ̃/du| at u* (a similarity by k maps ρ^α = a + b s to
// k^α a + k^(α−1) b s'). Through an inflection (α < 0: q = 0, ρ = ∞, the open end of the
// standard form's domain) the segment is two pieces, each ending at that domain end.
#include <complex>
#include <optional>
#include <utility>
#include <vector>

#include "lac/curves/planar/la_curve.hpp"
#include "lac/curves/planar/la_segment.hpp"

namespace lac {

/// z ↦ factor·m(z) + offset, m the identity or (mirror) complex conjugation.
struct Similarity {
  std::complex<double> factor{1, 0};  ///< scale times rotation (≠ 0)
  std::complex<double> offset{};
  bool mirror = false;

  std::complex<double> operator()(std::complex<double> z) const { return factor * (mirror ? std::conj(z) : z) + offset; }
  /// z ↦ (*this)(inner(z)).
  Similarity after(const Similarity& inner) const;
  Similarity inverse() const;
};

/// A piece of a standard-form curve traversed from `from` to `to` (in θ or s; to < from runs
/// against the standard form's direction), placed by `to_user`. An end may be the inflection,
/// the upper end of the domain when α < 0 and Λ > 0 (ρ = ∞ there).
struct StandardPiece {
  LaCurve curve;
  Parameter parameter = Parameter::s;
  double from = 0, to = 0;
  Similarity to_user;
};

/// θ at `from` and at `to` (θ_max = 1/((1−α)Λ) at the inflection), for closed forms in θ such as
/// igf_position_delta.
std::pair<double, double> theta_range(const StandardPiece& piece);
/// The same for s.
std::pair<double, double> s_range(const StandardPiece& piece);

/// The piece as a segment: u = s (or −s against the direction), q = ±ρ^α (α = 0: q = −log ρ,
/// σ = ±1), φ = ±θ, scale |factor|, rotation ±factor/|factor|. `standard_position_at_from` is the
/// standard form's position C(from) (0 when from = 0; otherwise known to the caller, e.g. 001's
/// search, or from position_at). InputError when an end is outside the (closed at the inflection)
/// domain, from = to, or the segment's values are not representable (ρ^α beyond the double range).
LaSegment to_segment(const StandardPiece& piece, std::complex<double> standard_position_at_from = {});

/// The segment as one standard-form piece, or two through an inflection, in s, in the segment's
/// order. A piece is anchored (s = 0, ρ = 1) at the segment's start when q ≠ 0 there, else at its
/// end; the end is also the anchor of the piece after an inflection. `end_point` is the segment's
/// user position at ub (position_at(seg, seg.length()) or a construction's end point), needed only
/// then (InputError "end_point" when it is needed and missing).
std::vector<StandardPiece> to_standard_pieces(const LaSegment& seg,
                                              std::optional<std::complex<double>> end_point = std::nullopt);

}  // namespace lac
