// Curve classes of lac._lac: the planar curve of a construction (lac.Curve), the space curve
// (lac.SpaceCurve), the standard-form LA curve of `lac eval` (lac.LaCurve) and the quadratic LA
// curve of `lac quadratic` (lac.QuadraticCurve). Each evaluates arrays of arc lengths into columns.
#include <cmath>
#include <limits>
#include <variant>

#include "bindings.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"

namespace lacpy {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> to_vector(const py::array_t<double, py::array::c_style | py::array::forcecast>& a, const char* name) {
  if (a.ndim() > 1) lac::throw_input_error("eval", name, "expected a scalar or a 1-D array");
  return std::vector<double>(a.data(), a.data() + a.size());
}

/// n ≥ 2 values equally spaced (to rounding): a polyline evaluates them incrementally.
bool uniform(const std::vector<double>& s) {
  if (s.size() < 2 || s.back() <= s.front()) return false;
  const double h = (s.back() - s.front()) / double(s.size() - 1);
  for (size_t i = 0; i < s.size(); ++i)
    if (std::abs(s[i] - (s.front() + double(i) * h)) > 1e-12 * (std::abs(s.back()) + std::abs(s.front())))
      return false;
  return true;
}

py::array_t<double> array(const std::vector<double>& v) { return py::array_t<double>(py::ssize_t(v.size()), v.data()); }

py::array strings(const std::vector<std::string>& v) {
  py::list l;
  for (const auto& s : v) l.append(s);
  return py::module_::import("numpy").attr("array")(l);
}

/// Columns s, x, y, theta, kappa, dkappa, status, error_estimate from position results (x, y NaN
/// where the position failed, as the CLI's null) and dκ/ds values.
py::object planar_columns(const std::vector<lac::PositionResult>& pts, const std::vector<double>& dkappa) {
  const size_t n = pts.size();
  std::vector<double> s(n), x(n), y(n), th(n), k(n), err(n);
  std::vector<std::string> st(n);
  for (size_t i = 0; i < n; ++i) {
    const auto& p = pts[i];
    const bool ok = lac::usable(p.status);
    s[i] = p.point.s;
    x[i] = ok ? p.point.position.real() : kNaN;
    y[i] = ok ? p.point.position.imag() : kNaN;
    th[i] = p.point.theta;
    k[i] = p.point.kappa;
    err[i] = ok ? p.error_estimate : kNaN;
    st[i] = status_text(p.status);
  }
  py::dict d;
  d["s"] = array(s);
  d["x"] = array(x);
  d["y"] = array(y);
  d["theta"] = array(th);
  d["kappa"] = array(k);
  d["dkappa"] = array(dkappa);
  d["status"] = strings(st);
  d["error_estimate"] = array(err);
  return columns(d);
}

/// The method for positions of a PlanarCurve: every registered one (igf by its closed form per segment).
template <class F>
auto with_method(const lac::AnyQuadrature& q, F&& f) {
  return std::visit([&](const auto& m) { return f(m); }, q);
}

py::object eval_planar(const Curve& c, py::array_t<double, py::array::c_style | py::array::forcecast> s_in,
                       std::optional<std::string> integrator) {
  if (c.curve.segments().empty()) lac::throw_input_error("Curve.eval", "curve", "the curve is empty");
  const std::vector<double> s = to_vector(s_in, "s");
  for (double v : s) c.curve.check_s(v, "s");
  const lac::AnyQuadrature method = integrator ? lac::make_quadrature(*integrator) : c.integrator;
  std::vector<lac::PositionResult> pts;
  std::vector<double> dk(s.size());
  {
    py::gil_scoped_release release;
    with_method(method, [&](const auto& m) {
      if (uniform(s)) {
        pts = lac::polyline(c.curve, s.front(), s.back(), int(s.size()), m);
      } else {
        pts.reserve(s.size());
        for (double v : s) pts.push_back(lac::position_at(c.curve, v, m));
      }
      return 0;
    });
    for (size_t i = 0; i < s.size(); ++i) dk[i] = c.curve.dkappa_ds_at(pts[i].point.s);
  }
  return planar_columns(pts, dk);
}

py::list planar_segments(const lac::PlanarCurve& curve) {
  py::list out;
  for (const lac::LaSegment& seg : curve.segments()) {
    const double alpha = seg.law().alpha, length = seg.length();
    const double k0 = seg.kappa_start(), k1 = seg.kappa_end();
    const double q0 = seg.law().q_of_kappa(k0), q1 = seg.law().q_of_kappa(k1);
    py::dict j;
    j["kind"] = "la";
    j["alpha"] = alpha;
    j["q0"] = q0;
    j["q1"] = q1;
    j["lambda"] = std::abs(q1 - q0) / (length * (alpha == 0 ? 1.0 : std::abs(alpha)));
    j["length"] = length;
    j["start"] = py::make_tuple(seg.start().real(), seg.start().imag());
    j["theta"] = seg.theta_start();
    j["kappa"] = k0;
    j["theta_end"] = seg.theta_end();
    j["kappa_end"] = k1;
    out.append(j);
  }
  return out;
}

py::object eval_space(const SpaceCurve& c, py::array_t<double, py::array::c_style | py::array::forcecast> s_in) {
  if (c.curve.pieces().empty()) lac::throw_input_error("SpaceCurve.eval", "curve", "the curve is empty");
  const std::vector<double> s = to_vector(s_in, "s");
  for (double v : s) c.curve.check_s(v, "s");
  std::vector<lac::SpacePoint> pts;
  {
    py::gil_scoped_release release;
    if (uniform(s)) {
      pts = c.curve.sample(s.front(), s.back(), int(s.size()));
    } else {
      for (double v : s) pts.push_back(c.curve.frame_at(v));
    }
  }
  const size_t n = pts.size();
  std::vector<double> ss(n), x(n), y(n), z(n), k(n), t(n), dk(n);
  std::vector<std::string> st(n);
  for (size_t i = 0; i < n; ++i) {
    const auto& p = pts[i];
    const bool ok = p.status == lac::Status::ok;
    ss[i] = p.s;
    x[i] = ok ? p.p.x() : kNaN;
    y[i] = ok ? p.p.y() : kNaN;
    z[i] = ok ? p.p.z() : kNaN;
    k[i] = p.kappa;
    t[i] = p.tau;
    dk[i] = p.dkappa_ds;
    st[i] = status_text(p.status);
  }
  py::dict d;
  d["s"] = array(ss);
  d["x"] = array(x);
  d["y"] = array(y);
  d["z"] = array(z);
  d["kappa"] = array(k);
  d["tau"] = array(t);
  d["dkappa"] = array(dk);
  d["status"] = strings(st);
  return columns(d);
}

lac::Parameter eval_parameter(const std::optional<py::object>& theta, const std::optional<py::object>& s) {
  if (theta && s) lac::throw_input_error("LaCurve.eval", "theta", "give one of theta or s, not both");
  if (!theta && !s) lac::throw_input_error("LaCurve.eval", "theta", "one of theta or s is required");
  return theta ? lac::Parameter::theta : lac::Parameter::s;
}

py::object eval_standard(const lac::LaCurve& curve, std::optional<py::object> theta, std::optional<py::object> s,
                         const std::string& form_name, const std::string& integrator) {
  const lac::Parameter p = eval_parameter(theta, s);
  const std::vector<double> t =
      to_vector(py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(theta ? *theta : *s),
                p == lac::Parameter::theta ? "theta" : "s");
  for (double v : t) curve.check(p, v, p == lac::Parameter::theta ? "theta" : "s");
  const lac::Form form = lac::parse_form(form_name);
  const lac::AnyQuadrature method = lac::make_quadrature(integrator);
  std::vector<lac::PositionResult> pts;
  {
    py::gil_scoped_release release;
    for (double v : t) pts.push_back(lac::position_at(curve, p, v, method, form));
  }
  std::vector<double> dk(pts.size()), rho(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    // 001 Table 1: dρ/ds = Λ ρ^(1−α), so dκ/ds = −Λ κ^(1+α)
    const double k = pts[i].point.kappa;
    dk[i] = -curve.lambda() * std::pow(k, 1.0 + curve.alpha());
    rho[i] = pts[i].point.rho;
  }
  py::object cols = planar_columns(pts, dk);
  cols["rho"] = array(rho);
  return cols;
}

py::object eval_quadratic(const lac::QuadraticLaCurve& curve, py::array_t<double, py::array::c_style | py::array::forcecast> s_in,
                          const std::string& integrator) {
  const std::vector<double> s = to_vector(s_in, "s");
  for (double v : s) curve.check_s(v, "s");
  const lac::AnyQuadrature method = lac::make_quadrature(integrator);
  std::vector<lac::PositionResult> pts;
  {
    py::gil_scoped_release release;
    if (uniform(s)) {
      pts = lac::polyline(curve, s.front(), s.back(), int(s.size()), method);
    } else {
      for (double v : s) pts.push_back(lac::position_at(curve, v, method));
    }
  }
  std::vector<double> dk(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    const double k = std::abs(pts[i].point.kappa);  // dκ/ds = 1 / (ds/dκ), also past the inflection (point symmetry)
    dk[i] = k > 0 && std::isfinite(k) ? 1.0 / curve.ds_dkappa(k) : kNaN;
  }
  return planar_columns(pts, dk);
}

}  // namespace

