#include "lac/curves/planar/linear_q.hpp"

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cfloat>
#include <cmath>
#include <vector>

#include "lac/integrators/gauss_legendre.hpp"

namespace lac::hermite::detail {
namespace {

// ∫_{t0}^{1} f(u(t)) u'(t) dt with u(t) = u0 + (e − u0)·t^p (p = 1: plain, p = 4: graded).
template <class Phi>
std::complex<double> graded(const Phi& phi, double u0, double e, double t0, int p, int panels, long& evaluations) {
  const GaussLegendreRule<20>& g = gauss_legendre_20();
  std::complex<double> sum{};
  // κ keeps its sign on a piece, so φ is monotonic there: one more panel per radian of turning.
  const double t0p = std::pow(t0, p);
  const double turning = std::abs(phi(u0 + (e - u0)) - phi(u0 + (e - u0) * t0p));
  if (!(turning <= kMaxResolvedTurning)) return {NAN, NAN};
  panels = std::max(panels, static_cast<int>(std::min(64.0, std::ceil(turning))));
  const double span = (1.0 - t0) / panels;
  for (int panel = 0; panel < panels; ++panel) {
    const double a = t0 + panel * span;
    for (size_t k = 0; k < 20; ++k) {
      const double t = a + span * g.nodes[k];
      double tp1 = 1.0;  // t^(p−1)
      for (int j = 1; j < p; ++j) tp1 *= t;
      const double u = u0 + (e - u0) * tp1 * t;
      const double du = p * (e - u0) * tp1;
      sum += (g.weights[k] * span * du) * std::polar(1.0, phi(u));
    }
  }
  evaluations += 20 * panels;
  return sum;
}

// t^β at the nodes t = (panel + x_k)/panels of `panels` equal panels on [0, 1]. They depend on
// α and the panel count only, so a solve at one α (every root-finder step of an S-curve, every
// Newton step of a G2 problem) computes them once per thread.
const std::vector<double>& node_powers(double beta, int panels) {
  struct Entry {
    double beta = NAN;
    int panels = 0;
    std::vector<double> values;
  };
  thread_local std::array<Entry, 16> cache;
  thread_local size_t next = 0;
  for (const Entry& e : cache)
    if (e.beta == beta && e.panels == panels) return e.values;
  Entry& e = cache[next++ % cache.size()];
  const GaussLegendreRule<20>& g = gauss_legendre_20();
  e.beta = beta;
  e.panels = panels;
  e.values.resize(20 * static_cast<size_t>(panels));
  for (int panel = 0; panel < panels; ++panel)
    for (size_t k = 0; k < 20; ++k)
      e.values[20 * static_cast<size_t>(panel) + k] = std::pow((panel + g.nodes[k]) / panels, beta);
  return e.values;
}

// The graded rule next to a zero u* of q (α < 0, α ≠ −1), with φ in closed form: by 004 Eq. (5)
// φ = F(q)/c0 + c2 with q = c0 (u − u*), and u − u* = (e − u*) t⁴ gives F(q) = F(q_e) t^β,
// β = 4(α−1)/α, so φ(t) = φ* + Δ t^β with φ* = c2 = φ(u*) and Δ = F(q_e)/c0 = φ(e) − φ*.
// The same nodes and weights as graded(..., p = 4), without a power per node when t0 = 0.
std::complex<double> graded_from_zero(double beta, double phi_zero, double delta, double u0, double e, double t0,
                                      int panels, long& evaluations) {
  const GaussLegendreRule<20>& g = gauss_legendre_20();
  const double turning = std::abs(delta) * (1.0 - std::pow(t0, beta));
  if (!(turning <= kMaxResolvedTurning)) return {NAN, NAN};
  panels = std::max(panels, static_cast<int>(std::min(64.0, std::ceil(turning))));
  const double span = (1.0 - t0) / panels;
  const std::vector<double>* powers = t0 == 0 ? &node_powers(beta, panels) : nullptr;
  std::complex<double> sum{};
  for (int panel = 0; panel < panels; ++panel) {
    const double a = t0 + panel * span;
    for (size_t k = 0; k < 20; ++k) {
      const double t = a + span * g.nodes[k];
      const double tb = powers ? (*powers)[20 * static_cast<size_t>(panel) + k] : std::pow(t, beta);
      sum += (g.weights[k] * span * 4.0 * t * t * t) * std::polar(1.0, phi_zero + delta * tb);
    }
  }
  evaluations += 20 * panels;
  return (e - u0) * sum;
}

}  // namespace


std::complex<double> integrate_tangent(const LaLaw& law, const LinearQSegment& seg, long& evaluations, int panels) {
  const double Fa = law.F(seg.qa);
  const auto phi = [&](double u) { return seg.phi_a + (u - seg.ua) * law.divided_difference(seg.qa, Fa, seg.q_at(u)); };
  const double ua = seg.ua, ub = seg.ub, len = ub - ua;
  const bool rough_at_zero = law.alpha < 0 && law.alpha != -1;
  if (rough_at_zero && seg.qa != seg.qb) {
    const double c0 = seg.slope(), u_zero = ua - seg.qa / c0;
    // 004 Eq. (5) with F(0) = 0 (α < 0): φ* = c2 = φa − F(qa)/c0, φ(e) − φ* = F(q_e)/c0.
    const double beta = 4.0 * (law.alpha - 1.0) / law.alpha, phi_zero = seg.phi_a - Fa / c0;
    if (u_zero > ua && u_zero < ub) {
      return -graded_from_zero(beta, phi_zero, Fa / c0, u_zero, ua, 0.0, panels, evaluations) +
             graded_from_zero(beta, phi_zero, law.F(seg.qb) / c0, u_zero, ub, 0.0, panels, evaluations);
    }
    if (u_zero <= ua && ua - u_zero < 0.5 * len) {
      const double t0 = std::pow((ua - u_zero) / (ub - u_zero), 0.25);
      return graded_from_zero(beta, phi_zero, law.F(seg.qb) / c0, u_zero, ub, t0, panels, evaluations);
    }
    if (u_zero >= ub && u_zero - ub < 0.5 * len) {
      const double t0 = std::pow((u_zero - ub) / (u_zero - ua), 0.25);
      return -graded_from_zero(beta, phi_zero, Fa / c0, u_zero, ua, t0, panels, evaluations);
    }
  }
  return graded(phi, ua, ub, 0.0, 1, panels, evaluations);
}

std::complex<double> integrate_tangent_reference(const LaLaw& law, const LinearQSegment& seg, double tolerance) {
  thread_local boost::math::quadrature::tanh_sinh<double> ts;  // integrate() is non-const
  std::vector<double> cuts{seg.ua};
  if (seg.qa * seg.qb < 0) {
    // A zero of q within rounding of an end (e.g. κ0 = 5e-324) leaves a piece of subnormal width,
    // on which tanh-sinh fails; that piece contributes nothing, so it is not split off.
    const double cut = seg.ua - seg.qa / seg.slope(), margin = 16 * DBL_EPSILON * seg.length();
    if (cut - seg.ua > margin && seg.ub - cut > margin) cuts.push_back(cut);
  }
  cuts.push_back(seg.ub);
  std::complex<double> sum{};
  // One complex-valued integral per piece (Boost ≥ 1.72 accepts complex integrands): cos and sin
  // share each evaluation of φ, half the cost of two real integrals.
  const auto f = [&](double u) { return std::polar(1.0, seg.phi_at(law, u)); };
  try {
    for (size_t k = 0; k + 1 < cuts.size(); ++k) sum += ts.integrate(f, cuts[k], cuts[k + 1], tolerance);
  } catch (const std::exception&) {  // Boost's domain/evaluation errors (non-finite nodes or values)
    return {NAN, NAN};
  }
  return sum;
}

}  // namespace lac::hermite::detail
