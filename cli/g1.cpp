// lac g1: monotonic-rhythm LA segment from control points a0, a1, a2 and α (001 §2).
// Also defines the output shared with `lac compound` (cli/compound.cpp).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "cli/command.hpp"
#include "cli/segment_args.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lac::cli {

namespace {

/// "bisection | secant (newton) | toms748 | ceres", from the registry.
std::string root_method_names() {
  std::string text;
  for (const RootMethodInfo& m : root_methods()) {
    text.append(text.empty() ? "" : " | ").append(m.name);
    for (size_t i = 0; i < m.aliases.size(); ++i) text.append(i == 0 ? " (" : ", ").append(m.aliases[i]);
    if (!m.aliases.empty()) text.append(")");
  }
  return text;
}

/// About n points from a0 to a2 as `lac g1` has always printed them: each piece uniform in s, the
/// pieces sharing n by length (at least 2 each), the joint once, and the piece (001's numbering)
/// of every point, the joint counted in piece 0. Positions by the integrator of the solve when it
/// integrates segments (igf, a closed form of the standard form, does not: then gk-tanh-sinh).
struct CurvePoints {
  std::vector<PositionResult> points;
  std::vector<int> piece;
};

CurvePoints sample_pieces(const TriangleResult& g, int n, const AnyQuadrature& integrator) {
  const PlanarCurve& curve = g.curve;
  const size_t count = curve.segments().size();
  auto piece_of = [&](size_t k) { return static_cast<int>(g.info.segment0_at_a0 ? k : count - 1 - k); };
  int n0 = n;  // points of piece 0
  if (count == 2) {
    const double share = curve.segments()[g.info.segment0_at_a0 ? 0 : 1].length() / curve.length();
    n0 = std::clamp(static_cast<int>(std::lround(n * share)), 2, std::max(2, n - 1));
  }
  const int n1 = std::max(2, n - n0 + 1);
  CurvePoints out;
  std::visit(
      [&](const auto& m) {
        for (size_t k = 0; k < count; ++k) {
          const int points = piece_of(k) == 0 ? n0 : n1;
          std::vector<PositionResult> part;
          if constexpr (QuadratureMethod<std::decay_t<decltype(m)>>)
            part = polyline(curve, curve.segment_start(k), curve.segment_start(k + 1), points, m);
          else
            part = polyline(curve, curve.segment_start(k), curve.segment_start(k + 1), points, GkTanhSinh{});
          for (size_t j = k == 0 ? 0 : 1; j < part.size(); ++j) {
            out.points.push_back(part[j]);
            out.piece.push_back(k == 0 && j + 1 == part.size() && count == 2 ? 0 : piece_of(k));
          }
        }
      },
      integrator);
  return out;
}

}  // namespace

void add_segment_options(CLI::App& sub, SegmentArgs& a) {
  sub.add_option("--points", a.points, "Control points \"x0,y0 x1,y1 x2,y2\": start, tangent intersection, end")->required();
  sub.add_option("--solver", a.solver, "Root finder: " + root_method_names())->capture_default_str();
  add_quadrature_options(sub, a.quadrature, "auto (the construction's default, gk-tanh-sinh)");
  sub.add_option("--points-out", a.points_out, "Number of curve points to print (0: none; svg uses 200 if 0)")->capture_default_str();
  a.format = add_format_option(sub, {"json", "csv", "svg"});
}

PreparedSegment prepare_segment(const SegmentArgs& a) {
  const auto p = parse_points(a.points, 3, "points");
  PreparedSegment s{{{p[0][0], p[0][1]}, {p[1][0], p[1][1]}, {p[2][0], p[2][1]}}, {}, false};
  s.options.solver = parse_root_method(a.solver);
  if (a.quadrature.integrator != "auto") {
    s.options.integrator = make_quadrature(a.quadrature.integrator, a.quadrature.options());
    s.explicit_integrator = true;
  } else if (a.quadrature.any_option()) {
    throw_input_error("lac", "integrator", "--h, --tol and --panels need an explicit --integrator (" +
                                               method_names_text(quadrature_methods(), " | ") + ")");
  }
  if (a.points_out < 0) throw_input_error("lac", "points-out", a.points_out, "[0, inf)");
  return s;
}

