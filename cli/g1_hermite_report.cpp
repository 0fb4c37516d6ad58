#include "cli/export.hpp"
#include "cli/g1_hermite_args.hpp"

namespace lac::cli {

namespace {

std::string g1_solver_help() {
  std::string text = "Solver: " + solver_names(g1_hermite_solvers()) + ":";
  for (const auto& s : g1_hermite_solvers()) text.append("\n  ").append(s.name).append(": ").append(s.description);
  return text;
}

}  // namespace

void add_g1_hermite_options(CLI::App& sub, G1HermiteArgs& a) {
  sub.add_option("--alpha", a.alpha, "Slope alpha of the logarithmic curvature graph: " + alpha_range_text(kG1MinAbsAlpha, kG1MaxAbsAlpha) + " (required)");
  sub.add_option("--solver", a.solver, g1_solver_help())->capture_default_str();
  add_quadrature_options(sub, a.quadrature, "auto (the solver's own Gauss-Legendre kernel; a named method also checks the result)");
  sub.add_option("--winding", a.winding,
                 "Only the turning theta1 - theta0 + 2 pi k (angles relative to the chord, each in (-pi, pi]), "
                 "k in [-100, 100]; default: every turning up to --max-turning, least first");
  sub.add_option("--max-turning", a.max_turning,
                 "Largest total turning (rad) searched without --winding, [pi, 200 pi] (default 4 pi)");
  add_common_options(sub, a.common, true);
  add_export_options(sub, a.common);
}

void add_hermite_data_options(CLI::App& sub, G1HermiteArgs& a) {
  sub.add_option("--p0", a.p0, "Start point \"x,y\"");
  sub.add_option("--theta0", a.theta0, "Tangent angle at the start (rad, or degrees with --degrees)");
  sub.add_option("--p1", a.p1, "End point \"x,y\"");
  sub.add_option("--theta1", a.theta1, "Tangent angle at the end");
}

G1HermiteOptions g1_hermite_options(const G1HermiteArgs& a) {
  G1HermiteOptions o;
  o.solver = parse_g1_solver(a.solver);
  o.winding = a.winding;
  if (a.max_turning) o.max_turning = *a.max_turning;
  o.accept = a.common.accept;
  if (a.quadrature.integrator != "auto") {
    o.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
    o.verify = true;
  } else if (a.quadrature.any_option()) {
    throw_input_error("lac", "integrator", "--h, --tol and --panels need an explicit --integrator (" +
                                               method_names_text(quadrature_methods(), " | ") + ")");
  }
  return o;
}

Report g1_hermite_report(const G1HermiteProblem& problem, const G1HermiteArgs& a,
                         std::vector<std::complex<double>> polygon) {
  const G1HermiteOptions o = g1_hermite_options(a);
  const int n = sample_count(a.common);
  const G1HermiteResult g = solve_g1_hermite(problem, o);
  Report r{construction_report(g.summary), std::move(polygon)};
  Json& j = r.json;
  if (o.verify) j["integrator"] = describe(o.integrator);
  if (g.usable()) add_planar_curve(j, g.curve);
  add_export(j, g.usable() ? &g.curve : nullptr, a.common);
  j["inflection"] = g.usable() ? number(g.info.inflection) : Json(nullptr);
  const G1HermiteInfo& info = g.info;
  j["info"] = {{"shape", std::string(to_string(info.shape))},
               {"turning", number(info.turning)},
               {"phi0", number(info.phi0)},
               {"phi1", number(info.phi1)},
               {"winding", info.winding},
               {"max_turning", o.winding ? Json(nullptr) : Json(info.max_turning)},
               {"constructions", g.summary.constructions},
               {"error_estimate", number(g.summary.error_estimate)}};
  if (g.usable()) add_planar_points(j, g.curve, n, o.integrator);
  return r;
}

}  // namespace lac::cli
