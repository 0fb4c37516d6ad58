#include "curves/quadratic/quadratic_position.hpp"

#include <array>
#include <cmath>
#include <variant>

namespace lac {

PositionResult position_at(const QuadraticLaCurve& c, double s, const AnyQuadrature& method) {
  return std::visit([&](const auto& m) { return position_at(c, s, m); }, method);
}

std::vector<PositionResult> polyline(const QuadraticLaCurve& c, double s0, double s1, int n, const AnyQuadrature& method) {
  return std::visit([&](const auto& m) { return polyline(c, s0, s1, n, m); }, method);
}

namespace {

// Exact data at one node of the march.
struct Node {
  double s, u, theta, kappa, dkappa;  // dκ/ds = κ · d(log κ)/ds
};

Node node_at(const QuadraticLaCurve& c, double s, double u_guess, long& iterations, Status& status) {
  const KappaSolution k = c.solve_kappa_near(s, u_guess);
  iterations += k.iterations;
  if (k.status != Status::ok && status == Status::ok) status = k.status;
  const double kappa = std::exp(k.log_kappa);
  return {s, k.log_kappa, c.theta_at_log_kappa(k.log_kappa), kappa, kappa * c.dlog_kappa_ds(k.log_kappa)};
}

// ∫ e^(iθ) over [a.s, b.s] with θ the quintic Hermite interpolant; adds the bound to `bound`.
std::complex<double> hermite_piece(const Node& a, const Node& b, double& bound) {
  // 4-point Gauss–Legendre on [0, 1].
  static constexpr std::array<double, 4> t = {0.069431844202973712, 0.33000947820757187, 0.66999052179242813,
                                              0.93056815579702629};
  static constexpr std::array<double, 4> w = {0.17392742256872693, 0.32607257743127307, 0.32607257743127307,
                                              0.17392742256872693};
  const double h = b.s - a.s;
  std::complex<double> sum{};
  double worst = 0;
  for (int j = 0; j < 4; ++j) {
    const double x = t[j], x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
    // Quintic Hermite basis (value, first, second derivative at 0 and at 1).
    const double h0 = 1 - 10 * x3 + 15 * x4 - 6 * x5, h1 = x - 6 * x3 + 8 * x4 - 3 * x5;
    const double h2 = 0.5 * x2 - 1.5 * x3 + 1.5 * x4 - 0.5 * x5, h3 = 10 * x3 - 15 * x4 + 6 * x5;
    const double h4 = -4 * x3 + 7 * x4 - 3 * x5, h5 = 0.5 * x3 - x4 + 0.5 * x5;
    const double quintic = a.theta * h0 + h * a.kappa * h1 + h * h * a.dkappa * h2 + b.theta * h3 + h * b.kappa * h4 +
                           h * h * b.dkappa * h5;
    // Cubic Hermite (value and first derivative) for the error bound.
    const double c0 = 1 - 3 * x2 + 2 * x3, c1 = x - 2 * x2 + x3, c2 = 3 * x2 - 2 * x3, c3 = -x2 + x3;
    const double cubic = a.theta * c0 + h * a.kappa * c1 + b.theta * c2 + h * b.kappa * c3;
    worst = std::max(worst, std::abs(quintic - cubic));
    sum += w[j] * std::polar(1.0, quintic);
  }
  bound += std::abs(h) * worst;
  return h * sum;
}

// Adds ∫ from node a to the node at s_next, splitting where the tangent turns > 0.25 rad.
Node advance(const QuadraticLaCurve& c, const Node& a, double s_next, std::complex<double>& pos, double& bound,
             long& iterations, long& evaluations, Status& status) {
  const double h = s_next - a.s;
  // Split where the tangent turns > 0.25 rad or log κ changes > 0.05 over the segment.
  const double need = std::max(std::abs(h * a.kappa) / 0.25, std::abs(h * c.dlog_kappa_ds(a.u)) / 0.05);
  const int pieces = need > 1 ? static_cast<int>(std::min(1e4, std::ceil(need))) : 1;
  Node cur = a;
  for (int p = 1; p <= pieces; ++p) {
    const double s = p == pieces ? s_next : a.s + h * p / pieces;
    const Node next = node_at(c, s, cur.u + (s - cur.s) * c.dlog_kappa_ds(cur.u), iterations, status);
    ++evaluations;
    pos += hermite_piece(cur, next, bound);
    cur = next;
  }
  return cur;
}

}  // namespace

std::vector<PositionResult> hermite_polyline(const QuadraticLaCurve& c, double s0, double s1, int n) {
  if (n < 2) throw_input_error("quadratic hermite_polyline", "points", n, "[2, inf)");
  c.check_s(s0, "s_from");
  c.check_s(s1, "s_to");
  const double hi = c.s_at_zero_kappa();
  if (s0 >= hi || s1 >= hi)
    throw_input_error("quadratic hermite_polyline", "s_to", std::max(s0, s1),
                      "below s(kappa->0) = " + format_number(hi) + " (no inflection continuation)");
  long iterations = 0, evaluations = 1;
  Status status = Status::ok;
  double bound = 0;
  std::complex<double> pos{};
  Node cur{0.0, 0.0, 0.0, 1.0, c.dlog_kappa_ds(0.0)};
  // From the reference point to s0 in steps of about the polyline's spacing.
  const double spacing = std::abs(s1 - s0) / (n - 1);
  const int lead = spacing > 0 ? static_cast<int>(std::min(1e6, std::ceil(std::abs(s0) / spacing))) : 1;
  for (int k = 1; k <= lead && s0 != 0; ++k)
    cur = advance(c, cur, k == lead ? s0 : s0 * k / lead, pos, bound, iterations, evaluations, status);
  std::vector<PositionResult> out(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double s = k + 1 == n ? s1 : s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(n - 1);
    if (k > 0) cur = advance(c, cur, s, pos, bound, iterations, evaluations, status);
    auto& r = out[static_cast<size_t>(k)];
    r.point = {s, cur.theta, 1.0 / cur.kappa, cur.kappa, pos};
    r.error_estimate = bound;
    r.evaluations = evaluations;
    r.status = status;
    if (status != Status::ok) r.message = "kappa(s): " + std::string(to_string(status));
    r.form = Form::s;
  }
  return out;
}

}  // namespace lac
