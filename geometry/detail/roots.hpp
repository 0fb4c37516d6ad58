#pragma once
// The bracketed root polish of the geometry searches: TOMS 748 (Boost.Math) on [lo, hi], where f
// changes sign, to 4 ulps of the root (and ε of the bracket's width where the root is near 0);
// of the final bracket's ends, the one with the smaller |f|.
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lac::detail {

template <class F>
double root_in(F&& f, double lo, double hi, double flo, double fhi, std::uintmax_t max_iterations = 100) {
  std::uintmax_t iterations = max_iterations;
  const double eps = std::numeric_limits<double>::epsilon(), floor = eps * (hi - lo);
  const auto close = [eps, floor](double a, double b) {
    return std::abs(b - a) <= 4 * eps * std::max(std::abs(a), std::abs(b)) + floor;
  };
  const auto r = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, close, iterations);
  return std::abs(f(r.first)) <= std::abs(f(r.second)) ? r.first : r.second;
}

}  // namespace lac::detail
