// lac eval: position and frame of a standard-form planar LA curve at θ or s.
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/command.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "io/timing.hpp"

namespace lac::cli {
namespace {

struct EvalArgs {
  double alpha = 0, lambda = 0;
  std::optional<double> theta, s;
  std::string form = "auto";
  QuadratureArgs quadrature{.integrator = "gauss-kronrod"};
  int points = 1;
  std::string* format = nullptr;
};

nlohmann::json to_json(const PositionResult& r, double seconds) {
  return {{"x", r.point.position.real()}, {"y", r.point.position.imag()}, {"s", r.point.s},
          {"theta", r.point.theta},       {"rho", r.point.rho},           {"kappa", r.point.kappa},
          {"error_estimate", r.error_estimate}, {"evaluations", r.evaluations}, {"seconds", seconds},
          {"status", std::string(to_string(r.status))}, {"form", std::string(to_string(r.form))}};
}

void run(const EvalArgs& a) {
  const LaCurve curve(a.alpha, a.lambda);
  const Parameter p = a.theta ? Parameter::theta : Parameter::s;
  const double t = a.theta ? *a.theta : *a.s;
  curve.check(p, t, p == Parameter::theta ? "theta" : "s");
  const Form form = parse_form(a.form);
  const AnyQuadrature method = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  if (a.points < 1 || a.points > 1'000'000) throw_input_error("lac eval", "points", a.points, "[1, 1000000]");
  io::Stopwatch clock;
  std::vector<PositionResult> results;
  if (a.points == 1) {
    results.push_back(position_at(curve, p, t, method, form));
  } else {
    results = polyline(curve, p, 0.0, t, a.points, method, form);
  }
  const double seconds = clock.seconds();
  for (const auto& r : results) record_status(r.status);  // a polyline is usable if every point is
  const Format fmt = parse_format(*a.format);
  if (fmt == Format::json) {
    if (a.points == 1) {
      std::cout << to_json(results.front(), seconds).dump(2) << "\n";
    } else {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& r : results) arr.push_back(to_json(r, seconds));
      std::cout << arr.dump(2) << "\n";
    }
    return;
  }
  const bool csv = fmt == Format::csv;
  const char* sep = csv ? "," : "  ";
  std::cout.precision(17);
  if (!csv) std::cout << "# " << describe(method) << ", form " << to_string(results.front().form) << ", " << seconds << " s\n";
  std::cout << "x" << sep << "y" << sep << "s" << sep << "theta" << sep << "rho" << sep << "kappa" << sep
            << "error_estimate" << sep << "evaluations" << sep << "status\n";
  for (const auto& r : results) {
    std::cout << r.point.position.real() << sep << r.point.position.imag() << sep << r.point.s << sep << r.point.theta
              << sep << r.point.rho << sep << r.point.kappa << sep << r.error_estimate << sep << r.evaluations << sep
              << to_string(r.status) << "\n";
  }
}

void setup(CLI::App& app) {
  auto* a = owned<EvalArgs>();
  auto* sub = app.add_subcommand("eval", "Point(s) on the standard-form planar LA curve (origin, tangent +x, rho = 1 at 0)");
  sub->add_option("--alpha", a->alpha, "Slope alpha of the logarithmic curvature graph (any finite real)")->required();
  sub->add_option("--lambda", a->lambda, "Lambda >= 0 (0 is the unit circle)")->required();
  auto* th = sub->add_option("--theta", a->theta, "Tangent angle (rad) at which to evaluate");
  auto* so = sub->add_option("--s", a->s, "Arc length at which to evaluate");
  th->excludes(so);
  so->excludes(th);
  sub->add_option("--form", a->form, "Position integral: theta | s | auto")->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  sub->add_option("--points", a->points, "Number of points from the reference point (0) to the given theta/s")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv", "table"});
  sub->callback([a, th, so] {
    if (!*th && !*so) throw_input_error("lac eval", "theta", "one of --theta or --s is required");
    run(*a);
  });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
