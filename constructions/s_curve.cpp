#include "lac/constructions/s_curve.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "lac/common/error.hpp"

namespace lac::hermite {
namespace {

constexpr double kPi = std::numbers::pi;

double wrap_angle(double a) { return std::remainder(a, 2.0 * kPi); }

// Standard-form length up to the end angle φD (004 Eqs. 11, 14, 15), for α < 0, Λ > 0:
// S-shaped s0 + s1 = (1 + w^p)/(−Λα), C-shaped (w^p − 1)/(Λα), w = 1 + (α−1)ΛφD, p = α/(α−1).
// Returns NaN where φD is not reachable (w < 0: φD above φmax, Eq. 13).
double standard_length(double alpha, double lambda, double phi_d, bool s_shaped) {
  const double x = (alpha - 1.0) * lambda * phi_d, p = alpha / (alpha - 1.0);
  if (!(x > -1.0)) return NAN;
  if (s_shaped) return (1.0 + std::exp(p * std::log1p(x))) / (-lambda * alpha);
  return std::expm1(p * std::log1p(x)) / (lambda * alpha);
}

lac::detail::LinearQ standard_segment(double alpha, double lambda, double length) {
  // q = 1 + αΛs: κ = 1 at s = 0, zero at the inflection s0 = −1/(Λα) (Eq. 12).
  return {0.0, length, 1.0, 1.0 + alpha * lambda * length, 0.0};
}

}  // namespace

std::string_view to_string(RootMethod m) { return m == RootMethod::bisection ? "bisection" : "toms748"; }
RootMethod parse_root_method(std::string_view name) {
  if (name == "bisection") return RootMethod::bisection;
  if (name == "toms748") return RootMethod::toms748;
  throw_input_error("scurve", "root", "'" + std::string(name) + "' is not one of bisection, toms748");
}
std::string_view to_string(SCurveShape s) {
  return s == SCurveShape::s_shaped ? "S" : s == SCurveShape::c_shaped ? "C" : "straight";
}

void SCurveOptions::validate() const {
  if (max_iterations < 1 || max_iterations > 10000)
    throw_input_error("scurve", "max_iterations", max_iterations, "[1, 10000]");
  if (bracket_doublings < 1 || bracket_doublings > 2000)
    throw_input_error("scurve", "bracket_doublings", bracket_doublings, "[1, 2000]");
}

namespace {
// Tangent angle and curvature in the user frame at standard-form arc length s (no quadrature).
void user_angle_curvature(const SCurveResult& r, double s, double& theta, double& kappa) {
  theta = r.standard.phi_at(r.law, s);
  kappa = r.standard.kappa_at(r.law, s);
  if (r.mirrored) theta = -theta, kappa = -kappa;
  if (r.reversed) theta += kPi, kappa = -kappa;
  theta = wrap_angle(theta + std::arg(r.rotation));
  kappa /= r.scale;
}
}  // namespace

CurveSample SCurveResult::at(double t) const {
  if (!(t >= 0 && t <= 1)) throw_input_error("SCurveResult::at", "t", t, "[0, 1]");
  const double L = standard.ub;
  const double s = (reversed ? 1.0 - t : t) * L;
  long evals = 0;
  const lac::detail::LinearQ part{0.0, s, standard.qa, standard.q_at(s), 0.0};
  std::complex<double> z = s > 0 ? lac::detail::integrate_tangent(law, part, evals) : std::complex<double>{};
  if (mirrored) z = std::conj(z);
  CurveSample out;
  out.S = t;
  out.s = t * L * scale;
  out.position = origin + rotation * scale * z;
  user_angle_curvature(*this, s, out.theta, out.kappa);
  return out;
}

std::vector<CurveSample> SCurveResult::polyline(int n) const {
  if (n < 2) throw_input_error("SCurveResult::polyline", "points", n, "[2, inf)");
  std::vector<CurveSample> out;
  for (int k = 0; k < n; ++k) out.push_back(at(k + 1 == n ? 1.0 : static_cast<double>(k) / (n - 1)));
  return out;
}

SCurveResult solve_s_curve(const std::array<std::complex<double>, 4>& P, double alpha, const SCurveOptions& o) {
  const auto t_begin = std::chrono::steady_clock::now();
  o.validate();
  const char* names[4][2] = {{"p0.x", "p0.y"}, {"p1.x", "p1.y"}, {"p2.x", "p2.y"}, {"p3.x", "p3.y"}};
  for (int k = 0; k < 4; ++k) {
    require_finite("scurve", names[k][0], P[k].real());
    require_finite("scurve", names[k][1], P[k].imag());
  }
  if (!(alpha < 0 && alpha >= -kMaxAbsAlpha))
    throw_input_error("scurve", "alpha", alpha, "[-5, 0) (an inflection needs alpha < 0, 004 §2.3)");
  // The construction is similarity invariant: work on the control polygon moved to P0 = 0 and
  // scaled by 1/ext, ext its largest extent. Finite coordinates can still have differences
  // beyond the double range (R10 in docs/robustness.md): refused here, not an infinite curve.
  const std::complex<double> d01 = P[1] - P[0], d03 = P[3] - P[0], d23 = P[3] - P[2];
  const double ext = std::max({std::abs(d01), std::abs(d03), std::abs(d23)});
  if (!std::isfinite(ext))
    throw_input_error("scurve", "points",
                      "differences beyond the double range (|p1 - p0|, |p3 - p0| and |p3 - p2| must be finite)");
  // Coincidence relative to the polygon's size and, against cancellation, its coordinates.
  double coordinate = 0;
  for (const auto& p : P) coordinate = std::max({coordinate, std::abs(p.real()), std::abs(p.imag())});
  const double tiny = 1e-12 * std::max(ext, coordinate);
  if (!(std::abs(d01) > tiny)) throw_input_error("scurve", "p1", "coincides with p0 (no start tangent)");
  if (!(std::abs(d23) > tiny)) throw_input_error("scurve", "p2", "coincides with p3 (no end tangent)");
  if (!(std::abs(d03) > tiny))
    throw_input_error("scurve", "p3", "coincides with p0 (the chord must have positive length)");
  const std::array<std::complex<double>, 4> Q{std::complex<double>{}, d01 / ext, d03 / ext - d23 / ext, d03 / ext};

  SCurveResult res;
  res.alpha = alpha;
  res.law = LaLaw{alpha, 1.0};
  auto finish = [&](Status st, std::string msg) {
    res.status = st;
    res.message = std::move(msg);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_begin).count();
    return res;
  };

