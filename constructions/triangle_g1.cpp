// Similar-triangle search for monotonic- and compound-rhythm LA segments (001 §2–4). See
// triangle_g1.hpp for the conventions and docs/planar_segments.md for the drawable-region argument.
#include "lac/constructions/triangle_g1.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/planar/standard_form.hpp"
#include "lac/solvers/bracket.hpp"

namespace lac {
namespace {

constexpr double kPi = std::numbers::pi;

/// Admissible scale of the control triangle, max |a_i − a0|: below DBL_MIN the differences are
/// subnormal (fewer than 53 significant bits); above DBL_MAX/8 the legs (≤ 2 scale), the curve
/// (length ≤ 3 scale) or the mapped points could overflow.
constexpr double kMinScale = std::numeric_limits<double>::min();
constexpr double kMaxScale = std::numeric_limits<double>::max() / 8;

/// The control triangle after swapping (short leg first), divided by its scale: the construction
/// is similarity-invariant, so angles are computed on legs of length ≤ 2 (no underflow of the
/// turning for tiny triangles, no overflow of lengths for huge ones, R5/R8 of docs/robustness.md).
struct Canonical {
  Point2 origin;          ///< b0 in user coordinates (a0, or a2 when swapped)
  double scale = 1;       ///< max |a_i − a0| (user units)
  Point2 leg0, leg1;      ///< (b1 − b0)/scale, (b2 − b1)/scale
  Point2 chord;           ///< (b2 − b0)/scale
  bool swapped = false;
  bool mirrored = false;  ///< b turns right
  double turning = 0;     ///< θ ∈ (0, π), unsigned
  double target = 0;      ///< angle at b0 between b1 − b0 and b2 − b0, in [θ/2, θ)
  double sign = 1;        ///< sign of the user triangle's turning
};

double cross(Point2 u, Point2 v) { return u.real() * v.imag() - u.imag() * v.real(); }

Canonical canonicalize(const ControlTriangle& t, const TriangleOptions& o, const char* fn) {
  const char* names[6] = {"a0.x", "a0.y", "a1.x", "a1.y", "a2.x", "a2.y"};
  const double v[6] = {t.a0.real(), t.a0.imag(), t.a1.real(), t.a1.imag(), t.a2.real(), t.a2.imag()};
  for (int k = 0; k < 6; ++k) require_finite(fn, names[k], v[k]);
  // Differences of finite doubles overflow to ±inf, so a non-finite scale means a side length
  // beyond the double range.
  const Point2 e1 = t.a1 - t.a0, e2 = t.a2 - t.a0;
  const double scale = std::max(std::abs(e1), std::abs(e2));
  auto range_text = [] {
    return "[" + format_number(kMinScale) + ", " + format_number(kMaxScale) + "]";
  };
  if (!(scale <= kMaxScale))
    throw_input_error(fn, "points", "max |a_i - a0| = " + format_number(scale) + " is outside " + range_text() +
                                        " (side lengths beyond the double range)");
  const Point2 d0 = e1, d1 = t.a2 - t.a1;  // |d1| ≤ 2·scale: finite
  double magnitude = 0;  // largest coordinate: the resolution of the differences
  for (double x : v) magnitude = std::max(magnitude, std::abs(x));
  if (std::abs(d0) <= 1e-14 * magnitude) throw_input_error(fn, "a1", "coincides with a0 (no start tangent)");
  if (std::abs(d1) <= 1e-14 * magnitude) throw_input_error(fn, "a2", "coincides with a1 (no end tangent)");
  if (!(scale >= kMinScale))
    throw_input_error(fn, "points", "max |a_i - a0| = " + format_number(scale) + " is outside " + range_text() +
                                        " (side lengths below the normal double range: fewer than 53 significant bits)");
  const Point2 u0 = d0 / scale, u1 = d1 / scale, u2 = e2 / scale;
  const double signed_turning = std::atan2(cross(u0, u1), u0.real() * u1.real() + u0.imag() * u1.imag());
  const double theta = std::abs(signed_turning);
  if (theta < o.min_turning)
    throw_input_error(fn, "turning", theta, interval_text(o.min_turning, kPi - o.min_turning, true, true) +
                                                " (a0, a1, a2 are collinear: no turning)");
  if (theta > kPi - o.min_turning)
    throw_input_error(fn, "turning", theta, interval_text(o.min_turning, kPi - o.min_turning, true, true) +
                                                " (turning >= pi: a2 lies behind a0)");
  Canonical c;
  c.sign = signed_turning > 0 ? 1.0 : -1.0;
  c.scale = scale;
  c.swapped = std::abs(d0) > std::abs(d1);  // 001 §4: ρ must increase from b0 to b2
  c.origin = c.swapped ? t.a2 : t.a0;
  c.leg0 = c.swapped ? -u1 : u0;
  c.leg1 = c.swapped ? -u0 : u1;
  c.chord = c.swapped ? -u2 : u2;
  c.mirrored = cross(c.leg0, c.leg1) < 0;
  c.turning = theta;
  c.target = std::abs(std::arg(c.chord / c.leg0));
  return c;
}

/// Everything the search varies for one Λ0: the standard-form curve of 001 Fig. 5.
///
/// Λ0 < 1/D keeps both segments inside their θ domains: segment 0 needs d0 Λ0 < 1 with
/// d0 = (1−α0)θ0 (configuration a) or (α0−1)θ0 (b); segment 1, when α1 < 1, needs
/// (1−α1)Λ1'θ1 < 1 with Λ1' = Λ0 ρc^(1−α0), i.e. (d0 + d1)Λ0 < 1 in configuration a
/// (ρc^(α0−1) = 1 − (1−α0)Λ0θ0) and d1 Λ0 < 1 in b (ρc = 1), d1 = max(0, 1−α1)θ1. This is
/// 001 §4's "search a smaller Λ0" rule in closed form.
///
/// A monotonic segment with α0 < 1 can be drawn in configuration b's form as well (`end_form`,
/// solve_g1's second search: ρ = 1 at its large-ρ end, θ ∈ [−θ0, 0]): the same curves, Λ' = Λ0 ρc^(1−α0) ∈ (0, ∞) instead of
/// Λ0 ∈ (0, Λmax). Near Λmax the curve depends on 1 − (1−α0)Λ0θ0, which a double Λ0 resolves only
/// to ~1e-16 absolute (a start angle off by 1e-11 rad when ρ grows 10^7-fold along the curve);
/// Λ' carries it with full relative precision.
struct Problem {
  double alpha0, alpha1, theta0, theta1;
  bool configuration_b;
  double turning;  // θ0 + θ1
  double d0, d1;   // the segments' terms of D
  double u_max;    // end of the search variable's range (1 = unbounded Λ0)
  double one_minus_u_max = 0;  // 1 − u_max, exact

