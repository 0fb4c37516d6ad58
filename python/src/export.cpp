// CAD export (export/, docs/export.md) for lac.Curve, lac.QuadraticCurve and lac.SpaceCurve: the
// B-spline of a planar curve, of a quadratic LA curve's arc or of a space curve within a bound, and
// their files (.dxf; .svg for planar curves; .step and .iges when the module is built with OpenCASCADE).
#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "lac/export/export_curve.hpp"
#include "lac/export/export_space_curve.hpp"

namespace lacpy {

namespace {

void put(py::detail::unchecked_mutable_reference<double, 2>& p, size_t i, std::complex<double> z) {
  p(static_cast<py::ssize_t>(i), 0) = z.real();
  p(static_cast<py::ssize_t>(i), 1) = z.imag();
}
template <class Point>
void put(py::detail::unchecked_mutable_reference<double, 2>& p, size_t i, const Point& v) {
  for (py::ssize_t k = 0; k < 3; ++k) p(static_cast<py::ssize_t>(i), k) = v[k];
}

/// A planar (ExportResult: control points n x 2) or space (SpaceExportResult: n x 3, no planar
/// curvature check: curvature_monotone None) B-spline result as a dict.
template <class R>
py::dict bspline_dict(const R& r) {
  constexpr bool planar = std::is_same_v<R, lac::ExportResult>;
  py::dict d;
  d["status"] = status_text(r.summary.status);
  d["message"] = r.summary.message;
  d["usable"] = r.usable();
  const auto& b = r.curve;
  d["degree"] = b.degree;
  py::array_t<double> knots(static_cast<py::ssize_t>(b.knots.size()));
  std::copy(b.knots.begin(), b.knots.end(), knots.mutable_data());
  d["knots"] = knots;
  py::array_t<double> points({static_cast<py::ssize_t>(b.control_points.size()), py::ssize_t{planar ? 2 : 3}});
  auto p = points.mutable_unchecked<2>();
  for (size_t i = 0; i < b.control_points.size(); ++i) put(p, i, b.control_points[i]);
  d["control_points"] = points;
  d["weights"] = py::none();
  d["tolerance"] = r.info.tolerance;
  d["max_deviation"] = r.info.max_deviation;
  d["spans"] = r.info.spans;
  if constexpr (planar) d["curvature_monotone"] = r.info.curvature_monotone;
  else d["curvature_monotone"] = py::none();
  d["continuity"] = r.info.continuity;
  return d;
}

constexpr lac::ExportNames kNames{"export_curve", "path", "tolerance", "degree", "fit_max_degree"};

lac::ExportOptions options(double tolerance, int degree, long max_spans, bool remove_knots, bool fit, int fit_max_degree) {
  return {.tolerance = tolerance,
          .max_spans = max_spans,
          .degree = degree,
          .remove_knots = remove_knots,
          .fit = fit,
          .fit_max_degree = fit_max_degree};
}

/// The B-spline `make()` returns (a to_bspline call), computed with the GIL released, as a dict.
template <class Make>
py::dict bspline_of(Make&& make) {
  decltype(make()) r;
  {
    py::gil_scoped_release release;
    r = make();
  }
  return bspline_dict(r);
}

/// The same for a file written by `write()` (an export_curve call): the dict gains file (None when
/// nothing was written) and format.
template <class Write>
py::dict written(const std::string& path, const lac::PreparedExport& prepared, Write&& write) {
  decltype(write()) r;
  {
    py::gil_scoped_release release;
    r = write();
  }
  py::dict d = bspline_dict(r);
  d["file"] = r.usable() ? py::object(py::str(path)) : py::none();
  d["format"] = lac::to_string(prepared.format);
  return d;
}

}  // namespace

void bind_export(py::module_& m) {
  m.def(
      "to_bspline",
      [](const Curve& c, double tolerance, int degree, long max_spans, bool remove_knots, bool fit,
         int fit_max_degree) {
        return bspline_of([&] { return lac::to_bspline(c.curve, options(tolerance, degree, max_spans, remove_knots, fit, fit_max_degree)); });
      },
      py::arg("curve"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = 5, py::arg("max_spans") = 1'000'000,
      py::arg("remove_knots") = true, py::arg("fit") = false, py::arg("fit_max_degree") = 0,
      "The curve as a B-spline with a certified bound on its deviation (docs/export.md): a dict with status, "
      "usable, degree, knots, control_points (n x 2), weights (None: polynomial), tolerance (absolute; 0 asks "
      "for 1e-6 x length), max_deviation (the certified bound), spans, curvature_monotone, continuity. "
      "degree 5 (default): G2 quintic spans; 3: G1 cubic ones. remove_knots (default True): the knots inside each "
      "LA segment removed within the tolerance (fewer control points); False: the Hermite spans' knots. fit "
      "(default False): also a least-squares fit with a proven bound, taken where it needs fewer points (its "
      "curvature follows the LA curve less closely); fit_max_degree (default 0: the fit has the degree `degree`): fits "
      "of every degree from 3 up to this (at most 9) are tried and the fewest control points kept, with the "
      "continuity of `degree` at joints and ends. A bound above the "
      "tolerance: status inaccurate.");
  m.def(
      "export_curve",
      [](const Curve& c, const std::string& path, double tolerance, std::optional<int> degree,
         std::optional<int> fit_max_degree) {
        const lac::PreparedExport p = lac::prepare_export(
            {.path = path, .tolerance = tolerance, .degree = degree, .fit_max_degree = fit_max_degree}, kNames);
        return written(path, p, [&] { return lac::export_curve(c.curve, path, p); });
      },
      py::arg("curve"), py::arg("path"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = py::none(),
      py::arg("fit_max_degree") = py::none(),
      "Writes the certified B-spline of the curve to `path`, the format from its extension (.step/.stp, "
      ".iges/.igs, .dxf, .svg); returns to_bspline's dict plus file (None when the bound exceeds the "
      "tolerance: nothing is written) and format. fit_max_degree (3-9; 3 for .svg): the fewest control "
      "points of the fits of degree 3 up to it (to_bspline's fit=True, fit_max_degree).");

  // A quadratic LA curve (lac.QuadraticCurve): the arc [s_from, s_to], by default its drawing range.
  auto arc = [](const lac::QuadraticLaCurve& c, std::optional<double> s_from, std::optional<double> s_to) {
    const lac::Interval r = c.default_range();
    return std::pair{s_from.value_or(r.lo), s_to.value_or(r.hi)};
  };
  m.def(
      "to_bspline",
      [arc](const lac::QuadraticLaCurve& c, std::optional<double> s_from, std::optional<double> s_to, double tolerance,
            int degree, long max_spans, bool remove_knots, bool fit,
         int fit_max_degree) {
        const auto [s0, s1] = arc(c, s_from, s_to);
        return bspline_of([&] { return lac::to_bspline(c, s0, s1, options(tolerance, degree, max_spans, remove_knots, fit, fit_max_degree)); });
      },
      py::arg("curve"), py::kw_only(), py::arg("s_from") = py::none(), py::arg("s_to") = py::none(),
      py::arg("tolerance") = 0.0, py::arg("degree") = 5, py::arg("max_spans") = 1'000'000, py::arg("remove_knots") = true,
      py::arg("fit") = false, py::arg("fit_max_degree") = 0,
      "The arc [s_from, s_to] of a quadratic LA curve (default: its default_range, as `lac quadratic` draws) "
      "as a certified B-spline, the same dict; its parameter is the arc length from s_from.");
  m.def(
      "export_curve",
      [arc](const lac::QuadraticLaCurve& c, const std::string& path, std::optional<double> s_from,
            std::optional<double> s_to, double tolerance, std::optional<int> degree, std::optional<int> fit_max_degree) {
        const lac::PreparedExport p = lac::prepare_export(
            {.path = path, .tolerance = tolerance, .degree = degree, .fit_max_degree = fit_max_degree}, kNames);
        const auto [s0, s1] = arc(c, s_from, s_to);
        return written(path, p, [&] { return lac::export_curve(c, s0, s1, path, p); });
      },
      py::arg("curve"), py::arg("path"), py::kw_only(), py::arg("s_from") = py::none(), py::arg("s_to") = py::none(),
      py::arg("tolerance") = 0.0, py::arg("degree") = py::none(), py::arg("fit_max_degree") = py::none(),
      "Writes the certified B-spline of the arc [s_from, s_to] of a quadratic LA curve (default: its "
      "default_range) to `path`; the same dict as for a planar curve.");

  m.def(
      "to_bspline",
      [](const SpaceCurve& c, double tolerance, int degree, long max_spans, bool remove_knots, bool fit,
         int fit_max_degree) {
        return bspline_of([&] { return lac::to_bspline(c.curve, options(tolerance, degree, max_spans, remove_knots, fit, fit_max_degree)); });
      },
      py::arg("curve"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = 5, py::arg("max_spans") = 1'000'000,
      py::arg("remove_knots") = true, py::arg("fit") = false, py::arg("fit_max_degree") = 0,
      "A space curve (lac.SpaceCurve) as a B-spline in space within max_deviation (docs/export.md): the same dict "
      "with control_points n x 3 and curvature_monotone None.");
  m.def(
      "export_curve",
      [](const SpaceCurve& c, const std::string& path, double tolerance, std::optional<int> degree,
         std::optional<int> fit_max_degree) {
        const lac::PreparedExport p = lac::prepare_space_export(
            {.path = path, .tolerance = tolerance, .degree = degree, .fit_max_degree = fit_max_degree}, kNames);
        return written(path, p, [&] { return lac::export_curve(c.curve, path, p); });
      },
      py::arg("curve"), py::arg("path"), py::kw_only(), py::arg("tolerance") = 0.0, py::arg("degree") = py::none(),
      py::arg("fit_max_degree") = py::none(),
      "Writes the B-spline of a space curve to `path` (.step/.stp, .iges/.igs, .dxf; .svg holds planar curves "
      "only: ValueError naming path).");
}

}  // namespace lacpy
