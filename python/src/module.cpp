// The Python module lac._lac: constructions, curve evaluation, batch solves and the special
// functions of the library, with the names and options of the command line (docs/python.md).
#include <algorithm>
#include <cmath>

#include "bindings.hpp"
#include "lac/special/erf_family.hpp"
#include "lac/special/incomplete_gamma.hpp"
#include "lac/version.hpp"

namespace lacpy {

namespace {

py::object number(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return py::none();
  return py::float_(*v);
}
py::object text_or_none(const std::string& s) { return s.empty() ? py::object(py::none()) : py::object(py::str(s)); }

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest(const std::string& name, const std::vector<std::string>& names) {
  std::string best;
  size_t best_d = std::string::npos;
  for (const std::string& n : names) {
    const size_t d = edit_distance(name, n);
    if (d < best_d) best_d = d, best = n;
  }
  return best;
}

void unknown_keyword(const char* function, const std::string& name, const std::vector<std::string>& valid) {
  std::string msg = std::string(function) + "() got an unexpected keyword argument '" + name + "'";
  if (!valid.empty()) msg += "; did you mean '" + closest(name, valid) + "'?";
  throw py::type_error(msg);
}

py::dict summary_dict(const Result& r) {
  const lac::Summary& s = r.summary;
  py::dict d;
  d["status"] = status_text(s.status);
  d["message"] = text_or_none(s.message);
  d["length"] = py::none();
  d["kappa0"] = py::none();
  d["kappa1"] = py::none();
  if (py::isinstance<Curve>(r.curve)) {
    const lac::PlanarCurve& c = r.curve.cast<const Curve&>().curve;
    d["length"] = number(c.length());
    d["kappa0"] = number(c.kappa_at(0));
    d["kappa1"] = number(c.kappa_at(c.length()));
  } else if (py::isinstance<SpaceCurve>(r.curve)) {
    const lac::SpaceCurve& c = r.curve.cast<const SpaceCurve&>().curve;
    d["length"] = number(c.length());
    d["kappa0"] = number(c.kappa_at(0));
    d["kappa1"] = number(c.kappa_at(c.length()));
  }
  d["iterations"] = s.iterations;
  d["evaluations"] = s.evaluations;
  d["seconds"] = s.seconds;
  d["solver"] = text_or_none(s.solver);
  d["integrator"] = text_or_none(s.integrator);
  py::dict res;
  res["position"] = number(s.residuals.position);
  res["angle"] = number(s.residuals.angle);
  res["curvature"] = number(s.residuals.curvature);
  d["residuals"] = res;
  d["error"] = number(s.error);
  d["accept"] = s.accept;
  d["constructions"] = s.constructions;
  d["error_estimate"] = number(s.error_estimate);
  return d;
}

std::optional<lac::AnyQuadrature> QuadratureArgs::method(const char* function) const {
  if (integrator == "auto") {
    if (any_option())
      lac::throw_input_error(function, "integrator", "h, tol and panels need an explicit integrator (" +
                                                         lac::method_names_text(lac::quadrature_methods(), " | ") + ")");
    return std::nullopt;
  }
  return lac::make_quadrature(integrator, options);
}

QuadratureArgs take_quadrature(py::dict& kw, const char* default_integrator) {
  QuadratureArgs q{default_integrator, {}};
  if (kw.contains("integrator")) q.integrator = py::str(kw["integrator"]), PyDict_DelItemString(kw.ptr(), "integrator");
  if (kw.contains("h")) q.options.h = kw["h"].cast<double>(), PyDict_DelItemString(kw.ptr(), "h");
  if (kw.contains("tol")) q.options.tol = kw["tol"].cast<double>(), PyDict_DelItemString(kw.ptr(), "tol");
  if (kw.contains("panels")) q.options.panels = kw["panels"].cast<int>(), PyDict_DelItemString(kw.ptr(), "panels");
  return q;
}

double real(py::handle h, const char* function, const char* name) {
  try {
    return h.cast<double>();
  } catch (const py::cast_error&) {
    lac::throw_input_error(function, name, "expected a real number, got " + std::string(py::str(py::type::of(h))));
  }
}

namespace {
std::vector<double> coordinates(py::handle h, size_t n, const char* function, const char* name) {
  if (n == 2 && PyComplex_Check(h.ptr())) {
    const auto z = h.cast<std::complex<double>>();
    return {z.real(), z.imag()};
  }
  std::vector<double> v;
  try {
    v = h.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    lac::throw_input_error(function, name, "expected " + std::to_string(n) + " coordinates, got " +
                                               std::string(py::str(py::type::of(h))));
  }
  if (v.size() != n)
    lac::throw_input_error(function, name, "expected " + std::to_string(n) + " coordinates, got " + std::to_string(v.size()));
  return v;
}
}  // namespace

std::complex<double> point2(py::handle h, const char* function, const char* name) {
  const auto v = coordinates(h, 2, function, name);
  return {v[0], v[1]};
}

lac::Vec3 point3(py::handle h, const char* function, const char* name) {
  const auto v = coordinates(h, 3, function, name);
  return {v[0], v[1], v[2]};
}

py::object columns(py::dict data) { return py::module_::import("lac._columns").attr("Columns")(data); }

namespace {

void bind_result(py::module_& m) {
  py::class_<Result>(m, "Result", "The result of a construction: status, summary, curve (None unless usable), info.")
      .def_property_readonly("status", [](const Result& r) { return status_text(r.summary.status); },
                             "ok, tolerance_not_met, fell_back (usable) or max_iterations, no_solution, "
                             "numerical_failure, not_converged, inaccurate")
      .def_property_readonly("message", [](const Result& r) { return r.summary.message; },
                             "Why, whenever the status is not ok (empty when ok)")
      .def_property_readonly("usable", [](const Result& r) { return r.summary.usable(); },
                             "True when the curve can be used (status ok, tolerance_not_met or fell_back)")
      .def_property_readonly("summary", &summary_dict,
                             "The report keys of the command line: status, message, length, kappa0, kappa1, iterations, "
                             "evaluations, seconds, solver, integrator, residuals {position, angle, curvature}, error, "
                             "accept, constructions, error_estimate")
      .def_property_readonly("curve", [](const Result& r) { return r.curve; }, "The curve (None unless usable)")
      .def_property_readonly("info", [](const Result& r) { return r.info; }, "What is particular to the construction")
      .def("__bool__", [](const Result& r) { return r.summary.usable(); })
      .def("__repr__", [](const Result& r) {
        std::string s = "<lac.Result status=" + status_text(r.summary.status);
        if (!r.summary.message.empty()) s += " message='" + r.summary.message + "'";
        return s + ">";
      });
}

}  // namespace

void bind_special(py::module_& m) {
  using namespace lac::special;
  m.def("erf", py::vectorize([](double x) { return lac::special::erf(x); }), py::arg("x"), "erf(x) (Boost.Math); arrays element-wise");
  m.def("erfc", py::vectorize([](double x) { return lac::special::erfc(x); }), py::arg("x"), "erfc(x) (Boost.Math)");
  m.def("erfi", py::vectorize([](double x) { return lac::special::erfi(x); }), py::arg("x"), "erfi(x) = -i erf(ix) (libcerf); +-inf beyond |x| ~ 26.64");
  m.def("dawson", py::vectorize([](double x) { return lac::special::dawson(x); }), py::arg("x"), "Dawson's integral D(x) = sqrt(pi)/2 exp(-x^2) erfi(x) (libcerf)");
  m.def("erfcx", py::vectorize([](double x) { return lac::special::erfcx(x); }), py::arg("x"), "erfcx(x) = exp(x^2) erfc(x) (libcerf)");
  m.def("erfc_inv", py::vectorize([](double q) { return lac::special::erfc_inv(q); }), py::arg("q"), "erfc^-1(q), 0 < q < 2 (Boost.Math); ValueError otherwise");
  m.def(
      "erf_inv",
      [](py::array_t<double> y, const std::string& method) {
        const bool boost = method == "boost";
        if (!boost && method != "hybrid-003")
          lac::throw_input_error("erf_inv", "method", "'" + method + "' is not one of boost | hybrid-003");
        return py::vectorize([boost](double v) {
          if (!(std::abs(v) < 1.0)) lac::throw_input_error("erf_inv", "y", v, "(-1, 1)");
          return boost ? erf_inv(v) : erf_inv_hybrid_003(v).value;
        })(y);
      },
      py::arg("y"), py::arg("method") = "boost",
      "erf^-1(y), -1 < y < 1, as `lac special erf-inv`: method boost (Boost.Math) | hybrid-003 (003's, |x| <= 5)");
  m.def(
      "erfi_inv",
      [](py::array_t<double> y, const std::string& method) {
        const ErfInverseMethod mth = parse_erf_inverse_method(method);
        return py::vectorize([mth](double v) {
          if (std::isnan(v)) lac::throw_input_error("erfi_inv", "y", v, "(any real number or +-inf)");
          return erfi_inv_detailed(v, mth).value;
        })(y);
      },
      py::arg("y"), py::arg("method") = "ours",
      "erfi^-1(y), any real y, as `lac special erfi-inv`: method ours | hybrid-003 (003's bisection-Newton, |x| <= 26)");
  m.def(
      "gamma_inc",
      [](double a, py::array_t<std::complex<double>> z, bool scaled) {
        return py::vectorize([a, scaled](std::complex<double> zz) {
          return (scaled ? gamma_inc_scaled(a, zz) : gamma_inc(a, zz)).value;
        })(z);
      },
      py::arg("a"), py::arg("z"), py::arg("scaled") = false,
      "Upper incomplete gamma function Gamma(a, z), real a in [-10, 10], complex z (principal branch), as `lac special "
      "gamma-inc`; scaled=True gives exp(z) z^-a Gamma(a, z)");
  m.def(
      "gamma_inc_detailed",
      [](double a, std::complex<double> z, bool scaled) {
        const GammaIncResult r = scaled ? gamma_inc_scaled(a, z) : gamma_inc(a, z);
        py::dict d;
        d["status"] = status_text(r.status);
        d["value"] = r.value;
        d["region"] = std::string(to_string(r.region));
        d["iterations"] = r.iterations;
        return d;
      },
      py::arg("a"), py::arg("z"), py::arg("scaled") = false,
      "Gamma(a, z) with status, region (series, continued_fraction, asymptotic, ...) and iterations");
}

}  // namespace lacpy

PYBIND11_MODULE(_lac, m) {
  using namespace lacpy;
  m.doc() = "lac: log-aesthetic curves (C++ library bindings). See docs/python.md.";
  m.attr("__version__") = std::string(lac::version);
  // lac::InputError -> lac.InputError, a ValueError whose message names the parameter and its valid
  // range; the parameter is also its attribute `parameter`.
  static py::exception<lac::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const lac::InputError& e) {
      py::object err = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      err.attr("parameter") = e.parameter();
      PyErr_SetObject(input_error.ptr(), err.ptr());
    }
  });
  bind_result(m);
  bind_curves(m);
  bind_constructions(m);
  bind_batch(m);
  bind_special(m);
  bind_geometry(m);
  bind_export(m);
}
