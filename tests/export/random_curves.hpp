#pragma once
// Random planar LA chains for the export tests: 1–3 segments of random α ∈ [−3, 3] (some α = 0,
// some offset form), curvatures in [−3, 3] (inflections for α < 0), lengths in [0.3, 4], random
// placement and scale; joined G1 (and G2 where the next curvature is taken from the previous end).
#include <random>
#include <vector>

#include "lac/curves/planar/planar_curve.hpp"

namespace lac::test {

inline LaSegment random_segment(std::mt19937_64& rng, double kappa_a, bool take_kappa_a, std::complex<double> start,
                                double theta_start) {
  std::uniform_real_distribution<double> U(0, 1);
  const int kind = static_cast<int>(U(rng) * 10);
  double alpha = kind == 0 ? 0.0 : -3 + 6 * U(rng);
  LaLaw law{alpha, U(rng) < 0.5 ? 1.0 : -1.0, kind == 1};
  double ka = take_kappa_a ? kappa_a : -3 + 6 * U(rng);
  if (ka == 0) ka = 0.1;
  double kb = -3 + 6 * U(rng);
  if (alpha >= 0 || law.offset) kb = std::copysign(std::max(0.05, std::abs(kb)), ka);  // one sign
  if (law.log_form()) {
    law.sigma = ka > 0 ? 1.0 : -1.0;
    ka = std::copysign(std::max(0.05, std::abs(ka)), law.sigma);
    kb = std::copysign(std::max(0.05, std::abs(kb)), law.sigma);
  }
  const double length = 0.3 + 3.7 * U(rng);
  const double scale = 0.3 + 2.7 * U(rng);
  // q is linear in u and κ = K(q)/scale: the ends' q from the curvatures in user units times scale.
  const double qa = law.q_of_kappa(ka * scale), qb = law.q_of_kappa(kb * scale);
  const double ub = length / scale;
  return LaSegment(law, 0.0, ub, qa, qb, 0.0, {start, scale, std::polar(1.0, theta_start)});
}

inline PlanarCurve random_chain(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0, 1);
  const int n = 1 + static_cast<int>(U(rng) * 3);
  std::vector<LaSegment> segs;
  std::complex<double> start{-5 + 10 * U(rng), -5 + 10 * U(rng)};
  double theta = -3 + 6 * U(rng), kappa = 0;
  for (int k = 0; k < n; ++k) {
    const bool g2 = k > 0 && U(rng) < 0.5;
    segs.push_back(random_segment(rng, kappa, g2, start, theta));
    const LaSegment& s = segs.back();
    start = position_at(s, s.length()).point.position;
    theta = s.theta_end();
    kappa = s.kappa_end();
  }
  return PlanarCurve(segs);
}

}  // namespace lac::test
