#pragma once
// Random planar LA segments of every regime for the tests that check a segment integral against the
// long-double oracle (fuzz/oracle_check.hpp).
#include <cmath>
#include <random>

#include "lac/curves/planar/la_law.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"

namespace lac::test {

// A random segment: α from the regimes, q at both ends from random end curvatures (κ·length in
// ±[1e-3, 30], either sign for α < 0, one sign otherwise), u ∈ [0, ub] with ub log-uniform.
struct Draw {
  LaLaw law;
  detail::LinearQ seg;
};

inline Draw draw(std::mt19937_64& g, double alpha, double max_kappa_len) {
  auto u = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); };
  Draw d;
  const bool offset = alpha != 0 && std::abs(alpha) < 0.05;
  const double sigma = u(0, 1) < 0.5 ? -1.0 : 1.0;
  d.law = LaLaw{alpha, sigma, offset};
  const double len = std::exp(u(std::log(1e-2), std::log(1e2)));
  double ka = sigma * std::exp(u(std::log(1e-3), std::log(max_kappa_len))) / len;
  double kb = sigma * std::exp(u(std::log(1e-3), std::log(max_kappa_len))) / len;
  if (max_kappa_len < 0) {  // near-antisymmetric S (α < 0): turning ≈ 0, the phase all quadratic
    ka = sigma * std::exp(u(std::log(0.1), std::log(-max_kappa_len))) / len;
    kb = alpha < 0 ? -ka * u(0.98, 1.02) : ka * u(0.5, 2);
  }
  if (max_kappa_len == 0) {  // steep: end curvatures 10^6 to 10^15 apart (q's zero just beyond an end)
    ka = sigma * std::exp(u(std::log(1e-2), std::log(10.0))) / len;
    kb = ka * std::exp(u(std::log(1e6), std::log(1e15)));
  }
  if (alpha < 0 && u(0, 1) < 0.5) kb = -kb;  // an inflection
  d.seg = {0.0, len, d.law.q_of_kappa(ka), d.law.q_of_kappa(kb), u(-3, 3)};
  return d;
}

}  // namespace lac::test
