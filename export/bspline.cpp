#include "lac/export/bspline.hpp"

#include "lac/export/detail/bspline_core.hpp"

namespace lac {

void BSpline::distinct_knots(std::vector<double>& values, std::vector<int>& multiplicities) const {
  detail::distinct_knots(knots, values, multiplicities);
}

void BSpline::validate() const { detail::validate_bspline("BSpline", degree, knots, control_points.size(), weights); }

std::complex<double> BSpline::point_at(double t) const {
  return detail::de_boor(degree, knots, control_points, weights, t);
}

}  // namespace lac