  double d() const { return configuration_b ? std::max(d0, d1) : d0 + d1; }
  // u = w/(1+w), w = Λ0 θ: maps Λ0 ∈ (0, Λmax) onto (0, u_max) for every α0, including the
  // unbounded α0 = 1 (001: "the bisection method is extended"). The search runs on
  // x = u_max − u ∈ (0, u_max], which resolves the end of the range with relative precision.
  double lambda_of(double x) const { return (u_max - x) / (one_minus_u_max + x) / turning; }
};

Problem make_problem(double alpha0, double alpha1, double theta0, double theta1, bool end_form = false) {
  const bool b = alpha0 > 1 || end_form;
  Problem p{alpha0, alpha1, theta0, theta1, b, theta0 + theta1, b ? (alpha0 - 1.0) * theta0 : (1.0 - alpha0) * theta0,
            theta1 > 0 ? std::max(0.0, 1.0 - alpha1) * theta1 : 0.0, 1.0};
  if (const double d = p.d(); d > 0) {
    const double w_max = p.turning / d;
    p.u_max = w_max / (1.0 + w_max);
    p.one_minus_u_max = 1.0 / (1.0 + w_max);
  }
  return p;
}

/// A trial curve in standard form (001 Fig. 5). Segment 0 is LaCurve(α0, Λ0) over θ ∈ [0, θ0]
/// (configuration a, α0 ≤ 1) or [−θ0, 0] (configuration b, α0 > 1). Segment 1 is drawn from the
/// joint J in its own standard form scaled by ρc: LaCurve(α1, Λ0 ρc^(1−α0)) over [0, θ1]
/// (equivalent to 001's θs … θs + θ1 on LaCurve(α1, Λ1), without the cancellation of
/// C(θs + θ1) − C(θs)).
struct StandardCurve {
  double lambda0 = 0;
  double log_rho_joint = 0;  ///< log ρc (0 in configuration b)
  Point2 start{}, joint{}, end{};
  double start_tangent = 0;  ///< θ at the start point
};

struct Trial {
  bool valid = false;  ///< false when the curve is not representable (overflow near a domain end)
  double phi = 0;      ///< angle at the start between its tangent and the chord
  StandardCurve form;
  long evaluations = 0;
  double error = 0;            ///< the positions' error estimate at the end point (standard-form units)
  Status status = Status::ok;  ///< of the positions (the first one not ok)
  std::string message;         ///< the positions' message when status is not ok
};

LaCurve segment1_curve(const Problem& p, const StandardCurve& f) {
  // Λ1' = Λ0 ρc^(1−α0) = dρ/ds at the joint (001 Eq. (3.5) expressed at ρ = ρc).
  return LaCurve(p.alpha1, f.lambda0 * std::exp((1.0 - p.alpha0) * f.log_rho_joint));
}

/// Trial positions are graded only against the loosest accept bound: the search needs their values
/// and estimates (summed into the trial's error), and the result is graded against the options'
/// accept by its summary.error.
constexpr double kTrialAccept = kMaxAccept;

template <class M>
Trial draw(const Problem& p, double lambda0, const M& method) {
  Trial t;
  StandardCurve& f = t.form;
  f.lambda0 = lambda0;
  try {
    const LaCurve c0(p.alpha0, lambda0);
    double joint_tangent = 0;
    if (!p.configuration_b) {  // 001 Fig. 5(a): segment 0 from θ = 0 to θ0
      const PositionResult r0 = position_at(c0, Parameter::theta, p.theta0, method, Form::automatic, kTrialAccept);
      t.evaluations += r0.evaluations;
      t.error += r0.error_estimate;
      t.status = r0.status;
      t.message = r0.message;
      f.joint = r0.point.position;
      f.log_rho_joint = c0.log_rho_at_theta(p.theta0);
      joint_tangent = p.theta0;
    } else {  // 001 Fig. 5(b): segment 0 from θ = −θ0 to 0, ρ = 1 at the joint
      const PositionResult r0 = position_at(c0, Parameter::theta, -p.theta0, method, Form::automatic, kTrialAccept);
      t.evaluations += r0.evaluations;
      t.error += r0.error_estimate;
      t.status = r0.status;
      t.message = r0.message;
      f.start = r0.point.position;
      f.start_tangent = -p.theta0;
    }
    f.end = f.joint;
    if (p.theta1 > 0) {
      const PositionResult r1 = position_at(segment1_curve(p, f), Parameter::theta, p.theta1, method, Form::automatic, kTrialAccept);
      t.evaluations += r1.evaluations;
      t.error += std::exp(f.log_rho_joint) * r1.error_estimate;
      if (r1.status != Status::ok && t.status == Status::ok) {
        t.status = r1.status;
        t.message = r1.message;
      }
      f.end = f.joint + std::exp(f.log_rho_joint) * std::polar(1.0, joint_tangent) * r1.point.position;
    }
    const Point2 chord = (f.end - f.start) * std::polar(1.0, -f.start_tangent);
    t.phi = std::atan2(chord.imag(), chord.real());
    t.valid = std::isfinite(t.phi) && std::isfinite(std::abs(f.end)) && std::isfinite(std::abs(f.start)) &&
              std::abs(chord) > 0;
  } catch (const InputError&) {
    t.valid = false;  // ρ, s or θ overflowed: this Λ0 is too close to the end of its range
  }
  return t;
}

/// The supremum of the trial curves' start angle over Λ0 ∈ [0, Λmax): its limit as Λ0 → Λmax,
/// the start angle being increasing in Λ0 (docs/planar_segments.md). `angle` = θ where the limit
/// curve's weight ρ(ψ) is not integrable (it concentrates at the end: 0 ≤ α < 1 at a ρ → ∞ end,
/// α1 ≥ 1 after a segment 0 whose ρc → ∞); otherwise arg of the limit curve's chord, its pieces
/// at the ends of their domains in closed-form substitutions, the others by position_at.
struct Limit {
  double angle = 0;
  double error = 0;  ///< estimate of |angle − exact| (rad)
  long evaluations = 0;
  bool ok = true;    ///< false when an integral failed: nothing is proven
};

Limit start_angle_limit(const Problem& p) {
  const GkTanhSinh method;
  Limit lim;
  struct Part {
    Point2 value;
    double error = 0;  // absolute
  };
  auto add = [&](const auto& r) {
    lim.evaluations += r.evaluations;
    if (!usable(r.status)) lim.ok = false;
  };
  // Piece ending where ρ → ∞ (α < 0, Λ = 1/((1−α)T)) or starting where ρ = 0 (α > 1,
  // Λ = 1/((α−1)T)), ρ = 1 at its other end, turning T, in the frame of its start tangent:
  // C = Tγ J (ρ = 0 start) or Tγ e^{iT} conj(J) (ρ = ∞ end), J = ∫_0^1 e^{iT v^γ} dv,
  // γ = (α−1)/α, after the substitution v^γ = ψ/T or 1 − ψ/T (v ∝ s, the s-form).
  auto end_piece = [&](double alpha, double T, bool rho_zero_start) -> Part {
    const double gamma = (alpha - 1.0) / alpha, factor = T * gamma;
    if (!std::isfinite(gamma) || !(factor > 0) || !std::isfinite(factor)) {
      lim.ok = false;
      return {};
    }
    const auto r = method.integrate([=](double v) { return std::polar(1.0, T * std::pow(v, gamma)); }, 0.0, 1.0);
    add(r);
    return {factor * (rho_zero_start ? r.value : std::polar(1.0, T) * std::conj(r.value)), factor * r.error_estimate};
  };
  auto regular = [&](const LaCurve& curve, double theta) -> Part {
    const PositionResult r = position_at(curve, Parameter::theta, theta, method, Form::automatic, kTrialAccept);
    add(r);
    return {r.point.position, r.error_estimate};
  };
  const Limit concentrated{p.turning, 0, 0, true};  // the weight concentrates at the end: φ → θ
  const bool compound = p.theta1 > 0;
  Part chord;           // of the limit curve
  double rotation = 0;  // its start tangent's angle in the frame of `chord`
  try {
    if (!p.configuration_b) {
      if (!compound) {
        if (p.alpha0 >= 0) return concentrated;
        chord = end_piece(p.alpha0, p.turning, false);
      } else if (p.alpha1 >= 1) {
        // Λ0 → Λmax makes ρc → ∞ and Λ1' → ∞: segment 0 shrinks relative to segment 1, which
        // tends to the piece from ρ = 0 (α1 > 1) or concentrates at its end (α1 = 1).
        if (p.alpha1 == 1) return concentrated;
        chord = end_piece(p.alpha1, p.theta1, true);
        rotation = -p.theta0;
      } else if (p.alpha1 >= 0) {
        return concentrated;
      } else {  // segment 1 ends at its inflection; segment 0 is regular at Λmax
        const LaCurve c0(p.alpha0, 1.0 / p.d());
        const double rho_c = std::exp(c0.log_rho_at_theta(p.theta0));
        const Part s0 = regular(c0, p.theta0), s1 = end_piece(p.alpha1, p.theta1, false);
        chord = {s0.value + rho_c * std::polar(1.0, p.theta0) * s1.value, s0.error + rho_c * s1.error};
      }
    } else {
      // The segment with the larger term of D = max(d0, d1) reaches the end of its domain.
      const bool end0 = p.d0 >= p.d1, end1 = compound && p.d1 >= p.d0;
      if (end1 && p.alpha1 >= 0) return concentrated;
      const double lambda = 1.0 / p.d();
      // In the frame of the joint tangent (ρ = 1 there); the start tangent is −θ0.
      Part s0 = end0 ? end_piece(p.alpha0, p.theta0, true) : regular(LaCurve(p.alpha0, lambda), -p.theta0);
      s0.value = end0 ? std::polar(1.0, -p.theta0) * s0.value : -s0.value;
      Part s1;
      if (compound) s1 = end1 ? end_piece(p.alpha1, p.theta1, false) : regular(LaCurve(p.alpha1, lambda), p.theta1);
      chord = {s0.value + s1.value, s0.error + s1.error};
      rotation = -p.theta0;
    }
  } catch (const InputError&) {
    lim.ok = false;
  }
  const double modulus = std::abs(chord.value);
  lim.angle = std::atan2(chord.value.imag(), chord.value.real()) - rotation;
  lim.error = chord.error / modulus;
  if (!(modulus > 0) || !std::isfinite(lim.angle) || !std::isfinite(lim.error)) lim.ok = false;
  return lim;
}

/// The first user-unit value of a solution that is not a finite double (nullptr if none). ρ at the
/// large-ρ end of the last piece may be +inf (the curve ends straight: κ underflows to 0).
const char* unrepresentable(const TriangleInfo& info, const Similarity& to_user) {
  auto finite = [](Point2 z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); };
  if (!finite(to_user.factor) || !finite(to_user.offset)) return "similarity onto the control points";
  if (info.compound && (!finite(info.joint) || !std::isfinite(info.rho_joint) || !(info.rho_joint > 0))) return "joint";
  for (size_t i = 0; i < info.pieces.size(); ++i) {
    const TrianglePiece& p = info.pieces[i];
    if (!std::isfinite(p.lambda_user)) return "lambda_user";
    if (!std::isfinite(p.rho_small) || !(p.rho_small > 0)) return "rho_small";
    const bool last = i + 1 == info.pieces.size();
    if (std::isnan(p.rho_large) || !(p.rho_large > 0) || (!last && std::isinf(p.rho_large))) return "rho_large";
  }
  return nullptr;
}

/// The solved standard-form curve placed on the control points, from a0 to a2 (001 §2: p0 → b0,
/// end → b2; reversed when the triangle was swapped). InputError when a piece has no segment
/// representation in double precision.
PlanarCurve place(const Problem& p, const StandardCurve& f, const Similarity& to_user, const Canonical& c,
                  const ControlTriangle& tri) {
  const bool b = p.configuration_b;
  std::vector<LaSegment> segments;
  segments.push_back(to_segment({LaCurve(p.alpha0, f.lambda0), Parameter::theta, b ? -p.theta0 : 0.0, b ? 0.0 : p.theta0, to_user},
                                b ? f.start : Point2{}));
  if (p.theta1 > 0) {
    const Similarity at_joint{std::exp(f.log_rho_joint) * std::polar(1.0, b ? 0.0 : p.theta0), f.joint, false};
    segments.push_back(to_segment({segment1_curve(p, f), Parameter::theta, 0.0, p.theta1, to_user.after(at_joint)}));
  }
  PlanarCurve curve(std::move(segments));
  return c.swapped ? curve.reversed(tri.a0) : curve;
}

/// The returned curve checked independently of the trial integrator (001 §2 places the end points
/// exactly, which holds only as far as the trial positions do): each segment's end by two
/// quadratures of the segment (the Gauss–Legendre kernel and gk-tanh-sinh), taken from the one
/// with the smaller estimate, with error the larger of that estimate and their difference; its
/// miss of the next segment's start or of a2, and the first start's miss of a0, over the chord
/// |a2 − a0|. A trial integrator's estimate bounds the trial curve's positions, not the end after
/// Λ0 is solved on them and the curve is scaled onto the triangle (a fixed-step rk4 end missed by
/// twice its estimate). The larger of this and the trial estimate is summary.error's position term.
void verify_placement(TriangleResult& g, const ControlTriangle& tri, const TriangleOptions& o, const char* fn) {
  Summary& sum = g.summary;
  const std::vector<LaSegment>& segs = g.curve.segments();
  const double chord = std::abs(tri.a2 - tri.a0);
  double miss = std::abs(segs.front().start() - tri.a0), estimate = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    const PositionResult kernel = position_at(segs[i], segs[i].length());
    const PositionResult adaptive = position_at(segs[i], segs[i].length(), GkTanhSinh{});
    sum.evaluations += kernel.evaluations + adaptive.evaluations;
    if (!usable(kernel.status) && !usable(adaptive.status)) {
      sum.status = Status::numerical_failure;
      sum.message = std::string(fn) + ": the end of the solution's segment " + std::to_string(i) +
                    " could not be verified: " + adaptive.message;
      g.curve = PlanarCurve();
      return;
    }
    const bool both = usable(kernel.status) && usable(adaptive.status);
    const PositionResult& r = !usable(adaptive.status) || (usable(kernel.status) && kernel.error_estimate <= adaptive.error_estimate) ? kernel : adaptive;
    estimate += both ? std::max(r.error_estimate, std::abs(kernel.point.position - adaptive.point.position)) : r.error_estimate;
    miss = std::max(miss, std::abs(r.point.position - (i + 1 < segs.size() ? segs[i + 1].start() : tri.a2)));
  }
  sum.residuals.position = miss;
  const double verified = (miss + estimate) / chord;
  if (!std::isfinite(verified)) {
    sum.status = Status::numerical_failure;
    sum.message = std::string(fn) + ": the verified end-point error of the solution is not a finite number";
    g.curve = PlanarCurve();
    return;
  }
  sum.error = std::max(*sum.error, verified);
  if (verified > o.tangent_tolerance && sum.status == Status::ok) {
    sum.status = Status::tolerance_not_met;
    sum.message = std::string(fn) + ": the verified end points miss the control points by " + format_number(verified) +
                  " of the chord, above the accuracy target tangent_tolerance = " + format_number(o.tangent_tolerance);
  }
}

