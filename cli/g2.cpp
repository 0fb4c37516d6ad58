// lac g2: G2 Hermite interpolation by a triple LA curve (004 §3); see docs/hermite.md.
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "lac/common/error.hpp"
#include "lac/constructions/g2_hermite.hpp"

namespace lac::cli {
namespace {

struct G2Args {
  std::string p0, p1;
  double theta0 = 0, theta1 = 0, kappa0 = 0, kappa1 = 0, alpha = -1;
  std::string solver = "newton", start = "fast";
  bool no_fallback = false;
  int points = 0;
  std::string* format = nullptr;
};

nlohmann::json sample_json(const hermite::CurveSample& s) {
  return {{"S", s.S},         {"s", s.s},        {"x", s.position.real()}, {"y", s.position.imag()},
          {"theta", s.theta}, {"kappa", s.kappa}};
}

void run(const G2Args& a) {
  const auto p0 = parse_tuple(a.p0, 2, "p0"), p1 = parse_tuple(a.p1, 2, "p1");
  hermite::G2Problem pr{{{p0[0], p0[1]}, a.theta0, a.kappa0}, {{p1[0], p1[1]}, a.theta1, a.kappa1}, a.alpha};
  hermite::G2Options o;
  o.solver = hermite::parse_g2_solver(a.solver);
  o.start = hermite::parse_g2_start(a.start);
  o.grid_fallback = !a.no_fallback;
  if (a.points < 0 || a.points == 1) throw_input_error("lac g2", "points", a.points, "0 or [2, inf)");
  const hermite::G2Result r = hermite::solve_g2(pr, o);
  std::vector<hermite::CurveSample> pts;
  if (a.points >= 2 && usable(r.status)) pts = r.curve.polyline(a.points);
  const Format fmt = parse_format(*a.format);
  const auto coefficients = r.curve.coefficients();
  if (fmt == Format::json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(r.status));
    if (!r.message.empty()) j["message"] = r.message;
    j["alpha"] = a.alpha;
    j["solver"] = a.solver;
    j["start"] = std::string(hermite::to_string(r.start_used));
    j["length"] = r.length;
    j["residual_position"] = r.residual_position;
    j["residual_angle"] = r.residual_angle;
    j["residual_curvature"] = r.residual_curvature;
    j["iterations"] = r.iterations;
    j["evaluations"] = r.evaluations;
    j["seconds"] = r.seconds;
    j["start_seconds"] = r.start_seconds;
    nlohmann::json segs = nlohmann::json::array();
    if (usable(r.status)) {
      for (const auto& c : coefficients)
        segs.push_back({{"S_begin", c.S_begin}, {"S_end", c.S_end}, {"c0", c.c0}, {"c1", c.c1}, {"c2", c.c2}});
    }
    j["segments"] = segs;
    if (a.points >= 2) {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& s : pts) arr.push_back(sample_json(s));
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (fmt == Format::csv) {
    if (a.points >= 2) {
      std::cout << "S,s,x,y,theta,kappa\n";
      for (const auto& s : pts)
        std::cout << s.S << "," << s.s << "," << s.position.real() << "," << s.position.imag() << "," << s.theta << ","
                  << s.kappa << "\n";
    } else {
      std::cout << "status,length,residual_position,residual_angle,residual_curvature,iterations,evaluations,seconds\n"
                << to_string(r.status) << "," << r.length << "," << r.residual_position << "," << r.residual_angle
                << "," << r.residual_curvature << "," << r.iterations << "," << r.evaluations << "," << r.seconds
                << "\n";
    }
    return;
  }
  std::cout << "status " << to_string(r.status) << (r.message.empty() ? "" : " (" + r.message + ")") << "\n"
            << "length " << r.length << "\nresiduals position " << r.residual_position << ", angle " << r.residual_angle
            << ", curvature " << r.residual_curvature << "\niterations " << r.iterations << ", " << r.seconds << " s\n";
  if (usable(r.status)) {
    for (const auto& c : coefficients)
      std::cout << "segment S in [" << c.S_begin << ", " << c.S_end << "]: c0 " << c.c0 << ", c1 " << c.c1 << ", c2 "
                << c.c2 << "\n";
  }
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
  sub->add_option("--solver", a->solver, "paper | newton | ceres")->capture_default_str();
  sub->add_option("--start", a->start, "Initial estimate: fast | bezier-grid")->capture_default_str();
  sub->add_flag("--no-fallback", a->no_fallback, "Do not retry from the Bezier-grid start when the fast start fails");
  sub->add_option("--points", a->points, "Number of curve points to print (0: none)")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv", "table"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
