#pragma once
// STEP and IGES export of a BSpline through OpenCASCADE (the optional component lac::export,
// CMake option LAC_WITH_OCCT): the curve becomes a Geom_BSplineCurve in the plane z = 0 (a
// BSpline3 of export/bspline3.hpp: in space),
// written by STEPControl_Writer (an edge on a B_SPLINE_CURVE_WITH_KNOTS, or its rational form)
// or IGESControl_Writer (entity 126, rational B-spline curve). DXF and SVG need no CAD kernel
// (export/write.hpp); write_any dispatches on the format.
#include <string>

#include "lac/export/bspline.hpp"
#include "lac/export/bspline3.hpp"
#include "lac/export/write.hpp"

namespace lac {

/// InputError naming "export" when the file cannot be written.
void write_step(const std::string& path, const BSpline& b);
void write_iges(const std::string& path, const BSpline& b);
/// Any format of export/write.hpp (`svg` for the SVG format only).
void write_any(const std::string& path, ExportFormat format, const BSpline& b, const SvgOptions& svg = {});
/// The same for a space B-spline (DXF through export/write3.hpp; no SVG: InputError).
void write_step(const std::string& path, const BSpline3& b);
void write_iges(const std::string& path, const BSpline3& b);
void write_any(const std::string& path, ExportFormat format, const BSpline3& b);

}  // namespace lac