/// Prints a solved segment as JSON, CSV or SVG. Pieces in 001's order (0 = segment 0, at the
/// small-ρ end); points from a0 to a2, `segment` naming their piece.
void print_segment(const TriangleResult& g, const SegmentArgs& a, const PreparedSegment& s) {
  const Format fmt = parse_format(*a.format);
  const int n = a.points_out > 0 ? a.points_out : (fmt == Format::svg ? 200 : 0);
  const TriangleInfo& info = g.info;
  const Summary& sum = g.summary;
  record_status(sum.status);
  const bool have_curve = g.usable() && !g.curve.segments().empty();
  const size_t pieces = have_curve ? g.curve.segments().size() : 0;
  auto piece_of_segment = [&](size_t k) { return info.segment0_at_a0 ? k : pieces - 1 - k; };
  CurvePoints sampled;
  if (n > 0 && have_curve) sampled = sample_pieces(g, std::max(n, 2), s.options.integrator);
  const std::vector<PositionResult>& pts = sampled.points;
  const std::vector<int>& pts_piece = sampled.piece;
  const double length = have_curve ? g.curve.length() : 0.0;
  const double kappa0 = have_curve ? g.curve.kappa_at(0) : 0.0, kappa1 = have_curve ? g.curve.kappa_at(length) : 0.0;
  std::vector<double> piece_lengths(pieces);
  for (size_t k = 0; k < pieces; ++k) piece_lengths[piece_of_segment(k)] = g.curve.segments()[k].length();
  if (fmt == Format::json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(sum.status));
    if (!sum.message.empty()) j["message"] = sum.message;
    j["length"] = length;
    j["kappa0"] = kappa0;
    j["kappa1"] = kappa1;
    nlohmann::json alpha = nlohmann::json::array(), lambda = nlohmann::json::array(), lambda_user = nlohmann::json::array();
    for (const auto& p : info.pieces) {
      alpha.push_back(p.alpha);
      lambda.push_back(p.lambda);
      lambda_user.push_back(p.lambda_user);
    }
    j["alpha"] = alpha;
    j["lambda"] = lambda;
    j["lambda_user"] = lambda_user;
    j["segment_lengths"] = piece_lengths;
    j["segment0_at_a0"] = info.segment0_at_a0;
    if (info.compound) {
      j["joint"] = {info.joint.real(), info.joint.imag()};
      j["rho_joint"] = info.rho_joint;
    }
    j["turning"] = info.turning;
    j["tangent_error"] = sum.residuals.angle.value_or(0.0);
    j["iterations"] = sum.iterations;
    j["bracket_probes"] = info.bracket_probes;
    j["trials"] = sum.constructions;
    j["evaluations"] = sum.evaluations;
    j["seconds"] = sum.seconds;
    j["solver"] = sum.solver;
    j["integrator"] = s.explicit_integrator ? describe(s.options.integrator) : sum.integrator;
    if (!pts.empty()) {
      nlohmann::json arr = nlohmann::json::array();
      for (size_t k = 0; k < pts.size(); ++k) {
        const CurvePoint& q = pts[k].point;
        arr.push_back({{"x", q.position.real()}, {"y", q.position.imag()}, {"s", q.s}, {"theta", q.theta},
                       {"kappa", q.kappa}, {"segment", pts_piece[k]}});
      }
      j["points"] = arr;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout.precision(17);
  if (fmt == Format::csv) {
    std::cout << "# status " << to_string(sum.status) << (sum.message.empty() ? "" : " (" + sum.message + ")") << ", length "
              << length << ", kappa0 " << kappa0 << ", kappa1 " << kappa1 << ", iterations " << sum.iterations
              << ", seconds " << sum.seconds << "\n";
    if (pts.empty()) {
      std::cout << "segment,alpha,lambda,lambda_user,turning,length,rho_small,rho_large\n";
      for (size_t k = 0; k < pieces; ++k) {
        const auto& p = info.pieces[k];
        std::cout << k << "," << p.alpha << "," << p.lambda << "," << p.lambda_user << "," << p.turning << ","
                  << piece_lengths[k] << "," << p.rho_small << "," << p.rho_large << "\n";
      }
    } else {
      std::cout << "x,y,s,theta,kappa,segment\n";
      for (size_t k = 0; k < pts.size(); ++k) {
        const CurvePoint& q = pts[k].point;
        std::cout << q.position.real() << "," << q.position.imag() << "," << q.s << "," << q.theta << "," << q.kappa
                  << "," << pts_piece[k] << "\n";
      }
    }
    return;
  }
  // SVG: control polygon (grey), curve (one colour per segment), y axis pointing up.
  const ControlTriangle& t = s.triangle;
  double x0 = std::min({t.a0.real(), t.a1.real(), t.a2.real()}), x1 = std::max({t.a0.real(), t.a1.real(), t.a2.real()});
  double y0 = std::min({t.a0.imag(), t.a1.imag(), t.a2.imag()}), y1 = std::max({t.a0.imag(), t.a1.imag(), t.a2.imag()});
  for (const auto& q : pts) {
    x0 = std::min(x0, q.point.position.real());
    x1 = std::max(x1, q.point.position.real());
    y0 = std::min(y0, q.point.position.imag());
    y1 = std::max(y1, q.point.position.imag());
  }
  const double pad = 0.05 * std::max(x1 - x0, y1 - y0);
  const double w = x1 - x0 + 2 * pad, h = y1 - y0 + 2 * pad;
  std::cout << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 - pad << " " << -(y1 + pad) << " " << w << " " << h
            << "\" width=\"600\" height=\"" << 600 * h / w << "\">\n";
  const double stroke = 0.004 * std::max(w, h);
  std::cout << "<!-- status " << to_string(sum.status) << " -->\n";
  std::cout << "<polyline fill=\"none\" stroke=\"#999\" stroke-width=\"" << stroke << "\" points=\"" << t.a0.real() << ","
            << -t.a0.imag() << " " << t.a1.real() << "," << -t.a1.imag() << " " << t.a2.real() << "," << -t.a2.imag() << "\"/>\n";
  for (int piece = 0; piece < 2; ++piece) {
    std::string path;
    for (size_t k = 0; k < pts.size(); ++k) {
      const bool in = pts_piece[k] == piece || (k + 1 < pts.size() && pts_piece[k + 1] == piece);
      if (in) path += std::to_string(pts[k].point.position.real()) + "," + std::to_string(-pts[k].point.position.imag()) + " ";
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
    print_segment(solve_g1(s.triangle, *alpha, s.options), *a, s);
  });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
