// SVG form of a planar report (cli/report.hpp): control polygon and curve points, y up; with
// --comb the curvature comb of the samples.
#include <algorithm>
#include <cmath>
#include <ostream>

#include "cli/report.hpp"
#include "lac/common/error.hpp"
#include "lac/export/write.hpp"

namespace lac::cli {

void write_svg(std::ostream& out, const Report& report, bool comb) {
  const Json& j = report.json;
  // Points with a position, and the segment of each (by the segments' lengths along s).
  std::vector<double> ends;
  double total = 0;
  for (const Json& seg : j["segments"]) ends.push_back(total += seg["length"].is_number() ? seg["length"].get<double>() : 0.0);
  struct P {
    double x, y;
    size_t segment;
    double theta, kappa;  // NaN when null
  };
  std::vector<P> pts;
  if (const auto it = j.find("points"); it != j.end()) {
    for (const Json& p : *it) {
      if (!p["x"].is_number() || !p["y"].is_number()) continue;
      const double s = std::abs(p["s"].get<double>());
      size_t k = 0;
      while (k + 1 < ends.size() && s > ends[k] * (1 + 1e-12)) ++k;
      const auto value = [&p](const char* key) { return p[key].is_number() ? p[key].get<double>() : std::nan(""); };
      pts.push_back({p["x"].get<double>(), p["y"].get<double>(), k, value("theta"), value("kappa")});
    }
  }
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool first = true;
  auto extend = [&](double x, double y) {
    x0 = first ? x : std::min(x0, x), x1 = first ? x : std::max(x1, x);
    y0 = first ? y : std::min(y0, y), y1 = first ? y : std::max(y1, y);
    first = false;
  };
  for (const auto& c : report.polygon) extend(c.real(), c.imag());
  for (const P& p : pts) extend(p.x, p.y);
  // The comb: a tooth from each sample along −κN, N = (−sin θ, cos θ) the unit left normal, so the
  // teeth stand away from the centre of curvature; c makes the longest kCombFraction (0.15) of the
  // diagonal of the polygon's and samples' bounding box.
  struct Tooth {
    double x, y, tx, ty;
  };
  std::vector<Tooth> teeth;
  double scale = 0;
  if (comb) {
    double kmax = 0;
    for (const P& p : pts)
      if (std::isfinite(p.kappa) && std::isfinite(p.theta)) kmax = std::max(kmax, std::abs(p.kappa));
    scale = kmax > 0 ? kCombFraction * std::hypot(x1 - x0, y1 - y0) / kmax : 0.0;
    for (const P& p : pts) {
      if (!std::isfinite(p.kappa) || !std::isfinite(p.theta)) continue;
      const double len = scale * p.kappa;
      teeth.push_back({p.x, p.y, p.x + len * std::sin(p.theta), p.y - len * std::cos(p.theta)});
    }
    for (const Tooth& t : teeth) extend(t.tx, t.ty);
  }
  const double span = std::max({x1 - x0, y1 - y0, 1e-300});
  const double pad = 0.05 * span, w = x1 - x0 + 2 * pad, h = y1 - y0 + 2 * pad, stroke = 0.004 * std::max(w, h);
  out.precision(9);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 - pad << " " << -(y1 + pad) << " " << w << " " << h
      << "\" width=\"600\" height=\"" << 600 * h / w << "\">\n";
  out << "<!-- status " << j["status"].get<std::string>() << " -->\n";
  if (comb)
    out << "<desc>Curvature comb: " << teeth.size()
        << " teeth, one per sample with a curvature, each from the point p to p - c kappa N, N = (-sin theta, cos "
           "theta) the unit left normal, kappa left turn positive (teeth away from the centre of curvature), c = "
        << format_number(scale) << " so that the longest tooth is " << kCombFraction
        << " of the diagonal of the curve's and control points' bounding box</desc>\n";
  if (!report.polygon.empty()) {
    out << "<polyline fill=\"none\" stroke=\"#999\" stroke-width=\"" << stroke << "\" points=\"";
    for (const auto& c : report.polygon) out << c.real() << "," << -c.imag() << " ";
    out << "\"/>\n";
  }
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  for (size_t k = 0; k < std::max<size_t>(ends.size(), 1); ++k) {
    std::string path;
    for (size_t i = 0; i < pts.size(); ++i) {
      const bool in = pts[i].segment == k || (i + 1 < pts.size() && pts[i + 1].segment == k);
      if (in) path += format_number(pts[i].x) + "," + format_number(-pts[i].y) + " ";
    }
    if (!path.empty())
      out << "<polyline fill=\"none\" stroke=\"" << colours[k % 4] << "\" stroke-width=\"" << 1.5 * stroke
          << "\" points=\"" << path << "\"/>\n";
  }
  if (comb) {
    out << "<path id=\"comb-teeth\" fill=\"none\" stroke=\"#ff7f0e\" stroke-width=\"" << 0.5 * stroke << "\" d=\"";
    std::string tips;
    for (const Tooth& t : teeth) {
      out << "M " << format_number(t.x) << "," << format_number(-t.y) << " L " << format_number(t.tx) << ","
          << format_number(-t.ty) << " ";
      tips += format_number(t.tx) + "," + format_number(-t.ty) + " ";
    }
    out << "\"/>\n<polyline id=\"comb-tips\" fill=\"none\" stroke=\"#ff7f0e\" stroke-width=\"" << stroke
        << "\" points=\"" << tips << "\"/>\n";
  }
  out << "</svg>\n";
}

}  // namespace lac::cli
