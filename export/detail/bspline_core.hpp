#pragma once
// Internal: the one implementation of the B-spline operations that do not depend on the control
// points' dimension, used by BSpline (export/bspline.hpp, planar) and BSpline3
// (export/bspline3.hpp, space): the check of degree, knots and weights, the distinct knots with
// their multiplicities, and de Boor's algorithm.
#include <algorithm>
#include <cmath>
#include <vector>

#include "lac/common/error.hpp"

namespace lac::detail {

/// InputError naming `who` and the field unless the sizes, degree, knot order and weights agree.
inline void validate_bspline(const char* who, int degree, const std::vector<double>& knots, size_t points,
                             const std::vector<double>& weights) {
  if (degree < 1 || degree > 25) throw_input_error(who, "degree", degree, "[1, 25]");
  if (points < static_cast<size_t>(degree) + 1)
    throw_input_error(who, "control_points", static_cast<double>(points), "at least degree + 1 points");
  if (knots.size() != points + degree + 1)
    throw_input_error(who, "knots", static_cast<double>(knots.size()), "control_points + degree + 1 values");
  for (size_t i = 0; i + 1 < knots.size(); ++i)
    if (!(knots[i] <= knots[i + 1])) throw_input_error(who, "knots", knots[i + 1], "a non-decreasing sequence");
  const double t_min = knots[degree], t_max = knots[knots.size() - 1 - degree];
  if (!(t_max > t_min)) throw_input_error(who, "knots", t_max, "a non-empty parameter range");
  if (!weights.empty()) {
    if (weights.size() != points)
      throw_input_error(who, "weights", static_cast<double>(weights.size()), "one weight per control point");
    for (double w : weights)
      if (!(w > 0) || !std::isfinite(w)) throw_input_error(who, "weights", w, "(0, inf)");
  }
}

inline void distinct_knots(const std::vector<double>& knots, std::vector<double>& values,
                           std::vector<int>& multiplicities) {
  values.clear();
  multiplicities.clear();
  for (double k : knots) {
    if (!values.empty() && values.back() == k) {
      ++multiplicities.back();
    } else {
      values.push_back(k);
      multiplicities.push_back(1);
    }
  }
}

/// The point at t (clamped to the parameter range) by de Boor's algorithm; weights empty for a
/// polynomial B-spline. P: any point type with P * double and P + P.
template <class P>
P de_boor(int p, const std::vector<double>& knots, const std::vector<P>& points, const std::vector<double>& weights,
          double t) {
  t = std::clamp(t, knots.at(p), knots.at(knots.size() - 1 - p));
  // The span k with knots[k] <= t < knots[k + 1] (the last non-empty span at t_max).
  auto it = std::upper_bound(knots.begin() + p, knots.end() - p - 1, t);
  size_t k = static_cast<size_t>(it - knots.begin()) - 1;
  while (k > static_cast<size_t>(p) && knots[k] == knots[k + 1]) --k;
  const bool rational = !weights.empty();
  std::vector<P> d(p + 1);
  std::vector<double> w(p + 1, 1.0);
  for (int j = 0; j <= p; ++j) {
    const size_t i = k - p + j;
    w[j] = rational ? weights[i] : 1.0;
    d[j] = points[i] * w[j];
  }
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const size_t i = k - p + j;
      const double a = (t - knots[i]) / (knots[i + p + 1 - r] - knots[i]);
      d[j] = (1.0 - a) * d[j - 1] + a * d[j];
      w[j] = (1.0 - a) * w[j - 1] + a * w[j];
    }
  return d[p] / w[p];
}

}  // namespace lac::detail
