// lac space: G1 or compound-rhythm LA space segment between two points with end tangents (000).
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli/command.hpp"
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
  o.integrator.method = parse_ode_method(a.integrator);
  if (a.tol) o.integrator.rtol = *a.tol, o.integrator.atol = 0.1 * *a.tol;
  o.tangent_tolerance = a.tangent_tolerance;
  if (a.points < 0 || a.points == 1) throw_input_error("lac space", "points", a.points, "0 or [2, inf)");
  const Result<SpaceCurve, SpaceInfo> r =
      compound ? solve_compound_space_segment(ends,
                                              {a.alpha, a.alpha1.value_or(a.alpha), a.beta, a.beta1.value_or(a.beta),
                                               a.omega, a.r_theta.value_or(0.5), type},
                                              o)
               : solve_g1_space_segment(ends, {a.alpha, a.beta, a.omega, type}, o);
  const Summary& sum = r.summary;
  const SpaceCurve& curve = r.curve;
  const bool drawn = !curve.pieces().empty();
  std::vector<SpacePoint> pts;
  if (a.points >= 2 && drawn) pts = curve.sample(a.points);
  record_status(sum.status);
  for (const SpacePoint& p : pts) record_status(p.status);
  const double scale = drawn ? curve.placement().scale : 0.0;
  const double tangent_error = sum.residuals.angle.value_or(std::numeric_limits<double>::infinity());
  auto optional_json = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };

  const Format fmt = parse_format(*a.format);
  if (fmt == Format::json) {
    nlohmann::json segs = nlohmann::json::array();
    for (const SpacePiece& p : curve.pieces())
      segs.push_back({{"alpha", p.law.alpha()}, {"beta", p.law.beta()}, {"lambda", p.law.lambda()},
                      {"omega", p.law.omega()}, {"nu", p.law.nu()}, {"type", static_cast<int>(p.law.type())},
                      {"s_begin", p.s_begin}, {"s_end", p.s_end}, {"length", scale * (p.s_end - p.s_begin)}});
    nlohmann::json j = {{"status", std::string(to_string(sum.status))},
                        {"message", sum.message},
                        {"kind", compound ? "compound" : "g1"},
                        {"solver", sum.solver},
                        {"integrator", sum.integrator},
                        {"length", drawn ? nlohmann::json(curve.length()) : nlohmann::json(nullptr)},
                        {"tangent_error", optional_json(sum.residuals.angle)},
                        {"position_error", optional_json(sum.residuals.position)},
                        {"torsion_sign", r.info.torsion_sign},
                        {"iterations", sum.iterations},
                        {"evaluations", sum.constructions},
                        {"ode_evaluations", sum.evaluations},
                        {"solver_runs", r.info.runs},
                        {"seconds", sum.seconds},
                        {"segments", segs}};
    if (r.info.joint && drawn) j["joint"] = vec_json(*r.info.joint);
    if (drawn) j["end_tangent"] = vec_json(r.info.end_tangent);
    if (!pts.empty()) {
      nlohmann::json arr = nlohmann::json::array();
      for (const SpacePoint& p : pts) {
        nlohmann::json q = {{"s", p.s}, {"x", p.p.x()}, {"y", p.p.y()}, {"z", p.p.z()}, {"tangent", vec_json(p.t)},
                            {"normal", vec_json(p.n)}, {"binormal", vec_json(p.b)}, {"kappa", p.kappa}, {"tau", p.tau},
                            {"segment", p.piece}};
        if (p.status != Status::ok) q["status"] = std::string(to_string(p.status)), q["message"] = p.message;
        arr.push_back(q);
      }
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (pts.empty()) {
    std::cout << "status,length,tangent_error,iterations,evaluations,seconds,segments\n";
    std::cout << to_string(sum.status) << ',' << curve.length() << ',' << tangent_error << ',' << sum.iterations << ','
              << sum.constructions << ',' << sum.seconds << ',' << curve.pieces().size() << "\n";
    return;
  }
  std::cout << "# status " << to_string(sum.status) << ", length " << curve.length() << ", tangent_error "
            << tangent_error << ", iterations " << sum.iterations << ", seconds " << sum.seconds << "\n";
  for (const SpacePoint& p : pts)
    if (p.status != Status::ok)
      std::cout << "# point at s = " << p.s << ": " << to_string(p.status) << " (" << p.message << ")\n";
  std::cout << "s,x,y,z,tx,ty,tz,kappa,tau,segment\n";
  for (const SpacePoint& p : pts)
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
  std::string solvers;
  for (const NonlinearMethodInfo& m : nonlinear_methods()) solvers.append(solvers.empty() ? "" : " | ").append(m.name);
  sub->add_option("--solver", a->solver, "N-D solver (simplex is 000's): " + solvers)->capture_default_str();
  sub->add_option("--integrator", a->integrator, "Frenet integration: " + method_names_text(ode_methods(), " | "))
      ->capture_default_str();
  sub->add_option("--tol", a->tol, "Integration rtol (default 1e-10; atol = tol/10)");
  sub->add_option("--tangent-tolerance", a->tangent_tolerance, "Success: end-tangent error <= this (rad)")->capture_default_str();
  sub->add_option("--points", a->points, "Also output this many curve points, uniform in arc length (0: none)")->capture_default_str();
  a->format = add_format_option(*sub, {"json", "csv"});
  sub->callback([a] { run(*a); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
