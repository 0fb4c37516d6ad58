// lac g2: G2 Hermite interpolation by a triple LA curve [Miura et al. 2013] §3; see docs/hermite.md.
#include "cli/batch.hpp"
#include "cli/export.hpp"
#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/constructions/g2_hermite.hpp"

namespace lac::cli {
namespace {

struct G2Args {
  CommonArgs common;
  std::optional<std::string> p0, p1;
  std::optional<double> theta0, theta1, kappa0, kappa1;
  double alpha = -1;
  std::string solver = "newton", start = "fast";
  QuadratureArgs quadrature{.integrator = "gauss-legendre"};
  bool no_fallback = false;
  bool paper_joints = false;
  std::optional<int> winding;
  std::optional<double> max_turning;
  std::optional<double> max_evaluations;
};

Report solve(const G2Args& a) {
  const auto p0 = parse_tuple(need(a.p0, "p0"), 2, "p0"), p1 = parse_tuple(need(a.p1, "p1"), 2, "p1");
  const G2Problem pr{{{p0[0], p0[1]}, radians(need(a.theta0, "theta0"), a.common), need(a.kappa0, "kappa0")},
                     {{p1[0], p1[1]}, radians(need(a.theta1, "theta1"), a.common), need(a.kappa1, "kappa1")},
                     a.alpha};
  G2Options o;
  o.solver = parse_g2_solver(a.solver);
  o.start = parse_g2_start(a.start);
  o.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  o.grid_fallback = !a.no_fallback;
  o.free_joints = !a.paper_joints;
  o.winding = a.winding;
  if (a.max_turning) o.max_turning = *a.max_turning;
  if (a.max_evaluations) o.max_evaluations = max_evaluations_option(a.max_evaluations, 1e12);
  o.accept = a.common.accept;
  const int n = sample_count(a.common);
  const G2Result res = solve_g2(pr, o);
  Report r{construction_report(res.summary), {pr.start.position, pr.end.position}};
  Json& j = r.json;
  j["integrator"] = describe(o.integrator);
  if (res.usable()) add_planar_curve(j, res.curve);
  add_export(j, res.usable() ? &res.curve : nullptr, a.common);
  j["info"] = {{"start", std::string(to_string(res.info.start_used))},
               {"start_seconds", res.info.start_seconds},
               {"h", res.usable() ? number(res.info.h) : Json(nullptr)},
               {"joints", res.usable() ? Json{res.info.joints[0], res.info.joints[1]} : Json(nullptr)},
               {"winding", res.info.winding},
               {"turning", number(res.info.turning)},
               {"max_turning", o.winding ? Json(nullptr) : Json(res.info.max_turning)},
               {"constructions", res.summary.constructions},
               {"error_estimate", number(res.summary.error_estimate)}};
  if (res.usable()) add_planar_points(j, res.curve, n, o.integrator);
  return r;
}

void setup(CLI::App& app) {
  auto* a = owned<G2Args>();
  auto* sub = app.add_subcommand("g2", "G2 Hermite interpolation by three LA segments of one alpha "
                                       "[Miura et al. 2013] section 3");
  sub->add_option("--p0", a->p0, "Start point \"x,y\" (required)");
  sub->add_option("--theta0", a->theta0, "Tangent angle at the start, rad (degrees with --degrees) (required)");
  sub->add_option("--kappa0", a->kappa0, "Signed curvature at the start, left turn positive (required)");
  sub->add_option("--p1", a->p1, "End point \"x,y\" (required)");
  sub->add_option("--theta1", a->theta1, "Tangent angle at the end, rad (degrees with --degrees) (required)");
  sub->add_option("--kappa1", a->kappa1, "Signed curvature at the end (required)");
  sub->add_option("--alpha", a->alpha, "Slope of the LCG, one for the three segments, " + alpha_range_text(kG2MinAbsAlpha, kG2MaxAbsAlpha))->capture_default_str();
  sub->add_option("--solver", a->solver, "N-D solver: " + solver_names(g2_solvers()))->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  sub->add_option("--start", a->start, "Initial estimate: fast | bezier-grid")->capture_default_str();
  sub->add_flag("--no-fallback", a->no_fallback, "Do not retry from the Bezier-grid start when the fast start fails");
  sub->add_flag("--paper-joints", a->paper_joints,
                "Joints at S = 1/4, 3/4 only (004); by default, where neither start gives a curve with those, "
                "the fast start is retried with joints at 1/8, 7/8 and 1/16, 15/16");
  sub->add_option("--winding", a->winding,
                  "Only the turning theta1 - theta0 + 2 pi k (angles relative to the chord, each in (-pi, pi]), "
                  "k in [-100, 100]; default: every turning up to --max-turning, least first");
  sub->add_option("--max-turning", a->max_turning,
                  "Largest total turning (rad) searched without --winding, [pi, 200 pi] (default 4 pi)");
  sub->add_option("--max-evaluations", a->max_evaluations,
                  "Integrand evaluations of the whole call (starts, solves, fallback), in [1, 1e12] (default 1e8; "
                  "then status max_iterations)");
  add_common_options(*sub, a->common, true);
  add_export_options(*sub, a->common);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