template <class M>
TriangleResult solve(const ControlTriangle& tri, double alpha0, double alpha1, double r, bool compound,
                     const TriangleOptions& o, const M& method, const char* fn, bool end_form = false) {
  o.validate();
  require_finite(fn, compound ? "alpha0" : "alpha", alpha0);
  if (compound) {
    require_finite(fn, "alpha1", alpha1);
    if (!(r > 0 && r < 1)) throw_input_error(fn, "r", r, "(0, 1)");
  }
  const Canonical c = canonicalize(tri, o, fn);
  const double theta0 = compound ? r * c.turning : c.turning;
  const double theta1 = compound ? c.turning - theta0 : 0.0;
  const Problem p = make_problem(alpha0, alpha1, theta0, theta1, end_form);

  TriangleResult g;
  Summary& sum = g.summary;
  TriangleInfo& info = g.info;
  sum.integrator = std::string(M::name);
  sum.solver = std::string(to_string(o.solver));
  info.compound = compound;
  info.turning = c.sign * c.turning;
  info.segment0_at_a0 = !c.swapped;
  info.target_angle = c.target;

  // f(x) = φ(Λ0(x)) − target. At x = u_max (Λ0 = 0) the curve is the circular arc: φ = θ/2 exactly.
  // The trial with the smallest |f| is kept: the root finders return that point, so the
  // solution curve need not be drawn again. A trial whose positions failed (a status that is not
  // usable, e.g. an integrator's step budget) has no value: NaN, and the first such failure is
  // the reason given if the search ends there.
  Trial best;
  double best_x = -1, best_f = std::numeric_limits<double>::infinity();
  Status failed = Status::ok;
  std::string failed_message;
  auto mismatch = [&](double x) {
    if (sum.evaluations >= o.max_evaluations) {
      if (failed == Status::ok) {
        failed = Status::max_iterations;
        failed_message = "the evaluation budget (max_evaluations = " + std::to_string(o.max_evaluations) +
                         ") is spent after " + std::to_string(sum.constructions) + " trial curves";
      }
      return std::numeric_limits<double>::quiet_NaN();
    }
    Trial t = draw(p, p.lambda_of(x), method);
    ++sum.constructions;
    sum.evaluations += t.evaluations;
    if (!usable(t.status) && failed == Status::ok) {
      failed = t.status;
      failed_message = "the positions of the trial curve at Lambda0 = " + format_number(p.lambda_of(x)) + " failed (" +
                       std::string(to_string(t.status)) + (t.message.empty() ? "" : ": " + t.message) + ")";
    }
    if (!t.valid || !usable(t.status)) return std::numeric_limits<double>::quiet_NaN();
    const double f = t.phi - c.target;
    if (std::abs(f) < best_f) {
      best_f = std::abs(f);
      best_x = x;
      best = std::move(t);
    }
    return f;
  };
  const double f0 = 0.5 * c.turning - c.target;  // ≤ 0 after the swap
  double x_root = p.u_max;
  if (std::abs(f0) > o.root.f_atol) {
    // Grow the bracket toward the end of the range (x → 0) until the sign changes (001:
    // "extended" bisection): probes u_max·0.5·r^k. In x the bracket is [lo, hi] = [where f ≥ 0,
    // where f < 0]. A trial without a value is not representable (or not integrable) any closer
    // to the end of the range: the search ends there.
    // Configuration (a) resolves Λ0 to ~1e-16 relative: probes down to 0.5·10^−12 of the range;
    // the end form resolves Λ' over the whole double range: probes a factor 10^−4 apart.
    BracketSearchOptions bo;
    bo.center = 0.0;
    bo.step = 0.5;
    bo.growth = end_form ? 1e-4 : 0.1;
    bo.max_probes = o.max_bracket_probes;
    bo.stop_at_failure = true;
    const BracketSearchResult s = search_bracket(mismatch, p.u_max, bo, f0);
    info.bracket_probes = s.probes;
    const bool found = s.found, unrepresentable_trial = s.stopped_at_failure;
    Bracket b = s.bracket;
    if (!found) b.hi = unrepresentable_trial ? s.previous_x : s.last_x;  // the last probe with f < 0
    if (!found) {
      // φ increases with Λ0: no curve iff the target is at or above φ's limit at the end of the
      // range (the same limit in either form of the curves).
      const Limit lim = start_angle_limit(p.configuration_b && p.alpha0 <= 1 ? make_problem(alpha0, alpha1, theta0, theta1) : p);
      sum.evaluations += lim.evaluations;
      if (lim.ok) info.start_angle_limit = lim.angle;
      const std::string range = "(0, " + (p.u_max < 1 ? format_number(p.lambda_of(0.0)) : std::string("inf")) + ")";
      if (lim.ok && c.target >= lim.angle + 1e-12 + lim.error) {
        sum.status = Status::no_solution;
        sum.message = std::string(fn) + ": outside the drawable region: the start angle of the curves increases with " +
                      "Lambda0 over " + range + " toward " + format_number(lim.angle) +
                      " rad, and the control triangle needs " + format_number(c.target) + " rad";
        return g;
      }
      // Not proven outside: a trial curve's positions failed (that status), or the search stalled.
      const bool positions_failed = unrepresentable_trial && failed != Status::ok;
      const std::string limit_text =
          lim.ok ? "the start angle tends to " + format_number(lim.angle) + " rad and the control triangle needs " +
                       format_number(c.target) + " rad, so a curve exists unless the two are equal within the limit's " +
                       "accuracy " + format_number(1e-12 + lim.error) + " rad"
                 : std::string("the limit of the start angle could not be computed");
      sum.status = positions_failed ? failed : Status::not_converged;
      if (positions_failed) {
        sum.message = std::string(fn) + ": " + failed_message + " while looking for a sign change of the start-angle " +
                      "mismatch; " + limit_text;
      } else {
        sum.message = std::string(fn) + ": no sign change of the start-angle mismatch in " +
                      std::to_string(info.bracket_probes) + " probes up to Lambda0 = " + format_number(p.lambda_of(b.hi)) +
                      " of " + range +
                      (unrepresentable_trial ? " (the next trial curve is not representable in double precision)" : "") +
                      "; " + limit_text + (lim.ok ? " (Lambda0 closer to the end of the range than the probes resolve)" : "");
      }
      return g;
    }
    const RootResult root = find_root(o.solver, mismatch, b, o.root);
    sum.iterations = root.iterations;
    info.residual = root.residual;
    if (!usable(root.status) || !std::isfinite(root.root)) {
      sum.status = root.status == Status::ok ? Status::numerical_failure : root.status;
      sum.message = std::string(fn) + ": " + root.message;
      if (failed != Status::ok) {  // the root finder met a trial without positions: that failure
        sum.status = failed;
        sum.message = std::string(fn) + ": " + failed_message + "; " + root.message;
      }
      return g;
    }
    sum.status = root.status;
    sum.message = root.message;
    x_root = root.root;
  } else {
    info.residual = f0;
  }

  Trial t;
  if (best_x == x_root && best.valid) {
    t = std::move(best);
  } else {
    t = draw(p, p.lambda_of(x_root), method);
    ++sum.constructions;
    sum.evaluations += t.evaluations;
  }
  if (!t.valid) {
    sum.status = Status::numerical_failure;
    sum.message = std::string(fn) + ": the solution curve is not representable in double precision";
    return g;
  }
  if (!usable(t.status)) {
    sum.status = t.status;
    sum.message = std::string(fn) + ": the positions of the solution curve failed" + (t.message.empty() ? "" : ": " + t.message);
    return g;
  }
  if (t.status != Status::ok && sum.status == Status::ok) {
    sum.status = Status::tolerance_not_met;
    sum.message = std::string(fn) + ": position quadrature did not meet its tolerance";
  }

  // Similarity onto the canonical triangle (001 §2: p0 → b0, end → b2).
  const StandardCurve& f = t.form;
  auto m = [&](Point2 z) { return c.mirrored ? std::conj(z) : z; };
  const Point2 a_scaled = c.chord / (m(f.end) - m(f.start));  // onto the triangle divided by its scale
  Similarity to_user{c.scale * a_scaled, {}, c.mirrored};
  to_user.offset = c.origin - to_user.factor * m(f.start);
  const double k = std::abs(to_user.factor);

  const LaCurve c0(alpha0, f.lambda0);
  const double rho_c = std::exp(f.log_rho_joint);
  TrianglePiece s0;
  s0.alpha = alpha0;
  // Λ0 of 001's standard form (ρ = 1 at the start) when the curve was drawn in the end form:
  // Λ' ρ_start^(1−α0), ρ_start ≤ 1 that form's start radius.
  s0.lambda = end_form ? f.lambda0 * std::exp((1.0 - alpha0) * c0.log_rho_at_theta(-theta0)) : f.lambda0;
  s0.lambda_user = f.lambda0 * std::pow(k, alpha0 - 1.0);
  s0.turning = theta0;
  s0.rho_small = k * (p.configuration_b ? c0.rho_at_theta(-theta0) : 1.0);
  s0.rho_large = k * rho_c;
  info.pieces.push_back(s0);
  if (compound) {
    const LaCurve c1 = segment1_curve(p, f);
    TrianglePiece s1;
    s1.alpha = alpha1;
    s1.lambda = f.lambda0 * std::exp((alpha1 - alpha0) * f.log_rho_joint);  // 001 Eq. (3.5)
    s1.lambda_user = s1.lambda * std::pow(k, alpha1 - 1.0);
    s1.turning = theta1;
    s1.rho_small = k * rho_c;
    s1.rho_large = k * (rho_c * c1.rho_at_theta(theta1));
    info.pieces.push_back(s1);
    info.joint = to_user(f.joint);
    info.rho_joint = k * rho_c;
  }

  // Tangent check in user coordinates: mapped end tangents against the control legs.
  auto mapped_direction = [&](double theta) { return a_scaled * m(std::polar(1.0, theta)); };
  const double end_tangent = p.configuration_b ? theta1 : theta0 + theta1;
  const double e0 = std::abs(std::arg(mapped_direction(f.start_tangent) / c.leg0));
  const double e1 = std::abs(std::arg(mapped_direction(end_tangent) / c.leg1));
  sum.residuals.angle = std::max(e0, e1);
  // Achieved error (common/accuracy.hpp): the end points are placed exactly, so the positions'
  // error estimate over the standard-form chord is the curve's error relative to |a2 − a0|.
  const double error_relative = t.error / std::abs(f.end - f.start);
  if (const double e = k * t.error; std::isfinite(e)) sum.error_estimate = e;
  sum.error = std::isfinite(error_relative) ? std::max(*sum.residuals.angle, error_relative)
                                            : std::numeric_limits<double>::quiet_NaN();
  sum.accept = o.accept;
  // The accuracy target is tangent_tolerance, on the end tangents and on the positions' error
  // relative to the chord (a fixed-step integrator reports ok positions whatever its step).
  if (!(*sum.residuals.angle <= o.tangent_tolerance) && usable(sum.status)) {
    sum.status = Status::tolerance_not_met;
    sum.message = std::string(fn) + ": end tangents miss the control legs by " + format_number(*sum.residuals.angle) + " rad";
  } else if (!(error_relative <= o.tangent_tolerance) && usable(sum.status)) {
    sum.status = Status::tolerance_not_met;
    sum.message = std::string(fn) + ": the positions' error estimate is " + format_number(error_relative) +
                  " of the chord, above the accuracy target tangent_tolerance = " + format_number(o.tangent_tolerance);
  }
  if (!usable(sum.status)) return g;
  // The standard-form solution is finite; its user-unit image may not be (Λ_user = Λ k^(α−1),
  // ρ = k ρ_std and κ = 1/ρ over- or underflow for extreme α or scale). Such a curve exists
  // but has no double-precision description: report it instead of returning inf.
  const char* bad = unrepresentable(info, to_user);
  std::string why;
  if (!bad) {
    try {
      g.curve = place(p, f, to_user, c, tri);
      if (!std::isfinite(g.curve.kappa_at(0)) || !std::isfinite(g.curve.kappa_at(g.curve.length()))) bad = "end curvature";
    } catch (const InputError& e) {
      bad = "segment";
      why = std::string(": ") + e.what();
    }
  }
  if (bad) {
    g.curve = PlanarCurve();
    sum.status = Status::numerical_failure;
    sum.message = std::string(fn) + ": the solution is not representable in user units (" + bad +
                  " is not a finite double; control triangle scale max |a_i - a0| = " + format_number(c.scale) + ")" + why;
  } else {
    verify_placement(g, tri, o, fn);
  }
  std::string message = std::move(sum.message);
  g.conclude(sum.status, std::move(message));  // inaccurate when summary.error exceeds accept
  return g;
}

