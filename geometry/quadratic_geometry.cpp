#include "lac/geometry/quadratic_geometry.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>

#include "lac/common/error.hpp"

namespace lac {

double dkappa_ds_at(const QuadraticLaCurve& curve, double s) {
  curve.check_s(s, "s");
  const KappaSolution k = curve.solve_kappa(s);
  if (k.kappa == 0) return -std::numeric_limits<double>::infinity();
  const bool past = curve.options().through_inflection && curve.has_inflection() && s > curve.s_at_zero_kappa();
  const double dlog = curve.dlog_kappa_ds(k.log_kappa);
  return k.kappa * (past ? -dlog : dlog);
}

OffsetCusp first_offset_cusp(const QuadraticLaCurve& curve, double d, double s0, double s1) {
  require_finite("first_offset_cusp", "d", d);
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  if (!(s1 > s0)) throw_input_error("first_offset_cusp", "s1", s1, interval_text(s0, curve.s_domain().hi));
  OffsetCusp c;
  if (d == 0) return c;
  Status failed = Status::ok;
  const auto g = [&](double s) {
    const KappaSolution k = curve.solve_kappa(s);
    if (!usable(k.status) && usable(failed)) failed = k.status;
    return 1.0 - d * k.kappa;
  };
  const double g0 = g(s0), g1 = g(s1);
  const auto fail = [&] {
    c.status = failed;
    c.message = "first_offset_cusp: kappa(s) could not be solved (" + std::string(to_string(failed)) + ")";
    return c;
  };
  if (!usable(failed)) return fail();
  if (g0 == 0) {
    c.s = s0;
    return c;
  }
  c.backwards_at_start = g0 < 0;
  const double sign = g0 > 0 ? 1.0 : -1.0;
  if (sign * g1 > 0) return c;  // monotonic: the sign is kept all along
  const auto f = [&](double s) { return sign * g(s); };
  std::uintmax_t iterations = 200;
  const double floor = std::numeric_limits<double>::epsilon() * (s1 - s0);
  const auto tol = [floor](double a, double b) {
    return std::abs(b - a) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)) + floor;
  };
  const auto bracket = boost::math::tools::toms748_solve(f, s0, s1, sign * g0, sign * g1, tol, iterations);
  if (!usable(failed)) return fail();
  c.s = f(bracket.first) <= 0 ? bracket.first : bracket.second;
  if (iterations >= 200) {
    c.status = Status::tolerance_not_met;
    c.message = "first_offset_cusp: TOMS 748 stopped at its cap of 200 iterations; bracket [" +
                format_number(bracket.first) + ", " + format_number(bracket.second) + "]";
  }
  return c;
}

}  // namespace lac
