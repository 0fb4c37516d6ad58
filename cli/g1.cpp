// lac g1: monotonic-rhythm LA segment from control points a0, a1, a2 and α (001 §2).
// Also defines the output shared with `lac compound` (cli/compound.cpp).
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/command.hpp"
#include "cli/segment_args.hpp"
#include "io/timing.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lac::cli {

void add_segment_options(CLI::App& sub, SegmentArgs& a) {
  sub.add_option("--points", a.points, "Control points \"x0,y0 x1,y1 x2,y2\": start, tangent intersection, end")->required();
  sub.add_option("--solver", a.solver, "Root finder: bisection | secant (newton) | toms748 | ceres")->capture_default_str();
  add_quadrature_options(sub, a.quadrature, "auto (the solvers' default, gk-tanh-sinh)");
  sub.add_option("--points-out", a.points_out, "Number of curve points to print (0: none; svg uses 200 if 0)")->capture_default_str();
  a.format = add_format_option(sub, {"json", "csv", "svg"});
}

PreparedSegment prepare_segment(const SegmentArgs& a) {
  const auto p = parse_points(a.points, 3, "points");
  PreparedSegment s{{{p[0][0], p[0][1]}, {p[1][0], p[1][1]}, {p[2][0], p[2][1]}}, {}, {}};
  s.options.solver = parse_root_method(a.solver);
  if (a.quadrature.integrator != "auto") {
    s.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
  } else if (a.quadrature.any_option()) {
    throw_input_error("lac", "integrator", "--h, --tol and --panels need an explicit --integrator (" +
                                               method_names_text(quadrature_methods(), " | ") + ")");
  }
  if (a.points_out < 0) throw_input_error("lac", "points-out", a.points_out, "[0, inf)");
  return s;
}