  // Step 1–2: start at the origin with tangent +x; φD, φE (Fig. 1).
  auto frame = [&](std::complex<double> A, std::complex<double> dA, std::complex<double> B, std::complex<double> dB,
                   double& phi_e, double& phi_d) {
    phi_e = std::arg((B - A) / dA);
    phi_d = std::arg(dB / dA);
  };
  double phi_e = 0, phi_d = 0;
  frame(Q[0], Q[1] - Q[0], Q[3], Q[3] - Q[2], phi_e, phi_d);
  // Step 3: Fig. 2 decision. Non-S when φE lies strictly between 0 and φD.
  if (phi_e == 0 && phi_d == 0) {
    res.shape = SCurveShape::straight;
    return finish(Status::no_solution,
                  "collinear control points with parallel tangents: the curve is a straight segment");
  }
  const bool s_shaped = !(phi_e * (phi_d - phi_e) > 0);
  res.shape = s_shaped ? SCurveShape::s_shaped : SCurveShape::c_shaped;
  std::complex<double> A = Q[0], dA = Q[1] - Q[0], B = Q[3], dB = Q[3] - Q[2];
  if (!s_shaped) {
    // Curvature decreases from the standard form's start: start at the end whose tangent
    // the chord is farther from.
    if (std::abs(phi_e) < 0.5 * std::abs(phi_d)) {
      res.reversed = true;
      A = Q[3], dA = Q[2] - Q[3], B = Q[0], dB = Q[0] - Q[1];
      frame(A, dA, B, dB, phi_e, phi_d);
    }
    res.mirrored = phi_d < 0;
  } else {
    res.mirrored = phi_e < 0 || (phi_e == 0 && phi_d > 0);  // the first turn is toward the chord side
  }
  if (res.mirrored) phi_e = -phi_e, phi_d = -phi_d;

  // Step 4: the range of Λ. S: no loop (total turning 2φmax − φD < 2π) and, when φD > 0,
  // φD < φmax (Eqs. 13, 16–17). C: 0 < Λ < 1/((1−α)φD).
  const double one_minus_alpha = 1.0 - alpha;
  const double lambda_reach = phi_d > 0 ? 1.0 / (one_minus_alpha * phi_d) : INFINITY;
  double lo = s_shaped ? 1.0 / (one_minus_alpha * (kPi + 0.5 * phi_d)) * (1 + 1e-9) : lambda_reach * 1e-12;
  double hi = std::isfinite(lambda_reach) ? lambda_reach * (1 - 1e-12) : 2 * lo;

