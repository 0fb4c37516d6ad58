// lac chain: one curve of LA segments through N points (constructions/chain.hpp), G1 (one G1
// Hermite segment per pair of points) or G2 (the triple LA curve of [Miura et al. 2013] per pair),
// with the tangents and curvatures at the points given or estimated from the points.
#include <algorithm>

#include "cli/batch.hpp"
#include "cli/export.hpp"
#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/constructions/chain.hpp"

namespace lac::cli {
namespace {

struct ChainArgs {
  CommonArgs common;
  std::optional<std::string> points, thetas, kappas;
  std::optional<double> alpha;
  std::string continuity = "g1";
  bool closed = false;
  std::string solver = "auto";
  QuadratureArgs quadrature{.integrator = "auto"};
  std::optional<int> winding;
  std::optional<double> max_turning;
};

std::string solver_help() {
  std::string text = "Solver of each pair: g1: " + solver_names(g1_hermite_solvers());
  text.append("; g2: ").append(solver_names(g2_solvers())).append(" (auto: g1 auto, g2 newton)");
  return text;
}

Report solve(const ChainArgs& a) {
  ChainProblem p;
  p.points = parse_point_list(need(a.points, "points"), "points");
  if (a.thetas) {
    p.thetas = parse_number_list(*a.thetas, "thetas");
    for (double& t : p.thetas) t = radians(t, a.common);
  }
  if (a.kappas) p.kappas = parse_number_list(*a.kappas, "kappas");
  p.alpha = need(a.alpha, "alpha");
  p.continuity = parse_chain_continuity(a.continuity);
  p.closed = a.closed;
  ChainOptions o;
  if (a.solver != "auto") {
    if (p.continuity == ChainContinuity::g1) o.g1.solver = parse_g1_solver(a.solver);
    else o.g2.solver = parse_g2_solver(a.solver);
  }
  o.g1.winding = o.g2.winding = a.winding;
  if (a.max_turning) o.g1.max_turning = o.g2.max_turning = *a.max_turning;
  o.g1.accept = o.g2.accept = a.common.accept;
  const bool explicit_integrator = a.quadrature.integrator != "auto";
  if (explicit_integrator) {
    o.g1.integrator = o.g2.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
    o.g1.verify = true;
  } else if (a.quadrature.any_option()) {
    throw_input_error("lac", "integrator", "--h, --tol and --panels need an explicit --integrator (" +
                                               method_names_text(quadrature_methods(), " | ") + ")");
  }
  const int n = sample_count(a.common);
  const ChainResult res = solve_chain(p, o);
  Report r{construction_report(res.summary), p.points};
  if (p.closed) r.polygon.push_back(p.points.front());
  Json& j = r.json;
  if (explicit_integrator) j["integrator"] = describe(o.g1.integrator);
  if (res.usable()) add_planar_curve(j, res.curve);
  add_export(j, res.usable() ? &res.curve : nullptr, a.common);
  Json thetas = Json::array(), kappas = Json::array();
  for (double t : res.info.thetas) thetas.push_back(number(t));
  for (double k : res.info.kappas) kappas.push_back(number(k));
  Json windings = Json::array(), turnings = Json::array();
  for (int k : res.info.windings) windings.push_back(k);
  for (double t : res.info.turnings) turnings.push_back(number(t));
  j["info"] = {{"continuity", a.continuity},
               {"closed", p.closed},
               {"pairs", res.info.pairs.size()},
               {"failed_pair", res.info.failed_pair >= 0 ? Json(res.info.failed_pair) : Json(nullptr)},
               {"tangents", res.info.estimated_thetas ? "estimated (circle through three neighbours)" : "given"},
               {"curvatures", p.continuity == ChainContinuity::g1 ? "not used (g1)"
                              : res.info.estimated_kappas         ? "estimated (circle through three neighbours)"
                                                                  : "given"},
               {"thetas", std::move(thetas)},
               {"kappas", std::move(kappas)},
               {"windings", std::move(windings)},
               {"turnings", std::move(turnings)},
               {"max_turning", a.winding ? Json(nullptr) : Json(o.g1.max_turning)},
               {"constructions", res.summary.constructions},
               {"error_estimate", number(res.summary.error_estimate)}};
  if (res.usable()) add_planar_points(j, res.curve, n, o.g1.integrator);
  return r;
}

void setup(CLI::App& app) {
  auto* a = owned<ChainArgs>();
  auto* sub = app.add_subcommand("chain", "LA chain: one curve of LA segments through N points, G1 or G2 at the points");
  sub->add_option("--points", a->points, "The points \"x0,y0 x1,y1 ...\", at least 2 (closed: 3) (required)");
  sub->add_option("--thetas", a->thetas, "Tangent angle at each point \"t0 t1 ...\" (default: estimated by the circle "
                                         "through each point and its two neighbours)");
  sub->add_option("--kappas", a->kappas, "Signed curvature at each point (g2; default: estimated like the tangents)");
  sub->add_option("--alpha", a->alpha, "Slope alpha of every segment's LCG (required)");
  sub->add_option("--continuity", a->continuity, "g1 | g2")->check(CLI::IsMember({"g1", "g2"}))->capture_default_str();
  sub->add_flag("--closed", a->closed, "Also join the last point to the first");
  sub->add_option("--solver", a->solver, solver_help())->capture_default_str();
  sub->add_option("--winding", a->winding,
                  "Only the turning theta1 - theta0 + 2 pi k of every pair (angles relative to its chord, each in "
                  "(-pi, pi]), k in [-100, 100]; default: each pair's least turning up to --max-turning");
  sub->add_option("--max-turning", a->max_turning,
                  "Largest total turning (rad) of a pair searched without --winding, [pi, 200 pi] (default 4 pi)");
  add_quadrature_options(*sub, a->quadrature, "auto (each construction's default)");
  add_common_options(*sub, a->common, true);
  add_export_options(*sub, a->common);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
