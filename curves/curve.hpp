#pragma once
// What every planar curve model answers (LaCurve, QuadraticLaCurve, PlanarCurve): a frame at an
// arc length, a position at an arc length with a quadrature method, and polylines, under the
// same names (the PlanarCurveModel concept at the end).
#include <complex>
#include <concepts>
#include <string>
#include <string_view>
#include <vector>

#include "lac/common/numeric.hpp"
#include "lac/common/status.hpp"

namespace lac {

/// A point of a planar curve with its Frenet data. tangent = (cos θ, sin θ). For LaCurve
/// (standard form) κ = 1/ρ > 0; the other models give the signed curvature κ and ρ = 1/κ (±inf
/// at an inflection).
struct CurvePoint {
  double s = 0;
  double theta = 0;
  double rho = 1;    ///< radius of curvature
  double kappa = 1;  ///< curvature 1/ρ
  std::complex<double> position{};
};

/// Which integral represents the position of a standard-form curve (la_position.hpp); the other
/// models integrate in arc length (Form::s).
enum class Form { theta, s, automatic };

constexpr std::string_view to_string(Form f) {
  return f == Form::theta ? "theta" : f == Form::s ? "s" : "auto";
}
Form parse_form(std::string_view text);  // "theta" | "s" | "auto"; InputError otherwise

/// A point with its position and how the position was obtained.
///
/// Polylines compute every point from a point already known to be right (the curve's reference
/// point, a segment's start, or an earlier point whose status is ok or fell_back), so a point
/// that fails never shifts the others. A point whose status is not usable() holds no position of
/// its own: `point.position` is that of the known point it was to be integrated from and
/// `error_estimate` is +inf. A point with status tolerance_not_met holds its computed position
/// (with the estimate) but is not used as a starting point for others.
struct PositionResult {
  CurvePoint point;
  double error_estimate = 0;  ///< absolute, on the position
  long evaluations = 0;       ///< integrand evaluations (cumulative along a polyline)
  Status status = Status::ok;
  std::string message;
  Form form = Form::theta;    ///< form actually used
};

/// A curve model of the library: arc-length domain, frame (everything but the position) at an
/// arc length, position at an arc length with a quadrature method, and n points uniform in arc
/// length, all with these names.
template <class C, class M>
concept PlanarCurveModel = requires(const C& c, double s, int n, const M& method) {
  { c.s_domain() } -> std::same_as<Interval>;
  { c.frame_at(s) } -> std::same_as<CurvePoint>;
  { position_at(c, s, method) } -> std::same_as<PositionResult>;
  { polyline(c, s, s, n, method) } -> std::same_as<std::vector<PositionResult>>;
};

}  // namespace lac
