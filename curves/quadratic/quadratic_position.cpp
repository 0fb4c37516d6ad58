#include "lac/curves/quadratic/quadratic_position.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <variant>

namespace lac {

namespace {

/// Names of the registered methods that are quadratures (all but closed forms).
template <std::size_t... I>
std::string quadrature_names(std::index_sequence<I...>) {
  std::string text;
  auto add = [&text](std::string_view name, bool quadrature) {
    if (quadrature) text.append(text.empty() ? "" : ", ").append(name);
  };
  (add(std::variant_alternative_t<I, AnyQuadrature>::name, QuadratureMethod<std::variant_alternative_t<I, AnyQuadrature>>), ...);
  return text;
}

/// Calls f with the method when it is a quadrature (every registered method but the closed form igf).
template <class F>
auto with_quadrature(const AnyQuadrature& method, F&& f) {
  return std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (QuadratureMethod<M>) {
          return f(m);
        } else {
          throw_input_error("quadratic position", "integrator",
                            std::string(M::name) + " applies to planar LA curves in standard form only; valid here: " +
                                quadrature_names(std::make_index_sequence<std::variant_size_v<AnyQuadrature>>{}));
          return f(GaussKronrod{});  // not reached; gives the lambda its return type
        }
      },
      method);
}

}  // namespace

PositionResult position_at(const QuadraticLaCurve& c, double s, const AnyQuadrature& method, double accept,
                           long max_evaluations) {
  return with_quadrature(method, [&](const auto& m) { return position_at(c, s, m, accept, max_evaluations); });
}

std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const AnyQuadrature& method,
                                     double accept, long max_evaluations) {
  return with_quadrature(method, [&](const auto& m) { return polyline(c, s0, s1, n, m, accept, max_evaluations); });
}

namespace {

// Data at one node of the march: κ = e^u and u' = du/ds = −Λ e^(−E(u)) exact (Halley on the
// closed form s(u)), θ accumulated by the local series of theta_difference (no cancellation).
struct Node {
  double s, u, theta, kappa, du_ds;
  std::complex<double> tangent;  // e^(iθ)
};

Node origin(const QuadraticLaCurve& c) { return {0.0, 0.0, 0.0, 1.0, c.dlog_kappa_ds(0.0), {1.0, 0.0}}; }

// Running totals of the march along one direction from s = 0.
struct Path {
  std::complex<double> position{};
  double bound = 0;
  long evaluations = 1;
  Status status = Status::ok;
};

// e^(iδ) for |δ| ≤ 0.5 by its Taylor polynomials (terms to δ^15: error < 1e-18), else polar.
std::complex<double> small_rotation(double d) {
  if (std::abs(d) > 0.5) return std::polar(1.0, d);
  const double x = d * d;
  const double cos_d =
      1 + x * (-1.0 / 2 + x * (1.0 / 24 + x * (-1.0 / 720 + x * (1.0 / 40320 + x * (-1.0 / 3628800 + x * (1.0 / 479001600 + x * (-1.0 / 87178291200.0)))))));
  const double sin_d =
      d * (1 + x * (-1.0 / 6 + x * (1.0 / 120 + x * (-1.0 / 5040 + x * (1.0 / 362880 + x * (-1.0 / 39916800 + x * (1.0 / 6227020800.0 + x * (-1.0 / 1307674368000.0))))))));
  return {cos_d, sin_d};
}

Node node_at(const QuadraticLaCurve& c, const Node& a, double s, Status& status, const char* end_name) {
  // Third-order Taylor predictor of u(s) (u'' = −E' u'², u''' = (2E'² − 2γ) u'³), so that one
  // Halley step usually lands within rounding and is accepted without a second F evaluation.
  const double h = s - a.s, d1 = a.du_ds;
  const double slope = 2.0 * c.gamma() * a.u - c.alpha();  // E'(u)
  const double d2 = -slope * d1 * d1, d3 = (2.0 * slope * slope - 2.0 * c.gamma()) * d1 * d1 * d1;
  const KappaSolution k = c.solve_kappa_near(s, a.u + h * (d1 + h * (0.5 * d2 + h * d3 / 6.0)));
  if (k.status != Status::ok && status == Status::ok) status = k.status;
  const double theta = a.theta + c.theta_difference(a.u, k.log_kappa);
  const double du_ds = c.dlog_kappa_ds(k.log_kappa);
  // Between s_from and s_to κ (or ρ, θ, dκ/ds) can leave the double range, e.g. κ = e^(−4660) = 0 for
  // small γ > 0 far along the curve: an input error naming the end, never a NaN in the points.
  if (!(k.kappa > 0) || !std::isfinite(k.kappa) || !std::isfinite(1.0 / k.kappa) || !std::isfinite(theta) ||
      !std::isfinite(du_ds * k.kappa))
    throw_input_error("quadratic hermite_polyline", end_name, s,
                      "(a range over which kappa, rho and theta are representable doubles)");
  // e^(iθ) by rotating the previous tangent (one rounding per node, no sincos).
  return {s, k.log_kappa, theta, k.kappa, du_ds, a.tangent * small_rotation(theta - a.theta)};
}

// ∫ e^(iθ) over [a.s, b.s] with θ the quintic Hermite interpolant (θ, κ = θ', κ' = κ u' at both
// ends); adds h·max|θ_quintic − θ_cubic| to `bound`.
std::complex<double> hermite_piece(const Node& a, const Node& b, double& bound) {
  // 4-point Gauss–Legendre on [0, 1].
  static constexpr std::array<double, 4> t = {0.069431844202973712, 0.33000947820757187, 0.66999052179242813,
                                              0.93056815579702629};
  static constexpr std::array<double, 4> w = {0.17392742256872693, 0.32607257743127307, 0.32607257743127307,
                                              0.17392742256872693};
  const double h = b.s - a.s, dtheta = b.theta - a.theta;
  const double ka = h * a.kappa, kb = h * b.kappa;
  const double dka = h * h * a.kappa * a.du_ds, dkb = h * h * b.kappa * b.du_ds;
  std::complex<double> sum{};
  double worst = 0;
  for (int j = 0; j < 4; ++j) {
    const double x = t[j], x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
    // Quintic Hermite basis (value, first, second derivative at 0 and at 1), relative to θ_a.
    const double h1 = x - 6 * x3 + 8 * x4 - 3 * x5, h2 = 0.5 * x2 - 1.5 * x3 + 1.5 * x4 - 0.5 * x5;
    const double h3 = 10 * x3 - 15 * x4 + 6 * x5, h4 = -4 * x3 + 7 * x4 - 3 * x5, h5 = 0.5 * x3 - x4 + 0.5 * x5;
    const double quintic = ka * h1 + dka * h2 + dtheta * h3 + kb * h4 + dkb * h5;
    // Cubic Hermite (value and first derivative) for the error bound.
    const double c1 = x - 2 * x2 + x3, c2 = 3 * x2 - 2 * x3, c3 = -x2 + x3;
    const double cubic = ka * c1 + dtheta * c2 + kb * c3;
    worst = std::max(worst, std::abs(quintic - cubic));
    sum += w[j] * small_rotation(quintic);
  }
  bound += std::abs(h) * worst;
  return h * a.tangent * sum;
}

// Marches from node a to s_next, splitting where the tangent turns > 0.25 rad or log κ changes
// by > 0.05 over a piece (at most 1e4 pieces).
Node advance(const QuadraticLaCurve& c, const Node& a, double s_next, Path& path, const char* end_name) {
  const double h = s_next - a.s;
  const double need = std::max(std::abs(h * a.kappa) / 0.25, std::abs(h * a.du_ds) / 0.05);
  const int pieces = need > 1 ? static_cast<int>(std::min(1e4, std::ceil(need))) : 1;
  Node cur = a;
  for (int p = 1; p <= pieces; ++p) {
    const double s = p == pieces ? s_next : a.s + h * p / pieces;
    const Node next = node_at(c, cur, s, path.status, end_name);
    ++path.evaluations;
    path.position += hermite_piece(cur, next, path.bound);
    // Past the 1e4-piece cap a piece can turn beyond the double range (e.g. s ~ 1e108): no NaN points.
    if (!std::isfinite(path.position.real()) || !std::isfinite(path.position.imag()) || !std::isfinite(path.bound))
      throw_input_error("quadratic hermite_polyline", end_name, s,
                        "(a range whose positions are representable: here one step of the polyline turns the "
                        "tangent by " + format_number(std::abs(next.theta - cur.theta)) + " rad)");
    cur = next;
  }
  return cur;
}

void store(PositionResult& r, const Node& node, const Path& path) {
  r.point = {node.s, node.theta, 1.0 / node.kappa, node.kappa, path.position};
  r.error_estimate = path.bound;
  r.evaluations = path.evaluations;
  r.status = path.status;
  if (path.status != Status::ok) r.message = "kappa(s): " + std::string(to_string(path.status));
  r.form = Form::s;
}

}  // namespace

