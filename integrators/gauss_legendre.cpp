#include "lac/integrators/gauss_legendre.hpp"

#include <boost/math/quadrature/gauss.hpp>

namespace lac {
namespace {

GaussLegendreRule make_rule() {
  using G = boost::math::quadrature::gauss<double, GaussLegendreRule::kPoints>;
  const auto& a = G::abscissa();  // non-negative half on [-1, 1]
  const auto& b = G::weights();
  GaussLegendreRule r;
  constexpr std::size_t n = GaussLegendreRule::kPoints;
  for (std::size_t k = 0; k < a.size(); ++k) {
    r.nodes[k] = 0.5 * (1.0 - a[k]);
    r.nodes[n - 1 - k] = 0.5 * (1.0 + a[k]);
    r.weights[k] = r.weights[n - 1 - k] = 0.5 * b[k];
  }
  return r;
}

}  // namespace

const GaussLegendreRule& gauss_legendre_20() {
  static const GaussLegendreRule r = make_rule();
  return r;
}

}  // namespace lac
