// lac quadratic: points of a quadratic log-aesthetic curve (003; docs/math.md §4) in standard form.
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/command.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"
#include "io/timing.hpp"

namespace lac::cli {
namespace {

struct QuadraticArgs {
  double alpha = 0, gamma = 0, lambda = 1;
  std::optional<double> s_from, s_to;
  int points = 100;
  QuadratureArgs quadrature{.integrator = "gauss-kronrod"};
  std::string inverse = "ours";
  bool through_inflection = false;
  std::string* format = nullptr;
};

// JSON has no infinity: an unbounded end is null.
nlohmann::json bound(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Default range: 99.9 % of a finite bound, ±2/Λ toward an unbounded end.
double default_end(double bound_value, double sign, double lambda) {
  return std::isfinite(bound_value) ? 0.999 * bound_value : sign * 2.0 / lambda;
}

void run(const QuadraticArgs& a) {
  QuadraticOptions options;
  options.inverse = special::parse_erf_inverse_method(a.inverse);
  options.through_inflection = a.through_inflection;
  const QuadraticLaCurve curve(a.alpha, a.gamma, a.lambda, options);
  const Interval d = curve.s_domain();
  const double s0 = a.s_from.value_or(default_end(d.lo, -1.0, a.lambda));
  const double s1 = a.s_to.value_or(default_end(d.hi, 1.0, a.lambda));
  curve.check_s(s0, "s-from");
  curve.check_s(s1, "s-to");
  if (a.points < 1) throw_input_error("lac quadratic", "points", a.points, "[1, inf)");
  const AnyQuadrature method = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  io::Stopwatch clock;
  std::vector<PositionResult> pts;
  if (a.points == 1) pts.push_back(position_at(curve, s1, method));
  else pts = polyline(curve, s0, s1, a.points, method);
  const double seconds = clock.seconds();
  for (const auto& r : pts) record_status(r.status);  // a polyline is usable if every point is
  const std::string described = describe(method);

  if (parse_format(*a.format) == Format::json) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& r : pts) {
      arr.push_back({{"s", r.point.s}, {"x", r.point.position.real()}, {"y", r.point.position.imag()},
                     {"theta", r.point.theta}, {"kappa", r.point.kappa}, {"rho", bound(r.point.rho)},
                     {"error_estimate", r.error_estimate}, {"evaluations", r.evaluations},
                     {"status", std::string(to_string(r.status))}});
    }
    const nlohmann::json j = {
        {"alpha", a.alpha}, {"gamma", a.gamma}, {"lambda", a.lambda},
        {"inverse", a.inverse}, {"integrator", described}, {"through_inflection", a.through_inflection},
        {"bounds", {{"s_at_infinite_kappa", bound(curve.s_at_infinite_kappa())},
                    {"s_at_zero_kappa", bound(curve.s_at_zero_kappa())},
                    {"has_inflection", curve.has_inflection()},
                    {"theta_at_zero_kappa", bound(curve.theta_at_zero_kappa())}}},
        {"seconds", seconds}, {"points", arr}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  std::cout << "# quadratic LA curve alpha=" << a.alpha << " gamma=" << a.gamma << " lambda=" << a.lambda << ", " << described
            << ", inverse " << a.inverse << ", " << seconds << " s\n"
            << "# s_at_infinite_kappa=" << curve.s_at_infinite_kappa() << " s_at_zero_kappa=" << curve.s_at_zero_kappa() << "\n"
            << "s,x,y,theta,kappa,rho,error_estimate,evaluations,status\n";
  for (const auto& r : pts) {
    std::cout << r.point.s << "," << r.point.position.real() << "," << r.point.position.imag() << "," << r.point.theta << ","
              << r.point.kappa << "," << r.point.rho << "," << r.error_estimate << "," << r.evaluations << ","
              << to_string(r.status) << "\n";
  }
}

void setup(CLI::App& app) {
  auto* a = owned<QuadraticArgs>();
  auto* sub = app.add_subcommand("quadratic", "Quadratic log-aesthetic curve (003): kappa=1, tangent +x at the origin at s=0");
  sub->add_option("--alpha", a->alpha, "Linear LCG coefficient alpha (finite)")->required();
  sub->add_option("--gamma", a->gamma, "Quadratic LCG coefficient gamma (finite; 0 is the LA curve)")->required();
  sub->add_option("--lambda", a->lambda, "Lambda > 0")->required();
  sub->add_option("--s-from", a->s_from, "First arc length (default: 99.9% of a finite bound, else -2/lambda)");
  sub->add_option("--s-to", a->s_to, "Last arc length (default: 99.9% of a finite bound, else 2/lambda)");
  sub->add_option("--points", a->points, "Number of points uniform in s (1: only --s-to)")->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  sub->add_option("--inverse", a->inverse, "erfi/erf inverse for kappa(s): ours | hybrid-003")
      ->check(CLI::IsMember({"ours", "hybrid-003"}))
      ->capture_default_str();
  sub->add_flag("--through-inflection", a->through_inflection, "Continue past kappa = 0 point-symmetrically (signed kappa)");
  a->format = add_format_option(*sub, {"json", "csv"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
