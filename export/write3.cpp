#include "lac/export/write3.hpp"

#include <cstdio>
#include <fstream>

#include "lac/common/error.hpp"

namespace lac {

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

void write_dxf(std::ostream& out, const BSpline3& b) {
  b.validate();
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
  g(70, std::to_string(b.rational() ? 4 : 0));  // not planar (+ rational)
  g(71, std::to_string(b.degree));
  g(72, std::to_string(b.knots.size()));
  g(73, std::to_string(b.control_points.size()));
  g(74, "0");
  g(42, "1e-10");
  g(43, "1e-10");
  for (double k : b.knots) g(40, num(k));
  for (size_t i = 0; i < b.control_points.size(); ++i) {
    if (b.rational()) g(41, num(b.weights[i]));
    g(10, num(b.control_points[i].x()));
    g(20, num(b.control_points[i].y()));
    g(30, num(b.control_points[i].z()));
  }
  g(0, "ENDSEC");
  g(0, "EOF");
}

void write_file(const std::string& path, ExportFormat format, const BSpline3& b) {
  if (format == ExportFormat::svg)
    throw_input_error("write_file", "export",
                      "'" + path + "': .svg holds planar curves; a space curve goes to .dxf, .step or .iges");
  if (format == ExportFormat::step || format == ExportFormat::iges)
    throw_input_error("write_file", "export",
                      "'" + path + "': " + to_string(format) +
                          " is written through OpenCASCADE (export/occt/occt_writer.hpp, lac::export)");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw_input_error("write_file", "export", "'" + path + "': cannot open the file for writing");
  write_dxf(out, b);
  out.flush();
  if (!out) throw_input_error("write_file", "export", "'" + path + "': writing failed");
}

}  // namespace lac
