// CAD export (export/, docs/export.md) for lac.Curve and lac.SpaceCurve: the certified B-spline of
// a planar curve, the B-spline of a space curve, and their files (.dxf, .svg for planar curves;
// .step and .iges when the module is built with OpenCASCADE).
#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "lac/export/export_curve.hpp"
#include "lac/export/export_space_curve.hpp"

namespace lacpy {

namespace {

py::dict bspline_dict(const lac::ExportResult& r) {
  py::dict d;
  d["status"] = status_text(r.summary.status);
  d["message"] = r.summary.message;
  d["usable"] = r.usable();
  const lac::BSpline& b = r.curve;
  d["degree"] = b.degree;
  py::array_t<double> knots(static_cast<py::ssize_t>(b.knots.size()));
  std::copy(b.knots.begin(), b.knots.end(), knots.mutable_data());
  d["knots"] = knots;
  py::array_t<double> points({static_cast<py::ssize_t>(b.control_points.size()), py::ssize_t{2}});
  auto p = points.mutable_unchecked<2>();
  for (size_t i = 0; i < b.control_points.size(); ++i) {
    p(static_cast<py::ssize_t>(i), 0) = b.control_points[i].real();
    p(static_cast<py::ssize_t>(i), 1) = b.control_points[i].imag();
  }
  d["control_points"] = points;
  d["weights"] = py::none();
  const lac::ExportInfo& in = r.info;
  d["tolerance"] = in.tolerance;
  d["max_deviation"] = in.max_deviation;
  d["spans"] = in.spans;
  d["curvature_monotone"] = in.curvature_monotone;
  d["continuity"] = in.continuity;
  return d;
}

/// The same for a space curve: control_points n x 3; the planar curvature check does not apply (None).
py::dict bspline_dict(const lac::SpaceExportResult& r) {
  py::dict d;
  d["status"] = status_text(r.summary.status);
  d["message"] = r.summary.message;
  d["usable"] = r.usable();
  const lac::BSpline3& b = r.curve;
  d["degree"] = b.degree;
  py::array_t<double> knots(static_cast<py::ssize_t>(b.knots.size()));
  std::copy(b.knots.begin(), b.knots.end(), knots.mutable_data());
  d["knots"] = knots;
  py::array_t<double> points({static_cast<py::ssize_t>(b.control_points.size()), py::ssize_t{3}});
  auto p = points.mutable_unchecked<2>();
  for (size_t i = 0; i < b.control_points.size(); ++i)
    for (py::ssize_t k = 0; k < 3; ++k) p(static_cast<py::ssize_t>(i), k) = b.control_points[i][k];
  d["control_points"] = points;
  d["weights"] = py::none();
  d["tolerance"] = r.info.tolerance;
  d["max_deviation"] = r.info.max_deviation;
  d["spans"] = r.info.spans;
  d["curvature_monotone"] = py::none();
  d["continuity"] = r.info.continuity;
  return d;
}

}  // namespace

void bind_export(py::module_& m) {
  m.def(
      "to_bspline",
      [](const Curve& c, double tolerance, int degree, long max_spans) {
        lac::ExportResult r;
        {
          py::gil_scoped_release release;
          r = lac::to_bspline(c.curve, {.tolerance = tolerance, .max_spans = max_spans, .degree = degree});
        }
        return bspline_dict(r);
      },
      py::arg("curve"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = 5, py::arg("max_spans") = 1'000'000,
      "The curve as a B-spline with a certified bound on its deviation (docs/export.md): a dict with status, "
      "usable, degree, knots, control_points (n x 2), weights (None: polynomial), tolerance (absolute; 0 asks "
      "for 1e-6 x length), max_deviation (the certified bound), spans, curvature_monotone, continuity. "
      "degree 5 (default): G2 quintic spans; 3: G1 cubic ones. A bound above the tolerance: status inaccurate.");
  m.def(
      "export_curve",
      [](const Curve& c, const std::string& path, double tolerance, std::optional<int> degree) {
        const lac::PreparedExport prepared = lac::prepare_export({.path = path, .tolerance = tolerance, .degree = degree},
                                                                 {"export_curve", "path", "tolerance", "degree"});
        lac::ExportResult r;
        {
          py::gil_scoped_release release;
          r = lac::export_curve(c.curve, path, prepared);
        }
        py::dict d = bspline_dict(r);
        d["file"] = r.usable() ? py::object(py::str(path)) : py::none();
        d["format"] = lac::to_string(prepared.format);
        return d;
      },
      py::arg("curve"), py::arg("path"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = py::none(),
      "Writes the certified B-spline of the curve to `path`, the format from its extension (.step/.stp, "
      ".iges/.igs, .dxf, .svg); returns to_bspline's dict plus file (None when the bound exceeds the "
      "tolerance: nothing is written) and format.");
  m.def(
      "to_bspline",
      [](const SpaceCurve& c, double tolerance, int degree, long max_spans) {
        lac::SpaceExportResult r;
        {
          py::gil_scoped_release release;
          r = lac::to_bspline(c.curve, {.tolerance = tolerance, .max_spans = max_spans, .degree = degree});
        }
        return bspline_dict(r);
      },
      py::arg("curve"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = 5, py::arg("max_spans") = 1'000'000,
      "A space curve (lac.SpaceCurve) as a B-spline in space within max_deviation (docs/export.md): the same dict "
      "with control_points n x 3 and curvature_monotone None.");
  m.def(
      "export_curve",
      [](const SpaceCurve& c, const std::string& path, double tolerance, std::optional<int> degree) {
        const lac::PreparedExport prepared = lac::prepare_space_export(
            {.path = path, .tolerance = tolerance, .degree = degree}, {"export_curve", "path", "tolerance", "degree"});
        lac::SpaceExportResult r;
        {
          py::gil_scoped_release release;
          r = lac::export_curve(c.curve, path, prepared);
        }
        py::dict d = bspline_dict(r);
        d["file"] = r.usable() ? py::object(py::str(path)) : py::none();
        d["format"] = lac::to_string(prepared.format);
        return d;
      },
      py::arg("curve"), py::arg("path"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = py::none(),
      "Writes the B-spline of a space curve to `path` (.step/.stp, .iges/.igs, .dxf; .svg holds planar curves "
      "only: ValueError naming path).");
}

}  // namespace lacpy
