#include "lac/integrators/gauss_legendre.hpp"

#include <boost/math/quadrature/gauss.hpp>

namespace lac {
namespace {

template <std::size_t N>
GaussLegendreRule<N> make_rule() {
  using G = boost::math::quadrature::gauss<double, N>;
  const auto& a = G::abscissa();  // non-negative half on [-1, 1] (with 0 first for odd N)
  const auto& b = G::weights();
  static_assert(N % 2 == 0, "even rules only: no node at the centre");
  GaussLegendreRule<N> r;
  for (std::size_t k = 0; k < a.size(); ++k) {
    r.nodes[k] = 0.5 * (1.0 - a[k]);
    r.nodes[N - 1 - k] = 0.5 * (1.0 + a[k]);
    r.weights[k] = r.weights[N - 1 - k] = 0.5 * b[k];
  }
  return r;
}

}  // namespace

const GaussLegendreRule<20>& gauss_legendre_20() {
  static const GaussLegendreRule<20> r = make_rule<20>();
  return r;
}

const GaussLegendreRule<10>& gauss_legendre_10() {
  static const GaussLegendreRule<10> r = make_rule<10>();
  return r;
}

}  // namespace lac
