#pragma once
// One export request, one file: the format from the path's extension, the degree (5, or 3 for
// .svg), the check that this build writes STEP and IGES, to_bspline and the writer (a PlanarCurve,
// or an arc of a quadratic LA curve). The CLI's
// --export and Python's lac.export_curve both call it. Inline on purpose: whether STEP and IGES
// are written is decided by the program that includes it (LAC_WITH_OCCT comes with lac::export).
//
//   const lac::PreparedExport p = lac::prepare_export({.path = "c.step", .tolerance = 1e-6}, names);
//   const lac::ExportResult r = lac::export_curve(curve, "c.step", p);  // written when r.usable()
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

#include "lac/common/error.hpp"
#include "lac/export/to_bspline.hpp"
#include "lac/export/write.hpp"
#ifdef LAC_WITH_OCCT
#include "lac/export/occt/occt_writer.hpp"
#endif

namespace lac {

struct ExportRequest {
  std::string path;            ///< its extension names the format (export_format_from_path)
  double tolerance = 0;        ///< absolute; 0: kDefaultExportTolerance × length
  std::optional<int> degree;   ///< 3 or 5; none: 3 for .svg (cubic Béziers), 5 otherwise
  long max_spans = 1'000'000;  ///< ExportOptions::max_spans
  bool comb = false;           ///< .svg: the B-spline's curvature comb (SvgOptions)
  /// ExportOptions::fit with fit_max_degree = this (3 … kMaxFitDegree; 3 for .svg): fits of degree
  /// 3 up to it, the fewest control points kept; none: no fit (the knot removal's B-spline).
  std::optional<int> fit_max_degree{};
};

/// The caller's names of the request's fields, for its InputErrors (CLI: "lac", "export",
/// "export-tol", "export-degree", "export-fit-degree"; Python: "export_curve", "path", "tolerance",
/// "degree", "fit_max_degree").
struct ExportNames {
  const char* who;
  const char* path;
  const char* tolerance;
  const char* degree;
  const char* fit_max_degree;
};

struct PreparedExport {
  ExportFormat format = ExportFormat::dxf;
  ExportOptions options;
  SvgOptions svg;
};

/// Whether this program writes STEP and IGES (linked with lac::export).
inline constexpr bool kExportsStepAndIges =
#ifdef LAC_WITH_OCCT
    true;
#else
    false;
#endif

/// Checks the request before any curve is computed: InputError naming the path for an unknown
/// extension or STEP/IGES without OpenCASCADE, the tolerance unless ≥ 0 and finite, the degree
/// unless 3 or 5 (3 for .svg), the fit's largest degree unless in [3, kMaxFitDegree] (3 for .svg).
inline PreparedExport prepare_export(const ExportRequest& request, const ExportNames& names) {
  PreparedExport p;
  p.format = export_format_from_path(request.path, names.path, names.who);
  if (!kExportsStepAndIges && (p.format == ExportFormat::step || p.format == ExportFormat::iges))
    throw_input_error(names.who, names.path,
                      "'" + request.path + "': " + to_string(p.format) +
                          " needs OpenCASCADE, and this build has none (LAC_WITH_OCCT=OFF); .dxf and .svg need none");
  if (!(request.tolerance >= 0 && std::isfinite(request.tolerance)))
    throw_input_error(names.who, names.tolerance, request.tolerance, "[0, inf) (0: 1e-6 x the curve's length)");
  const int degree = request.degree.value_or(p.format == ExportFormat::svg ? 3 : 5);
  if (degree != 3 && degree != 5) throw_input_error(names.who, names.degree, degree, "3 or 5");
  if (p.format == ExportFormat::svg && degree != 3)
    throw_input_error(names.who, names.degree, degree, "3 for .svg (SVG paths hold cubic Bezier curves)");
  if (request.fit_max_degree) {
    const int q = *request.fit_max_degree;
    if (q < 3 || q > kMaxFitDegree)
      throw_input_error(names.who, names.fit_max_degree, q, "[3, " + std::to_string(kMaxFitDegree) + "]");
    if (p.format == ExportFormat::svg && q != 3)
      throw_input_error(names.who, names.fit_max_degree, q, "3 for .svg (SVG paths hold cubic Bezier curves)");
    p.options.fit = true;
    p.options.fit_max_degree = q;
  }
  p.options.tolerance = request.tolerance;
  p.options.degree = degree;
  p.options.max_spans = request.max_spans;
  p.svg.comb = request.comb;
  return p;
}

/// Writes a B-spline result (planar ExportResult, or a space one: export_space_curve.hpp) to
/// `path` in the prepared format when it is usable (nothing is written otherwise); returns it.
/// InputError naming "export" when the file cannot be written. The SVG options apply to planar
/// B-splines (a space one has no SVG format).
template <class R>
R write_export(R r, const std::string& path, const PreparedExport& p) {
  if (!r.usable()) return r;
  const auto write = [&](auto&&... svg) {
#ifdef LAC_WITH_OCCT
    write_any(path, p.format, r.curve, svg...);
#else
    write_file(path, p.format, r.curve, svg...);
#endif
  };
  if constexpr (std::is_same_v<decltype(r.curve), BSpline>) write(p.svg);
  else write();
  return r;
}

/// The certified B-spline of `curve` (to_bspline), written to `path` in the prepared format when
/// it is usable (nothing is written otherwise). InputError naming "export" when the file cannot
/// be written.
inline ExportResult export_curve(const PlanarCurve& curve, const std::string& path, const PreparedExport& p) {
  return write_export(to_bspline(curve, p.options), path, p);
}

/// The same for the arc [s0, s1] of a quadratic LA curve (to_bspline's quadratic overload).
inline ExportResult export_curve(const QuadraticLaCurve& curve, double s0, double s1, const std::string& path,
                                 const PreparedExport& p) {
  return write_export(to_bspline(curve, s0, s1, p.options), path, p);
}

}  // namespace lac
