#pragma once
// One planar LA segment placed in the user's plane. In its own frame the segment is the linear-q
// form of la_law.hpp (004 Eqs. 2–8): q linear in a normalized parameter u ∈ [ua, ub], q per unit
// of u at both ends, tangent angle φa at ua. A similarity (start point, scale ℓ = user length per
// unit of u, rotation R) places it:
//   s = ℓ (u − ua),   κ(s) = K(q(u))/ℓ,   θ(s) = arg R + φ(u),
//   position(s) = start + ℓ R ∫_{ua}^{u} e^{iφ(v)} dv.
// The G2 triple (normalized S, chord units), the S-curve (standard-form s) and the standard form
// of 001 (curves/planar/standard_form.hpp) all map onto it without renormalizing.
// Mirror image: q → −q, φ → −φ (σ → −σ for α = 0), exact in floating point.
//
//   lac::LaSegment seg(lac::LaLaw{-1.0}, 0.0, 1.0, 1.0, -2.0, 0.0, {.start = {1, 2}, .scale = 3});
//   seg.kappa_at(1.5); seg.theta_at(1.5);                  // closed forms
//   auto p = lac::position_at(seg, 1.5);                   // Gauss–Legendre, or any method
//   auto q = lac::position_at(seg, 1.5, lac::Rk45{});      // p.point.position, p.error_estimate, p.status
#include <complex>
#include <optional>

#include "lac/curves/curve.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/curves/planar/la_law.hpp"
#include "lac/integrators/gauss_legendre.hpp"
#include "lac/integrators/quadrature.hpp"

namespace lac {

/// The similarity from a segment's frame onto the user's plane.
struct Placement {
  std::complex<double> start{};         ///< user position at ua
  double scale = 1;                     ///< ℓ: user length per unit of u (> 0)
  std::complex<double> rotation{1, 0};  ///< unit complex: the frame's x axis in the user's plane
};

class LaSegment {
 public:
  /// InputError naming the parameter unless: α finite and σ = ±1; ua < ub finite; qa, qb finite
  /// with finite curvature K(q) and, for α > 0, of one sign (κ cannot reach 0 or ∞ there); φa
  /// finite; start finite, scale > 0 with a finite length ℓ(ub − ua), |rotation| = 1 (to 1e-12).
  LaSegment(LaLaw law, double ua, double ub, double qa, double qb, double phi_a, Placement placement = {});
  LaSegment(LaLaw law, const detail::LinearQ& normalized, Placement placement = {})
      : LaSegment(law, normalized.ua, normalized.ub, normalized.qa, normalized.qb, normalized.phi_a, placement) {}

  const LaLaw& law() const { return law_; }
  const detail::LinearQ& normalized() const { return q_; }
  double ua() const { return q_.ua; }
  double ub() const { return q_.ub; }
  double qa() const { return q_.qa; }
  double qb() const { return q_.qb; }
  double phi_a() const { return q_.phi_a; }
  const Placement& placement() const { return placement_; }
  std::complex<double> start() const { return placement_.start; }
  double scale() const { return placement_.scale; }
  std::complex<double> rotation() const { return placement_.rotation; }
  double rotation_angle() const { return angle_; }  ///< arg R

  // In the normalized parameter u ∈ [ua, ub] and the segment's frame (closed forms).
  double q_at(double u) const { return q_.q_at(u); }
  double curvature_per_u(double u) const { return law_.kappa_of_q(q_at(u)); }  ///< K(q(u)) = ℓ κ
  double phi_at(double u) const { return q_.phi_at(law_, u); }
  double phi_b() const { return q_.phi_b(law_); }
  double turning() const { return q_.turning(law_); }  ///< φ(ub) − φ(ua)
  double u_at(double s) const;                         ///< ua + s/ℓ (ub exactly at s = length)
  /// The zero of q in [ua, ub] (α < 0: κ = 0 there), if any.
  std::optional<double> inflection_u() const;
  /// The data {u0, u1, q(u0), q(u1), φ(u0)} of the part [u0, u1] (the segment's own at its ends).
  detail::LinearQ part(double u0, double u1) const;

  // In user arc length s ∈ [0, length()] (closed forms, no integration).
  double length() const { return length_; }
  Interval s_domain() const { return {0.0, length_, true, true}; }
  /// Signed κ, θ and dκ/ds at s (InputError unless s ∈ [0, length()]).
  double kappa_at(double s) const {
    check_s(s, "s");
    return curvature_per_u(u_at(s)) / scale();
  }
  double theta_at(double s) const {
    check_s(s, "s");
    return angle_ + phi_at(u_at(s));
  }
  double dkappa_ds_at(double s) const;
  /// s, θ, κ and ρ = 1/κ (±inf at an inflection); the position is not computed (0).
  CurvePoint frame_at(double s) const;
  double kappa_start() const { return law_.kappa_of_q(qa()) / scale(); }
  double kappa_end() const { return law_.kappa_of_q(qb()) / scale(); }
  double theta_start() const { return angle_ + phi_a(); }
  double theta_end() const { return angle_ + phi_b(); }
  std::optional<double> inflection_s() const;

  /// The reflection across the line through start along R (the frame's x axis).
  LaSegment mirrored() const;
  /// The same curve traversed from the other end; `end_point` is its start, the user position at
  /// ub (e.g. position_at(seg, length()), or a construction's end point).
  LaSegment reversed(std::complex<double> end_point) const;
  /// The same normalized segment under another placement.
  LaSegment placed(const Placement& placement) const { return {law_, q_, placement}; }

  /// InputError naming `name` unless s ∈ [0, length()] (u ∈ [ua, ub]).
  void check_s(double s, const char* name) const;
  void check_u(double u, const char* name) const;

 private:
  LaLaw law_;
  detail::LinearQ q_;
  Placement placement_;
  double angle_ = 0;
  double length_ = 0;
};

/// ∫_{u0}^{u1} e^{iφ(u)} du in the segment's frame (u0, u1 ∈ [ua, ub], either order), with any
/// quadrature method. The inflection split and the graded substitution next to a zero of q
/// (detail::tangent_plan) apply to every method; pieces turning more than 64 rad are split
/// further, and the parts share the method's budget. GaussLegendre runs the fast path of
/// detail::integrate_tangent (per-radian panels, at most 64, cached node powers; its value bit for
/// bit) with the 10-point rule on twice as many panels as error estimate (status
/// tolerance_not_met above GaussLegendre::tol relative); beyond 1024 rad of turning on a piece it
/// gives status max_iterations and a NaN value. Every estimate adds the rounding of the integrand,
/// ε(1 + max|φ|)|u1 − u0|.
template <QuadratureMethod M>
IntegralResult<std::complex<double>> integrate_tangent(const LaSegment& seg, double u0, double u1, const M& method);

/// The same integral by Boost tanh-sinh in u, split at the inflection: an independent evaluation
/// for verification (slower). NaN when tanh-sinh cannot evaluate it.
std::complex<double> integrate_tangent_reference(const LaSegment& seg, double u0, double u1,
                                                 double tolerance = detail::kReferenceTolerance);

/// Position and frame at arc length s ∈ [0, length()], integrated from the segment's start.
/// When the status is not usable the position is the start's and the estimate +inf.
template <QuadratureMethod M = GaussLegendre>
PositionResult position_at(const LaSegment& seg, double s, const M& method = M{});

}  // namespace lac

#include "lac/curves/planar/detail/la_segment_integration.hpp"
