#include "lac/export/write.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "lac/common/error.hpp"
#include "lac/export/detail/bspline_core.hpp"
#include "lac/export/detail/write_text.hpp"

namespace lac {

using detail::number17;

ExportFormat export_format_from_path(const std::string& path, const char* parameter, const char* function) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == "step" || ext == "stp") return ExportFormat::step;
  if (ext == "iges" || ext == "igs") return ExportFormat::iges;
  if (ext == "dxf") return ExportFormat::dxf;
  if (ext == "svg") return ExportFormat::svg;
  throw_input_error(function, parameter,
                    "'" + path + "': the extension names no export format (.step, .stp, .iges, .igs, .dxf, .svg)");
}

std::vector<std::vector<std::complex<double>>> bezier_pieces(const BSpline& b) {
  b.validate();
  if (b.rational()) throw_input_error("bezier_pieces", "weights", "a polynomial (non-rational) B-spline");
  std::vector<double> breaks;
  std::vector<int> multiplicities;
  detail::distinct_knots(std::vector<double>(b.knots.begin() + b.degree, b.knots.end() - b.degree), breaks, multiplicities);
  return detail::bezier_pieces_on(b.degree, b.knots, b.control_points, breaks);
}

void write_dxf(std::ostream& out, const BSpline& b) {
  b.validate();
  detail::write_dxf_spline(out, true, b.degree, b.knots, b.weights, b.control_points, [](std::complex<double> c) {
    return std::array<std::string, 3>{number17(c.real()), number17(c.imag()), "0.0"};
  });
}

namespace {

/// A comb tooth: the base point and the signed curvature there (NaN where the tangent vanishes).
struct CombSample {
  std::complex<double> point, normal;
  double kappa;
};

/// Point, unit left normal and curvature (B' × B'')/|B'|³ of a cubic Bézier piece at t.
CombSample cubic_sample(const std::vector<std::complex<double>>& P, double t) {
  const double u = 1 - t;
  const std::complex<double> B = u * u * u * P[0] + 3 * u * u * t * P[1] + 3 * u * t * t * P[2] + t * t * t * P[3];
  const std::complex<double> d1 = 3.0 * (u * u * (P[1] - P[0]) + 2 * u * t * (P[2] - P[1]) + t * t * (P[3] - P[2]));
  const std::complex<double> d2 = 6.0 * (u * (P[2] - 2.0 * P[1] + P[0]) + t * (P[3] - 2.0 * P[2] + P[1]));
  const double speed = std::abs(d1);
  if (!(speed > 0)) return {B, {0, 0}, std::nan("")};
  const double cross = d1.real() * d2.imag() - d1.imag() * d2.real();
  return {B, std::complex<double>(0, 1) * d1 / speed, cross / (speed * speed * speed)};
}

}  // namespace

void write_svg(std::ostream& out, const BSpline& b, const SvgOptions& options) {
  if (b.degree != 3) throw_input_error("write_svg", "degree", b.degree, "3 (SVG paths hold cubic Bézier curves)");
  if (options.comb && !(options.comb_teeth_per_piece >= 1 && options.comb_teeth_per_piece <= 1000))
    throw_input_error("write_svg", "comb_teeth_per_piece", options.comb_teeth_per_piece, "[1, 1000]");
  const auto pieces = bezier_pieces(b);
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  auto extend = [&](std::complex<double> c) {
    x0 = std::min(x0, c.real());
    x1 = std::max(x1, c.real());
    y0 = std::min(y0, c.imag());
    y1 = std::max(y1, c.imag());
  };
  for (const auto& c : b.control_points) extend(c);
  // The comb: teeth at t = i/n of every piece, scaled to kCombFraction of the control points' diagonal.
  std::vector<CombSample> comb;
  double scale = 0;
  if (options.comb) {
    const int n = options.comb_teeth_per_piece;
    double kmax = 0;
    for (const auto& pc : pieces)
      for (int i = 0; i <= n; ++i) {
        comb.push_back(cubic_sample(pc, static_cast<double>(i) / n));
        if (std::isfinite(comb.back().kappa)) kmax = std::max(kmax, std::abs(comb.back().kappa));
      }
    const double diagonal = std::hypot(x1 - x0, y1 - y0);
    scale = kmax > 0 ? kCombFraction * diagonal / kmax : 0.0;
    for (const CombSample& c : comb)
      if (std::isfinite(c.kappa)) extend(c.point - scale * c.kappa * c.normal);
  }
  const double margin = 0.05 * std::max({x1 - x0, y1 - y0, 1e-300});
  const double w = x1 - x0 + 2 * margin, h = y1 - y0 + 2 * margin;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"" << number17(800 * h / w) << "\" viewBox=\""
      << number17(x0 - margin) << " " << number17(-(y1 + margin)) << " " << number17(w) << " " << number17(h) << "\">\n"
      << "<!-- lac: an LA curve as cubic Bézier commands in its own coordinates (y up; the group flips it) -->\n";
  if (options.comb)
    out << "<desc>Curvature comb of the cubic B-spline (its own curvature): " << options.comb_teeth_per_piece + 1
        << " teeth per Bezier piece at t = i/" << options.comb_teeth_per_piece
        << ", each from B(t) to B(t) - c kappa(t) N(t), N the unit left normal, kappa left turn positive (teeth away "
           "from the centre of curvature), c = "
        << number17(scale) << " so that the longest tooth is " << kCombFraction
        << " of the control points' bounding-box diagonal</desc>\n";
  out << "<g transform=\"scale(1,-1)\">\n<path fill=\"none\" stroke=\"black\" stroke-width=\"" << number17(w / 400)
      << "\" d=\"M " << number17(pieces.front()[0].real()) << " " << number17(pieces.front()[0].imag());
  for (const auto& pc : pieces) {
    out << "\nC";
    for (int i = 1; i <= 3; ++i) out << " " << number17(pc[i].real()) << " " << number17(pc[i].imag());
  }
  out << "\"/>\n";
  if (options.comb) {
    out << "<path id=\"comb-teeth\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"" << number17(w / 1600)
        << "\" d=\"";
    std::string tips;
    for (const CombSample& c : comb) {
      if (!std::isfinite(c.kappa)) continue;
      const std::complex<double> tip = c.point - scale * c.kappa * c.normal;
      out << "M " << number17(c.point.real()) << " " << number17(c.point.imag()) << " L " << number17(tip.real()) << " "
          << number17(tip.imag()) << "\n";
      tips += number17(tip.real()) + "," + number17(tip.imag()) + " ";
    }
    out << "\"/>\n<polyline id=\"comb-tips\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"" << number17(w / 800)
        << "\" points=\"" << tips << "\"/>\n";
  }
  out << "</g>\n</svg>\n";
}

void write_file(const std::string& path, ExportFormat format, const BSpline& b, const SvgOptions& svg) {
  detail::write_export_file(path, format, [&](std::ostream& out) {
    if (format == ExportFormat::dxf)
      write_dxf(out, b);
    else
      write_svg(out, b, svg);
  });
}

}  // namespace lac
