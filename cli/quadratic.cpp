// lac quadratic: points of a quadratic log-aesthetic curve [Yoshida–Saito 2016] (docs/math.md §4)
// in standard form.
#include <algorithm>
#include <cmath>

#include "cli/batch.hpp"
#include "cli/export.hpp"
#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "io/timing.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"

namespace lac::cli {
namespace {

struct QuadraticArgs {
  CommonArgs common{.samples = 100, .format = "json", .batch = {}, .degrees = false};
  std::optional<double> alpha, gamma, lambda, s_from, s_to;
  QuadratureArgs quadrature{.integrator = "gauss-kronrod"};
  std::string inverse = "ours";
  bool through_inflection = false;
  std::optional<double> max_evaluations;
};

Report solve(const QuadraticArgs& a) {
  QuadraticOptions options;
  options.inverse = special::parse_erf_inverse_method(a.inverse);
  options.through_inflection = a.through_inflection;
  const double lambda = need(a.lambda, "lambda");
  const QuadraticLaCurve curve(need(a.alpha, "alpha"), need(a.gamma, "gamma"), lambda, options);
  const Interval range = curve.default_range();  // docs/quadratic.md
  const double s0 = a.s_from.value_or(range.lo);
  const double s1 = a.s_to.value_or(range.hi);
  curve.check_s(s0, "s-from");
  curve.check_s(s1, "s-to");
  const long max_evaluations = max_evaluations_option(a.max_evaluations, 1e10);
  const double accept = a.common.accept;
  const AnyQuadrature method = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  const int n = sample_count(a.common);
  io::Stopwatch clock;
  const PositionResult start = position_at(curve, s0, method, accept, max_evaluations);
  std::vector<PositionResult> pts;
  if (n > 0) pts = polyline(curve, s0, s1, n, method, accept, max_evaluations);
  const double seconds = clock.seconds();
  const PositionResult* failed = usable(start.status) ? nullptr : &start;
  for (const PositionResult& q : pts)
    if (!failed && !usable(q.status)) failed = &q;
  const long evaluations = start.evaluations + (pts.empty() ? 0 : pts.back().evaluations);
  // error: the largest relative error over the printed points (estimate / arc length integrated over).
  double error = detail::relative_error(start);
  for (size_t k = 0; k < pts.size(); ++k) error = std::max(error, pts[k].error_estimate / detail::path_scale(pts, k));
  std::string message = failed ? failed->message : "";
  if (failed && failed->status == Status::max_iterations && message.find("evaluation budget") != std::string::npos)
    message += " (--max-evaluations, [1, 1e10])";
  Report r{evaluation_report(failed ? failed->status : Status::ok, message, evaluations, seconds,
                             describe(method), error, accept),
           {}};
  Json& j = r.json;
  const double kappa1 = curve.frame_at(s1).kappa;
  set_extent(j, s1 - s0, start.point.kappa, kappa1);
  const Json start_point = planar_point(start);
  j["segments"] = Json::array({Json{{"kind", "quadratic-la"},
                                    {"alpha", curve.alpha()},
                                    {"gamma", curve.gamma()},
                                    {"lambda", curve.lambda()},
                                    {"length", number(s1 - s0)},
                                    {"start", {{"x", start_point["x"]}, {"y", start_point["y"]}}},
                                    {"s", number(s0)},
                                    {"theta", number(start.point.theta)},
                                    {"kappa", number(start.point.kappa)},
                                    {"kappa_end", number(kappa1)}}});
  j["bounds"] = {{"s_at_infinite_kappa", number(curve.s_at_infinite_kappa())},
                 {"s_at_zero_kappa", number(curve.s_at_zero_kappa())},
                 {"has_inflection", curve.has_inflection()},
                 {"theta_at_zero_kappa", number(curve.theta_at_zero_kappa())}};
  j["info"] = {{"inverse", a.inverse}, {"through_inflection", a.through_inflection}};
  if (!pts.empty()) {
    Json arr = Json::array();
    for (const PositionResult& q : pts) arr.push_back(planar_point(q));
    j["points"] = std::move(arr);
  }
  // --export: the drawn arc, oriented by increasing s (the same points when --s-from > --s-to).
  const QuadraticArc arc{curve, std::min(s0, s1), std::max(s0, s1)};
  add_export(j, failed == nullptr && s0 != s1 ? &arc : nullptr, a.common);
  return r;
}

void setup(CLI::App& app) {
  auto* a = owned<QuadraticArgs>();
  auto* sub = app.add_subcommand("quadratic", "Quadratic log-aesthetic curve [Yoshida-Saito 2016]: kappa = 1, tangent +x "
                                              "at the origin at s = 0");
  sub->add_option("--alpha", a->alpha, "Linear LCG coefficient alpha, finite (required)");
  sub->add_option("--gamma", a->gamma, "Quadratic LCG coefficient gamma, finite; 0 is the LA curve (required)");
  sub->add_option("--lambda", a->lambda, "Lambda > 0 (required)");
  sub->add_option("--s-from", a->s_from,
                  "Start of the drawn arc (default: from s = 0 toward kappa -> inf until |theta| = 2 pi, kappa = 1e3 "
                  "or 99.9% of a finite bound, whichever comes first)");
  sub->add_option("--s-to", a->s_to,
                  "End of the drawn arc (default: toward kappa -> 0 until |theta| = 2 pi, kappa = 1e-3 or 99.9% of a "
                  "finite bound; with --through-inflection the mirror image of the start past the inflection)");
  add_quadrature_options(*sub, a->quadrature);
  sub->add_option("--max-evaluations", a->max_evaluations,
                  "Integrand evaluations the positions may spend, in [1, 1e10] (default: the integrator's budget, "
                  "e.g. 840021 + 1344 per point for gauss-kronrod)");
  sub->add_option("--inverse", a->inverse, "erfi/erf inverse for kappa(s): ours | hybrid-003")
      ->check(CLI::IsMember({"ours", "hybrid-003"}))
      ->capture_default_str();
  sub->add_flag("--through-inflection", a->through_inflection, "Continue past kappa = 0 point-symmetrically (signed kappa)");
  add_common_options(*sub, a->common, true);
  add_export_options(*sub, a->common);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
