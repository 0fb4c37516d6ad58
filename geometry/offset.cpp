#include "lac/geometry/offset.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "lac/common/error.hpp"

namespace lac {

OffsetPoint offset_at(const PlanarCurve& curve, double s, double d, const GaussLegendre& method) {
  require_finite("offset_at", "d", d);
  curve.check_s(s, "s");
  const PositionResult p = position_at(curve, s, method);
  OffsetPoint o;
  o.s = s;
  o.d = d;
  const std::complex<double> T = std::polar(1.0, p.point.theta), N = std::complex<double>(0, 1) * T;
  o.position = p.point.position + d * N;
  o.error_estimate = p.error_estimate;
  o.factor = 1.0 - d * p.point.kappa;
  o.tangent = o.factor < 0 ? -T : T;
  o.kappa = o.factor == 0 ? std::copysign(std::numeric_limits<double>::infinity(), p.point.kappa)
                          : p.point.kappa / o.factor;
  o.evaluations = p.evaluations;
  o.status = p.status;
  o.message = p.message;
  if (!usable(o.status)) o.error_estimate = std::numeric_limits<double>::infinity();
  return o;
}

OffsetCusp first_offset_cusp(const PlanarCurve& curve, double d) {
  require_finite("first_offset_cusp", "d", d);
  curve.check_s(0.0, "curve");
  OffsetCusp c;
  if (d == 0) return c;
  const auto g = [d](double kappa) { return 1.0 - d * kappa; };
  const double g0 = g(curve.segments().front().kappa_start());
  if (g0 == 0) {
    c.s = 0.0;
    return c;
  }
  c.backwards_at_start = g0 < 0;
  const double sign = g0 > 0 ? 1.0 : -1.0;  // the sign 1 − dκ starts with; a cusp where it is lost
  const auto lost = [sign](double v) { return !(sign * v > 0); };
  for (size_t k = 0; k < curve.segments().size(); ++k) {
    const LaSegment& seg = curve.segments()[k];
    const double s0 = curve.segment_start(k);
    if (lost(g(seg.kappa_start()))) {
      c.s = s0;
      c.at_joint = k > 0;
      return c;
    }
    if (!lost(g(seg.kappa_end()))) continue;
    // 1 − dκ loses its sign inside: κ is monotonic in u, so one root; TOMS 748 on the closed form.
    const auto f = [&](double u) { return sign * g(seg.curvature_per_u(u) / seg.scale()); };
    std::uintmax_t iterations = 200;
    const double floor = std::numeric_limits<double>::epsilon() * (seg.ub() - seg.ua());
    const auto tol = [floor](double a, double b) {
      return std::abs(b - a) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)) + floor;
    };
    const auto bracket = boost::math::tools::toms748_solve(f, seg.ua(), seg.ub(), f(seg.ua()), f(seg.ub()), tol, iterations);
    // The first u where the sign is lost: the upper end of the final bracket, unless the lower one.
    const double u = f(bracket.first) <= 0 ? bracket.first : bracket.second;
    c.s = std::min(curve.segment_start(k + 1), s0 + seg.scale() * (u - seg.ua()));
    if (iterations >= 200) {
      c.status = Status::tolerance_not_met;
      c.message = "first_offset_cusp: TOMS 748 stopped at its cap of 200 iterations; bracket [" +
                  format_number(bracket.first) + ", " + format_number(bracket.second) + "] in u";
    }
    return c;
  }
  return c;
}

}  // namespace lac
