#pragma once
// Writers of a BSpline (export/bspline.hpp) in the formats that need no CAD kernel:
//   .dxf  a SPLINE entity (AutoCAD 2000 group codes), written by hand: Debian has no DXF library
//         for C++ (ezdxf is Python; the tests read the file back with it)
//   .svg  cubic Bézier path commands (M … C …), the B-spline split at its knots, not a polyline
// STEP and IGES go through OpenCASCADE: export/occt/occt_writer.hpp (the optional lac::export).
// Numbers are written with 17 significant digits (round-trip exact).
#include <complex>
#include <ostream>
#include <string>
#include <vector>

#include "lac/export/bspline.hpp"

namespace lac {

enum class ExportFormat { step, iges, dxf, svg };

/// The format from a file name's extension (.step/.stp, .iges/.igs, .dxf, .svg; any case).
/// InputError naming `function` and `parameter` for another extension.
ExportFormat export_format_from_path(const std::string& path, const char* parameter = "export",
                                     const char* function = "export_format_from_path");
constexpr const char* to_string(ExportFormat f) {
  switch (f) {
    case ExportFormat::step: return "step";
    case ExportFormat::iges: return "iges";
    case ExportFormat::dxf: return "dxf";
    case ExportFormat::svg: return "svg";
  }
  return "unknown";
}

/// The Bézier pieces of a polynomial B-spline (each degree + 1 points), by knot insertion
/// (Boehm) up to multiplicity `degree` at every interior knot. InputError for a rational one.
std::vector<std::vector<std::complex<double>>> bezier_pieces(const BSpline& b);

/// A DXF document (R2000 group codes) holding one SPLINE entity in the xy plane.
void write_dxf(std::ostream& out, const BSpline& b);
/// An SVG document with one path of cubic Bézier commands (degree 3 only; InputError otherwise):
/// the path's coordinates are the curve's (y up), drawn upright by a scale(1, -1) group; the
/// viewBox holds the control points with a margin.
void write_svg(std::ostream& out, const BSpline& b);
/// Writes `b` to `path` in the DXF or SVG format; InputError naming "export" when the file
/// cannot be written or the format needs OpenCASCADE (STEP, IGES: export/occt/occt_writer.hpp).
void write_file(const std::string& path, ExportFormat format, const BSpline& b);

}  // namespace lac
