// The constructions of lac._lac, with the names and options of the command line (docs/cli.md):
// g1_hermite (lac g1), scurve, g2_hermite (lac g2), chain, compound, space. The keyword options of
// each construction are read through ONE table per construction below (name → options field), so
// that a renamed or added option field is one line here.
#include <cmath>
#include <numbers>

#include "bindings.hpp"
#include "lac/constructions/chain.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/space_segment.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lacpy {
namespace {

// ---- option tables ----

const std::vector<OptionRow<lac::G1HermiteOptions>>& g1_table() {
  using O = lac::G1HermiteOptions;
  static const std::vector<OptionRow<O>> t{
      {"solver", [](O& o, py::handle v) { o.solver = lac::parse_g1_solver(v.cast<std::string>()); },
       "auto | bisection | secant | toms748 | ceres | triangle | s-curve"},
      {"winding", [](O& o, py::handle v) { o.winding = v.cast<int>(); },
       "only the turning theta1 - theta0 + 2 pi k (chord-relative angles), k in [-100, 100]; default: least turning"},
      {"max_turning", [](O& o, py::handle v) { o.max_turning = v.cast<double>(); },
       "largest total turning searched without winding (rad), [pi, 200 pi]"},
      // Python keyword = options field name, so the Python option means what the C++ field means.
      {"accuracy", [](O& o, py::handle v) { o.accuracy = v.cast<double>(); }, "target for status ok (relative)"},
      {"accept", [](O& o, py::handle v) { o.accept = v.cast<double>(); }, "usable bound on the achieved error (relative), (0, 0.1]"},
      {"tolerance", [](O& o, py::handle v) { o.tolerance = v.cast<double>(); }, "on |f|, [1e-16, 1e-3]"},
      {"max_iterations", [](O& o, py::handle v) { o.max_iterations = v.cast<int>(); }, "[1, 10000]"},
      {"max_bracket_steps", [](O& o, py::handle v) { o.max_bracket_steps = v.cast<int>(); }, "[1, 100000]"},
  };
  return t;
}

const std::vector<OptionRow<lac::G2Options>>& g2_table() {
  using O = lac::G2Options;
  static const std::vector<OptionRow<O>> t{
      {"solver", [](O& o, py::handle v) { o.solver = lac::parse_g2_solver(v.cast<std::string>()); },
       "newton | ceres | simplex | paper"},
      {"start", [](O& o, py::handle v) { o.start = lac::parse_g2_start(v.cast<std::string>()); }, "fast | bezier-grid"},
      {"fallback", [](O& o, py::handle v) { o.grid_fallback = v.cast<bool>(); },
       "retry from the Bezier-grid start (the CLI's --no-fallback is fallback=False)"},
      {"free_joints", [](O& o, py::handle v) { o.free_joints = v.cast<bool>(); },
       "where the joints S = 1/4, 3/4 of 004 give no curve, retry at 1/8 and 1/16 (the CLI's --paper-joints is False)"},
      {"winding", [](O& o, py::handle v) { o.winding = v.cast<int>(); },
       "only the turning theta1 - theta0 + 2 pi k (chord-relative angles); default: least turning"},
      {"max_turning", [](O& o, py::handle v) { o.max_turning = v.cast<double>(); },
       "largest total turning searched without winding (rad), [pi, 200 pi]"},
      {"accuracy", [](O& o, py::handle v) { o.accuracy = v.cast<double>(); }, "target for status ok (relative)"},
      {"accept", [](O& o, py::handle v) { o.accept = v.cast<double>(); }, "usable bound on the achieved error (relative), (0, 0.1]"},
      {"tolerance", [](O& o, py::handle v) { o.tolerance = v.cast<double>(); }, "on the normalized residuals"},
      {"max_iterations", [](O& o, py::handle v) { o.max_iterations = v.cast<int>(); }, ""},
      {"max_inner_iterations", [](O& o, py::handle v) { o.max_inner_iterations = v.cast<int>(); }, ""},
      {"stagnation_window", [](O& o, py::handle v) { o.stagnation_window = v.cast<int>(); },
       "newton: stop a run whose residual fell by less than 1 % over this many iterations (0: never)"},
      {"max_evaluations", [](O& o, py::handle v) { o.max_evaluations = v.cast<long>(); }, ""},
      {"verify", [](O& o, py::handle v) { o.verify = v.cast<bool>(); }, "check of the residuals by the segment kernel's bound"},
  };
  return t;
}

const std::vector<OptionRow<lac::TriangleOptions>>& triangle_table() {
  using O = lac::TriangleOptions;
  static const std::vector<OptionRow<O>> t{
      {"solver", [](O& o, py::handle v) { o.solver = lac::parse_root_method(v.cast<std::string>()); },
       "bisection | secant | toms748 | ceres"},
      {"max_iterations", [](O& o, py::handle v) { o.root.max_iterations = v.cast<int>(); }, ""},
      {"tangent_tolerance", [](O& o, py::handle v) { o.tangent_tolerance = v.cast<double>(); }, ""},
      {"max_evaluations", [](O& o, py::handle v) { o.max_evaluations = v.cast<long>(); }, ""},
  };
  return t;
}

const std::vector<OptionRow<lac::SpaceSegmentOptions>>& space_table() {
  using O = lac::SpaceSegmentOptions;
  static const std::vector<OptionRow<O>> t{
      {"solver", [](O& o, py::handle v) { o.solver = lac::parse_nonlinear_method(v.cast<std::string>()); },
       "newton | ceres | simplex"},
      {"integrator", [](O& o, py::handle v) { o.integrator.method = lac::parse_ode_method(v.cast<std::string>()); },
       "rk4 | rk45 | magnus6"},
      {"tol", [](O& o, py::handle v) { o.integrator.rtol = v.cast<double>(), o.integrator.atol = 0.1 * o.integrator.rtol; },
       "integration rtol (atol = tol/10)"},
      {"tangent_tolerance", [](O& o, py::handle v) { o.tangent_tolerance = v.cast<double>(); }, ""},
      {"allow_mirror", [](O& o, py::handle v) { o.allow_mirror = v.cast<bool>(); }, ""},
      {"max_starts", [](O& o, py::handle v) { o.max_starts = v.cast<int>(); }, ""},
  };
  return t;
}

// ---- helpers ----

double angle(py::handle h, bool degrees, const char* function, const char* name) {
  const double v = real(h, function, name);
  return degrees ? v * (std::numbers::pi / 180.0) : v;
}

bool take_bool(py::dict& kw, const char* name) {
  if (!kw.contains(name)) return false;
  const bool v = kw[name].cast<bool>();
  PyDict_DelItemString(kw.ptr(), name);
  return v;
}

[[noreturn]] void missing(const char* function, const char* name) {
  lac::throw_input_error(function, name, std::string(name) + " is required");
}
double need(const std::optional<py::object>& v, const char* function, const char* name) {
  if (!v || v->is_none()) missing(function, name);
  return real(*v, function, name);
}

std::vector<std::complex<double>> point_list(py::handle h, const char* function, const char* name) {
  std::vector<std::complex<double>> out;
  for (py::handle p : py::iter(h)) out.push_back(point2(p, function, name));
  return out;
}

py::object opt(const std::optional<double>& v) { return v && std::isfinite(*v) ? py::object(py::float_(*v)) : py::none(); }

template <class R>
Result planar_result(R&& r, const lac::AnyQuadrature& integrator) {
  Result out;
  out.summary = r.summary;
  if (r.usable() && !r.curve.segments().empty()) out.curve = py::cast(Curve{std::move(r.curve), integrator});
  return out;
}

Result g1_solve(const lac::G1HermiteProblem& problem, py::dict kw, const char* function) {
  const lac::G1HermiteOptions o = g1_options(kw, function);
  lac::G1HermiteResult g;
  {
    py::gil_scoped_release release;
    g = lac::solve_g1_hermite(problem, o);
  }
  Result r = planar_result(g, o.integrator);
  const auto& i = g.info;
  r.info["shape"] = std::string(lac::to_string(i.shape));
  r.info["turning"] = i.turning;
  r.info["phi0"] = i.phi0;
  r.info["phi1"] = i.phi1;
  r.info["winding"] = i.winding;
  r.info["max_turning"] = i.max_turning;
  r.info["inflection"] = g.usable() ? opt(i.inflection) : py::none();
  return r;
}

Result g1_hermite(std::optional<py::object> p0, std::optional<py::object> theta0, std::optional<py::object> p1,
                  std::optional<py::object> theta1, std::optional<py::object> alpha, std::optional<py::object> points,
                  py::kwargs kwargs) {
  const char* fn = "g1_hermite";
  py::dict kw(kwargs);
  const bool degrees = take_bool(kw, "degrees");
  const double a = need(alpha, fn, "alpha");
  const bool hermite = p0 || p1 || theta0 || theta1;
  if (points && hermite) lac::throw_input_error(fn, "points", "give either points or p0/theta0/p1/theta1, not both");
  if (points) {
    const auto p = point_list(*points, fn, "points");
    if (p.size() != 3) lac::throw_input_error(fn, "points", "expected 3 control points (start, tangent intersection, end)");
    if (p[1] == p[0] || p[1] == p[2])
      lac::throw_input_error(fn, "points", "the tangent intersection a1 coincides with a0 or a2: no tangent direction there");
    return g1_solve({p[0], std::arg(p[1] - p[0]), p[2], std::arg(p[2] - p[1]), a}, kw, fn);
  }
  if (!hermite) lac::throw_input_error(fn, "points", "give points=(a0, a1, a2) or p0/theta0/p1/theta1");
  for (const auto& [v, name] : {std::pair{&p0, "p0"}, {&theta0, "theta0"}, {&p1, "p1"}, {&theta1, "theta1"}})
    if (!*v || (*v)->is_none()) missing(fn, name);
  return g1_solve({point2(*p0, fn, "p0"), angle(*theta0, degrees, fn, "theta0"), point2(*p1, fn, "p1"),
                   angle(*theta1, degrees, fn, "theta1"), a},
                  kw, fn);
}

Result scurve(py::object points, double alpha, py::kwargs kwargs) {
  const char* fn = "scurve";
  py::dict kw(kwargs);
  const auto p = point_list(points, fn, "points");
  if (p.size() != 4) lac::throw_input_error(fn, "points", "expected 4 control points");
  return g1_solve({p[0], std::arg(p[1] - p[0]), p[3], std::arg(p[3] - p[2]), alpha}, kw, fn);
}

Result g2_hermite(py::object p0, py::object theta0, py::object kappa0, py::object p1, py::object theta1,
                  py::object kappa1, double alpha, py::kwargs kwargs) {
  const char* fn = "g2_hermite";
  py::dict kw(kwargs);
  const bool degrees = take_bool(kw, "degrees");
  const lac::G2Problem pr{{point2(p0, fn, "p0"), angle(theta0, degrees, fn, "theta0"), real(kappa0, fn, "kappa0")},
                          {point2(p1, fn, "p1"), angle(theta1, degrees, fn, "theta1"), real(kappa1, fn, "kappa1")},
                          alpha};
  const lac::G2Options o = g2_options(kw, fn);
  lac::G2Result g;
  {
    py::gil_scoped_release release;
    g = lac::solve_g2(pr, o);
  }
  Result r = planar_result(g, o.integrator);
  r.info["start"] = std::string(lac::to_string(g.info.start_used));
  r.info["start_seconds"] = g.info.start_seconds;
  r.info["h"] = g.usable() ? py::object(py::float_(g.info.h)) : py::none();
  r.info["joints"] = g.usable() ? py::object(py::make_tuple(g.info.joints[0], g.info.joints[1])) : py::none();
  r.info["winding"] = g.info.winding;
  r.info["turning"] = g.info.turning;
  r.info["max_turning"] = g.info.max_turning;
  return r;
}

Result chain(py::object points, double alpha, std::optional<py::object> thetas, std::optional<py::object> kappas,
             const std::string& continuity, bool closed, py::kwargs kwargs) {
  const char* fn = "chain";
  py::dict kw(kwargs);
  const bool degrees = take_bool(kw, "degrees");
  lac::ChainProblem p;
  p.points = point_list(points, fn, "points");
  if (thetas && !thetas->is_none())
    for (py::handle t : py::iter(*thetas)) p.thetas.push_back(angle(t, degrees, fn, "thetas"));
  if (kappas && !kappas->is_none())
    for (py::handle k : py::iter(*kappas)) p.kappas.push_back(real(k, fn, "kappas"));
  p.alpha = alpha;
  p.continuity = lac::parse_chain_continuity(continuity);
  p.closed = closed;
  lac::ChainOptions o;
  const QuadratureArgs q = take_quadrature(kw, "auto");
  const auto method = q.method(fn);
  std::string solver = "auto";
  if (kw.contains("solver")) solver = py::str(kw["solver"]), PyDict_DelItemString(kw.ptr(), "solver");
  if (p.continuity == lac::ChainContinuity::g1) {
    if (solver != "auto") kw["solver"] = solver;
    o.g1 = g1_options(kw, fn);
    if (method) o.g1.integrator = *method, o.g1.verify = true;
  } else {
    if (solver != "auto") kw["solver"] = solver;
    o.g2 = g2_options(kw, fn);
    if (method) o.g2.integrator = *method;
  }
  lac::ChainResult g;
  {
    py::gil_scoped_release release;
    g = lac::solve_chain(p, o);
  }
  Result r = planar_result(g, p.continuity == lac::ChainContinuity::g1 ? o.g1.integrator : o.g2.integrator);
  r.info["continuity"] = continuity;
  r.info["closed"] = closed;
  r.info["pairs"] = g.info.pairs.size();
  r.info["failed_pair"] = g.info.failed_pair >= 0 ? py::object(py::int_(g.info.failed_pair)) : py::none();
  r.info["thetas"] = g.info.thetas;
  r.info["kappas"] = g.info.kappas;
  r.info["estimated_thetas"] = g.info.estimated_thetas;
  r.info["estimated_kappas"] = g.info.estimated_kappas;
  r.info["windings"] = g.info.windings;
  r.info["turnings"] = g.info.turnings;
  return r;
}

Result compound(py::object points, double alpha0, double alpha1, double r_share, py::kwargs kwargs) {
  const char* fn = "compound";
  py::dict kw(kwargs);
  const auto p = point_list(points, fn, "points");
  if (p.size() != 3) lac::throw_input_error(fn, "points", "expected 3 control points (start, tangent intersection, end)");
  const lac::TriangleOptions o = triangle_options(kw, fn);
  lac::TriangleResult g;
  {
    py::gil_scoped_release release;
    g = lac::solve_compound({p[0], p[1], p[2]}, alpha0, alpha1, r_share, o);
  }
  Result r = planar_result(g, o.integrator);
  r.info["segment0_at_a0"] = g.info.segment0_at_a0;
  r.info["turning"] = g.info.turning;
  r.info["bracket_probes"] = g.info.bracket_probes;
  r.info["joint"] = g.usable() ? py::object(py::make_tuple(g.info.joint.real(), g.info.joint.imag())) : py::none();
  r.info["rho_joint"] = g.usable() ? py::object(py::float_(g.info.rho_joint)) : py::none();
  return r;
}

Result space(py::object p0, py::object v0, py::object p1, py::object v1, double alpha, double beta, double omega,
             int type, std::optional<double> alpha1, std::optional<double> beta1, std::optional<double> r_theta,
             py::kwargs kwargs) {
  const char* fn = "space";
  py::dict kw(kwargs);
  const lac::SpaceEndpoints ends{point3(p0, fn, "p0"), point3(v0, fn, "v0"), point3(p1, fn, "p1"), point3(v1, fn, "v1")};
  if (type != 1 && type != 2) lac::throw_input_error(fn, "type", type, "{1, 2}");
  const lac::TorsionType tt = type == 1 ? lac::TorsionType::type1 : lac::TorsionType::type2;
  const bool is_compound = alpha1 || beta1 || r_theta;
  lac::SpaceSegmentOptions o;
  apply_options(o, kw, space_table(), fn);
  lac::Result<lac::SpaceCurve, lac::SpaceInfo> g;
  {
    py::gil_scoped_release release;
    g = is_compound ? lac::solve_compound_space_segment(
                          ends, {alpha, alpha1.value_or(alpha), beta, beta1.value_or(beta), omega, r_theta.value_or(0.5), tt}, o)
                    : lac::solve_g1_space_segment(ends, {alpha, beta, omega, tt}, o);
  }
  Result r;
  r.summary = g.summary;
  const bool drawn = g.usable() && !g.curve.pieces().empty();
  if (drawn) r.curve = py::cast(SpaceCurve{std::move(g.curve)});
  r.info["rhythm"] = is_compound ? "compound" : "g1";
  r.info["torsion_sign"] = g.info.torsion_sign;
  r.info["runs"] = g.info.runs;
  const auto& t = g.info.end_tangent;
  r.info["end_tangent"] = drawn ? py::object(py::make_tuple(t.x(), t.y(), t.z())) : py::none();
  if (is_compound)
    r.info["joint"] = drawn && g.info.joint ? py::object(py::make_tuple(g.info.joint->x(), g.info.joint->y(), g.info.joint->z()))
                                            : py::none();
  return r;
}

}  // namespace

