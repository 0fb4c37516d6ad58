#include "cli/export.hpp"
#include "cli/triangle_args.hpp"

namespace lac::cli {

void add_triangle_options(CLI::App& sub, TriangleArgs& a) {
  sub.add_option("--points", a.points, "Control points \"x0,y0 x1,y1 x2,y2\": start, tangent intersection, end (required)");
  sub.add_option("--solver", a.solver, "Root finder: " + solver_names(root_methods()))->capture_default_str();
  add_quadrature_options(sub, a.quadrature, "auto (the construction's default, gk-tanh-sinh)");
  sub.add_option("--max-evaluations", a.max_evaluations,
                 "Integrand evaluations the search may spend, in [1, 1e12] (default 1e8; then status max_iterations)");
  add_common_options(sub, a.common, true);
  add_export_options(sub, a.common);
}

PreparedTriangle prepare_triangle(const TriangleArgs& a) {
  const auto p = parse_points(need(a.points, "points"), 3, "points");
  PreparedTriangle s{{{p[0][0], p[0][1]}, {p[1][0], p[1][1]}, {p[2][0], p[2][1]}}, {}, false};
  s.options.solver = parse_root_method(a.solver);
  s.options.accept = a.common.accept;
  if (a.max_evaluations) s.options.max_evaluations = max_evaluations_option(a.max_evaluations, 1e12);
  if (a.quadrature.integrator != "auto") {
    s.options.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
    s.explicit_integrator = true;
  } else if (a.quadrature.any_option()) {
    throw_input_error("lac", "integrator", "--h, --tol and --panels need an explicit --integrator (" +
                                               method_names_text(quadrature_methods(), " | ") + ")");
  }
  return s;
}

Report triangle_report(const TriangleResult& g, const TriangleArgs& a, const PreparedTriangle& p) {
  const int n = sample_count(a.common);
  const Summary& sum = g.summary;
  Report r{construction_report(sum), {p.triangle.a0, p.triangle.a1, p.triangle.a2}};
  Json& j = r.json;
  if (p.explicit_integrator) j["integrator"] = describe(p.options.integrator);
  if (g.usable()) add_planar_curve(j, g.curve);
  add_export(j, g.usable() ? &g.curve : nullptr, a.common);
  const TriangleInfo& info = g.info;
  Json i;
  i["segment0_at_a0"] = info.segment0_at_a0;
  i["turning"] = number(info.turning);
  i["bracket_probes"] = info.bracket_probes;
  i["constructions"] = sum.constructions;
  i["error_estimate"] = number(sum.error_estimate);
  if (info.compound) {
    i["joint"] = g.usable() ? xy(info.joint) : Json{{"x", nullptr}, {"y", nullptr}};
    i["rho_joint"] = g.usable() ? number(info.rho_joint) : Json(nullptr);
  }
  j["info"] = std::move(i);
  if (g.usable()) add_planar_points(j, g.curve, n, p.options.integrator);
  return r;
}

}  // namespace lac::cli
