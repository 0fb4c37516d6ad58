#pragma once
// A planar B-spline curve in the form CAD formats store (STEP B_SPLINE_CURVE_WITH_KNOTS, IGES
// entity 126, DXF SPLINE): degree p, the full knot vector (p + 1 equal knots at both ends),
// control points and, for a rational curve, weights. Evaluated per span by de Boor's algorithm.
//
//   lac::BSpline b = lac::to_bspline(curve, {.tolerance = 1e-6}).curve;   // export/to_bspline.hpp
//   std::complex<double> p = b.point_at(b.knots.front());
#include <complex>
#include <vector>

namespace lac {

struct BSpline {
  int degree = 3;
  std::vector<double> knots;                          ///< non-decreasing, control_points.size() + degree + 1 values
  std::vector<std::complex<double>> control_points;  ///< (x, y)
  std::vector<double> weights;                        ///< empty: polynomial (non-rational)

  bool rational() const { return !weights.empty(); }
  double t_min() const { return knots.at(degree); }
  double t_max() const { return knots.at(knots.size() - 1 - degree); }
  /// Distinct knots and their multiplicities (as OpenCASCADE's Geom_BSplineCurve takes them).
  void distinct_knots(std::vector<double>& values, std::vector<int>& multiplicities) const;
  /// The point at parameter t ∈ [t_min, t_max] (clamped), by de Boor's algorithm.
  std::complex<double> point_at(double t) const;
  /// InputError naming the field unless the sizes, degree, knot order and weights are consistent.
  void validate() const;
};

}  // namespace lac
