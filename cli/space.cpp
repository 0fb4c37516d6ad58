// lac space: G1 or compound-rhythm LA space segment between two points with end tangents (000).
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/command.hpp"
#include "io/timing.hpp"
#include "lac/constructions/space_segment.hpp"

namespace lac::cli {
namespace {

struct SpaceArgs {
  std::string p0, v0, p1, v1;
  double alpha = 0, beta = 0, omega = 0.1;
  int type = 1;
  std::optional<double> alpha1, beta1, r_theta;
  std::string solver = "newton";
  std::string integrator = "magnus6";
  std::optional<double> tol;
  double tangent_tolerance = 1e-11;
  int points = 0;
  std::string* format = nullptr;
};

Vec3 vec(const std::string& text, const char* name) {
  const auto v = parse_tuple(text, 3, name);
  return {v[0], v[1], v[2]};
}

nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

void run(const SpaceArgs& a) {
  const SpaceEndpoints ends{vec(a.p0, "p0"), vec(a.v0, "v0"), vec(a.p1, "p1"), vec(a.v1, "v1")};
  if (a.type != 1 && a.type != 2) throw_input_error("lac space", "type", a.type, "{1, 2}");
  const TorsionType type = a.type == 1 ? TorsionType::type1 : TorsionType::type2;
  const bool compound = a.alpha1 || a.beta1 || a.r_theta;
  SpaceSegmentOptions o;
  o.solver = parse_nonlinear_method(a.solver);
  o.frenet.method = parse_ode_method(a.integrator);
  if (a.tol) o.frenet.rtol = *a.tol, o.frenet.atol = 0.1 * *a.tol;
  o.tangent_tolerance = a.tangent_tolerance;
  if (a.points < 0 || a.points == 1) throw_input_error("lac space", "points", a.points, "0 or [2, inf)");
  io::Stopwatch clock;
  SpaceSegmentResult r;
  if (compound) {
    const CompoundSpaceSpec spec{a.alpha, a.alpha1.value_or(a.alpha), a.beta, a.beta1.value_or(a.beta), a.omega,
                                 a.r_theta.value_or(0.5), type};
    r = solve_compound_space_segment(ends, spec, o);
  } else {
    r = solve_g1_space_segment(ends, {a.alpha, a.beta, a.omega, type}, o);
  }
  const double seconds = clock.seconds();
  std::vector<SpaceSample> pts;
  if (a.points >= 2 && !r.pieces.empty()) pts = space_segment_points(r, std::max(a.points, 2 * static_cast<int>(r.pieces.size())));

  const Format fmt = parse_format(*a.format);
  if (fmt == Format::json) {
    nlohmann::json segs = nlohmann::json::array();
    for (const auto& p : r.pieces)
      segs.push_back({{"alpha", p.alpha}, {"beta", p.beta}, {"lambda", p.lambda}, {"omega", p.omega}, {"nu", p.nu},
                      {"type", static_cast<int>(p.type)}, {"s_begin", p.s_begin}, {"s_end", p.s_end},
                      {"length", r.scale * (p.s_end - p.s_begin)}});
    nlohmann::json j = {{"status", std::string(to_string(r.status))},
                        {"message", r.message},
                        {"kind", compound ? "compound" : "g1"},
                        {"solver", std::string(to_string(r.solver))},
                        {"integrator", std::string(to_string(o.frenet.method))},
                        {"length", r.pieces.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.length)},
                        {"tangent_error", std::isfinite(r.tangent_error) ? nlohmann::json(r.tangent_error) : nlohmann::json(nullptr)},
                        {"position_error", r.pieces.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.position_error)},
                        {"torsion_sign", r.torsion_sign},
                        {"iterations", r.iterations},
                        {"evaluations", r.evaluations},
                        {"ode_evaluations", r.ode_evaluations},
                        {"solver_runs", r.runs},
                        {"seconds", seconds},
                        {"segments", segs}};
    if (compound && !r.pieces.empty()) j["joint"] = vec_json(r.joint);
    if (!r.pieces.empty()) j["end_tangent"] = vec_json(r.end_tangent);
    if (!pts.empty()) {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& p : pts)
        arr.push_back({{"s", p.s}, {"x", p.p.x()}, {"y", p.p.y()}, {"z", p.p.z()}, {"tangent", vec_json(p.t)},
                       {"normal", vec_json(p.n)}, {"binormal", vec_json(p.b)}, {"kappa", p.kappa}, {"tau", p.tau},
                       {"segment", p.piece}});
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (pts.empty()) {
    std::cout << "status,length,tangent_error,iterations,evaluations,seconds,segments\n";
    std::cout << to_string(r.status) << ',' << r.length << ',' << r.tangent_error << ',' << r.iterations << ','
              << r.evaluations << ',' << seconds << ',' << r.pieces.size() << "\n";
    return;
  }
  std::cout << "# status " << to_string(r.status) << ", length " << r.length << ", tangent_error " << r.tangent_error
            << ", iterations " << r.iterations << ", seconds " << seconds << "\n";
  std::cout << "s,x,y,z,tx,ty,tz,kappa,tau,segment\n";
  for (const auto& p : pts)
    std::cout << p.s << ',' << p.p.x() << ',' << p.p.y() << ',' << p.p.z() << ',' << p.t.x() << ',' << p.t.y() << ','
              << p.t.z() << ',' << p.kappa << ',' << p.tau << ',' << p.piece << "\n";
}

void setup(CLI::App& app) {
  auto* a = owned<SpaceArgs>();
  auto* sub = app.add_subcommand(
      "space",
      "LA space segment (000): G1 by the cone construction, or compound-rhythm when --alpha1/--beta1/--r-theta is given");
  sub->add_option("--p0", a->p0, "Start point X,Y,Z")->required();
  sub->add_option("--v0", a->v0, "Start tangent direction X,Y,Z (nonzero, not parallel to p1 - p0)")->required();
  sub->add_option("--p1", a->p1, "End point X,Y,Z")->required();
  sub->add_option("--v1", a->v1, "End tangent direction X,Y,Z (nonzero)")->required();
  sub->add_option("--alpha", a->alpha, "LCG slope (alpha0 of a compound segment), any finite real")->required();
  sub->add_option("--beta", a->beta, "LTG slope (beta0 of a compound segment), any finite real")->required();
  sub->add_option("--omega", a->omega, "Torsion parameter Omega (Omega0) >= 0")->required();
  sub->add_option("--type", a->type, "1: rho and mu increase; 2: rho increases, mu decreases")->required();
  sub->add_option("--alpha1", a->alpha1, "Compound: LCG slope of the second segment (default --alpha)");
  sub->add_option("--beta1", a->beta1, "Compound: LTG slope of the second segment (default --beta)");
  sub->add_option("--r-theta", a->r_theta, "Compound: cone ratio r_theta in (0, 1) placing the joint (default 0.5)");
  sub->add_option("--solver", a->solver, "simplex (000's) | ceres | newton")->capture_default_str();
  sub->add_option("--integrator", a->integrator, "Frenet integration: " + method_names_text(ode_methods(), " | "))
      ->capture_default_str();
  sub->add_option("--tol", a->tol, "Integration rtol (default 1e-10; atol = tol/10)");
  sub->add_option("--tangent-tolerance", a->tangent_tolerance, "Success: end-tangent error <= this (rad)")->capture_default_str();
  sub->add_option("--points", a->points, "Also output this many curve points (0: none)")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
