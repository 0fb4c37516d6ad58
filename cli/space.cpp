// lac space: G1 or compound-rhythm LA space segment between two points with end tangents
// [Yoshida–Fukuda–Saito–Saito 2011].
#include "cli/batch.hpp"
#include "cli/export.hpp"
#include "cli/options.hpp"
#include "lac/constructions/space_segment.hpp"

namespace lac::cli {
namespace {

struct SpaceArgs {
  CommonArgs common;
  std::optional<std::string> p0, v0, p1, v1;
  std::optional<double> alpha, beta;
  double omega = 0.1;
  int type = 1;
  std::optional<double> alpha1, beta1, r_theta;
  std::string solver = "newton";
  std::string integrator = "magnus6";
  std::optional<double> tol;
  double tangent_tolerance = 1e-11;
};

Vec3 vec(const std::optional<std::string>& text, const char* name) {
  const auto v = parse_tuple(need(text, name), 3, name);
  return {v[0], v[1], v[2]};
}

Report solve(const SpaceArgs& a) {
  const SpaceEndpoints ends{vec(a.p0, "p0"), vec(a.v0, "v0"), vec(a.p1, "p1"), vec(a.v1, "v1")};
  if (a.type != 1 && a.type != 2) throw_input_error("lac space", "type", a.type, "{1, 2}");
  const TorsionType type = a.type == 1 ? TorsionType::type1 : TorsionType::type2;
  const bool compound = a.alpha1 || a.beta1 || a.r_theta;
  const double alpha = need(a.alpha, "alpha"), beta = need(a.beta, "beta");
  SpaceSegmentOptions o;
  o.solver = parse_nonlinear_method(a.solver);
  o.integrator.method = parse_ode_method(a.integrator);
  if (a.tol) o.integrator.rtol = *a.tol, o.integrator.atol = 0.1 * *a.tol;
  o.tangent_tolerance = a.tangent_tolerance;
  o.accept = a.common.accept;
  const int n = sample_count(a.common);
  const Result<SpaceCurve, SpaceInfo> res =
      compound ? solve_compound_space_segment(ends,
                                              {alpha, a.alpha1.value_or(alpha), beta, a.beta1.value_or(beta), a.omega,
                                               a.r_theta.value_or(0.5), type},
                                              o)
               : solve_g1_space_segment(ends, {alpha, beta, a.omega, type}, o);
  Report r{construction_report(res.summary), {}};
  Json& j = r.json;
  const bool drawn = res.usable() && !res.curve.pieces().empty();
  if (drawn) add_space_curve(j, res.curve);
  const Json none3 = {{"x", nullptr}, {"y", nullptr}, {"z", nullptr}};
  Json info = {{"rhythm", compound ? "compound" : "g1"},
               {"torsion_sign", res.info.torsion_sign},
               {"runs", res.info.runs},
               {"constructions", res.summary.constructions},
               {"end_tangent", drawn ? xyz(res.info.end_tangent) : none3}};
  if (compound) info["joint"] = drawn && res.info.joint ? xyz(*res.info.joint) : none3;
  j["info"] = std::move(info);
  if (drawn) add_space_points(j, res.curve, n);
  add_export(j, drawn ? &res.curve : nullptr, a.common);
  return r;
}

void setup(CLI::App& app) {
  auto* a = owned<SpaceArgs>();
  auto* sub = app.add_subcommand(
      "space", "LA space segment [Yoshida-Fukuda-Saito-Saito 2011]: G1 by the cone construction, or compound-rhythm "
               "when --alpha1/--beta1/--r-theta is given");
  sub->add_option("--p0", a->p0, "Start point \"x,y,z\" (required)");
  sub->add_option("--v0", a->v0, "Start tangent vector \"x,y,z\" (nonzero, not parallel to p1 - p0) (required)");
  sub->add_option("--p1", a->p1, "End point \"x,y,z\" (required)");
  sub->add_option("--v1", a->v1, "End tangent vector \"x,y,z\" (nonzero) (required)");
  sub->add_option("--alpha", a->alpha, "LCG slope (alpha0 of a compound segment), finite (required)");
  sub->add_option("--beta", a->beta, "LTG slope (beta0 of a compound segment), finite (required)");
  sub->add_option("--omega", a->omega, "Torsion parameter Omega (Omega0) >= 0")->capture_default_str();
  sub->add_option("--type", a->type, "1: rho and mu increase; 2: rho increases, mu decreases")->capture_default_str();
  sub->add_option("--alpha1", a->alpha1, "Compound: LCG slope of the second segment (default --alpha)");
  sub->add_option("--beta1", a->beta1, "Compound: LTG slope of the second segment (default --beta)");
  sub->add_option("--r-theta", a->r_theta, "Compound: cone ratio r_theta in (0, 1) placing the joint (default 0.5)");
  sub->add_option("--solver", a->solver, "N-D solver: " + solver_names(nonlinear_methods()))->capture_default_str();
  sub->add_option("--integrator", a->integrator, "Frenet integration: " + method_names_text(ode_methods(), " | "))
      ->capture_default_str();
  sub->add_option("--tol", a->tol, "Integration rtol (default 1e-10; atol = tol/10)");
  sub->add_option("--tangent-tolerance", a->tangent_tolerance, "Success: end-tangent error <= this (rad)")->capture_default_str();
  add_common_options(*sub, a->common, false);
  add_export_options(*sub, a->common);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