std::vector<PositionResult> hermite_polyline(const QuadraticLaCurve& c, double s0, double s1, int n, double accept) {
  validate_accept("quadratic hermite_polyline", accept);
  if (n < 2) throw_input_error("quadratic hermite_polyline", "points", n, "[2, inf)");
  c.check_s(s0, "s_from");
  c.check_s(s1, "s_to");
  const double hi = c.s_at_zero_kappa();
  if (s0 >= hi || s1 >= hi)
    throw_input_error("quadratic hermite_polyline", "s_to", std::max(s0, s1),
                      "below s(kappa->0) = " + format_number(hi) + " (no inflection continuation)");
  const size_t count = static_cast<size_t>(n);
  auto grid = [&](size_t k) {
    return k + 1 == count ? s1 : s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(n - 1);
  };
  // Start at the grid point nearest the reference point s = 0 and march outward both ways, so
  // every node is a grid point (plus splits) and no node is spent between 0 and the grid.
  size_t first = 0;
  if (s1 != s0) {
    const double guess = std::clamp(std::round(-s0 / (s1 - s0) * (n - 1)), 0.0, n - 1.0);
    first = static_cast<size_t>(guess);
  }
  std::vector<PositionResult> out(count);
  Path start;
  // InputErrors name the end of the range the failing node lies toward.
  const char* kFrom = "s_from";
  const char* kTo = "s_to";
  const Node at_first = advance(c, origin(c), grid(first), start, first == 0 ? kFrom : kTo);
  store(out[first], at_first, start);
  Path up = start;
  Node cur = at_first;
  for (size_t k = first + 1; k < count; ++k) {
    cur = advance(c, cur, grid(k), up, kTo);
    store(out[k], cur, up);
  }
  Path down = start;
  cur = at_first;
  for (size_t k = first; k-- > 0;) {
    cur = advance(c, cur, grid(k), down, kFrom);
    store(out[k], cur, down);
  }
  detail::grade_positions(out, accept);
  return out;
}

}  // namespace lac
