#include "lac/curves/planar/detail/linear_q.hpp"

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cfloat>
#include <cmath>
#include <vector>

#include "lac/integrators/gauss_legendre.hpp"

namespace lac::detail {
namespace {

// 10-point Gauss–Legendre on twice the `panels` equal panels of [t0, 1] of the 20-point sums
// below (f(t) is the substituted integrand, du/dt included): as many nodes, a different rule, so
// its difference from the 20-point sum bounds the latter's error without the 10-point rule's own
// error on the wider panels (which would flag smooth pieces at 1e-8 while the sum is at 1e-15).
template <class F>
std::complex<double> coarse_sum(const F& f, double t0, int panels, long& evaluations) {
  const GaussLegendreRule<10>& g = gauss_legendre_10();
  panels *= 2;
  const double span = (1.0 - t0) / panels;
  std::complex<double> sum{};
  for (int panel = 0; panel < panels; ++panel) {
    const double a = t0 + panel * span;
    for (size_t k = 0; k < 10; ++k) sum += (g.weights[k] * span) * f(a + span * g.nodes[k]);
  }
  evaluations += 10 * panels;
  return sum;
}

// ∫_{0}^{1} f(u(t)) u'(t) dt with u(t) = u0 + (e − u0)·t: a plain piece.
template <class Phi>
std::complex<double> plain(const Phi& phi, double u0, double e, int panels, long& evaluations,
                           std::complex<double>* coarse) {
  const GaussLegendreRule<20>& g = gauss_legendre_20();
  std::complex<double> sum{};
  // κ keeps its sign on a piece, so φ is monotonic there: one more panel per radian of turning.
  const double turning = std::abs(phi(u0 + (e - u0)) - phi(u0));
  if (!(turning <= kMaxResolvedTurning)) {
    if (coarse) *coarse = {NAN, NAN};
    return {NAN, NAN};
  }
  panels = std::max(panels, static_cast<int>(std::min(64.0, std::ceil(turning))));
  const double span = 1.0 / panels, du = e - u0;
  for (int panel = 0; panel < panels; ++panel) {
    const double a = panel * span;
    for (size_t k = 0; k < 20; ++k) {
      const double t = a + span * g.nodes[k];
      sum += (g.weights[k] * span * du) * std::polar(1.0, phi(u0 + du * t));
    }
  }
  evaluations += 20 * panels;
  if (coarse) *coarse = coarse_sum([&](double t) { return du * std::polar(1.0, phi(u0 + du * t)); }, 0.0, panels, evaluations);
  return sum;
}

// A graded piece (TangentPiece) with φ in closed form: the same nodes and weights as a plain
// piece in t, without a power per node when t0 = 0 (gauss_legendre_20_node_powers).
std::complex<double> graded_from_zero(const TangentPiece& p, int panels, long& evaluations,
                                      std::complex<double>* coarse) {
  const GaussLegendreRule<20>& g = gauss_legendre_20();
  const double beta = p.beta, phi_zero = p.phi_zero, delta = p.delta, t0 = p.t0;
  const double turning = std::abs(delta) * (1.0 - std::pow(t0, beta));
  if (!(turning <= kMaxResolvedTurning)) {
    if (coarse) *coarse = {NAN, NAN};
    return {NAN, NAN};
  }
  panels = std::max(panels, static_cast<int>(std::min(64.0, std::ceil(turning))));
  const double span = (1.0 - t0) / panels;
  const std::vector<double>* powers = t0 == 0 ? &gauss_legendre_20_node_powers(beta, panels) : nullptr;
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
  if (coarse)
    *coarse = (p.e - p.u0) * coarse_sum([&](double t) { return 4.0 * t * t * t * std::polar(1.0, p.phi(t)); }, t0, panels,
                                        evaluations);
  return (p.e - p.u0) * sum;
}

// Ends of the parts of a plain piece with a steep end: for α > 0, q's zero at distance d < len/4
// beyond an end (κ ∝ r^(−1/α), r the distance to the zero), cut where r = d·ratio^k with
// ratio = e^(1/max(1, |p|)), p = 1 − 1/α (φ' changes by at most about e across a part); for α = 0,
// κ ∝ e^(c0 u) with 1/|c0| < len/4, cut at 1/|c0|·2^k from the steeper end. Equal panels in u over
// the whole piece put almost no node where such a segment turns (the 10-point estimate then says
// so: tolerance_not_met, errors up to 1e-3 on G1 solutions with a chord near a tangent).
// Empty (no allocation) when no end is steep.
std::vector<double> steep_cuts(const LaLaw& law, const LinearQ& seg) {
  const double len = seg.length(), c0 = seg.slope();
  std::vector<double> cuts;
  if (!(c0 != 0 && std::isfinite(c0))) return cuts;
  bool at_a = false;
  double first = 0, ratio = 2, offset = 0;  // distances from the steep end: (first·ratio^k − offset)
  if (law.log_form()) {
    // α = 0, or the offset form (small |α|: κ = σ|t|^(−1/α) close to the exponential): the
    // log-derivative of |κ| is c0/t (t = 1 − αq unsigned) and largest at the end of largest |κ|;
    // cut at 1/|c0/t|·2^k from it (log|κ| changes by at most 2^k on the part [2^k, 2^(k+1)]).
    at_a = std::abs(law.kappa_of_q(seg.qa)) > std::abs(law.kappa_of_q(seg.qb));
    const double t_end = 1.0 - law.alpha * (at_a ? seg.qa : seg.qb);
    first = std::abs(t_end / c0);
    if (!(first < 0.25 * len)) return cuts;
  } else if (law.alpha > 0) {
    at_a = seg.qa / c0 >= 0;  // the zero lies before ua
    const double d = at_a ? seg.qa / c0 : -seg.qb / c0;
    if (!(d >= 0 && d < 0.25 * len)) return cuts;
    ratio = std::exp(1 / std::max(1.0, std::abs(1 - 1 / law.alpha)));
    first = std::max(d, 1e-300) * ratio;
    offset = d;
  } else {
    return cuts;
  }
  std::vector<double> from_end;
  for (double r = first; r - offset < len && from_end.size() < 4096; r *= ratio) from_end.push_back(r - offset);
  cuts = {seg.ua};
  for (size_t k = 0; k < from_end.size(); ++k) {
    const double u = at_a ? seg.ua + from_end[k] : seg.ub - from_end[from_end.size() - 1 - k];
    if (u > cuts.back() && u < seg.ub) cuts.push_back(u);  // parts below rounding merge
  }
  cuts.push_back(seg.ub);
  return cuts;
}

}  // namespace

std::vector<double> layer_cuts(const LaLaw& law, const LinearQ& seg, double u0, double u1) {
  std::vector<double> cuts;
  const double c0 = seg.slope();
  if (law.alpha == 1 || !(c0 != 0 && std::isfinite(c0)) || !(u1 > u0)) return cuts;
  const double q0 = seg.q_at(u0), q1 = seg.q_at(u1), F0 = law.F(q0), F1 = law.F(q1);
  const double t0 = law.t_of_q(q0), t1 = law.t_of_q(q1);
  if ((t0 < 0 && t1 > 0) || (t0 > 0 && t1 < 0)) return cuts;  // not one-signed
  const double big = std::max(std::abs(F0), std::abs(F1)), small = std::min(std::abs(F0), std::abs(F1));
  const double range = std::log(big / small);  // inf where F = 0 at an end (the inflection, α < 0)
  const bool thin = law.log_form() || std::abs(1.0 - 1.0 / law.alpha) > 8;  // layer ~1/|p| of log|t|
  if (!thin || !(range > 8) || !std::isfinite(big) || big == 0) return cuts;
  const bool at_0 = std::abs(F0) > std::abs(F1);
  const double F_end = at_0 ? F0 : F1, side = t0 != 0 ? t0 : t1;
  for (double d = 0.25; d < std::min(range, 700.0); d *= 2) {
    const double u = u0 + (law.F_inverse(F_end * std::exp(-d), side) - q0) / c0;
    if (std::isfinite(u) && u > u0 && u < u1) cuts.push_back(u);
  }
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

TangentPlan tangent_plan(const LaLaw& law, const LinearQ& seg) {
  TangentPlan plan;
  plan.pieces[0].u0 = seg.ua;
  plan.pieces[0].e = seg.ub;
  const bool rough_at_zero = law.alpha < 0 && law.alpha != -1;
  if (!rough_at_zero || seg.qa == seg.qb) return plan;
  const double ua = seg.ua, ub = seg.ub, len = ub - ua, Fa = law.F(seg.qa);
  // The zero of t (the plain form's q; σ(1 − αq) in the offset form), where F = 0.
  const double ta = law.t_of_q(seg.qa), tb = law.t_of_q(seg.qb);
  const double c0 = seg.slope(), u_zero = ta == tb ? (ta == 0 ? ua : -HUGE_VAL) : ua - ta * len / (tb - ta);
  // 004 Eq. (5) with F(0) = 0 (α < 0): φ* = c2 = φa − F(qa)/c0, φ(e) − φ* = F(q_e)/c0.
  TangentPiece g;
  g.graded = true;
  g.u0 = u_zero;
  g.beta = 4.0 * (law.alpha - 1.0) / law.alpha;
  g.phi_zero = seg.phi_a - Fa / c0;
  TangentPiece toward_a = g, toward_b = g;
  toward_a.sign = -1;
  toward_a.e = ua;
  toward_a.delta = Fa / c0;
  toward_b.e = ub;
  if (u_zero > ua && u_zero < ub) {
    toward_b.delta = law.F(seg.qb) / c0;
    plan.pieces = {toward_a, toward_b};
    plan.count = 2;
  } else if (u_zero <= ua && ua - u_zero < 0.5 * len) {
    toward_b.delta = law.F(seg.qb) / c0;
    toward_b.t0 = std::pow((ua - u_zero) / (ub - u_zero), 0.25);
    plan.pieces[0] = toward_b;
  } else if (u_zero >= ub && u_zero - ub < 0.5 * len) {
    toward_a.t0 = std::pow((u_zero - ub) / (u_zero - ua), 0.25);
    plan.pieces[0] = toward_a;
  }
  return plan;
}

std::complex<double> integrate_tangent(const LaLaw& law, const LinearQ& seg, long& evaluations, int panels,
                                       std::complex<double>* coarse) {
  const TangentPlan plan = tangent_plan(law, seg);
  std::complex<double> value[2], rough[2];
  for (int i = 0; i < plan.count; ++i) {
    const TangentPiece& p = plan.pieces[static_cast<size_t>(i)];
    std::complex<double>* c = coarse ? &rough[i] : nullptr;
    if (p.graded) {
      value[i] = graded_from_zero(p, panels, evaluations, c);
    } else {
      const double Ka = law.kappa_of_q(seg.qa), Fa = law.F(seg.qa);
      const auto phi = [&](double u) { return seg.phi_a + (u - seg.ua) * law.divided(seg.qa, Ka, Fa, seg.q_at(u)); };
      // Parts toward a steep end, under the cap on the whole piece's turning (parts turn less):
      // beyond it one part, which gives NaN.
      const std::vector<double> cuts = steep_cuts(law, seg);
      if (cuts.empty() || !(std::abs(phi(seg.ub) - seg.phi_a) <= kMaxResolvedTurning)) {
        value[i] = plain(phi, seg.ua, seg.ub, panels, evaluations, c);
      } else {
        for (size_t k = 0; k + 1 < cuts.size(); ++k) {
          std::complex<double> part_coarse;
          value[i] += plain(phi, cuts[k], cuts[k + 1], panels, evaluations, c ? &part_coarse : nullptr);
          if (c) *c += part_coarse;
        }
      }
    }
    if (p.sign < 0) value[i] = -value[i], rough[i] = -rough[i];
  }
  if (coarse) *coarse = plan.count == 2 ? rough[0] + rough[1] : rough[0];
  return plan.count == 2 ? value[0] + value[1] : value[0];
}

std::complex<double> integrate_tangent_reference(const LaLaw& law, const LinearQ& seg, double tolerance) {
  thread_local boost::math::quadrature::tanh_sinh<double> ts;  // integrate() is non-const
  std::vector<double> cuts{seg.ua};
  if (seg.qa * seg.qb < 0) {
    // A zero of q within rounding of an end (e.g. κ0 = 5e-324) leaves a piece of subnormal width,
    // on which tanh-sinh fails; that piece contributes nothing, so it is not split off.
    const double cut = seg.ua - seg.qa / seg.slope(), margin = 16 * DBL_EPSILON * seg.length();
    if (cut - seg.ua > margin && seg.ub - cut > margin) cuts.push_back(cut);
  }
  cuts.push_back(seg.ub);
  // Boundary layers of small |α| on each one-signed side (tanh-sinh's estimate misses them).
  for (size_t k = 0, n = cuts.size(); k + 1 < n; ++k) {
    const std::vector<double> layer = layer_cuts(law, seg, cuts[k], cuts[k + 1]);
    cuts.insert(cuts.end(), layer.begin(), layer.end());
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
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

}  // namespace lac::detail
