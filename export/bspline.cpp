#include "lac/export/bspline.hpp"

#include <algorithm>
#include <cmath>

#include "lac/common/error.hpp"

namespace lac {

void BSpline::distinct_knots(std::vector<double>& values, std::vector<int>& multiplicities) const {
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

void BSpline::validate() const {
  constexpr const char* kWho = "BSpline";
  if (degree < 1 || degree > 25) throw_input_error(kWho, "degree", degree, "[1, 25]");
  if (control_points.size() < static_cast<size_t>(degree) + 1)
    throw_input_error(kWho, "control_points", static_cast<double>(control_points.size()), "at least degree + 1 points");
  if (knots.size() != control_points.size() + degree + 1)
    throw_input_error(kWho, "knots", static_cast<double>(knots.size()), "control_points + degree + 1 values");
  for (size_t i = 0; i + 1 < knots.size(); ++i)
    if (!(knots[i] <= knots[i + 1])) throw_input_error(kWho, "knots", knots[i + 1], "a non-decreasing sequence");
  if (!(t_max() > t_min())) throw_input_error(kWho, "knots", t_max(), "a non-empty parameter range");
  if (!weights.empty()) {
    if (weights.size() != control_points.size())
      throw_input_error(kWho, "weights", static_cast<double>(weights.size()), "one weight per control point");
    for (double w : weights)
      if (!(w > 0) || !std::isfinite(w)) throw_input_error(kWho, "weights", w, "(0, inf)");
  }
}

std::complex<double> BSpline::point_at(double t) const {
  const int p = degree;
  t = std::clamp(t, t_min(), t_max());
  // The span k with knots[k] <= t < knots[k + 1] (the last non-empty span at t_max).
  auto it = std::upper_bound(knots.begin() + p, knots.end() - p - 1, t);
  size_t k = static_cast<size_t>(it - knots.begin()) - 1;
  while (k > static_cast<size_t>(p) && knots[k] == knots[k + 1]) --k;
  const bool rat = rational();
  std::vector<std::complex<double>> d(p + 1);
  std::vector<double> w(p + 1, 1.0);
  for (int j = 0; j <= p; ++j) {
    const size_t i = k - p + j;
    w[j] = rat ? weights[i] : 1.0;
    d[j] = control_points[i] * w[j];
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

}  // namespace lac