/// Runs the construction with the options' integrator and records the wall time of the call.
template <class Run>
TriangleResult timed(const TriangleOptions& o, Run run) {
  const auto start = std::chrono::steady_clock::now();
  TriangleResult g = std::visit(run, o.integrator);
  g.summary.seconds = seconds_since(start);
  return g;
}

}  // namespace

void TriangleOptions::validate() const {
  std::visit([](const auto& m) { m.validate(); }, integrator);
  root.validate();
  if (!(min_turning > 0 && min_turning < 0.1)) throw_input_error("TriangleOptions", "min_turning", min_turning, "(0, 0.1)");
  if (max_bracket_probes < 1 || max_bracket_probes > 30)
    throw_input_error("TriangleOptions", "max_bracket_probes", max_bracket_probes, "[1, 30]");
  if (max_evaluations < 1 || max_evaluations > 1'000'000'000'000)
    throw_input_error("TriangleOptions", "max_evaluations", static_cast<double>(max_evaluations), "[1, 1e12]");
  if (!(tangent_tolerance > 0)) throw_input_error("TriangleOptions", "tangent_tolerance", tangent_tolerance, "(0, inf)");
  validate_accept("TriangleOptions", accept);
}

TriangleResult solve_g1(const ControlTriangle& t, double alpha, const TriangleOptions& o) {
  return timed(o, [&](const auto& m) {
    TriangleResult g = solve(t, alpha, alpha, 1.0, false, o, m, "solve_g1");
    // Configuration (a) resolves Λ0 near the end of its range only to ~1e-16 absolute (Problem):
    // a search that did not end ok there (tangents missed, no sign change resolved) is run again
    // in the end form, whose result is taken when it is ok. The work of both is counted.
    const Status st = g.summary.status;
    if (alpha < 1 && (st == Status::tolerance_not_met || st == Status::not_converged)) {
      TriangleResult e = solve(t, alpha, alpha, 1.0, false, o, m, "solve_g1", true);
      TriangleResult& kept = e.summary.status == Status::ok ? e : g;
      const TriangleResult& other = e.summary.status == Status::ok ? g : e;
      kept.summary.iterations += other.summary.iterations;
      kept.summary.evaluations += other.summary.evaluations;
      kept.summary.constructions += other.summary.constructions;
      kept.info.bracket_probes += other.info.bracket_probes;
      return std::move(kept);
    }
    return g;
  });
}

TriangleResult solve_compound(const ControlTriangle& t, double alpha0, double alpha1, double r, const TriangleOptions& o) {
  return timed(o, [&](const auto& m) { return solve(t, alpha0, alpha1, r, true, o, m, "solve_compound"); });
}

}  // namespace lac
