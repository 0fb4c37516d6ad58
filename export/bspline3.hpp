#pragma once
// A B-spline curve in space, the form CAD formats store (STEP B_SPLINE_CURVE_WITH_KNOTS, IGES
// entity 126, DXF SPLINE): BSpline (export/bspline.hpp) with (x, y, z) control points. Both share
// one implementation of the knot check and de Boor's algorithm (export/detail/bspline_core.hpp).
//
//   lac::BSpline3 b = lac::to_bspline(space_curve, {.tolerance = 1e-6}).curve;  // export/space_to_bspline.hpp
//   Eigen::Vector3d p = b.point_at(b.t_min());
#include <Eigen/Core>
#include <vector>

namespace lac {

struct BSpline3 {
  int degree = 3;
  std::vector<double> knots;                    ///< non-decreasing, control_points.size() + degree + 1 values
  std::vector<Eigen::Vector3d> control_points;  ///< (x, y, z)
  std::vector<double> weights;                  ///< empty: polynomial (non-rational)

  bool rational() const { return !weights.empty(); }
  double t_min() const { return knots.at(degree); }
  double t_max() const { return knots.at(knots.size() - 1 - degree); }
  /// Distinct knots and their multiplicities (as OpenCASCADE's Geom_BSplineCurve takes them).
  void distinct_knots(std::vector<double>& values, std::vector<int>& multiplicities) const;
  /// The point at parameter t ∈ [t_min, t_max] (clamped), by de Boor's algorithm.
  Eigen::Vector3d point_at(double t) const;
  /// InputError naming the field unless the sizes, degree, knot order and weights are consistent.
  void validate() const;
};

}  // namespace lac
