// Similar-triangle search for monotonic- and compound-rhythm LA segments (001 §2–4,
// MATH.md §2). See g1_segment.hpp for the conventions.
#include "lac/constructions/triangle_g1.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lac/common/error.hpp"

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

Canonical canonicalize(const ControlTriangle& t, const SegmentOptions& o, const char* fn) {
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
struct Problem {
  double alpha0, alpha1, theta0, theta1;
  bool configuration_b;
  double turning;  // θ0 + θ1
  double u_max;    // end of the search variable's range (1 = unbounded Λ0)

  // u = w/(1+w), w = Λ0 θ: maps Λ0 ∈ (0, Λmax) onto (0, u_max) for every α0, including the
  // unbounded α0 = 1 (001: "the bisection method is extended").
  double lambda_of(double u) const { return u / (1.0 - u) / turning; }
};

/// Λ0 < 1/D keeps both segments inside their θ domains (MATH.md §1 table): segment 0 needs
/// (1−α0)Λ0θ0 < 1 (configuration a) or (α0−1)Λ0θ0 < 1 (b); segment 1, when α1 < 1, needs
/// (1−α1)Λ1'θ1 < 1 with Λ1' = Λ0 ρc^(1−α0), i.e. (1−α0)Λ0θ0 + (1−α1)Λ0θ1 < 1 in configuration
/// a (ρc^(α0−1) = 1 − (1−α0)Λ0θ0) and (1−α1)Λ0θ1 < 1 in b (ρc = 1). This is 001 §4's
/// "search a smaller Λ0" rule in closed form.
Problem make_problem(double alpha0, double alpha1, double theta0, double theta1) {
  Problem p{alpha0, alpha1, theta0, theta1, alpha0 > 1, theta0 + theta1, 1.0};
  const double seg1 = theta1 > 0 ? std::max(0.0, 1.0 - alpha1) * theta1 : 0.0;
  const double d = p.configuration_b ? std::max((alpha0 - 1.0) * theta0, seg1) : (1.0 - alpha0) * theta0 + seg1;
  if (d > 0) {
    const double w_max = p.turning / d;
    p.u_max = w_max / (1.0 + w_max);
  }
  return p;
}

struct Trial {
  bool valid = false;  ///< false when the curve is not representable (overflow near a domain end)
  double phi = 0;      ///< angle at the start between its tangent and the chord
  StandardForm form;
  long evaluations = 0;
  Status status = Status::ok;
};

template <class M>
Trial draw(const Problem& p, double lambda0, const M& method) {
  Trial t;
  StandardForm& f = t.form;
  f.alpha0 = p.alpha0;
  f.alpha1 = p.alpha1;
  f.theta0 = p.theta0;
  f.theta1 = p.theta1;
  f.configuration_b = p.configuration_b;
  f.lambda0 = lambda0;
  try {
    const LaCurve c0(p.alpha0, lambda0);
    double joint_tangent = 0;
    if (!p.configuration_b) {  // 001 Fig. 5(a): segment 0 from θ = 0 to θ0
      const PositionResult r0 = position_at(c0, Parameter::theta, p.theta0, method);
      t.evaluations += r0.evaluations;
      t.status = r0.status;
      f.start = 0;
      f.start_tangent = 0;
      f.joint = r0.point.position;
      f.log_rho_joint = c0.log_rho_at_theta(p.theta0);
      joint_tangent = p.theta0;
    } else {  // 001 Fig. 5(b): segment 0 from θ = −θ0 to 0, ρ = 1 at the joint
      const PositionResult r0 = position_at(c0, Parameter::theta, -p.theta0, method);
      t.evaluations += r0.evaluations;
      t.status = r0.status;
      f.start = r0.point.position;
      f.start_tangent = -p.theta0;
      f.joint = 0;
      f.log_rho_joint = 0;
    }
    f.end = f.joint;
    if (p.theta1 > 0) {
      // Segment 1 in its own standard form at the joint, scaled by ρc: Λ1' = Λ0 ρc^(1−α0)
      // = dρ/ds at the joint (001 Eq. (3.5) expressed at ρ = ρc).
      const double rho_c = std::exp(f.log_rho_joint);
      const LaCurve c1(p.alpha1, lambda0 * std::exp((1.0 - p.alpha0) * f.log_rho_joint));
      const PositionResult r1 = position_at(c1, Parameter::theta, p.theta1, method);
      t.evaluations += r1.evaluations;
      if (r1.status != Status::ok && t.status == Status::ok) t.status = r1.status;
      f.end = f.joint + rho_c * std::polar(1.0, joint_tangent) * r1.point.position;
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

/// The first user-unit result of `g` that is not a finite double (nullptr if none). ρ at the
/// large-ρ end of the last piece may be +inf (the curve ends straight: κ underflows to 0).
const char* unrepresentable(const G1Segment& g) {
  auto finite = [](Point2 z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); };
  if (!std::isfinite(g.length)) return "length";
  if (!std::isfinite(g.kappa0) || !std::isfinite(g.kappa1)) return "end curvature";
  if (!finite(g.form.scale_rotation) || !finite(g.form.offset)) return "similarity onto the control points";
  if (g.compound && (!finite(g.joint) || !std::isfinite(g.rho_joint) || !(g.rho_joint > 0))) return "joint";
  for (size_t i = 0; i < g.pieces.size(); ++i) {
    const SegmentPiece& p = g.pieces[i];
    if (!std::isfinite(p.lambda_user)) return "lambda_user";
    if (!std::isfinite(p.length)) return "piece length";
    if (!std::isfinite(p.rho_small) || !(p.rho_small > 0)) return "rho_small";
    const bool last = i + 1 == g.pieces.size();
    if (std::isnan(p.rho_large) || !(p.rho_large > 0) || (!last && std::isinf(p.rho_large))) return "rho_large";
  }
  return nullptr;
}

template <class M>
G1Segment solve(const ControlTriangle& tri, double alpha0, double alpha1, double r, bool compound,
                const SegmentOptions& o, const M& method, const char* fn) {
  o.validate();
  method.validate();
  require_finite(fn, compound ? "alpha0" : "alpha", alpha0);
  if (compound) {
    require_finite(fn, "alpha1", alpha1);
    if (!(r > 0 && r < 1)) throw_input_error(fn, "r", r, "(0, 1)");
  }
  const Canonical c = canonicalize(tri, o, fn);
  const double theta0 = compound ? r * c.turning : c.turning;
  const double theta1 = compound ? c.turning - theta0 : 0.0;
  const Problem p = make_problem(alpha0, alpha1, theta0, theta1);

  G1Segment g;
  g.compound = compound;
  g.turning = c.sign * c.turning;
  g.segment0_at_a0 = !c.swapped;

  // f(u) = φ(Λ0(u)) − target. At u = 0 the curve is the circular arc: φ = θ/2 exactly.
  // The trial with the smallest |f| is kept: the root finders return that point, so the
  // solution curve need not be drawn again.
  Trial best;
  double best_u = -1, best_f = std::numeric_limits<double>::infinity();
  auto mismatch = [&](double u) {
    Trial t = draw(p, p.lambda_of(u), method);
    ++g.trials;
    g.evaluations += t.evaluations;
    if (!t.valid) return std::numeric_limits<double>::quiet_NaN();
    const double f = t.phi - c.target;
    if (std::abs(f) < best_f) {
      best_f = std::abs(f);
      best_u = u;
      best = std::move(t);
    }
    return f;
  };
  const double f0 = 0.5 * c.turning - c.target;  // ≤ 0 after the swap
  double u_root = 0;
  if (std::abs(f0) > o.root.f_atol) {
    // Grow the bracket toward u_max until the sign changes (001: "extended" bisection).
    Bracket b{0.0, 0.0, f0, 0.0};
    bool found = false;
    double delta = 0.5;
    for (int k = 0; k < o.max_bracket_probes; ++k, delta *= 0.1) {
      const double u = p.u_max * (1.0 - delta);
      const double fu = mismatch(u);
      ++g.bracket_probes;
      if (!std::isfinite(fu)) break;  // not representable any closer to the end of the range
      if (fu >= 0) {
        b.hi = u;
        b.f_hi = fu;
        found = true;
        break;
      }
      b.lo = u;
      b.f_lo = fu;
    }
    if (!found) {
      g.status = Status::no_solution;
      g.message = std::string(fn) + ": outside the drawable region (or closer to the end of the Lambda0 range than double " +
                  "precision resolves): the start angle of the trial curves stays below the control triangle's (" +
                  format_number(c.target) + " rad) up to Lambda0 = " +
                  format_number(p.lambda_of(b.lo)) + " (range (0, " +
                  (p.u_max < 1 ? format_number(p.lambda_of(p.u_max)) : std::string("inf")) + "))";
      return g;
    }
    const RootResult root = find_root(o.solver, mismatch, b, o.root);
    g.iterations = root.iterations;
    g.residual = root.residual;
    if (!usable(root.status) || !std::isfinite(root.root)) {
      g.status = root.status == Status::ok ? Status::numerical_failure : root.status;
      g.message = std::string(fn) + ": " + root.message;
      return g;
    }
    g.status = root.status;
    g.message = root.message;
    u_root = root.root;
  } else {
    g.residual = f0;
  }

  Trial t;
  if (best_u == u_root && best.valid) {
    t = std::move(best);
  } else {
    t = draw(p, p.lambda_of(u_root), method);
    ++g.trials;
    g.evaluations += t.evaluations;
  }
  if (!t.valid) {
    g.status = Status::numerical_failure;
    g.message = std::string(fn) + ": the solution curve is not representable in double precision";
    return g;
  }
  if (t.status != Status::ok && g.status == Status::ok) {
    g.status = Status::tolerance_not_met;
    g.message = std::string(fn) + ": position quadrature did not meet its tolerance";
  }

  // Similarity onto the canonical triangle (001 §2: p0 → b0, end → b2).
  StandardForm& f = t.form;
  f.mirrored = c.mirrored;
  f.swapped = c.swapped;
  auto m = [&](Point2 z) { return c.mirrored ? std::conj(z) : z; };
  const Point2 a_scaled = c.chord / (m(f.end) - m(f.start));  // onto the triangle divided by its scale
  f.scale_rotation = c.scale * a_scaled;
  f.offset = c.origin - f.scale_rotation * m(f.start);
  const double k = std::abs(f.scale_rotation);

  const LaCurve c0(alpha0, f.lambda0);
  const double rho_c = std::exp(f.log_rho_joint);
  SegmentPiece s0;
  s0.alpha = alpha0;
  s0.lambda = f.lambda0;
  s0.lambda_user = f.lambda0 * std::pow(k, alpha0 - 1.0);
  s0.turning = theta0;
  s0.length = k * (f.configuration_b ? -c0.s_at_theta(-theta0) : c0.s_at_theta(theta0));
  s0.rho_small = k * (f.configuration_b ? c0.rho_at_theta(-theta0) : 1.0);
  s0.rho_large = k * rho_c;
  g.pieces.push_back(s0);
  double rho_end = rho_c;
  if (compound) {
    const LaCurve c1(alpha1, f.lambda0 * std::exp((1.0 - alpha0) * f.log_rho_joint));
    SegmentPiece s1;
    s1.alpha = alpha1;
    s1.lambda = f.lambda0 * std::exp((alpha1 - alpha0) * f.log_rho_joint);  // 001 Eq. (3.5)
    s1.lambda_user = s1.lambda * std::pow(k, alpha1 - 1.0);
    s1.turning = theta1;
    s1.length = k * rho_c * c1.s_at_theta(theta1);
    s1.rho_small = k * rho_c;
    rho_end = rho_c * c1.rho_at_theta(theta1);
    s1.rho_large = k * rho_end;
    g.pieces.push_back(s1);
    g.joint = f.scale_rotation * m(f.joint) + f.offset;
    g.rho_joint = k * rho_c;
  }
  for (const auto& piece : g.pieces) g.length += piece.length;
  const double kappa_b0 = c.sign / g.pieces.front().rho_small;  // the curve turns one way throughout
  const double kappa_b2 = c.sign / (k * rho_end);
  g.kappa0 = c.swapped ? kappa_b2 : kappa_b0;
  g.kappa1 = c.swapped ? kappa_b0 : kappa_b2;

  // Tangent check in user coordinates: mapped end tangents against the control legs.
  auto mapped_direction = [&](double theta) { return a_scaled * m(std::polar(1.0, theta)); };
  const double end_tangent = f.configuration_b ? theta1 : theta0 + theta1;
  const double e0 = std::abs(std::arg(mapped_direction(f.start_tangent) / c.leg0));
  const double e1 = std::abs(std::arg(mapped_direction(end_tangent) / c.leg1));
  g.tangent_error = std::max(e0, e1);
  if (!(g.tangent_error <= o.tangent_tolerance) && usable(g.status)) {
    g.status = Status::tolerance_not_met;
    g.message = std::string(fn) + ": end tangents miss the control legs by " + format_number(g.tangent_error) + " rad";
  }
  g.form = f;
  // The standard-form solution is finite; its user-unit image may not be (Λ_user = Λ k^(α−1),
  // ρ = k ρ_std and κ = 1/ρ over- or underflow for extreme α or scale). Such a curve exists
  // but has no double-precision description: report it instead of returning inf.
  if (usable(g.status)) {
    const char* bad = unrepresentable(g);
    if (bad) {
      g.status = Status::numerical_failure;
      g.message = std::string(fn) + ": the solution is not representable in user units (" + bad +
                  " is not a finite double; control triangle scale max |a_i - a0| = " + format_number(c.scale) + ")";
    }
  }
  return g;
}

template <class M>
std::vector<SegmentSample> sample(const G1Segment& g, int n, const M& method) {
  if (!usable(g.status) || g.pieces.empty()) throw_input_error("sample_segment", "segment", "has no usable curve (status " + std::string(to_string(g.status)) + ")");
  if (n < 2) throw_input_error("sample_segment", "n", n, "[2, inf)");
  const StandardForm& f = g.form;
  const double k = std::abs(f.scale_rotation);
  const double rho_c = std::exp(f.log_rho_joint);
  auto m = [&](Point2 z) { return f.mirrored ? std::conj(z) : z; };
  const double rot = std::arg(f.scale_rotation);
  const double orientation = f.mirrored ? -1.0 : 1.0;
  const double sign = g.turning > 0 ? 1.0 : -1.0;

  std::vector<SegmentSample> out;  // canonical order b0 → b2, s from b0
  const int pieces = static_cast<int>(g.pieces.size());
  int n0 = n;
  if (pieces == 2) n0 = std::clamp(static_cast<int>(std::lround(n * g.pieces[0].length / g.length)), 2, std::max(2, n - 1));
  const int n1 = pieces == 2 ? std::max(2, n - n0 + 1) : 0;

  const LaCurve c0(f.alpha0, f.lambda0);
  const double s_a = f.configuration_b ? c0.s_at_theta(-f.theta0) : 0.0;
  const double s_b = f.configuration_b ? 0.0 : c0.s_at_theta(f.theta0);
  // Uniform in s; when an end lies at the edge of the s domain in double precision (ρ → 0 at
  // the start of configuration b, ρ → ∞ at an inflection), uniform in θ instead.
  auto piece_points = [&](const LaCurve& curve, double s_lo, double s_hi, double th_lo, double th_hi, int count) {
    try {
      return polyline(curve, Parameter::s, s_lo, s_hi, count, method);
    } catch (const InputError&) {
      return polyline(curve, Parameter::theta, th_lo, th_hi, count, method);
    }
  };
  const double th_a = f.configuration_b ? -f.theta0 : 0.0, th_b = f.configuration_b ? 0.0 : f.theta0;
  for (const auto& r : piece_points(c0, s_a, s_b, th_a, th_b, n0)) {
    SegmentSample q;
    q.position = f.scale_rotation * m(r.point.position) + f.offset;
    q.s = k * (r.point.s - s_a);
    q.theta = rot + orientation * r.point.theta;
    q.kappa = sign / (k * r.point.rho);
    q.piece = 0;
    out.push_back(q);
  }
  if (pieces == 2) {
    const LaCurve c1(f.alpha1, f.lambda0 * std::exp((1.0 - f.alpha0) * f.log_rho_joint));
    const double joint_tangent = f.configuration_b ? 0.0 : f.theta0;
    const double s_joint = out.back().s;
    const Point2 turn = rho_c * std::polar(1.0, joint_tangent);
    const auto pts = piece_points(c1, 0.0, c1.s_at_theta(f.theta1), 0.0, f.theta1, n1);
    for (size_t j = 1; j < pts.size(); ++j) {
      const auto& r = pts[j];
      SegmentSample q;
      q.position = f.scale_rotation * m(f.joint + turn * r.point.position) + f.offset;
      q.s = s_joint + k * rho_c * r.point.s;
      q.theta = rot + orientation * (joint_tangent + r.point.theta);
      q.kappa = sign / (k * rho_c * r.point.rho);
      q.piece = 1;
      out.push_back(q);
    }
  }
  if (f.swapped) {  // user order a0 → a2 is the reverse of b0 → b2
    std::reverse(out.begin(), out.end());
    const double total = out.front().s;
    for (auto& q : out) {
      q.s = total - q.s;
      q.theta += kPi;
    }
  }
  return out;
}

}  // namespace

GkTanhSinh default_segment_integrator() { return GkTanhSinh{}; }

void SegmentOptions::validate() const {
  root.validate();
  if (!(min_turning > 0 && min_turning < 0.1)) throw_input_error("SegmentOptions", "min_turning", min_turning, "(0, 0.1)");
  if (max_bracket_probes < 1 || max_bracket_probes > 30)
    throw_input_error("SegmentOptions", "max_bracket_probes", max_bracket_probes, "[1, 30]");
  if (!(tangent_tolerance > 0)) throw_input_error("SegmentOptions", "tangent_tolerance", tangent_tolerance, "(0, inf)");
}

G1Segment solve_g1(const ControlTriangle& t, double alpha, const SegmentOptions& o) {
  return solve(t, alpha, alpha, 1.0, false, o, default_segment_integrator(), "solve_g1");
}

G1Segment solve_g1(const ControlTriangle& t, double alpha, const SegmentOptions& o, const AnyQuadrature& method) {
  return std::visit([&](const auto& mm) { return solve(t, alpha, alpha, 1.0, false, o, mm, "solve_g1"); }, method);
}

G1Segment solve_compound(const ControlTriangle& t, double alpha0, double alpha1, double r, const SegmentOptions& o) {
  return solve(t, alpha0, alpha1, r, true, o, default_segment_integrator(), "solve_compound");
}

G1Segment solve_compound(const ControlTriangle& t, double alpha0, double alpha1, double r, const SegmentOptions& o,
                         const AnyQuadrature& method) {
  return std::visit([&](const auto& mm) { return solve(t, alpha0, alpha1, r, true, o, mm, "solve_compound"); }, method);
}

std::vector<SegmentSample> sample_segment(const G1Segment& g, int n) { return sample(g, n, default_segment_integrator()); }

std::vector<SegmentSample> sample_segment(const G1Segment& g, int n, const AnyQuadrature& method) {
  return std::visit([&](const auto& mm) { return sample(g, n, mm); }, method);
}

}  // namespace lac
