// libFuzzer target: planar G1 and compound-rhythm segments (constructions/triangle_g1) from arbitrary
// control triangles and slopes, with every root finder and every integrator, and samples of usable
// results (PlanarCurve::sample); and the 1-D root finders themselves on a cubic with arbitrary
// coefficients and bracket.
// Properties: see fuzz/fuzz_support.hpp.
#include <string>
#include <variant>

#include "fuzz/fuzz_support.hpp"
#include "lac/constructions/triangle_g1.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::show;

namespace {

void check_segment(const std::string& what, const TriangleResult& g) {
  if (!g.usable()) return;
  const PlanarCurve& c = g.curve;
  require_finite_result(what + " length", c.length());
  require_finite_result(what + " kappa0", c.kappa_at(0));
  require_finite_result(what + " kappa1", c.kappa_at(c.length()));
  require_finite_result(what + " turning", g.info.turning);
  require_finite_result(what + " tangent error", g.summary.residuals.angle.value_or(NAN));
  require_finite_result(what + " joint", g.info.joint);
  require_finite_result(what + " rho_joint", g.info.rho_joint);
  for (const auto& p : g.info.pieces) {
    require_finite_result(what + " piece lambda", p.lambda);
    require_finite_result(what + " piece lambda_user", p.lambda_user);
    require_finite_result(what + " piece rho_small", p.rho_small);
    lac::fuzz::require_not_nan(what + " piece rho_large", p.rho_large);  // +inf: straight end (α ≤ 0 limit)
  }
  for (const auto& s : c.segments()) require_finite_result(what + " segment length", s.length());
}

void check_samples(const std::string& what, const std::vector<PositionResult>& pts) {
  for (const auto& q : pts) {
    if (!usable(q.status)) continue;  // holds no position of its own (curves/curve.hpp)
    require_finite_result(what + " position", q.point.position);
    require_finite_result(what + " s", q.point.s);
    require_finite_result(what + " theta", q.point.theta);
    require_finite_result(what + " kappa", q.point.kappa);
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
  TriangleOptions o;
  o.solver = solver;
  // The mode's upper bits pick the integrator: 0 the construction's default, k the k-th registered method.
  const size_t integrator = (mode / 4u) % (quadrature_methods().size() + 1);
  if (integrator > 0) o.integrator = make_quadrature(quadrature_methods()[integrator - 1].name);
  // Budgets per trial curve (a search draws up to ~100): rk4 (h = 10^-3) would otherwise run up
  // to 5·10^6 steps on each, and gauss-kronrod (1e-14) up to 8·10^5 evaluations on the pieces next
  // to ρ → 0 or ∞ of skewed triangles (~1 s per solve without the sanitizers, as before the
  // integrator became an option): the fuzzer is after wrong answers, not these known costs.
  if (auto* rk4 = std::get_if<Rk4>(&o.integrator)) rk4->max_steps = 20'000;
  if (auto* rk45 = std::get_if<Rk45>(&o.integrator)) rk45->max_steps = 2'500;
  if (auto* gk = std::get_if<GaussKronrod>(&o.integrator)) gk->max_intervals = 1'000;
  const std::string triangle = "(" + show(t.a0.real()) + "," + show(t.a0.imag()) + " " + show(t.a1.real()) + "," +
                               show(t.a1.imag()) + " " + show(t.a2.real()) + "," + show(t.a2.imag()) + ") " +
                               std::string(to_string(solver)) + " " + describe(o.integrator);
  TriangleResult g;
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
  if (g.usable()) {
    const int n = in.int_in(-1, 64);
    guarded(what + " sample " + std::to_string(n), [&] { check_samples(what, g.curve.sample(n, GkTanhSinh{})); });
  }
  return 0;
}
