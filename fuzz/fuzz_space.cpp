// libFuzzer target: LA space curves (curves/space) and space segments (constructions/space_segment) fed
// arbitrary doubles: the curve laws, Frenet integration (every method) to an arc length and to a
// cone, the joint continuation, the cone construction at given unknowns, and the G1 / compound
// solvers (every solver; starts and evaluation caps kept small so that one call stays within
// the fuzzer's time bound). Properties: see fuzz/fuzz_support.hpp.
#include <optional>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "lac/constructions/space_segment.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::require_not_nan;
using lac::fuzz::show;

namespace {

std::string show3(const Vec3& v) { return "(" + show(v.x()) + "," + show(v.y()) + "," + show(v.z()) + ")"; }

void check_vec(const std::string& what, const Vec3& v) {
  for (int i = 0; i < 3; ++i) require_finite_result(what, v[i]);
}

void check_frenet(const std::string& what, const FrenetResult& r) {
  if (!usable(r.status)) return;
  check_vec(what + " p", r.frame.p);
  check_vec(what + " t", r.frame.t);
  check_vec(what + " n", r.frame.n);
  check_vec(what + " b", r.frame.b);
  require_finite_result(what + " s", r.s);
}

void check_segment(const std::string& what, const Result<SpaceCurve, SpaceInfo>& r) {
  if (!r.usable()) return;
  const SpaceCurve& c = r.curve;
  require_finite_result(what + " length", c.length());
  require_finite_result(what + " scale", c.placement().scale);
  require_finite_result(what + " tangent_error", r.summary.residuals.angle.value_or(NAN));
  require_finite_result(what + " position_error", r.summary.residuals.position.value_or(NAN));
  check_vec(what + " end_tangent", r.info.end_tangent);
  if (r.info.joint) check_vec(what + " joint", *r.info.joint);
  check_vec(what + " origin", c.placement().origin);
  for (const SpacePiece& p : c.pieces()) {
    require_finite_result(what + " lambda", p.law.lambda());
    require_finite_result(what + " omega", p.law.omega());
    require_finite_result(what + " nu", p.law.nu());
    require_finite_result(what + " s_end", p.s_end);
  }
}

Vec3 vec(lac::fuzz::FuzzInput& in) {
  const double x = in.number(), y = in.number(), z = in.number();
  return {x, y, z};
}

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const uint8_t mode = in.byte();
  CompoundSpaceSpec spec;
  spec.alpha0 = in.number();
  spec.beta0 = in.number();
  spec.omega0 = in.number();
  spec.type = in.byte() % 2 ? TorsionType::type2 : TorsionType::type1;
  SpaceSegmentOptions o;
  // The byte's choice as before OdeMethod was reordered (rk4 first), so stored inputs keep their method.
  constexpr OdeMethod kMethods[] = {OdeMethod::rk45, OdeMethod::rk4, OdeMethod::magnus6};
  o.integrator.method = kMethods[in.byte() % 3];
  // A twentieth of the default step cap: every call integrates the 12-dimensional Frenet system,
  // and at 20000 steps the 10^6-execution campaign ran at ~110 executions/s.
  o.integrator.max_steps = 1'000;
  const std::string spec_text = "alpha " + show(spec.alpha0) + " beta " + show(spec.beta0) + " omega " +
                                show(spec.omega0) + " type " + std::to_string(static_cast<int>(spec.type)) +
                                " method " + std::string(to_string(o.integrator.method));

