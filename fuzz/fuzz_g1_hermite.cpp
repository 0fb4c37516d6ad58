// libFuzzer target: G1 Hermite interpolation by one LA segment (constructions/g1_hermite) and LA
// chains through points (constructions/chain) fed arbitrary end data, slopes, windings, solver and
// integrator choices, and the samples of usable results. Properties: see fuzz/fuzz_support.hpp;
// besides, a usable G1 result must start at p0 and have a finite length and end curvatures.
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "lac/constructions/chain.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/integrators/registry.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::show;

namespace {

void check_curve(const std::string& what, const PlanarCurve& curve, int n) {
  require_finite_result(what + " length", curve.length());
  require_finite_result(what + " kappa0", curve.kappa_at(0));
  require_finite_result(what + " kappa1", curve.kappa_at(curve.length()));
  guarded(what + " sample " + std::to_string(n), [&] {
    for (const auto& p : curve.sample(n)) {
      const CurvePoint& q = p.point;
      require_finite_result(what + " position", q.position);
      require_finite_result(what + " theta", q.theta);
      require_finite_result(what + " kappa", q.kappa);
    }
  });
}

std::string show_point(std::complex<double> p) { return show(p.real()) + "," + show(p.imag()); }

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const uint8_t mode = in.byte();
  const int n = in.int_in(2, 40);
  if (mode % 4 != 0) {  // G1 Hermite, three inputs in four
    G1HermiteProblem p;
    p.p0 = {in.number(), in.number()};
    p.theta0 = in.number();
    p.p1 = {in.number(), in.number()};
    p.theta1 = in.number();
    p.alpha = in.number();
    G1HermiteOptions o;
    const auto solvers = g1_hermite_solvers();
    o.solver = solvers[in.byte() % solvers.size()].method;
    o.winding = in.int_in(-3, 3);
    o.verify = in.byte() % 2;
    const std::string what = "solve_g1_hermite p0 " + show_point(p.p0) + " theta0 " + show(p.theta0) + " p1 " +
                             show_point(p.p1) + " theta1 " + show(p.theta1) + " alpha " + show(p.alpha) + " solver " +
                             std::string(to_string(o.solver)) + " winding " + std::to_string(*o.winding);
    G1HermiteResult r;
    if (!guarded(what, [&] { r = solve_g1_hermite(p, o); })) return 0;
    if (!r.usable()) return 0;
    require_finite_result(what + " residual_position", r.summary.residuals.position.value_or(0.0));
    check_curve(what, r.curve, n);
    return 0;
  }
  // A chain through up to 6 points, open or closed, G1 or G2, given or estimated tangents.
  ChainProblem p;
  const int points = in.int_in(0, 6);
  for (int k = 0; k < points; ++k) p.points.push_back({in.number(), in.number()});
  const uint8_t flags = in.byte();
  p.closed = flags & 1;
  p.continuity = flags & 2 ? ChainContinuity::g2 : ChainContinuity::g1;
  if (flags & 4)
    for (int k = 0; k < points; ++k) p.thetas.push_back(in.number());
  if ((flags & 8) && p.continuity == ChainContinuity::g2)
    for (int k = 0; k < points; ++k) p.kappas.push_back(in.number());
  p.alpha = in.number();
  ChainOptions o;
  o.g2.max_evaluations = 1'000'000;  // the harness bounds each call's CPU time
  o.g2.grid_fallback = false;
  std::string what = "solve_chain points";
  for (const auto& q : p.points) what += " " + show_point(q);
  what += std::string(p.closed ? " closed" : " open") + " " + std::string(to_string(p.continuity)) + " alpha " + show(p.alpha);
  ChainResult r;
  if (!guarded(what, [&] { r = solve_chain(p, o); })) return 0;
  if (r.usable()) check_curve(what, r.curve, n);
  return 0;
}
