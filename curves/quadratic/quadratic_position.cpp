#include "curves/quadratic/quadratic_position.hpp"

#include <variant>

namespace lac {

PositionResult position_at(const QuadraticLaCurve& c, double s, const AnyQuadrature& method) {
  return std::visit([&](const auto& m) { return position_at(c, s, m); }, method);
}

std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const AnyQuadrature& method) {
  return std::visit([&](const auto& m) { return polyline(c, s0, s1, n, m); }, method);
}

}  // namespace lac
