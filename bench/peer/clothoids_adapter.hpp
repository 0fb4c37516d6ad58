#pragma once
// The Clothoids library (github.com/ebertolazzi/Clothoids) behind a plain interface, for
// bench/peer_speed.cpp. scripts/peer_speed.sh compiles clothoids_adapter.cpp against the peer's
// own headers (its bundled Eigen 5) into one object whose only global symbols are these
// functions, so the peer's Eigen never meets lac's (Eigen 3) at link time. Nothing of the peer is
// in this repository; docs/peer_speed.md says how to get and build it.

namespace lac_peer {

/// A peer curve after a solve, evaluated by the peer itself.
struct Check {
  double end_x = 0, end_y = 0;    ///< end point of the last piece
  double end_theta = 0;           ///< tangent angle at the end (rad, not wrapped)
  double end_kappa = 0;           ///< curvature at the end
  double start_x = 0, start_y = 0;  ///< start point of the first piece
  double start_theta = 0, start_kappa = 0;
  double joint_position_gap = 0;  ///< largest |end of one piece − start of the next| (G2: two joints)
  double joint_angle_gap = 0;     ///< largest tangent-angle jump at a joint (rad, wrapped to (−π, π])
  double joint_kappa_gap = 0;     ///< largest curvature jump at a joint
  double length = 0;              ///< total length
};

/// ClothoidCurve::build_G1 (Bertolazzi–Frego 2015) with its default tolerance, on one curve object
/// reused from call to call. True when it returns without throwing (the library reports a failed
/// Newton by an exception) and its return value says success.
bool g1(double x0, double y0, double theta0, double x1, double y1, double theta1) noexcept;
Check g1_check() noexcept;  ///< of the curve of the last g1 call

/// G2solve3arc::build (Bertolazzi–Frego 2018, three clothoids) with its defaults (tolerance 1e-10,
/// 100 iterations), on one solver object reused from call to call. True when it returns an
/// iteration count (≥ 0; −1 means failure).
bool g2(double x0, double y0, double theta0, double kappa0, double x1, double y1, double theta1,
        double kappa1) noexcept;
Check g2_check() noexcept;  ///< of the three pieces of the last g2 call

}  // namespace lac_peer