void bind_curves(py::module_& m) {
  py::class_<Curve>(m, "Curve", "A planar curve of LA segments (the curve of a planar construction).")
      .def_property_readonly("length", [](const Curve& c) { return c.curve.length(); }, "Arc length")
      .def_property_readonly("segments", [](const Curve& c) { return planar_segments(c.curve); },
                             "The LA segments as dicts (keys as the CLI's segments: kind, alpha, q0, q1, lambda, length, "
                             "start, theta, kappa, theta_end, kappa_end)")
      .def_property_readonly("integrator", [](const Curve& c) { return lac::describe(c.integrator); },
                             "Quadrature method of the positions")
      .def("eval", &eval_planar, py::arg("s"), py::arg("integrator") = py::none(),
           "Columns s, x, y, theta, kappa, dkappa, status, error_estimate at the arc lengths s (array or scalar in "
           "[0, length]); equally spaced s are integrated incrementally. integrator: a quadrature name (default: the "
           "construction's)")
      .def(
          "sample", [](const Curve& c, int n) {
            if (n < 2 || n > 1'000'000) lac::throw_input_error("Curve.sample", "n", n, "[2, 1000000]");
            std::vector<double> s(n);
            for (int i = 0; i < n; ++i) s[i] = c.curve.length() * i / (n - 1);
            s.back() = c.curve.length();
            return eval_planar(c, py::array_t<double>(n, s.data()), std::nullopt);
          },
          py::arg("n"), "n points uniform in arc length (as the CLI's --samples)")
      .def("kappa", py::vectorize([](const Curve* c, double s) { c->curve.check_s(s, "s"); return c->curve.kappa_at(s); }),
           py::arg("s"), "Signed curvature at s (closed form)")
      .def("theta", py::vectorize([](const Curve* c, double s) { c->curve.check_s(s, "s"); return c->curve.theta_at(s); }),
           py::arg("s"), "Tangent angle at s (closed form, continuous)")
      .def("__repr__", [](const Curve& c) {
        return "<lac.Curve length=" + lac::format_number(c.curve.length()) +
               " segments=" + std::to_string(c.curve.segments().size()) + ">";
      });

  py::class_<SpaceCurve>(m, "SpaceCurve", "A space curve of LA space pieces (the curve of lac.space).")
      .def_property_readonly("length", [](const SpaceCurve& c) { return c.curve.length(); })
      .def_property_readonly("pieces", [](const SpaceCurve& c) { return c.curve.pieces().size(); }, "Number of pieces")
      .def("eval", &eval_space, py::arg("s"),
           "Columns s, x, y, z, kappa, tau, dkappa, status at the arc lengths s (integrated Frenet frames)")
      .def(
          "sample", [](const SpaceCurve& c, int n) {
            if (n < 2 || n > 1'000'000) lac::throw_input_error("SpaceCurve.sample", "n", n, "[2, 1000000]");
            std::vector<double> s(n);
            for (int i = 0; i < n; ++i) s[i] = c.curve.length() * i / (n - 1);
            s.back() = c.curve.length();
            return eval_space(c, py::array_t<double>(n, s.data()));
          },
          py::arg("n"))
      .def("__repr__", [](const SpaceCurve& c) {
        return "<lac.SpaceCurve length=" + lac::format_number(c.curve.length()) + ">";
      });

  py::class_<lac::LaCurve>(m, "LaCurve",
                           "Planar LA curve in standard form (origin, tangent +x, rho = 1 at s = 0), as `lac eval`.")
      .def(py::init<double, double>(), py::arg("alpha"), py::arg("lambda_"),
           "alpha any finite real, lambda_ >= 0 (0: the unit circle)")
      .def_property_readonly("alpha", &lac::LaCurve::alpha)
      .def_property_readonly("lambda_", &lac::LaCurve::lambda)
      .def_property_readonly("s_domain", [](const lac::LaCurve& c) { return py::make_tuple(c.s_domain().lo, c.s_domain().hi); },
                             "Open domain of s")
      .def_property_readonly("theta_domain",
                             [](const lac::LaCurve& c) { return py::make_tuple(c.theta_domain().lo, c.theta_domain().hi); })
      .def("eval", &eval_standard, py::kw_only(), py::arg("theta") = py::none(), py::arg("s") = py::none(),
           py::arg("form") = "auto", py::arg("integrator") = "gauss-kronrod",
           "Columns s, x, y, theta, kappa, rho, dkappa, status, error_estimate at theta or s (arrays), as `lac eval`; "
           "form theta | s | auto")
      .def("__repr__", [](const lac::LaCurve& c) {
        return "<lac.LaCurve alpha=" + lac::format_number(c.alpha()) + " lambda=" + lac::format_number(c.lambda()) + ">";
      });

  py::class_<lac::QuadraticLaCurve>(m, "QuadraticCurve",
                                    "Quadratic LA curve [Yoshida-Saito 2016] in standard form (kappa = 1, tangent +x at the "
                                    "origin at s = 0), as `lac quadratic`.")
      .def(py::init([](double alpha, double gamma, double lambda, const std::string& inverse, bool through_inflection) {
             lac::QuadraticOptions o;
             o.inverse = lac::special::parse_erf_inverse_method(inverse);
             o.through_inflection = through_inflection;
             return lac::QuadraticLaCurve(alpha, gamma, lambda, o);
           }),
           py::arg("alpha"), py::arg("gamma"), py::arg("lambda_"), py::kw_only(), py::arg("inverse") = "ours",
           py::arg("through_inflection") = false)
      .def_property_readonly("alpha", &lac::QuadraticLaCurve::alpha)
      .def_property_readonly("gamma", &lac::QuadraticLaCurve::gamma)
      .def_property_readonly("lambda_", &lac::QuadraticLaCurve::lambda)
      .def_property_readonly("s_domain", [](const lac::QuadraticLaCurve& c) {
        return py::make_tuple(c.s_domain().lo, c.s_domain().hi);
      })
      .def_property_readonly("default_range", [](const lac::QuadraticLaCurve& c) {
        const lac::Interval r = c.default_range();
        return py::make_tuple(r.lo, r.hi);
      }, "The default drawing range (s_from, s_to) of `lac quadratic` (docs/quadratic.md)")
      .def_property_readonly("bounds", [](const lac::QuadraticLaCurve& c) {
        py::dict d;
        d["s_at_infinite_kappa"] = c.s_at_infinite_kappa();
        d["s_at_zero_kappa"] = c.s_at_zero_kappa();
        d["has_inflection"] = c.has_inflection();
        d["theta_at_zero_kappa"] = c.theta_at_zero_kappa();
        return d;
      })
      .def("eval", &eval_quadratic, py::arg("s"), py::arg("integrator") = "gauss-kronrod",
           "Columns s, x, y, theta, kappa, dkappa, status, error_estimate at the arc lengths s (in s_domain)")
      .def("lcg", py::vectorize([](const lac::QuadraticLaCurve* c, double log_rho) { return c->lcg(log_rho); }),
           py::arg("log_rho"), "The LCG parabola log(rho ds/drho) = gamma (log rho)^2 + alpha log rho - log Lambda");
}

}  // namespace lacpy
