#include "lac/export/bspline3.hpp"

#include "lac/export/detail/bspline_core.hpp"

namespace lac {

void BSpline3::distinct_knots(std::vector<double>& values, std::vector<int>& multiplicities) const {
  detail::distinct_knots(knots, values, multiplicities);
}

void BSpline3::validate() const { detail::validate_bspline("BSpline3", degree, knots, control_points.size(), weights); }

Eigen::Vector3d BSpline3::point_at(double t) const {
  return detail::de_boor(degree, knots, control_points, weights, t);
}

}  // namespace lac
