#include "cli/options.hpp"

#include <algorithm>
#include <cctype>
#include <numbers>
#include <string>
#include <vector>

#include "lac/common/error.hpp"

namespace lac::cli {

namespace {

/// An --export file name with the .svg extension (any case).
bool ends_with_svg(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".svg";
}

}  // namespace

void add_common_options(CLI::App& sub, CommonArgs& a, bool planar) {
  sub.add_option("--samples", a.samples,
                 "Number of curve points to print, uniform in arc length (0: none" +
                     std::string(planar ? "; svg draws 200" : "") + ")")
      ->capture_default_str();
  std::vector<std::string> formats{"json", "csv"};
  if (planar) formats.emplace_back("svg");
  sub.add_option("--format", a.format, "Output format: " + CLI::detail::join(formats, " | "))
      ->check(CLI::IsMember(formats))
      ->capture_default_str();
  sub.add_option("--batch", a.batch,
                 "CSV file (- for stdin) of problems, one per row, its header naming options without dashes; "
                 "prints one result per row (JSON Lines, or CSV rows)");
  sub.add_flag("--degrees", a.degrees, "Angles given on the command line are in degrees (output angles stay radians)");
  sub.add_option("--accept", a.accept,
                 "Accept bound on the achieved error, relative to the curve's size (chord, or arc length for "
                 "points), (0, 0.1]: a result beyond it is inaccurate (exit 3)")
      ->capture_default_str();
  if (planar)
    sub.add_flag("--comb", a.comb,
                 "Draw the curvature comb (teeth along the normal, length proportional to |kappa|, on the side away "
                 "from the centre of curvature; the longest 0.15 x the drawing's diagonal) on the --format svg "
                 "drawing and on an --export FILE.svg (the B-spline's own curvature)");
}

void add_export_options(CLI::App& sub, CommonArgs& a) {
  sub.add_option("--export", a.export_path,
                 "Write the curve as a B-spline within a certified distance --export-tol: FILE.step/.stp (STEP), "
                 ".iges/.igs (IGES entity 126), .dxf (SPLINE), .svg (cubic Bezier path); DIR/ (trailing slash; "
                 "created if missing): DIR/curve.<--export-format>; with --batch one file per row, _row<N> before "
                 "the extension");
  sub.add_option("--export-format", a.export_format,
                 "Format of an --export DIR/: step | stp | iges | igs | dxf | svg (default step); with --export FILE, "
                 "FILE's own extension");
  sub.add_option("--export-tol", a.export_tol,
                 "Bound on the exported curve's distance from the LA curve, absolute (default 1e-6 x curve length); "
                 "a larger certified bound makes the result inaccurate (exit 3)");
  sub.add_option("--export-degree", a.export_degree,
                 "5: quintic spans, curvature continuous (G2; default) | 3: cubic spans (G1; the default and only "
                 "choice for .svg, whose paths hold cubic Beziers)");
  sub.add_option("--export-fit-degree", a.export_fit_degree,
                 "Fewest control points: also fit B-splines of degree 3 up to this (3-9; 3 for .svg) with a proven "
                 "bound and keep the one with the fewest points (joints and end data as --export-degree gives them; "
                 "its curvature follows the LA curve less closely than the default's)");
}

int sample_count(const CommonArgs& a) {
  if (a.samples == 1 || a.samples < 0 || a.samples > 1'000'000)
    throw_input_error("lac", "samples", a.samples, "0 or [2, 1000000]");
  if (a.comb && a.format != "svg" && !ends_with_svg(export_file(a)))
    throw_input_error("lac", "comb",
                      "--comb draws on an SVG: it needs --format svg (the sampled curve) or --export FILE.svg (the "
                      "B-spline)");
  return a.samples == 0 && a.format == "svg" ? 200 : a.samples;
}

long max_evaluations_option(const std::optional<double>& value, double max) {
  if (!value) return 0;
  if (!(*value >= 1 && *value <= max)) throw_input_error("lac", "max-evaluations", *value, "[1, " + format_number(max) + "]");
  return static_cast<long>(*value);
}

std::string export_file(const CommonArgs& a) {
  static const std::vector<std::string> kFormats{"step", "stp", "iges", "igs", "dxf", "svg"};
  std::string format;
  if (a.export_format) {
    format = *a.export_format;
    std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return std::tolower(c); });
    if (std::find(kFormats.begin(), kFormats.end(), format) == kFormats.end())
      throw_input_error("lac", "export-format", "'" + *a.export_format + "' is not one of step, stp, iges, igs, dxf, svg");
  }
  if (a.export_path.empty()) {
    if (a.export_format) throw_input_error("lac", "export-format", "--export-format needs --export DIR/");
    return {};
  }
  if (a.export_path.back() == '/') return a.export_path + "curve." + (format.empty() ? "step" : format);
  if (!format.empty()) {
    const size_t dot = a.export_path.find_last_of('.'), slash = a.export_path.find_last_of('/');
    std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : a.export_path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != format)
      throw_input_error("lac", "export-format",
                        "'" + *a.export_format + "' contradicts the extension of --export '" + a.export_path +
                            "' (give a folder, DIR/, to name the format apart)");
  }
  return a.export_path;
}

double radians(double value, const CommonArgs& a) { return a.degrees ? value * (std::numbers::pi / 180.0) : value; }

std::string alpha_range_text(double min_abs, double max_abs) {
  if (!(min_abs > 0)) return interval_text(-max_abs, max_abs, true, true);
  return "0 or " + format_number(min_abs) + " <= |alpha| <= " + format_number(max_abs);
}

void throw_missing(const char* name) { throw_input_error("lac", name, std::string("--") + name + " is required"); }

}  // namespace lac::cli
