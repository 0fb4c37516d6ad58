// See clothoids_adapter.hpp. Compiled by scripts/peer_speed.sh with the peer's include paths; not
// part of the CMake build.
#include "clothoids_adapter.hpp"

#include <algorithm>
#include <cmath>

#include "Clothoids.hh"

namespace lac_peer {
namespace {

using G2lib::ClothoidCurve;

ClothoidCurve& g1_curve() {
  static ClothoidCurve c{"lac_peer g1"};
  return c;
}

G2lib::G2solve3arc& g2_solver() {
  static G2lib::G2solve3arc s;
  return s;
}

constexpr double kPi = 3.141592653589793238462643383279502884;  // C++17, as the peer: no <numbers>

double wrap(double a) {  // to (−π, π]
  a = std::remainder(a, 2 * kPi);
  return a <= -kPi ? a + 2 * kPi : a;
}

void join(Check& c, const ClothoidCurve& a, const ClothoidCurve& b) {
  c.joint_position_gap =
      std::max(c.joint_position_gap, std::hypot(b.x_begin() - a.x_end(), b.y_begin() - a.y_end()));
  c.joint_angle_gap = std::max(c.joint_angle_gap, std::abs(wrap(b.theta_begin() - a.theta_end())));
  c.joint_kappa_gap = std::max(c.joint_kappa_gap, std::abs(b.kappa_begin() - a.kappa_end()));
}

Check ends(const ClothoidCurve& first, const ClothoidCurve& last) {
  Check c;
  c.start_x = first.x_begin();
  c.start_y = first.y_begin();
  c.start_theta = first.theta_begin();
  c.start_kappa = first.kappa_begin();
  c.end_x = last.x_end();
  c.end_y = last.y_end();
  c.end_theta = last.theta_end();
  c.end_kappa = last.kappa_end();
  return c;
}

}  // namespace

bool g1(double x0, double y0, double theta0, double x1, double y1, double theta1) noexcept {
  try {
    return g1_curve().build_G1(x0, y0, theta0, x1, y1, theta1) != 0;
  } catch (...) {
    return false;
  }
}

Check g1_check() noexcept {
  try {
    const ClothoidCurve& c = g1_curve();
    Check r = ends(c, c);
    r.length = c.length();
    return r;
  } catch (...) {
    return Check{NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  }
}

bool g2(double x0, double y0, double theta0, double kappa0, double x1, double y1, double theta1,
        double kappa1) noexcept {
  try {
    return g2_solver().build(x0, y0, theta0, kappa0, x1, y1, theta1, kappa1) >= 0;
  } catch (...) {
    return false;
  }
}

Check g2_check() noexcept {
  try {
    const G2lib::G2solve3arc& s = g2_solver();
    Check r = ends(s.S0(), s.S1());
    join(r, s.S0(), s.SM());
    join(r, s.SM(), s.S1());
    r.length = s.total_length();
    return r;
  } catch (...) {
    return Check{NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  }
}

}  // namespace lac_peer
