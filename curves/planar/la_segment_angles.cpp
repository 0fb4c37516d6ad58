#include "lac/curves/planar/la_segment_angles.hpp"

#include <algorithm>
#include <cmath>

namespace lac::detail {

std::vector<double> angle_cuts(const LaSegment& seg, double beta, double period, size_t cap, bool* capped) {
  *capped = false;
  const LaLaw& law = seg.law();
  const detail::LinearQ& q = seg.normalized();
  std::vector<double> out{seg.ua()};
  std::vector<double> cuts{seg.ua()};
  if (const auto u = seg.inflection_u(); u && *u > seg.ua() && *u < seg.ub()) cuts.push_back(*u);
  cuts.push_back(seg.ub());
  const double c0 = q.slope(), Fa = law.F(q.qa), angle = seg.rotation_angle();
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double u_lo = cuts[i], u_hi = cuts[i + 1];
    const double phi_lo = seg.phi_at(u_lo), phi_hi = seg.phi_at(u_hi);
    const double sign = law.t_of_q(seg.q_at(0.5 * (u_lo + u_hi))) < 0 ? -1.0 : 1.0;
    // θ = angle + φ ≡ beta (mod period): φ_j = beta + j·period − angle strictly between the ends.
    const double a = std::min(phi_lo, phi_hi) + angle - beta, b = std::max(phi_lo, phi_hi) + angle - beta;
    const double j0 = std::floor(a / period) + 1, j1 = std::ceil(b / period) - 1;
    if (!(j1 - j0 < static_cast<double>(cap))) {
      *capped = true;
      return {};
    }
    std::vector<double> found;
    for (double j = j0; j <= j1; ++j) {
      const double target = beta + j * period - angle;
      // φ(u) − φa = (F(q(u)) − F(qa))/c0: u from F⁻¹ on this side of q = 0, then Newton on
      // φ(u) = target (φ' = K(q)) for the rounding.
      double u = c0 == 0 ? q.ua + (target - q.phi_a) / law.kappa_of_q(q.qa)
                         : q.ua + (law.F_inverse(Fa + c0 * (target - q.phi_a), sign) - q.qa) / c0;
      if (!(u >= u_lo && u <= u_hi)) u = u_lo + (u_hi - u_lo) * (target - phi_lo) / (phi_hi - phi_lo);
      for (int it = 0; it < 4; ++it) {
        const double slope = seg.curvature_per_u(u);
        if (!(slope != 0)) break;
        const double next = std::clamp(u - (seg.phi_at(u) - target) / slope, u_lo, u_hi);
        if (!std::isfinite(next)) break;
        u = next;
      }
      found.push_back(std::clamp(u, u_lo, u_hi));
    }
    std::sort(found.begin(), found.end());
    for (double u : found)
      if (u > out.back()) out.push_back(u);
    if (u_hi > out.back()) out.push_back(u_hi);
  }
  return out;
}

}  // namespace lac::detail
