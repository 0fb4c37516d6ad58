#include "lac/integrators/gauss_legendre.hpp"

#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <vector>

namespace lac {
namespace {

template <std::size_t N>
GaussLegendreRule<N> make_rule() {
  using G = boost::math::quadrature::gauss<double, N>;
  const auto& a = G::abscissa();  // non-negative half on [-1, 1] (with 0 first for odd N)
  const auto& b = G::weights();
  GaussLegendreRule<N> r;
  const std::size_t first = N % 2;  // odd N: a[0] = 0 is the centre node, index N / 2
  if (first) r.nodes[N / 2] = 0.5, r.weights[N / 2] = 0.5 * b[0];
  for (std::size_t k = first; k < a.size(); ++k) {
    r.nodes[k - first] = 0.5 * (1.0 - a[k]);
    r.nodes[N - 1 - (k - first)] = 0.5 * (1.0 + a[k]);
    r.weights[k - first] = r.weights[N - 1 - (k - first)] = 0.5 * b[k];
  }
  return r;
}

}  // namespace

template <std::size_t N>
const GaussLegendreRule<N>& gauss_legendre_rule() {
  static const GaussLegendreRule<N> r = make_rule<N>();
  return r;
}
template const GaussLegendreRule<7>& gauss_legendre_rule<7>();
template const GaussLegendreRule<10>& gauss_legendre_rule<10>();
template const GaussLegendreRule<12>& gauss_legendre_rule<12>();
template const GaussLegendreRule<16>& gauss_legendre_rule<16>();
template const GaussLegendreRule<20>& gauss_legendre_rule<20>();

const std::vector<double>& gauss_legendre_20_node_powers(double beta, int panels) {
  struct Entry {
    double beta = std::numeric_limits<double>::quiet_NaN();
    int panels = 0;
    std::vector<double> values;
  };
  thread_local std::array<Entry, 16> cache;
  thread_local std::size_t next = 0;
  for (std::size_t j = 0; j < cache.size(); ++j)
    if (cache[j].beta == beta && cache[j].panels == panels) {
      if (next % cache.size() == j) ++next;  // the entry returned last is never replaced next
      return cache[j].values;
    }
  Entry& e = cache[next++ % cache.size()];
  const GaussLegendreRule<20>& g = gauss_legendre_20();
  e.beta = beta;
  e.panels = panels;
  e.values.resize(20 * static_cast<std::size_t>(panels));
  for (int panel = 0; panel < panels; ++panel)
    for (std::size_t k = 0; k < 20; ++k)
      e.values[20 * static_cast<std::size_t>(panel) + k] = std::pow((panel + g.nodes[k]) / panels, beta);
  return e.values;
}

}  // namespace lac
