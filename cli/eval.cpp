// lac eval: position and frame of a standard-form planar LA curve at θ or s (docs/math.md §1).
#include <algorithm>
#include <cmath>

#include "cli/batch.hpp"
#include "cli/export.hpp"
#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "io/timing.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/planar/standard_form.hpp"

namespace lac::cli {
namespace {

struct EvalArgs {
  CommonArgs common;
  std::optional<double> alpha, lambda, theta, s;
  std::string form = "auto";
  QuadratureArgs quadrature{.integrator = "gauss-kronrod"};
};

/// The arc of the standard form from s = 0 to `s_end` as a curve of one segment (none when
/// s_end = 0 or its values are not representable).
std::optional<PlanarCurve> standard_arc(const LaCurve& curve, double s_end) {
  if (s_end == 0) return std::nullopt;
  try {
    return PlanarCurve({to_segment(StandardPiece{curve, Parameter::s, 0.0, s_end, {}})});
  } catch (const InputError&) {
    return std::nullopt;
  }
}

Report solve(const EvalArgs& a) {
  const LaCurve curve(need(a.alpha, "alpha"), need(a.lambda, "lambda"));
  if (a.theta && a.s) throw_input_error("lac eval", "theta", "give one of --theta or --s, not both");
  if (!a.theta && !a.s) throw_input_error("lac eval", "theta", "one of --theta or --s is required");
  const Parameter p = a.theta ? Parameter::theta : Parameter::s;
  const double t = a.theta ? radians(*a.theta, a.common) : *a.s;
  curve.check(p, t, p == Parameter::theta ? "theta" : "s");
  const Form form = parse_form(a.form);
  const AnyQuadrature method = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  const int n = sample_count(a.common);
  io::Stopwatch clock;
  const double accept = a.common.accept;
  const PositionResult at = position_at(curve, p, t, method, form, accept);
  std::vector<PositionResult> pts;
  // Samples uniform in arc length from s = 0 to the evaluated point (docs/cli.md).
  if (n > 0) pts = polyline(curve, Parameter::s, 0.0, at.point.s, n, method, form, accept);
  const double seconds = clock.seconds();
  const long evaluations = at.evaluations + (pts.empty() ? 0 : pts.back().evaluations);  // cumulative along a polyline
  // error: the largest relative error over the printed points (estimate / arc length integrated over).
  double error = detail::relative_error(at);
  for (size_t k = 0; k < pts.size(); ++k) error = std::max(error, pts[k].error_estimate / detail::path_scale(pts, k));
  Report r{evaluation_report(at.status, at.status == Status::ok ? "" : at.message, evaluations, seconds, describe(method),
                             error, accept),
           {}};
  Json& j = r.json;
  const double s_end = at.point.s;
  set_extent(j, std::abs(s_end), 1.0, at.point.kappa);
  const std::optional<PlanarCurve> arc = standard_arc(curve, s_end);
  j["segments"] = Json::array();
  if (arc) j["segments"].push_back(planar_segment(arc->segments().front()));
  j["point"] = planar_point(at);
  j["info"] = {{"form", std::string(to_string(at.form))},
               {"rho", number(at.point.rho)},
               {"error_estimate", number(at.error_estimate)}};
  if (!pts.empty()) {
    Json arr = Json::array();
    for (const PositionResult& q : pts) arr.push_back(planar_point(q));
    j["points"] = std::move(arr);
  }
  add_export(j, usable(at.status) && arc ? &*arc : nullptr, a.common);  // --export: that arc
  return r;
}

void setup(CLI::App& app) {
  auto* a = owned<EvalArgs>();
  auto* sub = app.add_subcommand("eval", "Point on the standard-form planar LA curve (origin, tangent +x, rho = 1 at s = 0)");
  sub->add_option("--alpha", a->alpha, "Slope alpha of the logarithmic curvature graph, any finite real (required)");
  sub->add_option("--lambda", a->lambda, "Lambda >= 0, 0 is the unit circle (required)");
  sub->add_option("--theta", a->theta, "Tangent angle at which to evaluate, rad (degrees with --degrees)");
  sub->add_option("--s", a->s, "Arc length at which to evaluate");
  sub->add_option("--form", a->form, "Position integral: theta | s | auto")->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  add_common_options(*sub, a->common, true);
  add_export_options(*sub, a->common);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
