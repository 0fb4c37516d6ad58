// lac scurve: S-shaped (or C-shaped) LA curve from four control points, α < 0
// [Miura et al. 2013] §2.4–2.5.
#include "cli/batch.hpp"
#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/constructions/s_curve.hpp"

namespace lac::cli {
namespace {

struct SCurveArgs {
  CommonArgs common;
  std::optional<std::string> points;
  double alpha = -1;
  std::string solver = "toms748";
  QuadratureArgs quadrature{.integrator = "gauss-legendre"};
};

Report solve(const SCurveArgs& a) {
  const auto p = parse_points(need(a.points, "points"), 4, "points");
  std::array<std::complex<double>, 4> P;
  for (size_t k = 0; k < 4; ++k) P[k] = {p[k][0], p[k][1]};
  SCurveOptions o;
  o.solver = parse_root_method(a.solver);
  o.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  const int n = sample_count(a.common);
  const SCurveResult res = solve_s_curve(P, a.alpha, o);
  Report r{construction_report(res.summary), {P.begin(), P.end()}};
  Json& j = r.json;
  j["integrator"] = describe(o.integrator);
  if (res.usable()) add_planar_curve(j, res.curve);
  Json inflection = {{"s", nullptr}, {"x", nullptr}, {"y", nullptr}};
  if (res.usable() && res.info.inflection_s) {
    const PositionResult q = position_at(res.curve, *res.info.inflection_s);
    inflection = {{"s", number(*res.info.inflection_s)},
                  {"x", usable(q.status) ? number(q.point.position.real()) : Json(nullptr)},
                  {"y", usable(q.status) ? number(q.point.position.imag()) : Json(nullptr)}};
  }
  j["inflection"] = std::move(inflection);
  j["info"] = {{"shape", std::string(to_string(res.info.shape))},
               {"lambda", res.usable() ? number(res.info.lambda) : Json(nullptr)},
               {"mirrored", res.info.mirrored},
               {"reversed", res.info.reversed},
               {"constructions", res.summary.constructions},
               {"error_estimate", number(res.summary.error_estimate)}};
  if (res.usable()) add_planar_points(j, res.curve, n, o.integrator);
  return r;
}

void setup(CLI::App& app) {
  auto* a = owned<SCurveArgs>();
  auto* sub = app.add_subcommand("scurve", "S-shaped LA curve from four control points and alpha < 0 "
                                           "[Miura et al. 2013] sections 2.4-2.5");
  sub->add_option("--points", a->points,
                  "Control points \"x0,y0 x1,y1 x2,y2 x3,y3\": start tangent P0->P1, end tangent P2->P3 (required)");
  sub->add_option("--alpha", a->alpha, "Slope of the LCG, [-5, 0)")->capture_default_str();
  sub->add_option("--solver", a->solver,
                  "Root finder on Lambda: " + solver_names(root_methods()) + " ([Miura et al. 2013]: bisection)")
      ->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  add_common_options(*sub, a->common, true);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
