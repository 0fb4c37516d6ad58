#include "lac/constructions/space_segment.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/curves/space/certified_frenet.hpp"
#include "lac/solvers/nonlinear.hpp"

namespace lac {
namespace {

using Vec2 = Eigen::Vector2d;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Box of the unknowns x = (log Λ0, log ν0): outside it a trial counts as undefined. It keeps
// trial curves away from ν → 0 (unbounded torsion, unbounded step counts) and overflow.
constexpr double kLogLambdaMin = -25, kLogLambdaMax = 10;
constexpr double kLogNuMin = -10, kLogNuMax = 15;

// The problem in the local frame of 000 §2.2 (P0 at 0, v0 = +x, P1 in the xy plane, y > 0).
struct Problem {
  SpaceEndpoints ends;            // as given
  Eigen::Matrix3d local_to_user;  // columns e1 = v̂0, e2, e3 = e1 × e2
  Vec3 origin;
  double distance = 0;            // |P1 − P0|
  double theta = 0;               // cone half-angle
  Vec3 target;                    // v̂1 in local coordinates (z negated when mirrored)
  Vec3 u1, u2;                    // orthonormal basis ⊥ target (for the stereographic residual)
  bool mirror = false;
  bool compound = false;
  CompoundSpaceSpec spec;         // G1 uses alpha0, beta0, omega0
  const SpaceSegmentOptions* opt = nullptr;
};

// One construction for given (Λ0, ν0). Undefined: `status` and `why` say why.
struct Trial {
  bool defined = false;
  Status status = Status::no_solution;
  std::string why;
  std::optional<SpacePiece> piece0, piece1;
  Frame3 joint, end;       // standard form
  double phi = 0;          // rotation about x that brings the end point into the xy plane
  double scale = 0;
  Vec3 end_tangent_local;  // after the rotation (local coordinates)
  long ode_evaluations = 0;
};

void check_vec(const char* who, const char* name, const Vec3& v) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(v[i])) throw_input_error(who, name, v[i], "(finite coordinates)");
}