/// Prints a solved segment as JSON, CSV or SVG.
void print_segment(const G1Segment& g, const SegmentArgs& a, const PreparedSegment& s, double seconds) {
  const Format fmt = parse_format(*a.format);
  const int n = a.points_out > 0 ? a.points_out : (fmt == Format::svg ? 200 : 0);
  std::vector<SegmentSample> pts;
  if (n > 0 && usable(g.status))
    pts = s.integrator ? sample_segment(g, std::max(n, 2), *s.integrator) : sample_segment(g, std::max(n, 2));
  if (fmt == Format::json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(g.status));
    if (!g.message.empty()) j["message"] = g.message;
    j["length"] = g.length;
    j["kappa0"] = g.kappa0;
    j["kappa1"] = g.kappa1;
    nlohmann::json alpha = nlohmann::json::array(), lambda = nlohmann::json::array(), lambda_user = nlohmann::json::array(),
                   lengths = nlohmann::json::array();
    for (const auto& p : g.pieces) {
      alpha.push_back(p.alpha);
      lambda.push_back(p.lambda);
      lambda_user.push_back(p.lambda_user);
      lengths.push_back(p.length);
    }
    j["alpha"] = alpha;
    j["lambda"] = lambda;
    j["lambda_user"] = lambda_user;
    j["segment_lengths"] = lengths;
    j["segment0_at_a0"] = g.segment0_at_a0;
    if (g.compound) {
      j["joint"] = {g.joint.real(), g.joint.imag()};
      j["rho_joint"] = g.rho_joint;
    }
    j["turning"] = g.turning;
    j["tangent_error"] = g.tangent_error;
    j["iterations"] = g.iterations;
    j["bracket_probes"] = g.bracket_probes;
    j["trials"] = g.trials;
    j["evaluations"] = g.evaluations;
    j["seconds"] = seconds;
    j["solver"] = std::string(to_string(s.options.solver));
    j["integrator"] = s.integrator ? describe(*s.integrator) : std::string(GkTanhSinh::name);
    if (!pts.empty()) {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& q : pts) arr.push_back({{"x", q.position.real()}, {"y", q.position.imag()}, {"s", q.s},
                                               {"theta", q.theta}, {"kappa", q.kappa}, {"segment", q.piece}});
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (fmt == Format::csv) {
    std::cout << "# status " << to_string(g.status) << (g.message.empty() ? "" : " (" + g.message + ")") << ", length "
              << g.length << ", kappa0 " << g.kappa0 << ", kappa1 " << g.kappa1 << ", iterations " << g.iterations
              << ", seconds " << seconds << "\n";
    if (pts.empty()) {
      std::cout << "segment,alpha,lambda,lambda_user,turning,length,rho_small,rho_large\n";
      for (size_t k = 0; k < g.pieces.size(); ++k) {
        const auto& p = g.pieces[k];
        std::cout << k << "," << p.alpha << "," << p.lambda << "," << p.lambda_user << "," << p.turning << ","
                  << p.length << "," << p.rho_small << "," << p.rho_large << "\n";
      }
    } else {
      std::cout << "x,y,s,theta,kappa,segment\n";
      for (const auto& q : pts)
        std::cout << q.position.real() << "," << q.position.imag() << "," << q.s << "," << q.theta << "," << q.kappa
                  << "," << q.piece << "\n";
    }
    return;
  }
  // SVG: control polygon (grey), curve (one colour per segment), y axis pointing up.
  const ControlTriangle& t = s.triangle;
  double x0 = std::min({t.a0.real(), t.a1.real(), t.a2.real()}), x1 = std::max({t.a0.real(), t.a1.real(), t.a2.real()});
  double y0 = std::min({t.a0.imag(), t.a1.imag(), t.a2.imag()}), y1 = std::max({t.a0.imag(), t.a1.imag(), t.a2.imag()});
  for (const auto& q : pts) {
    x0 = std::min(x0, q.position.real());
    x1 = std::max(x1, q.position.real());
    y0 = std::min(y0, q.position.imag());
    y1 = std::max(y1, q.position.imag());
  }
  const double pad = 0.05 * std::max(x1 - x0, y1 - y0);
  const double w = x1 - x0 + 2 * pad, h = y1 - y0 + 2 * pad;
  std::cout << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 - pad << " " << -(y1 + pad) << " " << w << " " << h
            << "\" width=\"600\" height=\"" << 600 * h / w << "\">\n";
  const double stroke = 0.004 * std::max(w, h);
  std::cout << "<!-- status " << to_string(g.status) << " -->\n";
  std::cout << "<polyline fill=\"none\" stroke=\"#999\" stroke-width=\"" << stroke << "\" points=\"" << t.a0.real() << ","
            << -t.a0.imag() << " " << t.a1.real() << "," << -t.a1.imag() << " " << t.a2.real() << "," << -t.a2.imag() << "\"/>\n";
  for (int piece = 0; piece < 2; ++piece) {
    std::string path;
    for (size_t k = 0; k < pts.size(); ++k) {
      const bool in = pts[k].piece == piece || (k + 1 < pts.size() && pts[k + 1].piece == piece);
      if (in) path += std::to_string(pts[k].position.real()) + "," + std::to_string(-pts[k].position.imag()) + " ";
    }
    if (!path.empty())
      std::cout << "<polyline fill=\"none\" stroke=\"" << (piece == 0 ? "#1f77b4" : "#d62728") << "\" stroke-width=\""
                << 1.5 * stroke << "\" points=\"" << path << "\"/>\n";
  }
  std::cout << "</svg>\n";
}

namespace {

void setup(CLI::App& app) {
  auto* a = owned<SegmentArgs>();
  auto* alpha = owned<double>(0.0);
  auto* sub = app.add_subcommand("g1", "Monotonic-rhythm LA segment from control points a0, a1, a2 and alpha (001 section 2)");
  add_segment_options(*sub, *a);
  sub->add_option("--alpha", *alpha, "Slope alpha of the logarithmic curvature graph (finite)")->required();
  sub->callback([a, alpha] {
    const PreparedSegment s = prepare_segment(*a);
    io::Stopwatch clock;
    const G1Segment g = s.integrator ? solve_g1(s.triangle, *alpha, s.options, *s.integrator)
                                      : solve_g1(s.triangle, *alpha, s.options);
    print_segment(g, *a, s, clock.seconds());
  });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
