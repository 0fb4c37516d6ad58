// lac scurve: S-shaped (or C-shaped) LA curve from four control points, α < 0 (004 §2.4–2.5).
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/common/error.hpp"
#include "lac/constructions/s_curve.hpp"

namespace lac::cli {
namespace {

struct SCurveArgs {
  std::string points;
  double alpha = -1;
  std::string solver = "toms748";
  QuadratureArgs quadrature{.integrator = "gauss-legendre"};
  int points_out = 0;
  std::string* format = nullptr;
};

/// A value as the output has always shown it where the result has none: residuals 0 (no usable
/// curve), inflection_s −1 (no inflection).
double shown(const std::optional<double>& v, double none = 0.0) { return v.value_or(none); }

void run(const SCurveArgs& a) {
  const auto p = parse_points(a.points, 4, "points");
  std::array<std::complex<double>, 4> P;
  for (size_t k = 0; k < 4; ++k) P[k] = {p[k][0], p[k][1]};
  SCurveOptions o;
  o.solver = parse_root_method(a.solver);
  o.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  if (a.points_out < 0 || a.points_out == 1)
    throw_input_error("lac scurve", "points-out", a.points_out, "0 or [2, inf)");
  const SCurveResult r = solve_s_curve(P, a.alpha, o);
  const Summary& sum = r.summary;
  record_status(sum.status);
  // Points by the curve's Gauss–Legendre positions; t = s / length from P0, uniform.
  std::vector<PositionResult> pts;
  if (a.points_out >= 2 && r.usable()) pts = r.curve.sample(a.points_out);
  const auto t_at = [&](size_t k) { return k + 1 == pts.size() ? 1.0 : static_cast<double>(k) / (pts.size() - 1); };
  const Format fmt = parse_format(*a.format);
  if (fmt == Format::json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(sum.status));
    if (!sum.message.empty()) j["message"] = sum.message;
    j["shape"] = std::string(to_string(r.info.shape));
    j["alpha"] = a.alpha;
    j["solver"] = sum.solver;
    j["integrator"] = describe(o.integrator);
    j["lambda"] = r.info.lambda;
    j["length"] = r.curve.length();
    j["inflection_s"] = shown(r.info.inflection_s, -1.0);
    j["mirrored"] = r.info.mirrored;
    j["reversed"] = r.info.reversed;
    j["residual_position"] = shown(sum.residuals.position);
    j["residual_angle"] = shown(sum.residuals.angle);
    j["iterations"] = sum.iterations;
    j["evaluations"] = sum.evaluations;
    j["seconds"] = sum.seconds;
    if (a.points_out >= 2) {
      nlohmann::json arr = nlohmann::json::array();
      for (size_t k = 0; k < pts.size(); ++k) {
        const CurvePoint& q = pts[k].point;
        arr.push_back({{"t", t_at(k)}, {"s", q.s}, {"x", q.position.real()}, {"y", q.position.imag()},
                       {"theta", q.theta}, {"kappa", q.kappa}});
      }
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (a.points_out >= 2) {
    std::cout << "t,s,x,y,theta,kappa\n";
    for (size_t k = 0; k < pts.size(); ++k) {
      const CurvePoint& q = pts[k].point;
      std::cout << t_at(k) << "," << q.s << "," << q.position.real() << "," << q.position.imag() << "," << q.theta << ","
                << q.kappa << "\n";
    }
  } else {
    std::cout << "status,shape,lambda,length,inflection_s,residual_position,residual_angle,iterations,seconds\n"
              << to_string(sum.status) << "," << to_string(r.info.shape) << "," << r.info.lambda << ","
              << r.curve.length() << "," << shown(r.info.inflection_s, -1.0) << "," << shown(sum.residuals.position)
              << "," << shown(sum.residuals.angle) << "," << sum.iterations << "," << sum.seconds << "\n";
  }
}

std::string solver_names() {
  std::string out;
  for (const auto& m : root_methods()) out += (out.empty() ? "" : " | ") + std::string(m.name);
  return out;
}

void setup(CLI::App& app) {
  auto* a = owned<SCurveArgs>();
  auto* sub = app.add_subcommand("scurve", "S-shaped LA curve from four control points and alpha < 0 (004 §2.4-2.5)");
  sub->add_option("--points", a->points,
                  "Control points \"x0,y0 x1,y1 x2,y2 x3,y3\": start tangent P0->P1, end tangent P2->P3")
      ->required();
  sub->add_option("--alpha", a->alpha, "Slope of the LCG, [-5, 0)")->capture_default_str();
  sub->add_option("--solver,--root", a->solver,
                  "Root finder on Lambda: " + solver_names() + " (004: bisection); --root is the former name")
      ->capture_default_str();
  add_quadrature_options(*sub, a->quadrature);
  sub->add_option("--points-out", a->points_out, "Number of curve points to print (0: none)")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