lac::G1HermiteOptions g1_options(py::dict kw, const char* function) {
  lac::G1HermiteOptions o;
  const QuadratureArgs q = take_quadrature(kw, "auto");
  if (const auto method = q.method(function)) o.integrator = *method, o.verify = true;
  apply_options(o, kw, g1_table(), function);
  o.validate();
  return o;
}

lac::G2Options g2_options(py::dict kw, const char* function) {
  lac::G2Options o;
  const QuadratureArgs q = take_quadrature(kw, "gauss-legendre");
  if (const auto method = q.method(function)) o.integrator = *method;
  apply_options(o, kw, g2_table(), function);
  o.validate();
  return o;
}

lac::TriangleOptions triangle_options(py::dict kw, const char* function) {
  lac::TriangleOptions o;
  const QuadratureArgs q = take_quadrature(kw, "auto");
  if (const auto method = q.method(function)) o.integrator = *method;
  apply_options(o, kw, triangle_table(), function);
  o.validate();
  return o;
}

void bind_constructions(py::module_& m) {
  m.def("g1_hermite", &g1_hermite, py::kw_only(), py::arg("p0") = py::none(), py::arg("theta0") = py::none(),
        py::arg("p1") = py::none(), py::arg("theta1") = py::none(), py::arg("alpha") = py::none(),
        py::arg("points") = py::none(),
        "One LA segment of slope alpha from p0 with tangent angle theta0 to p1 with theta1 (G1 Hermite), or from a "
        "control triangle points=(a0, a1, a2), as `lac g1`. Options: solver (auto | bisection | secant | toms748 | ceres "
        "| triangle | s-curve), integrator (auto or a quadrature name; a named one also checks the result) with h, tol, "
        "panels, winding, max_turning, accuracy, accept, tolerance, max_iterations, max_bracket_steps, degrees.");
  m.def("scurve", &scurve, py::arg("points"), py::kw_only(), py::arg("alpha") = -1.0,
        "One LA segment from four control points (tangent P0->P1 at P0, P2->P3 at P3), as `lac scurve`; options as "
        "g1_hermite (solver s-curve: [Miura et al. 2013]'s search).");
  m.def("g2_hermite", &g2_hermite, py::kw_only(), py::arg("p0"), py::arg("theta0"), py::arg("kappa0"), py::arg("p1"),
        py::arg("theta1"), py::arg("kappa1"), py::arg("alpha") = -1.0,
        "G2 Hermite interpolation by three LA segments of one alpha in [-5, 5], as `lac g2`. Options: solver (newton | "
        "ceres | simplex | paper), integrator (default gauss-legendre) with h, tol, panels, start (fast | bezier-grid), "
        "fallback, accept, tolerance, max_iterations, max_inner_iterations, stagnation_window, max_evaluations, verify, "
        "degrees.");
  m.def("chain", &chain, py::arg("points"), py::kw_only(), py::arg("alpha"), py::arg("thetas") = py::none(),
        py::arg("kappas") = py::none(), py::arg("continuity") = "g1", py::arg("closed") = false,
        "One curve of LA segments through the points, G1 or G2 (continuity), tangents (and curvatures) given or "
        "estimated, as `lac chain`. Options: solver (auto, or one of the pair construction's), integrator, the options "
        "of g1_hermite or g2_hermite, degrees.");
  m.def("compound", &compound, py::arg("points"), py::kw_only(), py::arg("alpha0"), py::arg("alpha1"), py::arg("r") = 0.5,
        "Compound-rhythm LA curve (two LCG slopes, G3 joint) from a control triangle, as `lac compound`. Options: "
        "solver (bisection | secant | toms748 | ceres), integrator with h, tol, panels, max_iterations, tangent_tolerance, "
        "max_evaluations.");
  m.def("space", &space, py::kw_only(), py::arg("p0"), py::arg("v0"), py::arg("p1"), py::arg("v1"), py::arg("alpha"),
        py::arg("beta"), py::arg("omega") = 0.1, py::arg("type") = 1, py::arg("alpha1") = py::none(),
        py::arg("beta1") = py::none(), py::arg("r_theta") = py::none(),
        "LA space segment between two points with end tangents, G1 or compound-rhythm (alpha1, beta1 or r_theta given), "
        "as `lac space`. Options: solver (newton | ceres | simplex), integrator (magnus6 | rk45 | rk4), tol, "
        "tangent_tolerance, allow_mirror, max_starts.");
}

}  // namespace lacpy
