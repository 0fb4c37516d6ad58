#pragma once
// The 20-point Gauss–Legendre rule on [0, 1] (nodes and weights from Boost.Math's tables), for
// fixed-node composite quadrature where an adaptive driver is too slow (the G2 and S-curve solvers
// integrate e^{iφ} over a few panels thousands of times per solve).
#include <array>
#include <cstddef>

namespace lac {

struct GaussLegendreRule {
  static constexpr std::size_t kPoints = 20;
  std::array<double, kPoints> nodes{};    ///< ascending in (0, 1)
  std::array<double, kPoints> weights{};  ///< sum to 1
};

/// The rule, built once.
const GaussLegendreRule& gauss_legendre_20();

}  // namespace lac
