// Geometry on planar curves (geometry/, docs/geometry.md) for lac.Curve: closest point,
// intersections with a line or another curve, offsets and their first cusp, transforms; closest
// point and intersections (with a line, a curve or another arc) for arcs of lac.QuadraticCurve;
// closest point and plane intersections for lac.SpaceCurve.
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "bindings.hpp"
#include "lac/geometry/closest_point.hpp"
#include "lac/geometry/intersections.hpp"
#include "lac/geometry/offset.hpp"
#include "lac/geometry/space_closest_point.hpp"
#include "lac/geometry/space_intersections.hpp"
#include "lac/geometry/transforms.hpp"

namespace lacpy {

namespace {

py::tuple xy(std::complex<double> z) { return py::make_tuple(z.real(), z.imag()); }

lac::GeometryOptions options(double tolerance, long max_spans, double accept, long max_points = 10000) {
  lac::GeometryOptions o;
  o.tolerance = tolerance;
  o.max_spans = max_spans;
  o.accept = accept;
  o.max_points = max_points;
  return o;
}

py::dict intersections(const lac::Intersections& r) {
  py::list points;
  for (const lac::Intersection& p : r.points) {
    py::dict d;
    d["s"] = p.s;
    d["t"] = p.t;
    d["point"] = xy(p.point);
    d["kind"] = std::string(lac::to_string(p.kind));
    d["error_estimate"] = p.error_estimate;
    points.append(d);
  }
  py::dict d;
  d["status"] = status_text(r.status);
  d["message"] = r.message;
  d["points"] = points;
  d["error_estimate"] = std::isfinite(r.error_estimate) ? py::object(py::float_(r.error_estimate)) : py::object(py::none());
  d["spans"] = r.spans;
  d["evaluations"] = r.evaluations;
  return d;
}

py::object curve(const Curve& like, lac::PlanarCurve c) { return py::cast(Curve{std::move(c), like.integrator}); }

Result result(const lac::Summary& summary, py::object c) {
  Result r;
  r.summary = summary;
  r.curve = summary.usable() ? std::move(c) : py::none();
  return r;
}

/// A ClosestPoint as the dict of lac.closest_point.
py::tuple xyz(const lac::Vec3& v) { return py::make_tuple(v[0], v[1], v[2]); }

// A closest point (planar or space) as a dict; its point as (x, y) or (x, y, z).
template <class R>
py::dict closest_dict(const R& r) {
        py::dict d;
        d["status"] = status_text(r.status);
        d["message"] = r.message;
        d["s"] = r.s;
        if constexpr (std::is_same_v<R, lac::SpaceClosestPoint>) d["point"] = xyz(r.point);
        else d["point"] = xy(r.point);
        d["distance"] = r.distance;
        d["error_estimate"] = std::isfinite(r.error_estimate) ? py::object(py::float_(r.error_estimate)) : py::object(py::none());
        d["spans"] = r.spans;
        d["evaluations"] = r.evaluations;
        return d;
}

}  // namespace

void bind_geometry(py::module_& m) {
  constexpr const char* kOptions =
      " Options: tolerance (relative to the length, default 1e-10), max_spans (work cap, default 200000), accept "
      "(default 1e-6).";
  m.def(
      "closest_point",
      [](const Curve& c, py::handle point, double tolerance, long max_spans, double accept) {
        const lac::ClosestPoint r =
            lac::closest_point(c.curve, point2(point, "closest_point", "point"), options(tolerance, max_spans, accept));
        return closest_dict(r);
      },
      py::arg("curve"), py::arg("point"), py::kw_only(), py::arg("tolerance") = 1e-10, py::arg("max_spans") = 200000,
      py::arg("accept") = lac::kDefaultAccept,
      (std::string("The point of the curve closest to `point` (global over the whole curve): dict status, message, s, "
                   "point, distance, error_estimate, spans, evaluations.") + kOptions).c_str());
  m.def(
      "intersect_line",
      [](const Curve& c, py::handle point, py::handle direction, double tolerance, long max_spans, double accept,
         long max_points) {
        return intersections(lac::intersect_line(c.curve, point2(point, "intersect_line", "point"),
                                                 point2(direction, "intersect_line", "direction"),
                                                 options(tolerance, max_spans, accept, max_points)));
      },
      py::arg("curve"), py::arg("point"), py::arg("direction"), py::kw_only(), py::arg("tolerance") = 1e-10,
      py::arg("max_spans") = 200000, py::arg("accept") = lac::kDefaultAccept, py::arg("max_points") = 10000,
      (std::string("Every intersection of the curve with the line through `point` along `direction`, ordered by s: dict "
                   "status, message, points (dicts s, t = coordinate along the unit direction, point, kind = crossing | "
                   "tangent, error_estimate), error_estimate, spans, evaluations.") + kOptions +
       " max_points: cap on the intersections (default 10000).").c_str());
  // Arcs of a quadratic LA curve (s_from / s_to: the curve's default_range() when None).
  const auto arc = [](const lac::QuadraticLaCurve& c, std::optional<double> s_from, std::optional<double> s_to) {
    const lac::Interval r = c.default_range();
    return std::pair{s_from.value_or(r.lo), s_to.value_or(r.hi)};
  };
  m.def(
      "closest_point",
      [arc](const lac::QuadraticLaCurve& c, py::handle point, std::optional<double> s_from, std::optional<double> s_to,
            double tolerance, long max_spans, double accept) {
        const auto [s0, s1] = arc(c, s_from, s_to);
        const lac::ClosestPoint r = lac::closest_point(c, s0, s1, point2(point, "closest_point", "point"),
                                                       options(tolerance, max_spans, accept));
        return closest_dict(r);
      },
      py::arg("curve"), py::arg("point"), py::kw_only(), py::arg("s_from") = py::none(), py::arg("s_to") = py::none(),
      py::arg("tolerance") = 1e-10, py::arg("max_spans") = 200000, py::arg("accept") = lac::kDefaultAccept,
      (std::string("The point of the arc [s_from, s_to] of a QuadraticCurve closest to `point` (global over the arc; "
                   "default: the curve's default_range): the same dict. Tolerance relative to s_to - s_from.") + kOptions)
          .c_str());
  m.def(
      "intersect_line",
      [arc](const lac::QuadraticLaCurve& c, py::handle point, py::handle direction, std::optional<double> s_from,
            std::optional<double> s_to, double tolerance, long max_spans, double accept, long max_points) {
        const auto [s0, s1] = arc(c, s_from, s_to);
        return intersections(lac::intersect_line(c, s0, s1, point2(point, "intersect_line", "point"),
                                                 point2(direction, "intersect_line", "direction"),
                                                 options(tolerance, max_spans, accept, max_points)));
      },
      py::arg("curve"), py::arg("point"), py::arg("direction"), py::kw_only(), py::arg("s_from") = py::none(),
      py::arg("s_to") = py::none(), py::arg("tolerance") = 1e-10, py::arg("max_spans") = 200000,
      py::arg("accept") = lac::kDefaultAccept, py::arg("max_points") = 10000,
      (std::string("Every intersection of the arc [s_from, s_to] of a QuadraticCurve (default: its default_range) "
                   "with the line, ordered by s: the same dict.") + kOptions).c_str());
  m.def(
      "intersect_curves",
      [](const Curve& a, const Curve& b, double tolerance, long max_spans, double accept, long max_points) {
        return intersections(lac::intersect_curves(a.curve, b.curve, options(tolerance, max_spans, accept, max_points)));
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("tolerance") = 1e-10, py::arg("max_spans") = 200000,
      py::arg("accept") = lac::kDefaultAccept, py::arg("max_points") = 10000,
      (std::string("Every intersection of the curves a and b, ordered by s on a (t: arc length on b); as "
                   "intersect_line.") + kOptions + " max_points: cap on the intersections (default 10000).").c_str());
  m.def(
      "intersect_curves",
      [arc](const lac::QuadraticLaCurve& a, const Curve& b, std::optional<double> s_from, std::optional<double> s_to,
            double tolerance, long max_spans, double accept, long max_points) {
        const auto [s0, s1] = arc(a, s_from, s_to);
        return intersections(
            lac::intersect_curves(a, s0, s1, b.curve, options(tolerance, max_spans, accept, max_points)));
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("s_from") = py::none(), py::arg("s_to") = py::none(),
      py::arg("tolerance") = 1e-10, py::arg("max_spans") = 200000, py::arg("accept") = lac::kDefaultAccept,
      py::arg("max_points") = 10000,
      (std::string("Every intersection of the arc [s_from, s_to] of a QuadraticCurve a (default: its default_range) "
                   "with the curve b, ordered by s on a (t: arc length on b); as intersect_line.") + kOptions).c_str());
  m.def(
      "intersect_curves",
      [arc](const lac::QuadraticLaCurve& a, const lac::QuadraticLaCurve& b, std::optional<double> a_from,
            std::optional<double> a_to, std::optional<double> b_from, std::optional<double> b_to, double tolerance,
            long max_spans, double accept, long max_points) {
        const auto [a0, a1] = arc(a, a_from, a_to);
        const auto [b0, b1] = arc(b, b_from, b_to);
        return intersections(
            lac::intersect_curves(a, a0, a1, b, b0, b1, options(tolerance, max_spans, accept, max_points)));
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("a_from") = py::none(), py::arg("a_to") = py::none(),
      py::arg("b_from") = py::none(), py::arg("b_to") = py::none(), py::arg("tolerance") = 1e-10,
      py::arg("max_spans") = 200000, py::arg("accept") = lac::kDefaultAccept, py::arg("max_points") = 10000,
      (std::string("Every intersection of the arcs [a_from, a_to] of QuadraticCurve a and [b_from, b_to] of "
                   "QuadraticCurve b (defaults: their default_range), ordered by s on a (t: arc length on b); as "
                   "intersect_line.") + kOptions).c_str());
  // Space curves: the closest point and the plane's intersections (positions are the curve's own).
  m.def(
      "closest_point",
      [](const SpaceCurve& c, py::handle point, double tolerance, long max_spans, double accept) {
        return closest_dict(
            lac::closest_point(c.curve, point3(point, "closest_point", "point"), options(tolerance, max_spans, accept)));
      },
      py::arg("curve"), py::arg("point"), py::kw_only(), py::arg("tolerance") = 1e-10, py::arg("max_spans") = 200000,
      py::arg("accept") = lac::kDefaultAccept,
      (std::string("The point of a SpaceCurve closest to `point` (x, y, z; global over the curve): the same dict, "
                   "point as (x, y, z); error_estimate bounds the search's gap relative to the curve's own positions.") +
       kOptions).c_str());
  m.def(
      "intersect_plane",
      [](const SpaceCurve& c, py::handle point, py::handle normal, double tolerance, long max_spans, double accept,
            long max_points) {
        const lac::SpaceIntersections r =
            lac::intersect_plane(c.curve, point3(point, "intersect_plane", "point"),
                                 point3(normal, "intersect_plane", "normal"),
                                 options(tolerance, max_spans, accept, max_points));
        py::list points;
        for (const lac::SpaceIntersection& x : r.points) {
          py::dict p;
          p["s"] = x.s;
          p["point"] = xyz(x.point);
          p["residual"] = x.residual;
          p["kind"] = std::string(lac::to_string(x.kind));
          points.append(p);
        }
        py::dict d;
        d["status"] = status_text(r.status);
        d["message"] = r.message;
        d["points"] = points;
        d["spans"] = r.spans;
        d["evaluations"] = r.evaluations;
        return d;
      },
      py::arg("curve"), py::arg("point"), py::arg("normal"), py::kw_only(), py::arg("tolerance") = 1e-10,
      py::arg("max_spans") = 200000, py::arg("accept") = lac::kDefaultAccept, py::arg("max_points") = 10000,
      (std::string("Every intersection of a SpaceCurve with the plane through `point` with normal `normal`, ordered "
                   "by s: dict status, message, points (dicts s, point, residual = distance from the plane, kind = "
                   "crossing | tangent), spans, evaluations.") + kOptions +
       " max_points: cap on the intersections (default 10000).").c_str());
  m.def(
      "offset",
      [](const Curve& c, py::array_t<double, py::array::c_style | py::array::forcecast> s, double d) {
        if (s.ndim() > 1) lac::throw_input_error("offset", "s", "expected a scalar or a 1-D array");
        const size_t n = static_cast<size_t>(s.size());
        std::vector<double> x(n), y(n), factor(n), kappa(n), err(n), ss(s.data(), s.data() + n);
        py::list status;
        for (size_t i = 0; i < n; ++i) {
          const lac::OffsetPoint o = lac::offset_at(c.curve, ss[i], d);
          const bool ok = lac::usable(o.status);
          x[i] = ok ? o.position.real() : std::numeric_limits<double>::quiet_NaN();
          y[i] = ok ? o.position.imag() : std::numeric_limits<double>::quiet_NaN();
          factor[i] = o.factor;
          kappa[i] = o.kappa;
          err[i] = ok ? o.error_estimate : std::numeric_limits<double>::quiet_NaN();
          status.append(status_text(o.status));
        }
        const auto arr = [](const std::vector<double>& v) { return py::array_t<double>(py::ssize_t(v.size()), v.data()); };
        py::dict out;
        out["s"] = arr(ss);
        out["x"] = arr(x);
        out["y"] = arr(y);
        out["factor"] = arr(factor);
        out["kappa"] = arr(kappa);
        out["status"] = py::module_::import("numpy").attr("array")(status);
        out["error_estimate"] = arr(err);
        return columns(out);
      },
      py::arg("curve"), py::arg("s"), py::arg("d"),
      "The offset p(s) + d N(s) (N the left normal) at the arc lengths s: columns s, x, y, factor = 1 - d kappa "
      "(negative: the offset runs backwards), kappa (the offset's curvature), status, error_estimate");
  m.def(
      "offset_cusp", [](const Curve& c, double d) -> py::object {
        const lac::OffsetCusp r = lac::first_offset_cusp(c.curve, d);
        if (!r.s) return py::none();
        return py::float_(*r.s);
      },
      py::arg("curve"), py::arg("d"),
      "The first arc length where 1 - d kappa(s) is 0 or changes sign (the offset at distance d has a cusp there), None if there is none");
  m.def("translate", [](const Curve& c, py::handle v) { return curve(c, lac::translated(c.curve, point2(v, "translate", "offset"))); },
        py::arg("curve"), py::arg("offset"), "The curve moved by `offset` (exact: same laws)");
  m.def(
      "rotate",
      [](const Curve& c, double angle, py::handle center) {
        return curve(c, lac::rotated(c.curve, angle, point2(center, "rotate", "center")));
      },
      py::arg("curve"), py::arg("angle"), py::arg("center") = py::make_tuple(0.0, 0.0),
      "The curve rotated by `angle` (rad) about `center` (exact: same laws)");
  m.def(
      "scale",
      [](const Curve& c, double factor, py::handle center) {
        return curve(c, lac::scaled(c.curve, factor, point2(center, "scale", "center")));
      },
      py::arg("curve"), py::arg("factor"), py::arg("center") = py::make_tuple(0.0, 0.0),
      "The curve scaled by factor > 0 about `center` (exact: same alpha, lengths x factor)");
  m.def(
      "mirror",
      [](const Curve& c, py::handle point, py::handle direction) {
        return curve(c, lac::mirrored(c.curve, point2(point, "mirror", "point"), point2(direction, "mirror", "direction")));
      },
      py::arg("curve"), py::arg("point"), py::arg("direction"),
      "The mirror image about the line through `point` along `direction` (exact: same alpha, curvature negated)");
  m.def(
      "split",
      [](const Curve& c, double s, double tolerance, double accept) {
        const auto r = lac::split(c.curve, s, options(tolerance, 200000, accept));
        return result(r.summary, py::make_tuple(curve(c, r.curve.first), curve(c, r.curve.second)));
      },
      py::arg("curve"), py::arg("s"), py::kw_only(), py::arg("tolerance") = 1e-10, py::arg("accept") = lac::kDefaultAccept,
      "lac.Result whose curve is the pair (part [0, s], part [s, length]), 0 < s < length");
  m.def(
      "trim",
      [](const Curve& c, double s0, double s1, double tolerance, double accept) {
        const auto r = lac::trimmed(c.curve, s0, s1, options(tolerance, 200000, accept));
        return result(r.summary, curve(c, r.curve));
      },
      py::arg("curve"), py::arg("s0"), py::arg("s1"), py::kw_only(), py::arg("tolerance") = 1e-10,
      py::arg("accept") = lac::kDefaultAccept, "lac.Result whose curve is the part [s0, s1]");
  m.def(
      "append",
      [](const Curve& a, const Curve& b, double gap_tolerance, double tolerance, double accept) {
        const auto r = lac::appended(a.curve, b.curve, gap_tolerance, options(tolerance, 200000, accept));
        return result(r.summary, curve(a, r.curve));
      },
      py::arg("a"), py::arg("b"), py::arg("gap_tolerance"), py::kw_only(), py::arg("tolerance") = 1e-10,
      py::arg("accept") = lac::kDefaultAccept,
      "lac.Result whose curve is a then b; InputError naming b when b starts farther than gap_tolerance from a's end");
  m.def(
      "reverse",
      [](const Curve& c, double tolerance, double accept) {
        const auto r = lac::reversed(c.curve, options(tolerance, 200000, accept));
        return result(r.summary, curve(c, r.curve));
      },
      py::arg("curve"), py::kw_only(), py::arg("tolerance") = 1e-10, py::arg("accept") = lac::kDefaultAccept,
      "lac.Result whose curve is the curve traversed from its end (curvature negated)");
}

}  // namespace lacpy
