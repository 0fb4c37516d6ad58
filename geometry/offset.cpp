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
  for (size_t k = 0; k < curve.segments().size(); ++k) {
    const LaSegment& seg = curve.segments()[k];
    const double s0 = curve.segment_start(k);
    if (g(seg.kappa_start()) <= 0) {
      c.s = s0;
      c.at_joint = k > 0 && g(curve.segments()[k - 1].kappa_end()) > 0;
      return c;
    }
    if (g(seg.kappa_end()) > 0) continue;
    // 1 − dκ changes sign inside: κ is monotonic in u, so one root; TOMS 748 on the closed form.
    const auto f = [&](double u) { return g(seg.curvature_per_u(u) / seg.scale()); };
    std::uintmax_t iterations = 200;
    const auto tol = [](double a, double b) { return std::abs(b - a) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)); };
    const auto bracket = boost::math::tools::toms748_solve(f, seg.ua(), seg.ub(), f(seg.ua()), f(seg.ub()), tol, iterations);
    // The first u with 1 − dκ ≤ 0: the upper end of the final bracket.
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
