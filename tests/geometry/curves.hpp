#pragma once
// Test curves of the geometry tests: a clothoid spiral turning 31 rad (5 turns), a logarithmic
// spiral (α = 0) turning 9 rad, and a G1 compound curve (α = −0.5 through an inflection, then
// α = 2) turning about 6 rad; each start is the previous segment's end by the library.
#include <complex>
#include <vector>

#include "lac/curves/planar/planar_curve.hpp"

namespace lac::test {

struct Part {
  LaLaw law;
  double ua, ub, qa, qb, scale;
};

inline PlanarCurve chain(const std::vector<Part>& parts, double phi0, std::complex<double> start, double angle) {
  std::vector<LaSegment> segs;
  double phi = phi0;
  for (const Part& p : parts) {
    const LaSegment seg(p.law, p.ua, p.ub, p.qa, p.qb, phi, Placement{start, p.scale, std::polar(1.0, angle)});
    segs.push_back(seg);
    start = position_at(seg, seg.length()).point.position;
    phi = seg.phi_b();
  }
  return PlanarCurve(segs);
}

inline PlanarCurve clothoid_spiral() { return chain({{LaLaw{-1.0}, 0.0, 1.0, 2.0, 60.0, 10.0}}, 0.3, {1, -2}, 0.7); }
inline PlanarCurve log_spiral() {
  return chain({{LaLaw{0.0, 1.0}, 0.0, 1.0, std::log(0.5), std::log(40.0), 5.0}}, -0.4, {0.5, 0.25}, -1.1);
}
inline PlanarCurve compound() {
  return chain({{LaLaw{-0.5}, 0.0, 1.0, -1.5, 2.0, 3.0}, {LaLaw{2.0}, 0.0, 1.5, 0.25, 0.01, 3.0}}, 0.2, {-1, 0.5}, 0.4);
}
inline std::vector<PlanarCurve> test_curves() { return {clothoid_spiral(), log_spiral(), compound()}; }

}  // namespace lac::test
