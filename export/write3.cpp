#include "lac/export/write3.hpp"

#include <array>

#include "lac/common/error.hpp"
#include "lac/export/detail/write_text.hpp"

namespace lac {

void write_dxf(std::ostream& out, const BSpline3& b) {
  b.validate();
  detail::write_dxf_spline(out, false, b.degree, b.knots, b.weights, b.control_points, [](const Eigen::Vector3d& c) {
    return std::array<std::string, 3>{detail::number17(c.x()), detail::number17(c.y()), detail::number17(c.z())};
  });
}

void write_file(const std::string& path, ExportFormat format, const BSpline3& b) {
  if (format == ExportFormat::svg)
    throw_input_error("write_file", "export",
                      "'" + path + "': .svg holds planar curves; a space curve goes to .dxf, .step or .iges");
  detail::write_export_file(path, format, [&](std::ostream& out) { write_dxf(out, b); });
}

}  // namespace lac
