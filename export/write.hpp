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

/// The Bézier pieces of a polynomial B-spline (each degree + 1 points), one per non-empty knot
/// span (blossoms: detail::bezier_pieces_on). InputError for a rational one.
std::vector<std::vector<std::complex<double>>> bezier_pieces(const BSpline& b);

/// What write_svg draws besides the curve.
struct SvgOptions {
  /// The curvature comb of the B-spline itself (its curvature from the Bézier pieces, not the LA
  /// curve's): at `comb_teeth_per_piece` + 1 parameters t = i/n of every piece (both ends, so a
  /// curvature jump at a knot shows as two teeth), a tooth from B(t) to B(t) − c·κ(t)·N(t), N the
  /// unit left normal, κ = (B' × B'')/|B'|³ (left turn positive): the teeth stand on the side away
  /// from the centre of curvature; c makes the longest tooth 0.15 × the diagonal of the control
  /// points' bounding box. The tips are joined by one polyline.
  bool comb = false;
  int comb_teeth_per_piece = 16;
};
/// The fraction of the drawing's bounding-box diagonal that the longest comb tooth spans (both
/// SVG writers: here and `lac … --format svg --comb`).
inline constexpr double kCombFraction = 0.15;

/// A DXF document (R2000 group codes) holding one SPLINE entity in the xy plane.
void write_dxf(std::ostream& out, const BSpline& b);
/// An SVG document with one path of cubic Bézier commands (degree 3 only; InputError otherwise):
/// the path's coordinates are the curve's (y up), drawn upright by a scale(1, -1) group; the
/// viewBox holds the control points (and the comb) with a margin. With `options.comb` also the
/// curvature comb (SvgOptions): a <path id="comb-teeth"> of "M base L tip" pairs, one per tooth,
/// and a <polyline id="comb-tips">; InputError "comb_teeth_per_piece" outside [1, 1000].
void write_svg(std::ostream& out, const BSpline& b, const SvgOptions& options = {});
/// Writes `b` to `path` in the DXF or SVG format; InputError naming "export" when the file
/// cannot be written or the format needs OpenCASCADE (STEP, IGES: export/occt/occt_writer.hpp).
/// `svg` is used by the SVG format only.
void write_file(const std::string& path, ExportFormat format, const BSpline& b, const SvgOptions& svg = {});

}  // namespace lac