  // Steps 5–7: the end point's direction minus φE.
  auto g = [&](double lambda) {
    const double L = standard_length(alpha, lambda, phi_d, s_shaped);
    if (!std::isfinite(L)) return std::numeric_limits<double>::quiet_NaN();
    const auto end = lac::detail::integrate_tangent(res.law, standard_segment(alpha, lambda, L), res.evaluations);
    return std::arg(end) - phi_e;
  };
  double g_lo = g(lo), g_hi = g(hi);
  for (int k = 0;
       k < o.bracket_doublings && !std::isfinite(lambda_reach) && std::isfinite(g_hi) && (g_hi > 0) == (g_lo > 0);
       ++k) {
    lo = hi, g_lo = g_hi;
    hi *= 2;
    g_hi = g(hi);
  }
  if (!std::isfinite(g_lo) || !std::isfinite(g_hi) || (g_lo > 0) == (g_hi > 0)) {
    if (g_lo == 0 || g_hi == 0) {
      hi = lo = g_lo == 0 ? lo : hi;
    } else {
      return finish(Status::no_solution, s_shaped ? "no Lambda gives the end direction without a loop (004 §2.5 step 4)"
                                                  : "no Lambda gives the end direction (C-shaped case)");
    }
  }
  // Step 8: converge.
  double lambda = lo;
  if (lo != hi) {
    boost::uintmax_t iters = static_cast<boost::uintmax_t>(o.max_iterations);
    const boost::math::tools::eps_tolerance<double> tol(50);
    std::pair<double, double> bracket;
    if (o.root == RootMethod::toms748) {
      bracket = boost::math::tools::toms748_solve(g, lo, hi, g_lo, g_hi, tol, iters);
    } else {
      bracket = boost::math::tools::bisect(g, lo, hi, tol, iters);
    }
    res.iterations = static_cast<int>(iters);
    lambda = 0.5 * (bracket.first + bracket.second);
    if (static_cast<int>(iters) >= o.max_iterations && bracket.second - bracket.first > 1e-12 * lambda) {
      return finish(Status::max_iterations, "root finder on Lambda reached its iteration cap");
    }
  }
  const double L = standard_length(alpha, lambda, phi_d, s_shaped);
  res.lambda = lambda;
  res.standard = standard_segment(alpha, lambda, L);
  const auto end = lac::detail::integrate_tangent(res.law, res.standard, res.evaluations);
  // Similarity onto the user's points: |B − A| / |end| in the normalized frame, times ext.
  const double scale_normalized = std::abs(B - A) / std::abs(end);
  res.scale = ext * scale_normalized;
  res.rotation = dA / std::abs(dA);
  res.origin = res.reversed ? P[3] : P[0];
  res.length = L * res.scale;
  if (s_shaped) {
    const double s0 = -1.0 / (lambda * alpha) * res.scale;  // Eq. (12)
    res.inflection_s = res.reversed ? res.length - s0 : s0;
  }
  // User-unit results must be representable: the length, the curvature (|κ| is largest at an
  // end of the standard form) and every point, which lies within length/2 of the chord's
  // midpoint (the ellipse with foci P0, P3 and major axis `length`).
  const double kappa_max =
      std::max(std::abs(res.law.kappa_of_q(res.standard.qa)), std::abs(res.law.kappa_of_q(res.standard.qb))) /
      res.scale;
  const std::complex<double> mid = 0.5 * P[0] + 0.5 * P[3];
  const double reach = (std::max(std::abs(mid.real()), std::abs(mid.imag())) + 0.5 * res.length) * (1 + 1e-9);
  if (!(std::isfinite(res.length) && res.scale > 0 && std::isfinite(kappa_max) && std::isfinite(reach))) {
    res.length = 0, res.inflection_s = -1;  // nothing non-finite reaches the caller, usable or not
    return finish(Status::numerical_failure,
                  "the curve's length, curvature or extent in user units is beyond the double range");
  }
  // Residuals with the independent tanh-sinh evaluation, in the normalized frame (no overflow).
  std::complex<double> z = o.verify ? lac::detail::integrate_tangent_reference(res.law, res.standard) : end;
  if (res.mirrored) z = std::conj(z);
  res.residual_position = ext * std::abs(A + res.rotation * scale_normalized * z - B);
  // End angles from φ's closed form (004 Eq. 5 in linear-q form) at both ends; at(t) would also
  // integrate the position, which is not needed here.
  double theta0 = 0, theta1 = 0, kappa = 0;
  user_angle_curvature(res, res.reversed ? L : 0.0, theta0, kappa);
  user_angle_curvature(res, res.reversed ? 0.0 : L, theta1, kappa);
  res.residual_angle =
      std::max(std::abs(wrap_angle(theta0 - std::arg(d01))), std::abs(wrap_angle(theta1 - std::arg(d23))));
  // A check that cannot be evaluated (e.g. α = −1e-304: the reference integral overflows) leaves
  // the curve unverified: not usable.
  if (!std::isfinite(res.residual_position) || !std::isfinite(res.residual_angle))
    return finish(Status::numerical_failure, "the residual check of the end conditions is not a finite number");
  return finish(Status::ok, "");
}

}  // namespace lac::hermite
