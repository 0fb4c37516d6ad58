#pragma once
// The export request of export/export_curve.hpp for a space curve (SpaceCurve): the same checks
// of the path, tolerance and degree, no SVG (its paths are planar), to_bspline of
// export/space_to_bspline.hpp and the space writers (export/write3.hpp; STEP and IGES through
// OpenCASCADE when the program links lac::export).
//
//   const lac::PreparedExport p = lac::prepare_space_export({.path = "c.step"}, names);
//   const lac::SpaceExportResult r = lac::export_curve(space_curve, "c.step", p);
#include <string>

#include "lac/export/export_curve.hpp"
#include "lac/export/space_to_bspline.hpp"
#include "lac/export/write3.hpp"

namespace lac {

/// prepare_export for a space curve: InputError naming the path for .svg (planar curves only)
/// besides prepare_export's checks; the degree defaults to 5.
inline PreparedExport prepare_space_export(const ExportRequest& request, const ExportNames& names) {
  if (export_format_from_path(request.path, names.path, names.who) == ExportFormat::svg)
    throw_input_error(names.who, names.path,
                      "'" + request.path + "': .svg holds planar curves; a space curve goes to .dxf, .step or .iges");
  return prepare_export(request, names);
}

/// The B-spline of `curve` (to_bspline), written to `path` in the prepared format when usable
/// (nothing is written otherwise). InputError naming "export" when the file cannot be written.
inline SpaceExportResult export_curve(const SpaceCurve& curve, const std::string& path, const PreparedExport& p) {
  return write_export(to_bspline(curve, p.options), path, p);
}

}  // namespace lac
