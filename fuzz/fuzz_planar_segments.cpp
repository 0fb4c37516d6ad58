// libFuzzer target: planar G1 and compound-rhythm segments (constructions/triangle_g1) from arbitrary
// control triangles and slopes, with every root finder, and sample_segment of usable results;
// and the 1-D root finders themselves on a cubic with arbitrary coefficients and bracket.
// Properties: see fuzz/fuzz_support.hpp.
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "lac/constructions/triangle_g1.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::show;

namespace {

void check_segment(const std::string& what, const G1Segment& g) {
  if (!usable(g.status)) return;
  require_finite_result(what + " length", g.length);
  require_finite_result(what + " kappa0", g.kappa0);
  require_finite_result(what + " kappa1", g.kappa1);
  require_finite_result(what + " turning", g.turning);
  require_finite_result(what + " tangent_error", g.tangent_error);
  require_finite_result(what + " joint", g.joint);
  require_finite_result(what + " rho_joint", g.rho_joint);
  for (const auto& p : g.pieces) {
    require_finite_result(what + " piece lambda", p.lambda);
    require_finite_result(what + " piece lambda_user", p.lambda_user);
    require_finite_result(what + " piece length", p.length);
    require_finite_result(what + " piece rho_small", p.rho_small);
    lac::fuzz::require_not_nan(what + " piece rho_large", p.rho_large);  // +inf: straight end (α ≤ 0 limit)
  }
}

void check_samples(const std::string& what, const std::vector<SegmentSample>& pts) {
  for (const auto& q : pts) {
    require_finite_result(what + " position", q.position);
    require_finite_result(what + " s", q.s);
    require_finite_result(what + " theta", q.theta);
    require_finite_result(what + " kappa", q.kappa);
  }
}

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const uint8_t mode = in.byte();
  const RootMethod solver = static_cast<RootMethod>(in.byte() % root_methods().size());

  if (mode % 4 == 3) {  // the root finders on f(x) = c0 + c1 x + c2 x² + c3 x³
    const double c0 = in.number(), c1 = in.number(), c2 = in.number(), c3 = in.number();
    const double lo = in.number(), hi = in.number();
    RootOptions o;
    if (in.byte() % 2) o.max_iterations = in.int_in(-5, 300);
    auto f = [=](double x) { return c0 + x * (c1 + x * (c2 + x * c3)); };
    guarded(std::string(to_string(solver)) + " on cubic (" + show(c0) + ", " + show(c1) + ", " + show(c2) + ", " +
                show(c3) + ") in [" + show(lo) + ", " + show(hi) + "]",
            [&] {
              const RootResult r = find_root(solver, f, make_bracket(f, lo, hi), o);
              if (r.status == Status::ok) {
                require_finite_result("root", r.root);
                require_finite_result("residual", r.residual);
              }
            });
    return 0;
  }

  ControlTriangle t;
  t.a0 = {in.number(), in.number()};
  t.a1 = {in.number(), in.number()};
  t.a2 = {in.number(), in.number()};
  const double alpha0 = in.number(), alpha1 = in.number(), r = in.number();
  SegmentOptions o;
  o.solver = solver;
  const std::string triangle = "(" + show(t.a0.real()) + "," + show(t.a0.imag()) + " " + show(t.a1.real()) + "," +
                               show(t.a1.imag()) + " " + show(t.a2.real()) + "," + show(t.a2.imag()) + ") " +
                               std::string(to_string(solver));
  G1Segment g;
  std::string what;
  bool ok = false;
  if (mode % 4 == 0 || mode % 4 == 2) {
    what = "solve_g1 " + triangle + " alpha " + show(alpha0);
    ok = guarded(what, [&] { g = solve_g1(t, alpha0, o); });
  } else {
    what = "solve_compound " + triangle + " alpha0 " + show(alpha0) + " alpha1 " + show(alpha1) + " r " + show(r);
    ok = guarded(what, [&] { g = solve_compound(t, alpha0, alpha1, r, o); });
  }
  if (!ok) return 0;
  check_segment(what, g);
  if (usable(g.status)) {
    const int n = in.int_in(-1, 64);
    guarded(what + " sample_segment " + std::to_string(n), [&] { check_samples(what, sample_segment(g, n)); });
  }
  return 0;
}
