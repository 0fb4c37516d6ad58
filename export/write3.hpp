#pragma once
// Writers of a space B-spline (export/bspline3.hpp) in the formats that need no CAD kernel: .dxf,
// a SPLINE entity with z coordinates (group 30), not flagged planar. SVG holds planar curves only
// (InputError); STEP and IGES go through OpenCASCADE (export/occt/occt_writer.hpp).
#include <ostream>
#include <string>

#include "lac/export/bspline3.hpp"
#include "lac/export/write.hpp"

namespace lac {

/// A DXF document (R2000 group codes) holding one SPLINE entity in space.
void write_dxf(std::ostream& out, const BSpline3& b);
/// Writes `b` to `path` as DXF; InputError naming "export" for .svg (planar curves only), for
/// STEP and IGES (OpenCASCADE: export/occt/occt_writer.hpp) and when the file cannot be written.
void write_file(const std::string& path, ExportFormat format, const BSpline3& b);

}  // namespace lac
