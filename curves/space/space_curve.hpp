#pragma once
// A space curve made of LA space pieces (la_space_curve.hpp) placed one after the other: what the
// space constructions of 000 return (one piece for a G1 segment, two for a compound-rhythm one).
// Each piece keeps its own standard form — its laws, the standard-form arc-length interval it is
// drawn over and the standard-form Frenet frame at its start — so every piece is evaluated on its
// own and an evaluation never integrates across pieces. One similarity (SpacePlacement) maps the
// standard form onto the user's space; a mirrored placement gives negative torsion.
//
// κ, τ and dκ/ds at a user arc length are closed forms of the piece's laws; the frame (position,
// T, N, B) is integrated (Frenet–Serret, frenet.hpp) from the start of the piece, with the ODE
// settings the curve was made with.
//
//   auto r = lac::solve_compound_space_segment(ends, spec);   // r.curve is a SpaceCurve
//   auto f = r.curve.frame_at(0.5 * r.curve.length());       // f.p, f.t, f.kappa, f.tau, f.status
//   auto pts = r.curve.sample(200);                           // uniform in s
#include <Eigen/Core>
#include <string>
#include <vector>

#include "lac/common/numeric.hpp"
#include "lac/common/status.hpp"
#include "lac/curves/space/frenet.hpp"
#include "lac/curves/space/la_space_curve.hpp"
#include "lac/integrators/ode_registry.hpp"

namespace lac {

/// One piece in its own standard form: its laws, the standard-form arc lengths it is drawn over
/// and its standard-form frame at s_begin (piece 0 of a construction: the standard frame at 0;
/// piece 1 of a compound segment: the joint frame at s_c, 000 Eq. (17)).
struct SpacePiece {
  LaSpaceCurve law;
  double s_begin = 0, s_end = 0;
  Frame3 start;
};

/// The similarity from the standard form onto the user's space: user point = origin + matrix ·
/// standard-form point, matrix = scale · Q with Q orthogonal and det Q = torsion_sign (−1: a
/// mirror image, whose torsion is negative).
struct SpacePlacement {
  Vec3 origin = Vec3::Zero();
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Identity();
  double scale = 1;
  int torsion_sign = 1;
};

/// A point of a SpaceCurve in user coordinates and units.
///
/// Samples are integrated from a point known to be right (the start of their piece or the last
/// sample of the same piece whose status is ok), so a sample that fails never shifts the others. A
/// point whose status is not ok holds no frame of its own: p, t, n, b are those of the known point
/// it was to be integrated from; s, piece, κ, τ and dκ/ds are its own (closed forms).
struct SpacePoint {
  double s = 0;       ///< user arc length from the curve's start
  size_t piece = 0;   ///< the piece it was evaluated on
  Vec3 p = Vec3::Zero(), t = Vec3::UnitX(), n = Vec3::UnitY(), b = Vec3::UnitZ();  ///< b = t × n
  double kappa = 0, tau = 0, dkappa_ds = 0;  ///< τ < 0 on a mirrored curve
  long evaluations = 0;  ///< ODE right-hand-side evaluations (cumulative along a sampling)
  Status status = Status::ok;
  std::string message;
};

class SpaceCurve {
 public:
  /// An empty curve (length 0; every evaluation throws InputError).
  SpaceCurve() = default;
  /// At least one piece; each piece's [s_begin, s_end] inside its laws' s range with a finite
  /// start frame; placement finite with scale > 0, torsion_sign ±1 and matrix = scale · Q as
  /// documented; valid ODE settings. InputError naming the offending argument otherwise.
  SpaceCurve(std::vector<SpacePiece> pieces, const SpacePlacement& placement, const OdeOptions& ode);

  const std::vector<SpacePiece>& pieces() const { return pieces_; }
  const SpacePlacement& placement() const { return placement_; }
  const OdeOptions& ode_options() const { return ode_; }
  double length() const { return length_; }
  Interval s_domain() const { return {0.0, length_, true, true}; }
  /// User arc length at which piece k starts (k = pieces().size(): the length).
  double piece_start(size_t k) const { return starts_.at(k); }
  /// The piece holding s (the later one at a joint).
  size_t piece_at(double s) const;
  /// The standard-form arc length of user arc length s on piece k (clamped to the piece).
  double standard_s(size_t k, double s) const;

  /// Closed forms at s ∈ [0, length()], user units.
  double kappa_at(double s) const;
  double tau_at(double s) const;
  double dkappa_ds_at(double s) const;

  /// Position and frame at s ∈ [0, length()], integrated from the start of the piece holding s.
  SpacePoint frame_at(double s) const;
  /// n ∈ [2, 10^6] points uniform in s over [0, length()].
  std::vector<SpacePoint> sample(int n) const;
  /// n ∈ [2, 10^6] points uniform in s from s0 to s1 ≥ s0 (both in [0, length()]). A point at a
  /// joint reached from an earlier point is evaluated on the earlier piece. The points share one
  /// step budget (ODE max_steps + 64 per point): when it is spent the rest are max_iterations.
  std::vector<SpacePoint> sample(double s0, double s1, int n) const;

  /// InputError naming `name` unless s ∈ [0, length()] (and the curve is not empty).
  void check_s(double s, const char* name) const;

 private:
  SpacePoint closed_forms(size_t k, double s) const;
  SpacePoint to_user(const SpacePoint& closed, const Frame3& frame) const;

  std::vector<SpacePiece> pieces_;
  SpacePlacement placement_;
  OdeOptions ode_;
  std::vector<double> starts_{0.0};  // user arc length of each piece's start, then the length
  double length_ = 0;
};

}  // namespace lac
