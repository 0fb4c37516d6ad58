// lac scurve: S-shaped (or C-shaped) LA curve from four control points, α < 0 (004 §2.4–2.5).
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "lac/common/error.hpp"
#include "lac/constructions/s_curve.hpp"

namespace lac::cli {
namespace {

struct SCurveArgs {
  std::string points;
  double alpha = -1;
  std::string root = "toms748";
  int points_out = 0;
  std::string* format = nullptr;
};

void run(const SCurveArgs& a) {
  const auto p = parse_points(a.points, 4, "points");
  std::array<std::complex<double>, 4> P;
  for (size_t k = 0; k < 4; ++k) P[k] = {p[k][0], p[k][1]};
  hermite::SCurveOptions o;
  o.root = hermite::parse_root_method(a.root);
  if (a.points_out < 0 || a.points_out == 1)
    throw_input_error("lac scurve", "points-out", a.points_out, "0 or [2, inf)");
  const hermite::SCurveResult r = hermite::solve_s_curve(P, a.alpha, o);
  std::vector<hermite::CurveSample> pts;
  if (a.points_out >= 2 && usable(r.status)) pts = r.polyline(a.points_out);
  const Format fmt = parse_format(*a.format);
  if (fmt == Format::json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(r.status));
    if (!r.message.empty()) j["message"] = r.message;
    j["shape"] = std::string(hermite::to_string(r.shape));
    j["alpha"] = r.alpha;
    j["lambda"] = r.lambda;
    j["length"] = r.length;
    j["inflection_s"] = r.inflection_s;
    j["mirrored"] = r.mirrored;
    j["reversed"] = r.reversed;
    j["residual_position"] = r.residual_position;
    j["residual_angle"] = r.residual_angle;
    j["iterations"] = r.iterations;
    j["evaluations"] = r.evaluations;
    j["seconds"] = r.seconds;
    if (a.points_out >= 2) {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& s : pts)
        arr.push_back({{"t", s.S},
                       {"s", s.s},
                       {"x", s.position.real()},
                       {"y", s.position.imag()},
                       {"theta", s.theta},
                       {"kappa", s.kappa}});
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (a.points_out >= 2) {
    std::cout << "t,s,x,y,theta,kappa\n";
    for (const auto& s : pts)
      std::cout << s.S << "," << s.s << "," << s.position.real() << "," << s.position.imag() << "," << s.theta << ","
                << s.kappa << "\n";
  } else {
    std::cout << "status,shape,lambda,length,inflection_s,residual_position,residual_angle,iterations,seconds\n"
              << to_string(r.status) << "," << hermite::to_string(r.shape) << "," << r.lambda << "," << r.length << ","
              << r.inflection_s << "," << r.residual_position << "," << r.residual_angle << "," << r.iterations << ","
              << r.seconds << "\n";
  }
}

void setup(CLI::App& app) {
  auto* a = owned<SCurveArgs>();
  auto* sub = app.add_subcommand("scurve", "S-shaped LA curve from four control points and alpha < 0 (004 §2.4-2.5)");
  sub->add_option("--points", a->points,
                  "Control points \"x0,y0 x1,y1 x2,y2 x3,y3\": start tangent P0->P1, end tangent P2->P3")
      ->required();
  sub->add_option("--alpha", a->alpha, "Slope of the LCG, [-5, 0)")->capture_default_str();
  sub->add_option("--root", a->root, "Root finder on Lambda: bisection (004) | toms748")->capture_default_str();
  sub->add_option("--points-out", a->points_out, "Number of curve points to print (0: none)")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
