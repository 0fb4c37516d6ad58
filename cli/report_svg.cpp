// SVG form of a planar report (cli/report.hpp): control polygon and curve points, y up.
#include <algorithm>
#include <ostream>

#include "cli/report.hpp"
#include "lac/common/error.hpp"

namespace lac::cli {

void write_svg(std::ostream& out, const Report& report) {
  const Json& j = report.json;
  // Points with a position, and the segment of each (by the segments' lengths along s).
  std::vector<double> ends;
  double total = 0;
  for (const Json& seg : j["segments"]) ends.push_back(total += seg["length"].is_number() ? seg["length"].get<double>() : 0.0);
  struct P {
    double x, y;
    size_t segment;
  };
  std::vector<P> pts;
  if (const auto it = j.find("points"); it != j.end()) {
    for (const Json& p : *it) {
      if (!p["x"].is_number() || !p["y"].is_number()) continue;
      const double s = std::abs(p["s"].get<double>());
      size_t k = 0;
      while (k + 1 < ends.size() && s > ends[k] * (1 + 1e-12)) ++k;
      pts.push_back({p["x"].get<double>(), p["y"].get<double>(), k});
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
  const double span = std::max({x1 - x0, y1 - y0, 1e-300});
  const double pad = 0.05 * span, w = x1 - x0 + 2 * pad, h = y1 - y0 + 2 * pad, stroke = 0.004 * std::max(w, h);
  out.precision(9);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 - pad << " " << -(y1 + pad) << " " << w << " " << h
      << "\" width=\"600\" height=\"" << 600 * h / w << "\">\n";
  out << "<!-- status " << j["status"].get<std::string>() << " -->\n";
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
  out << "</svg>\n";
}

}  // namespace lac::cli
