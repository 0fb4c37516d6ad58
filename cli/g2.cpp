// lac g2: G2 Hermite interpolation by a triple LA curve (004 §3); see docs/hermite.md.
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/common/error.hpp"
#include "lac/constructions/g2_hermite.hpp"

namespace lac::cli {
namespace {

struct G2Args {
  std::string p0, p1;
  double theta0 = 0, theta1 = 0, kappa0 = 0, kappa1 = 0, alpha = -1;
  std::string solver = "newton", start = "fast";
  QuadratureArgs quadrature{.integrator = "gauss-legendre"};
  bool no_fallback = false;
  int points = 0;
  std::string* format = nullptr;
};

/// A residual as the output has always shown it: 0 where the result has none (no usable curve).
double shown(const std::optional<double>& v) { return v.value_or(0.0); }

void run(const G2Args& a) {
  const auto p0 = parse_tuple(a.p0, 2, "p0"), p1 = parse_tuple(a.p1, 2, "p1");
  const G2Problem pr{{{p0[0], p0[1]}, a.theta0, a.kappa0}, {{p1[0], p1[1]}, a.theta1, a.kappa1}, a.alpha};
  G2Options o;
  o.solver = parse_g2_solver(a.solver);
  o.start = parse_g2_start(a.start);
  o.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  o.grid_fallback = !a.no_fallback;
  if (a.points < 0 || a.points == 1) throw_input_error("lac g2", "points", a.points, "0 or [2, inf)");
  const G2Result r = solve_g2(pr, o);
  const Summary& sum = r.summary;
  record_status(sum.status);
  // Points by the curve's Gauss–Legendre positions; S = s / length, uniform.
  std::vector<PositionResult> pts;
  if (a.points >= 2 && r.usable()) pts = r.curve.sample(a.points);
  const auto S_at = [&](size_t k) { return k + 1 == pts.size() ? 1.0 : static_cast<double>(k) / (pts.size() - 1); };
  const Format fmt = parse_format(*a.format);
  if (fmt == Format::json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(sum.status));
    if (!sum.message.empty()) j["message"] = sum.message;
    j["alpha"] = a.alpha;
    j["solver"] = sum.solver;
    j["integrator"] = describe(o.integrator);
    j["start"] = std::string(to_string(r.info.start_used));
    j["length"] = r.curve.length();
    j["residual_position"] = shown(sum.residuals.position);
    j["residual_angle"] = shown(sum.residuals.angle);
    j["residual_curvature"] = shown(sum.residuals.curvature);
    j["iterations"] = sum.iterations;
    j["evaluations"] = sum.evaluations;
    j["seconds"] = sum.seconds;
    j["start_seconds"] = r.info.start_seconds;
    nlohmann::json segs = nlohmann::json::array();
    if (r.usable()) {
      for (const auto& c : r.info.coefficients)
        segs.push_back({{"S_begin", c.S_begin}, {"S_end", c.S_end}, {"c0", c.c0}, {"c1", c.c1}, {"c2", c.c2}});
    }
    j["segments"] = segs;
    if (a.points >= 2) {
      nlohmann::json arr = nlohmann::json::array();
      for (size_t k = 0; k < pts.size(); ++k) {
        const CurvePoint& q = pts[k].point;
        arr.push_back({{"S", S_at(k)}, {"s", q.s}, {"x", q.position.real()}, {"y", q.position.imag()},
                       {"theta", q.theta}, {"kappa", q.kappa}});
      }
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (fmt == Format::csv) {
    if (a.points >= 2) {
      std::cout << "S,s,x,y,theta,kappa\n";
      for (size_t k = 0; k < pts.size(); ++k) {
        const CurvePoint& q = pts[k].point;
        std::cout << S_at(k) << "," << q.s << "," << q.position.real() << "," << q.position.imag() << "," << q.theta
                  << "," << q.kappa << "\n";
      }
    } else {
      std::cout << "status,length,residual_position,residual_angle,residual_curvature,iterations,evaluations,seconds\n"
                << to_string(sum.status) << "," << r.curve.length() << "," << shown(sum.residuals.position) << ","
                << shown(sum.residuals.angle) << "," << shown(sum.residuals.curvature) << "," << sum.iterations << ","
                << sum.evaluations << "," << sum.seconds << "\n";
    }
    return;
  }
  std::cout << "status " << to_string(sum.status) << (sum.message.empty() ? "" : " (" + sum.message + ")") << "\n"
            << "solver " << sum.solver << ", integrator " << describe(o.integrator) << "\n"
            << "length " << r.curve.length() << "\nresiduals position " << shown(sum.residuals.position) << ", angle "
            << shown(sum.residuals.angle) << ", curvature " << shown(sum.residuals.curvature) << "\niterations "
            << sum.iterations << ", " << sum.seconds << " s\n";
  if (r.usable()) {
    for (const auto& c : r.info.coefficients)
      std::cout << "segment S in [" << c.S_begin << ", " << c.S_end << "]: c0 " << c.c0 << ", c1 " << c.c1 << ", c2 "
                << c.c2 << "\n";
  }
}

std::string solver_names() {
  std::string out;
  for (const auto& m : g2_solvers()) out += (out.empty() ? "" : " | ") + std::string(m.name);
  return out;
}

void setup(CLI::App& app) {
  auto* a = owned<G2Args>();
  auto* sub = app.add_subcommand("g2", "G2 Hermite interpolation by three LA segments of one alpha (004 §3)");
  sub->add_option("--p0", a->p0, "Start point \"x,y\"")->required();
  sub->add_option("--theta0", a->theta0, "Tangent angle at the start (rad)")->required();
  sub->add_option("--kappa0", a->kappa0, "Signed curvature at the start")->required();
  sub->add_option("--p1", a->p1, "End point \"x,y\"")->required();
  sub->add_option("--theta1", a->theta1, "Tangent angle at the end (rad)")->required();
  sub->add_option("--kappa1", a->kappa1, "Signed curvature at the end")->required();
  sub->add_option("--alpha", a->alpha, "Slope of the LCG, one for the three segments, [-5, 5]")->capture_default_str();
  sub->add_option("--solver", a->solver, solver_names() + " (N-D registry, or 004's paper)")->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  sub->add_option("--start", a->start, "Initial estimate: fast | bezier-grid")->capture_default_str();
  sub->add_flag("--no-fallback", a->no_fallback, "Do not retry from the Bezier-grid start when the fast start fails");
  sub->add_option("--points", a->points, "Number of curve points to print (0: none)")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv", "table"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
