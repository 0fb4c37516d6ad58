#pragma once
// Fixed-node Gauss–Legendre quadrature: the 7- to 20-point rules on [0, 1] (nodes and weights
// from Boost.Math's tables) and the composite method `GaussLegendre` on equal panels. A fixed rule
// is what the G2 and S-curve solvers need: they integrate e^{iφ} over a few panels thousands of
// times per solve, where an adaptive driver's bookkeeping would cost more than the integrand.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

#include "lac/integrators/quadrature.hpp"

namespace lac {

template <std::size_t N>
struct GaussLegendreRule {
  static constexpr std::size_t kPoints = N;
  std::array<double, N> nodes{};    ///< in (0, 1): node k and node N − 1 − k are mirror images about 1/2
  std::array<double, N> weights{};  ///< sum to 1
};

/// The N-point rule on [0, 1], built once; N ∈ {7, 10, 12, 16, 20}.
template <std::size_t N>
const GaussLegendreRule<N>& gauss_legendre_rule();
/// The 20-point rule on [0, 1].
inline const GaussLegendreRule<20>& gauss_legendre_20() { return gauss_legendre_rule<20>(); }
/// The 10-point rule on [0, 1] (the error estimate of GaussLegendre).
inline const GaussLegendreRule<10>& gauss_legendre_10() { return gauss_legendre_rule<10>(); }

/// t^β at the nodes t = (panel + x_k)/panels of the 20-point rule on `panels` equal panels of
/// [0, 1] (index 20·panel + k). Graded integrals (t^β substitutions near an inflection or a steep
/// end) need them at one β for every trial of a solve, so they are kept per thread. The entry
/// returned last is never the one replaced next: two lookups in a row stay valid together.
const std::vector<double>& gauss_legendre_20_node_powers(double beta, int panels);

/// Composite 20-point Gauss–Legendre on `panels` equal panels (exact for polynomials of degree 39
/// on each). The value is the 20-point rule on every panel halved (2·panels, 40 nodes a panel).
/// Error estimate: the larger of two differences, the 20-point rule on the panels against the
/// halved panels and against the 10-point rule on the panels, plus the rounding term
/// 4ε∫|f|·√(2·panels). Each difference bounds the halved panels' error when the coarser value errs
/// at least twice as much (the rule's error shrinks with the panel, and the 10-point rule is the
/// less accurate): the returned value is never the one the estimate is measured from. The 10-point
/// difference catches an integrand the panels do not resolve (e.g. e^{iθ} turning many times over
/// a panel), where two 20-point values can see the same aliasing. Cost 70 evaluations per panel,
/// counted. No adaptivity: a rough integrand shows as a large estimate (status tolerance_not_met
/// when it exceeds `tol`·|∫f|).
struct GaussLegendre {
  static constexpr std::string_view name = "gauss-legendre";
  int panels = 1;     ///< equal panels over [a, b], [1, 1e6]
  double tol = 1e-8;  ///< relative tolerance the estimate is checked against (status only)

  void validate() const {
    if (panels < 1 || panels > 1'000'000) throw_input_error("gauss-legendre", "panels", panels, "[1, 1000000]");
    if (!(tol > 0) || !std::isfinite(tol)) throw_input_error("gauss-legendre", "tol", tol, "(0, inf)");
  }

  template <Integrand F>
  IntegralResult<IntegrandValue<F>> integrate(F&& f, double a, double b) const {
    using V = IntegrandValue<F>;
    validate();
    IntegralResult<V> r;
    if (a == b) return r;
    const auto& g20 = gauss_legendre_20();
    const auto& g10 = gauss_legendre_10();
    const double span = (b - a) / panels;
    V g10_value{}, g20_value{};
    double l1 = 0;
    for (int p = 0; p < panels; ++p) {
      const double lo = a + p * span;
      for (std::size_t k = 0; k < g20.kPoints; ++k) g20_value += (g20.weights[k] * span) * f(lo + span * g20.nodes[k]);
      for (std::size_t k = 0; k < g10.kPoints; ++k) g10_value += (g10.weights[k] * span) * f(lo + span * g10.nodes[k]);
      V panel{};  // summed apart: rounding grows with √panels, not with the node count
      for (int half = 0; half < 2; ++half)
        for (std::size_t k = 0; k < g20.kPoints; ++k) {
          const V v = f(lo + 0.5 * span * (half + g20.nodes[k]));
          panel += (g20.weights[k] * 0.5 * span) * v;
          l1 += g20.weights[k] * 0.5 * std::abs(span) * std::abs(v);
        }
      r.value += panel;
    }
    r.evaluations = static_cast<long>(panels) * static_cast<long>(3 * g20.kPoints + g10.kPoints);
    r.error_estimate = std::max(std::abs(g20_value - g10_value), std::abs(g20_value - r.value)) +
                       4 * std::numeric_limits<double>::epsilon() * l1 * std::sqrt(2.0 * panels);
    if (!std::isfinite(std::abs(r.value)) || !std::isfinite(r.error_estimate)) {
      r.status = Status::numerical_failure;
      r.message = "gauss-legendre: non-finite integrand value";
    } else if (r.error_estimate > tol * std::abs(r.value) && r.error_estimate > 100 * std::numeric_limits<double>::epsilon() * l1) {
      r.status = Status::tolerance_not_met;
      r.message = "gauss-legendre: error estimate " + format_number(r.error_estimate) + " above tolerance with " +
                  std::to_string(panels) + " panels; raise panels";
    }
    return r;
  }
};

static_assert(QuadratureMethod<GaussLegendre>);

}  // namespace lac