  switch (mode % 4) {
    case 0: {  // the curve and its Frenet integration
      const double lambda = in.number(), nu = in.number(), s0 = in.number(), s1 = in.number(), cone = in.number();
      const std::string what = "LaSpaceCurve " + spec_text + " lambda " + show(lambda) + " nu " + show(nu);
      std::optional<LaSpaceCurve> c;
      if (!guarded(what, [&] { c.emplace(spec.alpha0, spec.beta0, lambda, spec.omega0, nu, spec.type); })) return 0;
      const Interval range = c->s_range();
      if (std::isnan(range.lo) || std::isnan(range.hi) || !(range.lo < range.hi))
        lac::fuzz::finding("NAN", what + ": empty or NaN s_range");
      const std::string at = what + " s " + show(s0);
      if (c->contains(s0)) {
        guarded(at + " turning", [&] { require_not_nan("turning", c->turning(s0)); });
        guarded(at + " torsion_turning", [&] { require_not_nan("torsion_turning", c->torsion_turning(s0)); });
      }
      guarded(at + " s_at_turning", [&] { require_not_nan("s_at_turning", c->s_at_turning(s0)); });
      guarded(at + " s_at_log_rho", [&] { require_not_nan("s_at_log_rho", c->s_at_log_rho(s0)); });
      guarded(at + " integrate_frenet to " + show(s1),
              [&] { check_frenet("integrate_frenet", integrate_frenet(*c, Frame3{}, s0, s1, o.integrator)); });
      guarded(at + " integrate_to_cone " + show(s1) + " cone " + show(cone),
              [&] { check_frenet("integrate_to_cone", integrate_to_cone(*c, Frame3{}, s0, s1, cone, o.integrator)); });
      break;
    }
    case 1: {  // joint continuation
      const double a1 = in.number(), b1 = in.number(), l0 = in.number(), rc = in.number(), mc = in.number();
      guarded("continue_at_joint " + spec_text + " " + show(a1) + " " + show(b1) + " " + show(l0) + " " + show(rc) +
                  " " + show(mc),
              [&] {
                const JointContinuation j = continue_at_joint(spec.alpha0, a1, spec.beta0, b1, l0, spec.omega0,
                                                              spec.type, rc, mc);
                if (j.valid) {
                  require_finite_result("lambda1", j.lambda1);
                  require_finite_result("omega1", j.omega1);
                  require_finite_result("s_c", j.s_c);
                  require_finite_result("nu1", j.nu1);
                }
              });
      break;
    }
    default: {  // the segment construction and solvers
      const bool compound = mode % 4 == 3;
      spec.alpha1 = in.number();
      spec.beta1 = in.number();
      spec.r_theta = in.number();
      SpaceEndpoints ends;
      ends.p0 = vec(in);
      ends.v0 = vec(in);
      ends.p1 = vec(in);
      ends.v1 = vec(in);
      const double lambda = in.number(), nu = in.number();
      const bool mirror = in.byte() % 2;
      const std::string what = std::string(compound ? "compound " : "g1 ") + spec_text + " alpha1 " +
                               show(spec.alpha1) + " beta1 " + show(spec.beta1) + " r " + show(spec.r_theta) +
                               " p0 " + show3(ends.p0) + " v0 " + show3(ends.v0) + " p1 " + show3(ends.p1) +
                               " v1 " + show3(ends.v1);
      const G1SpaceSpec g1{spec.alpha0, spec.beta0, spec.omega0, spec.type};
      guarded(what + " construct lambda " + show(lambda) + " nu " + show(nu), [&] {
        check_segment("construct", compound ? construct_compound_space_segment(ends, spec, lambda, nu, mirror, o)
                                            : construct_g1_space_segment(ends, g1, lambda, nu, mirror, o));
      });
      constexpr NonlinearMethod kSolvers[] = {NonlinearMethod::simplex, NonlinearMethod::ceres, NonlinearMethod::newton};
      o.solver = kSolvers[in.byte() % 3];
      o.max_starts = in.int_in(0, 2);
      o.max_evaluations = in.int_in(5, 120);
      o.max_ode_evaluations = 10'000;  // ≤ ~0.05 s under the sanitizers with the last construction's overshoot
      o.allow_mirror = mirror;
      Result<SpaceCurve, SpaceInfo> r;
      if (!guarded(what + " solve " + std::string(to_string(o.solver)), [&] {
            r = compound ? solve_compound_space_segment(ends, spec, o) : solve_g1_space_segment(ends, g1, o);
          }))
        return 0;
      check_segment("solve", r);
      if (r.usable()) {
        const int n = in.int_in(-1, 40);
        guarded(what + " SpaceCurve::sample " + std::to_string(n), [&] {
          for (const SpacePoint& q : r.curve.sample(n)) {
            check_vec("sample p", q.p);  // a flagged point holds a known point's frame
            check_vec("sample t", q.t);
            require_not_nan("sample dkappa_ds", q.dkappa_ds);  // may overflow at extreme scales
            if (q.status != Status::ok) continue;
            require_finite_result("sample kappa", q.kappa);
            require_finite_result("sample tau", q.tau);
          }
        });
      }
      break;
    }
  }
  return 0;
}
