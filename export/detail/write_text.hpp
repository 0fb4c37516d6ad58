#pragma once
// Internal: what the writers of the planar BSpline (export/write.hpp) and the space BSpline3
// (export/write3.hpp) share: the number format of every hand-written export (17 significant
// digits: round-trip exact), the one DXF writer of a SPLINE entity (R2000 group codes) and the
// writing of a file with its errors.
#include <array>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/export/write.hpp"

namespace lac::detail {

/// `v` with 17 significant digits.
inline std::string number17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// A DXF document holding one SPLINE entity: degree, knots, weights (empty: polynomial) and the
/// control points, xyz(point) giving each one's coordinates as written (group codes 10, 20, 30).
/// `planar`: flagged planar (70: +8) with the xy plane's normal (210, 220, 230).
template <class P, class Xyz>
void write_dxf_spline(std::ostream& out, bool planar, int degree, const std::vector<double>& knots,
                      const std::vector<double>& weights, const std::vector<P>& points, const Xyz& xyz) {
  auto g = [&out](int code, const std::string& value) { out << code << "\n" << value << "\n"; };
  g(0, "SECTION");
  g(2, "HEADER");
  g(9, "$ACADVER");
  g(1, "AC1015");
  g(9, "$INSUNITS");
  g(70, "0");
  g(0, "ENDSEC");
  g(0, "SECTION");
  g(2, "ENTITIES");
  g(0, "SPLINE");
  g(5, "100");
  g(100, "AcDbEntity");
  g(8, "0");
  g(100, "AcDbSpline");
  if (planar) {
    g(210, "0.0");
    g(220, "0.0");
    g(230, "1.0");
  }
  g(70, std::to_string((planar ? 8 : 0) + (weights.empty() ? 0 : 4)));  // planar, rational
  g(71, std::to_string(degree));
  g(72, std::to_string(knots.size()));
  g(73, std::to_string(points.size()));
  g(74, "0");
  g(42, "1e-10");
  g(43, "1e-10");
  for (double k : knots) g(40, number17(k));
  for (size_t i = 0; i < points.size(); ++i) {
    if (!weights.empty()) g(41, number17(weights[i]));
    const std::array<std::string, 3> c = xyz(points[i]);
    g(10, c[0]);
    g(20, c[1]);
    g(30, c[2]);
  }
  g(0, "ENDSEC");
  g(0, "EOF");
}

/// Writes `path` by write(std::ostream&) (DXF, SVG); InputError naming "export" for STEP and IGES
/// (OpenCASCADE: export/occt/occt_writer.hpp) and when the file cannot be written.
template <class Write>
void write_export_file(const std::string& path, ExportFormat format, const Write& write) {
  if (format == ExportFormat::step || format == ExportFormat::iges)
    throw_input_error("write_file", "export",
                      "'" + path + "': " + to_string(format) +
                          " is written through OpenCASCADE (export/occt/occt_writer.hpp, lac::export)");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw_input_error("write_file", "export", "'" + path + "': cannot open the file for writing");
  write(out);
  out.flush();
  if (!out) throw_input_error("write_file", "export", "'" + path + "': writing failed");
}

}  // namespace lac::detail
