#pragma once
// Internal: the one implementation of the B-spline operations that do not depend on the control
// points' dimension, used by BSpline (export/bspline.hpp, planar) and BSpline3
// (export/bspline3.hpp, space): the check of degree, knots and weights, the distinct knots with
// their multiplicities, de Boor's algorithm, the blossom and the Bézier pieces, and the norm of a
// point of either type.
#include <algorithm>
#include <cmath>
#include <complex>
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

inline double point_norm(const std::complex<double>& a) { return std::abs(a); }
template <class V>
double point_norm(const V& a) {
  return a.norm();
}
template <class P>
double point_distance(const P& a, const P& b) {
  return point_norm(P(a - b));
}

/// The blossom of the B-spline's piece on knot span k (U[k] < U[k+1]) at t[0], …, t[p − 1]: de Boor's
/// algorithm with level r taking its own argument t[r − 1] (The NURBS Book §5.3; Ramshaw).
template <class P>
P blossom(int p, const std::vector<double>& U, const std::vector<P>& pts, size_t k, const double* t) {
  std::vector<P> d(pts.begin() + static_cast<std::ptrdiff_t>(k - p), pts.begin() + static_cast<std::ptrdiff_t>(k + 1));
  for (int r = 1; r <= p; ++r)
    for (int i = p; i >= r; --i) {
      const size_t lo = k - p + i;
      const double a = (t[r - 1] - U[lo]) / (U[k + 1 + i - r] - U[lo]);
      d[i] = (1 - a) * d[i - 1] + a * d[i];
    }
  return d[p];
}

/// The Bézier pieces (p + 1 points each) of the B-spline on the intervals between consecutive
/// `breaks` (sorted, distinct, from t_min to t_max, holding every distinct knot in between): point i
/// of the piece on [x0, x1] is the blossom at (x0 × (p − i), x1 × i).
template <class P>
std::vector<std::vector<P>> bezier_pieces_on(int p, const std::vector<double>& U, const std::vector<P>& pts,
                                             const std::vector<double>& breaks) {
  std::vector<std::vector<P>> out(breaks.size() - 1);
  std::vector<double> t(p);
  for (size_t j = 0; j < out.size(); ++j) {
    const double x0 = breaks[j], x1 = breaks[j + 1], mid = 0.5 * (x0 + x1);
    size_t k = static_cast<size_t>(std::upper_bound(U.begin(), U.end(), mid) - U.begin()) - 1;
    k = std::min(k, U.size() - p - 2);
    out[j].resize(p + 1);
    for (int i = 0; i <= p; ++i) {
      for (int r = 0; r < p; ++r) t[r] = r < p - i ? x0 : x1;
      out[j][i] = blossom(p, U, pts, k, t.data());
    }
  }
  return out;
}

}  // namespace lac::detail