Problem make_problem(const char* who, const SpaceEndpoints& e, bool mirror) {
  check_vec(who, "p0", e.p0);
  check_vec(who, "v0", e.v0);
  check_vec(who, "p1", e.p1);
  check_vec(who, "v1", e.v1);
  if (!(e.v0.norm() > 0)) throw_input_error(who, "v0", "must be a nonzero vector");
  if (!(e.v1.norm() > 0)) throw_input_error(who, "v1", "must be a nonzero vector");
  const Vec3 chord = e.p1 - e.p0;
  const double scale_ref = std::max({e.p0.cwiseAbs().maxCoeff(), e.p1.cwiseAbs().maxCoeff(), 1e-300});
  if (!(chord.norm() > 1e-12 * scale_ref)) throw_input_error(who, "p1", "must differ from p0");
  Problem p;
  p.ends = e;
  const Vec3 e1 = e.v0.normalized();
  p.theta = std::atan2(e1.cross(chord).norm(), e1.dot(chord));
  constexpr double kMinAngle = 1e-8;
  if (!(p.theta > kMinAngle && p.theta < M_PI - kMinAngle))
    throw_input_error(who, "v0", p.theta,
                      "angle(v0, p1 - p0) in (1e-8, pi - 1e-8): v0 parallel to p1 - p0 makes the cone degenerate");
  const Vec3 e2 = (chord - chord.dot(e1) * e1).normalized();
  p.local_to_user.col(0) = e1;
  p.local_to_user.col(1) = e2;
  p.local_to_user.col(2) = e1.cross(e2);
  p.origin = e.p0;
  p.distance = chord.norm();
  p.mirror = mirror;
  p.target = p.local_to_user.transpose() * e.v1.normalized();
  if (mirror) p.target.z() = -p.target.z();
  // any orthonormal pair ⊥ target
  const Vec3 helper = std::abs(p.target.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  p.u1 = (helper - helper.dot(p.target) * p.target).normalized();
  p.u2 = p.target.cross(p.u1);
  return p;
}

void validate_spec(const char* who, const CompoundSpaceSpec& s, bool compound) {
  require_finite(who, compound ? "alpha0" : "alpha", s.alpha0);
  require_finite(who, compound ? "beta0" : "beta", s.beta0);
  if (!(s.omega0 >= 0) || !std::isfinite(s.omega0)) throw_input_error(who, compound ? "omega0" : "omega", s.omega0, "[0, inf)");
  if (s.type != TorsionType::type1 && s.type != TorsionType::type2)
    throw_input_error(who, "type", static_cast<double>(s.type), "{1, 2}");
  if (!compound) return;
  require_finite(who, "alpha1", s.alpha1);
  require_finite(who, "beta1", s.beta1);
  if (!(s.r_theta > 0 && s.r_theta < 1)) throw_input_error(who, "r_theta", s.r_theta, "(0, 1)");
}

CompoundSpaceSpec as_compound(const G1SpaceSpec& g) {
  CompoundSpaceSpec c;
  c.alpha0 = c.alpha1 = g.alpha;
  c.beta0 = c.beta1 = g.beta;
  c.omega0 = g.omega;
  c.type = g.type;
  return c;
}

// Largest s a trial may integrate to from s0: inside the s range (with a margin), and within the
// remaining turning and torsion-turning budgets. ≤ s0 means no room. `cap`: the option that
// binds, or nullptr when the end of the s range does (the curve itself ends there).
struct Limit {
  double s = kInf;
  const char* cap = nullptr;
};
Limit s_limit(const LaSpaceCurve& c, double s0, double turn_budget, double torsion_budget, double max_length) {
  const double hi = c.s_range().hi;
  Limit lim{std::isfinite(hi) ? hi - 1e-9 * std::max(1.0, std::abs(hi)) : kInf, nullptr};
  auto take = [&lim](double s, const char* cap) {
    if (s < lim.s) lim = {s, cap};
  };
  take(max_length, "max_length");  // the turning of α < 1 is bounded: the budgets may never bind
  take(c.s_at_turning(c.turning(s0) + turn_budget), "max_turning");
  take(c.s_at_torsion_turning(c.torsion_turning(s0) + torsion_budget), "max_torsion_turning");
  return lim;
}

// A trial that stops short of its cone: a curve that ends first has no solution for these
// unknowns; one stopped by a cap of the options reached that cap.
void stopped_short(Trial& t, const Limit& lim, const std::string& what) {
  if (lim.cap) {
    t.status = Status::max_iterations;
    t.why = what + " does not meet its cone before the cap " + lim.cap + " (at s = " + format_number(lim.s) + ")";
  } else {
    t.status = Status::no_solution;
    t.why = what + " ends (its s range, s < " + format_number(lim.s) + " with the margin) before it meets its cone";
  }
}

// A trial whose integration failed: its status and message.
void integration_failed(Trial& t, const FrenetResult& r) {
  t.status = r.status;
  t.why = r.message;
}

// `frenet`: integration settings (default: the options'); screening uses coarser ones.
Trial construct_unchecked(const Problem& pb, double lambda0, double nu0, const OdeOptions* frenet) {
  Trial t;
  const SpaceSegmentOptions& o = *pb.opt;
  const OdeOptions& fo = frenet ? *frenet : o.integrator;
  const CompoundSpaceSpec& s = pb.spec;
  if (!(lambda0 >= 0) || !(nu0 > 0) || !std::isfinite(lambda0) || !std::isfinite(nu0)) {
    t.why = "lambda0 or nu0 out of range";
    return t;
  }
  const LaSpaceCurve c0(s.alpha0, s.beta0, lambda0, s.omega0, nu0, s.type);
  const double cone0 = pb.compound ? s.r_theta * pb.theta : pb.theta;
  const Limit lim0 = s_limit(c0, 0.0, o.max_turning, o.max_torsion_turning, o.max_length);
  if (!(lim0.s > 0)) {
    stopped_short(t, lim0, "segment 0");
    return t;
  }
  const FrenetResult a = integrate_to_cone(c0, Frame3{}, 0.0, lim0.s, cone0, fo);
  t.ode_evaluations += a.evaluations;
  if (a.status != Status::ok) {
    integration_failed(t, a);
    return t;
  }
  if (!a.met_cone) {
    stopped_short(t, lim0, "segment 0");
    return t;
  }
  t.piece0 = SpacePiece{c0, 0.0, a.s, Frame3{}};
  t.joint = a.frame;
  Frame3 end = a.frame;
  if (pb.compound) {
    const JointContinuation j =
        continue_at_joint(s.alpha0, s.alpha1, s.beta0, s.beta1, lambda0, s.omega0, s.type, c0.rho(a.s), c0.mu(a.s));
    if (!j.valid) {
      t.why = "no positive nu1 continues the torsion law at the joint";
      return t;
    }
    const LaSpaceCurve c1(s.alpha1, s.beta1, j.lambda1, j.omega1, j.nu1, s.type);
    if (!c1.contains(j.s_c)) {
      t.why = "joint arc length outside segment 1's s range";
      return t;
    }
    const Limit lim1 = s_limit(c1, j.s_c, o.max_turning - c0.turning(a.s), o.max_torsion_turning - c0.torsion_turning(a.s),
                               o.max_length);
    if (!(lim1.s > j.s_c) || !std::isfinite(lim1.s)) {
      stopped_short(t, lim1, "segment 1");
      return t;
    }
    const FrenetResult b = integrate_to_cone(c1, a.frame, j.s_c, lim1.s, pb.theta, fo);
    t.ode_evaluations += b.evaluations;
    if (b.status != Status::ok) {
      integration_failed(t, b);
      return t;
    }
    if (!b.met_cone) {
      stopped_short(t, lim1, "segment 1");
      return t;
    }
    t.piece1 = SpacePiece{c1, j.s_c, b.s, a.frame};
    end = b.frame;
  }
  t.end = end;
  t.phi = std::atan2(end.p.z(), end.p.y());
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(-t.phi, Vec3::UnitX()).toRotationMatrix();
  t.end_tangent_local = rot * end.t;
  t.scale = pb.distance / end.p.norm();
  t.defined = std::isfinite(t.scale) && t.scale > 0;
  if (!t.defined) t.why = "the curve meets its cone at the apex P0";
  return t;
}

// A trial whose curve laws are not representable (LaSpaceCurve rejects Λ, Ω, ν or an arc length
// where k·s overflows: R11 of docs/robustness.md) is an undefined trial, not the caller's error.
Trial construct(const Problem& pb, double lambda0, double nu0, const OdeOptions* frenet = nullptr) {
  try {
    return construct_unchecked(pb, lambda0, nu0, frenet);
  } catch (const InputError& e) {
    Trial t;
    t.status = Status::numerical_failure;
    t.why = std::string("trial curve not representable in double precision: ") + e.what();
    return t;
  }
}

double tangent_angle(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

std::optional<Vec2> stereographic_residual(const Problem& pb, const Trial& t) {
  const Vec3& te = t.end_tangent_local;
  const double d = 1.0 + te.dot(pb.target);
  if (!(d > 1e-12)) return std::nullopt;
  return Vec2(2.0 * te.dot(pb.u1) / d, 2.0 * te.dot(pb.u2) / d);
}

bool in_box(const Vec2& x) {
  return x[0] >= kLogLambdaMin && x[0] <= kLogLambdaMax && x[1] >= kLogNuMin && x[1] <= kLogNuMax;
}

using SpaceResult = Result<SpaceCurve, SpaceInfo>;

// The result of one construction: its curve (when defined), end-tangent and end-point errors and
// status; the counters are the caller's. summary.error (common/accuracy.hpp): the end-point
// residual / |P1 − P0| and, when v1 is a condition of the result (`tangent_is_condition`: a solve,
// not a construction at given unknowns, where v1 only enters residuals.angle), the end-tangent error.
SpaceResult to_result(const Problem& pb, const Trial& t, bool tangent_is_condition = true) {
  const SpaceSegmentOptions& o = *pb.opt;
  SpaceResult r;
  r.summary.integrator = std::string(to_string(o.integrator.method));
  r.summary.evaluations = t.ode_evaluations;
  r.info.ends = pb.ends;
  r.info.torsion_sign = pb.mirror ? -1 : 1;
  if (!t.defined) {
    r.summary.status = t.status;
    r.summary.message = t.why;
    return r;
  }
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(-t.phi, Vec3::UnitX()).toRotationMatrix();
  Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
  if (pb.mirror) mirror(2, 2) = -1;
  const SpacePlacement placement{pb.origin, pb.local_to_user * mirror * rot * t.scale, t.scale, r.info.torsion_sign};
  std::vector<SpacePiece> pieces{*t.piece0};
  if (pb.compound) pieces.push_back(*t.piece1);
  try {
    r.curve = SpaceCurve(std::move(pieces), placement, o.integrator);
  } catch (const InputError& e) {  // e.g. a length beyond DBL_MAX
    r.summary.status = Status::numerical_failure;
    r.summary.message = std::string("curve not representable in double precision: ") + e.what();
    return r;
  }
  const Vec3 p1_user = pb.origin + pb.local_to_user * Vec3(pb.distance * std::cos(pb.theta), pb.distance * std::sin(pb.theta), 0);
  r.info.end_tangent = (pb.local_to_user * mirror * t.end_tangent_local).normalized();
  if (pb.compound) r.info.joint = placement.origin + placement.matrix * t.joint.p;
  r.summary.accept = o.accept;
  // The solver's residuals, by its integrator; success (ok) is the end tangent within tangent_tolerance.
  const double tangent_error = tangent_angle(t.end_tangent_local, pb.target);
  const Vec3 end_user = placement.origin + placement.matrix * t.end.p;
  const double position_error = (end_user - p1_user).norm();
  r.summary.residuals.angle = tangent_error;
  r.summary.residuals.position = position_error;
  // The achieved error, verified: the curve as returned is each piece's law from its stored start
  // frame, integrated again by the certified Taylor integrator (curves/space/certified_frenet.hpp);
  // its ends against the stored next start (the joint: position and frame components) and against
  // P1 and v1, plus the proven bounds. The integrator's own end values alone are not trusted (a
  // magnus6 joint frame was off by 1.9e-6 with residuals of 1e-15: oracle space problem 499895).
  const auto certified = [](const SpacePiece& pc) { return integrate_frenet_certified(pc.law, pc.start, pc.s_begin, pc.s_end); };
  const CertifiedFrame c0 = certified(*t.piece0);
  std::optional<CertifiedFrame> c1;
  if (pb.compound && c0.status == Status::ok) c1 = certified(*t.piece1);
  const CertifiedFrame& last = c1 ? *c1 : c0;
  if (c0.status != Status::ok || last.status != Status::ok) {
    r.conclude(Status::not_converged, "the curve's integration error could not be bounded (certified Frenet integration: " +
                                          (c0.status != Status::ok ? c0.message : last.message) + ")");
    return r;
  }
  double joint_error = 0;  // position relative to |P1 − P0|, frame components absolute
  if (pb.compound) {
    const Frame3& a = c0.frame;
    const Frame3& b = t.piece1->start;
    const double frame_gap = std::max({(a.t - b.t).lpNorm<Eigen::Infinity>(), (a.n - b.n).lpNorm<Eigen::Infinity>(),
                                       (a.b - b.b).lpNorm<Eigen::Infinity>()});
    joint_error = std::max(((a.p - b.p).norm() + c0.position_error) * t.scale / pb.distance, frame_gap + c0.frame_error);
  }
  const Vec3 end_certified = placement.origin + placement.matrix * last.frame.p;
  const double verified_tangent = tangent_angle(rot * last.frame.t, pb.target) + last.frame_error;
  const double verified_position = (end_certified - p1_user).norm() + last.position_error * t.scale;
  r.summary.error_estimate = (end_certified - end_user).norm() + last.position_error * t.scale;
  r.summary.error = std::max({std::max(verified_position, position_error) / pb.distance,
                              tangent_is_condition ? std::max(verified_tangent, tangent_error) : 0.0, joint_error});
  const bool met = tangent_error <= o.tangent_tolerance;
  r.conclude(met ? Status::ok : Status::tolerance_not_met,
             met ? "" : "end tangent missed by " + format_number(tangent_error) + " rad (tangent_tolerance " +
                            format_number(o.tangent_tolerance) + ")");
  return r;
}

struct RunOutcome {
  Vec2 x;
  Status status = Status::not_converged;
  double merit = kInf;  // ‖r‖ (simplex: the end-tangent angle) where the run stopped
  int iterations = 0;
  long evaluations = 0;
  std::string message;
};

// One solver run from x0 with Frenet settings `frenet` (nullptr: the options'), to `tolerance`, with
// finite-difference steps `fd_step` (Newton, Ceres) or an initial simplex of edge `simplex_step`.
RunOutcome run_once(const Problem& pb, NonlinearMethod method, const Vec2& x0, long& ode_evals, const OdeOptions* frenet,
                    double tolerance, double fd_step, double simplex_step) {
  const SpaceSegmentOptions& o = *pb.opt;
  auto trial = [&](const Vec2& x) -> std::optional<Trial> {
    if (!in_box(x) || ode_evals >= o.max_ode_evaluations) return std::nullopt;  // budget spent: undefined
    Trial t = construct(pb, std::exp(x[0]), std::exp(x[1]), frenet);
    ode_evals += t.ode_evaluations;
    if (!t.defined) return std::nullopt;
    return t;
  };
  NonlinearOptions so;
  so.residual_tolerance = tolerance;  // simplex: on the end-tangent angle
  so.simplex.initial_step = simplex_step;
  so.simplex.x_tolerance = 1e-13;
  so.simplex.max_evaluations = o.max_evaluations;
  so.simplex.max_iterations = static_cast<int>(std::min<long>(o.max_evaluations, std::numeric_limits<int>::max()));
  so.simplex.restarts = 3;
  // Data without a curve: runs collapse onto a positive minimum of the end-tangent angle (often
  // ~0.7 rad); stopping there saves ~5/6 of such a run (docs/space_curves.md).
  so.simplex.minimum_spread = 1e-6;
  so.simplex.merit = [&](ConstVectorMap x) -> std::optional<double> {
    const auto t = trial(Vec2(x));
    if (!t) return std::nullopt;
    return tangent_angle(t->end_tangent_local, pb.target);
  };
  so.newton.max_evaluations = o.max_evaluations;
  so.newton.fd_step = fd_step;
  so.newton.max_step = 1.5;
  so.newton.max_iterations = 25;  // converging runs need 4–8; a run this long is better restarted elsewhere
  so.newton.max_halvings = 12;    // steps down to 1.5·2^-12 in log Λ0, log ν0: a run that needs less is stalled
  so.ceres.max_iterations = 100;
  const NonlinearResidual residual{2, [&](ConstVectorMap x, VectorMap r) {
                                     const auto t = trial(Vec2(x));
                                     if (!t) return false;
                                     const auto s = stereographic_residual(pb, *t);
                                     if (!s) return false;
                                     r = *s;
                                     return true;
                                   }};
  const NonlinearResult res = solve_nonlinear(method, residual, x0, so);
  return {res.x, res.status, res.merit, res.iterations, res.evaluations, res.message};
}

// Rough integration (rtol 1e-8) is a few times cheaper than the default 1e-10 and moves the end
// tangent by ~1e-8 rad: a run first converges on it to kRoughTolerance (finite differences of
// 1e-4, far above its noise), then is polished at the options' settings from there (the simplex
// from a fresh simplex of edge kPolishStep). A run whose rough phase stops farther than
// kRoughNear from the end tangent (most runs on data without a curve) fails at the rough cost.
constexpr double kRoughRtol = 1e-8, kRoughTolerance = 1e-6, kRoughFdStep = 1e-4, kRoughNear = 1e-2;
constexpr double kSimplexStep = 0.3, kPolishStep = 1e-4;
constexpr double kFallbackNear = 0.05;

RunOutcome run_solver(const Problem& pb, NonlinearMethod method, const Vec2& x0, long& ode_evals) {
  const SpaceSegmentOptions& o = *pb.opt;
  OdeOptions rough = o.integrator;
  rough.rtol = std::max(rough.rtol, kRoughRtol);
  rough.atol = std::max(rough.atol, 0.1 * kRoughRtol);
  const bool simplex = method == NonlinearMethod::simplex;
  const bool two_phase = o.integrator.method != OdeMethod::rk4 && rough.rtol > o.integrator.rtol &&
                         o.tangent_tolerance < kRoughTolerance;
  if (!two_phase) return run_once(pb, method, x0, ode_evals, nullptr, o.tangent_tolerance, 1e-7, kSimplexStep);
  RunOutcome first = run_once(pb, method, x0, ode_evals, &rough, kRoughTolerance, kRoughFdStep, kSimplexStep);
  if (first.status != Status::ok && !(first.merit <= kRoughNear)) {
    first.message = "at rtol " + format_number(kRoughRtol) + ": " + first.message;
    return first;
  }
  RunOutcome out = run_once(pb, method, first.x, ode_evals, nullptr, o.tangent_tolerance, 1e-7, simplex ? kPolishStep : kSimplexStep);
  out.iterations += first.iterations;
  out.evaluations += first.evaluations;
  return out;
}

SpaceResult solve(const char* who, const SpaceEndpoints& ends, const CompoundSpaceSpec& spec, bool compound,
                  const SpaceSegmentOptions& opt) {
  const auto t_begin = std::chrono::steady_clock::now();
  opt.validate();
  validate_spec(who, spec, compound);
  std::array<Problem, 2> problems = {make_problem(who, ends, false), make_problem(who, ends, true)};
  for (auto& p : problems) {
    p.compound = compound;
    p.spec = spec;
    p.opt = &opt;
  }
  // Automatic Λ0 start (lambda_start = 0): for α0 < 1 the total turning is bounded by
  // 1/((1 − α0)Λ0) (docs/math.md §1 θ range) and must exceed about twice the cone angle.
  const double lambda_start = opt.lambda_start > 0 ? opt.lambda_start
                              : spec.alpha0 < 1  ? std::min(1.0, 1.0 / (3.0 * problems[0].theta * (1.0 - spec.alpha0)))
                                                 : 1.0;
  const Vec2 x_start(std::log(lambda_start), std::log(opt.nu_start));
  long ode = 0, evals = 0;
  int iterations = 0, runs = 0;
  const int hands = opt.allow_mirror ? 2 : 1;
  struct Candidate {
    double error;
    int hand;
    Vec2 x;
  };
  // End-tangent error of the construction at x for each hand; undefined points are dropped.
  // Screening only ranks starting points: a coarse tolerance (1e-6) is enough and 3–4× cheaper.
  OdeOptions coarse = opt.integrator;
  coarse.rtol = std::max(coarse.rtol, 1e-6);
  coarse.atol = std::max(coarse.atol, 1e-7);
  coarse.h = std::max(coarse.h, 1e-2);
  std::string last_why = "no start was tried";  // why the last screened trial was undefined
  auto screen = [&](const Vec2& x, std::vector<Candidate>& out, const OdeOptions* fo) {
    for (int h = 0; h < hands; ++h) {
      if (!in_box(x) || ode >= opt.max_ode_evaluations) continue;
      const Trial t = construct(problems[h], std::exp(x[0]), std::exp(x[1]), fo);
      ode += t.ode_evaluations;
      ++evals;
      if (t.defined) out.push_back({tangent_angle(t.end_tangent_local, problems[h].target), h, x});
      else last_why = t.why;
    }
  };
  // The method of the run that found the curve: opt.solver, or simplex for the fallback run.
  NonlinearMethod solved_by = opt.solver;
  auto finish = [&](SpaceResult r) {
    r.summary.iterations = iterations;
    r.summary.constructions = evals;
    r.summary.evaluations = ode;
    r.summary.integrator = std::string(to_string(opt.integrator.method));
    r.summary.solver = std::string(to_string(solved_by));
    r.info.runs = runs;
    r.summary.seconds = seconds_since(t_begin);
    return r;
  };
  std::optional<RunOutcome> closest;  // the failed run that stopped nearest to a solution
  int closest_hand = 0;
  auto attempt = [&](const Candidate& c, NonlinearMethod method) -> std::optional<SpaceResult> {
    const Problem& pb = problems[c.hand];
    ++runs;
    RunOutcome out = run_solver(pb, method, c.x, ode);
    iterations += out.iterations;
    evals += out.evaluations;
    if (out.status == Status::ok) {
      const Trial t = construct(pb, std::exp(out.x[0]), std::exp(out.x[1]));
      ode += t.ode_evaluations;
      ++evals;
      SpaceResult r = to_result(pb, t);
      if (r.summary.status == Status::ok) {
        if (method != opt.solver) {
          solved_by = method;
          r.summary.message = std::string(to_string(opt.solver)) + " found no curve; solved by a " +
                              std::string(to_string(method)) + " run from its closest stop";
        }
        return finish(std::move(r));
      }
      out.status = Status::not_converged;
      out.message = "the solver's solution did not reproduce: " + r.summary.message;
    }
    if (!closest || out.merit < closest->merit) {
      closest = std::move(out);
      closest_hand = c.hand;
    }
    return std::nullopt;
  };
  auto by_error = [](const Candidate& a, const Candidate& b) { return a.error < b.error; };
  // Phase 1: the given start, with the hand whose end tangent is closer.
  std::vector<Candidate> first;
  screen(x_start, first, nullptr);
  std::sort(first.begin(), first.end(), by_error);
  if (!first.empty())
    if (auto r = attempt(first.front(), opt.solver)) return *r;
  // Phase 2: screen a log-space grid around the start (both hands) and run the solver from the
  // best remaining points, up to max_starts runs in all.
  std::vector<Candidate> grid;
  for (int i = -3; i <= 3; ++i)
    for (int k = -2; k <= 3; ++k)
      if (i != 0 || k != 0) screen(x_start + Vec2(i, k), grid, &coarse);
  if (first.size() > 1) grid.push_back(first[1]);
  std::sort(grid.begin(), grid.end(), by_error);
  for (const Candidate& c : grid) {
    if (runs >= opt.max_starts || ode >= opt.max_ode_evaluations) break;
    if (auto r = attempt(c, opt.solver)) return *r;
  }
  // Phase 3: Newton and Ceres stop where their direction fails (near folds of the end-tangent
  // map); when the closest run stopped within kFallbackNear rad, one simplex run from there.
  const bool fallback = opt.solver != NonlinearMethod::simplex && closest && closest->merit <= kFallbackNear &&
                        ode < opt.max_ode_evaluations;
  if (fallback)
    if (auto r = attempt({closest->merit, closest_hand, closest->x}, NonlinearMethod::simplex)) return *r;
  // No curve. The search (the start, then the best points of the grid) is not complete, so a
  // curve may still exist: not_converged, or the closest run's own status (e.g. max_iterations).
  SpaceResult r;
  r.info.ends = ends;
  const std::string solver(to_string(opt.solver));
  const std::string searched = std::to_string(runs) + " solver run" + (runs == 1 ? "" : "s") + " (at most max_starts = " +
                               std::to_string(opt.max_starts) + ") from the start (Lambda0, nu0) = (" +
                               format_number(lambda_start) + ", " + format_number(opt.nu_start) +
                               ") and the best points of the 7 x 6 grid of (log Lambda0, log nu0) around it" +
                               (hands == 2 ? ", both hands" : "") +
                               (fallback ? ", the last a simplex run from the closest stop" : "");
  if (ode >= opt.max_ode_evaluations) {
    r.summary.status = Status::max_iterations;
    r.summary.message = solver + ": Frenet evaluation budget max_ode_evaluations = " +
                        std::to_string(opt.max_ode_evaluations) + " spent after " + searched +
                        (closest ? " (closest run: " + closest->message + ")" : " (" + last_why + ")");
  } else if (!closest) {
    r.summary.status = Status::not_converged;
    r.summary.message = solver + ": no start gave a defined curve (the start and the 7 x 6 grid around it" +
                        (hands == 2 ? ", both hands" : "") + "; last: " + last_why + ")";
  } else {
    r.summary.status = usable(closest->status) ? Status::not_converged : closest->status;
    r.summary.message = solver + ": no curve met the end tangent within tangent_tolerance = " +
                        format_number(opt.tangent_tolerance) + " rad after " + searched +
                        "; the closest run stopped with " + std::string(to_string(closest->status)) + " at residual " +
                        format_number(closest->merit) + (closest->message.empty() ? "" : ": " + closest->message);
  }
  return finish(std::move(r));
}

SpaceResult construct_only(const char* who, const SpaceEndpoints& ends, const CompoundSpaceSpec& spec, bool compound,
                           double lambda0, double nu0, bool mirror, const SpaceSegmentOptions& opt) {
  const auto t_begin = std::chrono::steady_clock::now();
  opt.validate();
  validate_spec(who, spec, compound);
  if (!(lambda0 >= 0) || !std::isfinite(lambda0)) throw_input_error(who, "lambda0", lambda0, "[0, inf)");
  if (!(nu0 > 0) || !std::isfinite(nu0)) throw_input_error(who, "nu0", nu0, "(0, inf)");
  Problem pb = make_problem(who, ends, mirror);
  pb.compound = compound;
  pb.spec = spec;
  pb.opt = &opt;
  SpaceResult r = to_result(pb, construct(pb, lambda0, nu0), false);
  r.summary.constructions = 1;
  r.summary.seconds = seconds_since(t_begin);
  return r;
}

}  // namespace

void SpaceSegmentOptions::validate() const {
  constexpr const char* who = "SpaceSegmentOptions";
  if (!(tangent_tolerance >= 1e-14 && tangent_tolerance < 1)) throw_input_error(who, "tangent_tolerance", tangent_tolerance, "[1e-14, 1)");
  validate_accept(who, accept);
  integrator.validate();
  if (!(max_turning > 0)) throw_input_error(who, "max_turning", max_turning, "(0, inf]");
  if (!(max_torsion_turning > 0)) throw_input_error(who, "max_torsion_turning", max_torsion_turning, "(0, inf]");
  if (!(max_length > 0) || !std::isfinite(max_length)) throw_input_error(who, "max_length", max_length, "(0, inf)");
  if (!(lambda_start >= 0) || !std::isfinite(lambda_start)) throw_input_error(who, "lambda_start", lambda_start, "[0, inf)");
  if (!(nu_start > 0) || !std::isfinite(nu_start)) throw_input_error(who, "nu_start", nu_start, "(0, inf)");
  if (max_starts < 1) throw_input_error(who, "max_starts", max_starts, "[1, inf)");
  if (max_evaluations < 10) throw_input_error(who, "max_evaluations", static_cast<double>(max_evaluations), "[10, inf)");
  if (max_ode_evaluations < 1)
    throw_input_error(who, "max_ode_evaluations", static_cast<double>(max_ode_evaluations), "[1, inf)");
}

Result<SpaceCurve, SpaceInfo> solve_g1_space_segment(const SpaceEndpoints& ends, const G1SpaceSpec& spec,
                                                     const SpaceSegmentOptions& options) {
  return solve("solve_g1_space_segment", ends, as_compound(spec), false, options);
}

Result<SpaceCurve, SpaceInfo> solve_compound_space_segment(const SpaceEndpoints& ends, const CompoundSpaceSpec& spec,
                                                           const SpaceSegmentOptions& options) {
  return solve("solve_compound_space_segment", ends, spec, true, options);
}

Result<SpaceCurve, SpaceInfo> construct_g1_space_segment(const SpaceEndpoints& ends, const G1SpaceSpec& spec,
                                                         double lambda, double nu, bool mirror,
                                                         const SpaceSegmentOptions& options) {
  return construct_only("construct_g1_space_segment", ends, as_compound(spec), false, lambda, nu, mirror, options);
}

Result<SpaceCurve, SpaceInfo> construct_compound_space_segment(const SpaceEndpoints& ends,
                                                               const CompoundSpaceSpec& spec, double lambda0,
                                                               double nu0, bool mirror,
                                                               const SpaceSegmentOptions& options) {
  return construct_only("construct_compound_space_segment", ends, spec, true, lambda0, nu0, mirror, options);
}

Result<SpaceCurve, SpaceInfo> drawable_endpoints(const CompoundSpaceSpec& spec, bool compound, double lambda0,
                                                 double nu0, double theta, const SpaceSegmentOptions& options) {
  if (!(theta > 1e-8 && theta < M_PI - 1e-8)) throw_input_error("drawable_endpoints", "theta", theta, "(1e-8, pi - 1e-8)");
  const SpaceEndpoints e{Vec3::Zero(), Vec3::UnitX(), Vec3(std::cos(theta), std::sin(theta), 0), Vec3::UnitX()};
  SpaceResult r = construct_only("drawable_endpoints", e, spec, compound, lambda0, nu0, false, options);
  if (!r.usable()) return r;
  // v1 := the construction's own end tangent, which it then meets exactly.
  r.info.ends.v1 = r.info.end_tangent;
  r.summary.residuals.angle = 0.0;
  r.summary.error = *r.summary.residuals.position / r.info.ends.p1.norm();
  r.conclude(Status::ok, "");
  return r;
}

}  // namespace lac
