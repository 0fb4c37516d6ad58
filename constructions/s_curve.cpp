#include "lac/constructions/s_curve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "lac/common/error.hpp"
#include "lac/common/numeric.hpp"
#include "lac/constructions/detail/tangent_integral.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/solvers/bracket.hpp"

namespace lac {
namespace {

constexpr double kPi = std::numbers::pi;
/// Boost.Math's eps_tolerance(50), which 004's search used: 2^-49 relative.
constexpr double kLambdaRtol = 0x1p-49;

// Standard-form length up to the end angle φD (004 Eqs. 11, 14, 15), for α < 0, Λ > 0:
// S-shaped s0 + s1 = (1 + w^p)/(−Λα), C-shaped (w^p − 1)/(Λα), w = 1 + (α−1)ΛφD, p = α/(α−1).
// Returns NaN where φD is not reachable (w < 0: φD above φmax, Eq. 13).
double standard_length(double alpha, double lambda, double phi_d, bool s_shaped) {
  const double x = (alpha - 1.0) * lambda * phi_d, p = alpha / (alpha - 1.0);
  if (!(x > -1.0)) return NAN;
  if (s_shaped) return (1.0 + std::exp(p * std::log1p(x))) / (-lambda * alpha);
  return std::expm1(p * std::log1p(x)) / (lambda * alpha);
}

detail::LinearQ standard_segment(double alpha, double lambda, double length) {
  // q = 1 + αΛs: κ = 1 at s = 0, zero at the inflection s0 = −1/(Λα) (Eq. 12).
  return {0.0, length, 1.0, 1.0 + alpha * lambda * length, 0.0};
}

}  // namespace

std::string_view to_string(SCurveShape s) {
  return s == SCurveShape::s_shaped ? "S" : s == SCurveShape::c_shaped ? "C" : "straight";
}

void SCurveOptions::validate() const {
  if (static_cast<int>(solver) < 0 || static_cast<size_t>(solver) >= root_methods().size())
    throw_input_error("scurve", "solver", static_cast<double>(solver), "a RootMethod");
  if (max_iterations < 1 || max_iterations > 10000)
    throw_input_error("scurve", "max_iterations", max_iterations, "[1, 10000]");
  if (max_evaluations < 1) throw_input_error("scurve", "max_evaluations", static_cast<double>(max_evaluations), "[1, inf)");
  if (bracket_doublings < 1 || bracket_doublings > 2000)
    throw_input_error("scurve", "bracket_doublings", bracket_doublings, "[1, 2000]");
  validate_accept("scurve", accept);
  if (!(accuracy > 0 && accuracy <= accept))
    throw_input_error("scurve", "accuracy", accuracy, "(0, accept] with accept = " + format_number(accept));
  std::visit([](const auto& m) { m.validate(); }, integrator);
}

SCurveResult solve_s_curve(const std::array<std::complex<double>, 4>& P, double alpha, const SCurveOptions& o) {
  const auto t_begin = std::chrono::steady_clock::now();
  o.validate();
  const char* names[4][2] = {{"p0.x", "p0.y"}, {"p1.x", "p1.y"}, {"p2.x", "p2.y"}, {"p3.x", "p3.y"}};
  for (int k = 0; k < 4; ++k) {
    require_finite("scurve", names[k][0], P[k].real());
    require_finite("scurve", names[k][1], P[k].imag());
  }
  if (!(alpha < 0 && alpha >= -kG2MaxAbsAlpha))
    throw_input_error("scurve", "alpha", alpha,
                      "[" + format_number(-kG2MaxAbsAlpha) + ", 0) (an inflection needs alpha < 0, 004 §2.3)");
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
  SCurveInfo& info = res.info;
  Summary& sum = res.summary;
  sum.integrator = std::string(name_of(o.integrator));
  sum.solver = std::string(to_string(o.solver));
  const LaLaw law{alpha, 1.0};
  detail::TrialIntegrator integrate(o.integrator, o.max_evaluations);
  auto finish = [&](Status st, std::string msg) {
    res.conclude(st, std::move(msg));
    if (!res.usable()) info.inflection_s.reset();
    sum.seconds = seconds_since(t_begin);
    return res;
  };
  // A failure after trial Λ stopped being integrated is the evaluation budget's.
  auto fail = [&](Status st, std::string msg) {
    if (sum.evaluations >= o.max_evaluations)
      return finish(Status::max_iterations, "integrand evaluation budget max_evaluations = " +
                                                std::to_string(o.max_evaluations) + " spent (" + msg + ")");
    return finish(st, std::move(msg));
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
    info.shape = SCurveShape::straight;
    return finish(Status::no_solution,
                  "collinear control points with parallel tangents: the curve is a straight segment");
  }
  const bool s_shaped = !(phi_e * (phi_d - phi_e) > 0);
  info.shape = s_shaped ? SCurveShape::s_shaped : SCurveShape::c_shaped;
  std::complex<double> A = Q[0], dA = Q[1] - Q[0], B = Q[3], dB = Q[3] - Q[2];
  if (!s_shaped) {
    // Curvature decreases from the standard form's start: start at the end whose tangent
    // the chord is farther from.
    if (std::abs(phi_e) < 0.5 * std::abs(phi_d)) {
      info.reversed = true;
      A = Q[3], dA = Q[2] - Q[3], B = Q[0], dB = Q[0] - Q[1];
      frame(A, dA, B, dB, phi_e, phi_d);
    }
    info.mirrored = phi_d < 0;
  } else {
    info.mirrored = phi_e < 0 || (phi_e == 0 && phi_d > 0);  // the first turn is toward the chord side
  }
  if (info.mirrored) phi_e = -phi_e, phi_d = -phi_d;

  // Step 4: the range of Λ. S: no loop (total turning 2φmax − φD < 2π) and, when φD > 0,
  // φD < φmax (Eqs. 13, 16–17). C: 0 < Λ < 1/((1−α)φD).
  const double one_minus_alpha = 1.0 - alpha;
  const double lambda_reach = phi_d > 0 ? 1.0 / (one_minus_alpha * phi_d) : INFINITY;
  double lo = s_shaped ? 1.0 / (one_minus_alpha * (kPi + 0.5 * phi_d)) * (1 + 1e-9) : lambda_reach * 1e-12;
  double hi = std::isfinite(lambda_reach) ? lambda_reach * (1 - 1e-12) : 2 * lo;

  // Standard-form length; C-shaped also at the ends of its range: Λ = 0 is the circular arc
  // turning φD, Λ = 1/((1−α)φD) the curve whose curvature reaches 0 at the end (Eq. 11's limit).
  auto length_at = [&](double lambda) {
    if (!s_shaped && lambda == 0) return phi_d;
    if (!s_shaped && lambda == lambda_reach) return -1.0 / (lambda * alpha);
    return standard_length(alpha, lambda, phi_d, s_shaped);
  };
  // Steps 5–7: the end point's direction minus φE.
  auto g = [&](double lambda) {
    const double L = length_at(lambda);
    if (!std::isfinite(L)) return std::numeric_limits<double>::quiet_NaN();
    ++sum.constructions;
    const auto end = integrate(law, standard_segment(alpha, lambda, L), sum.evaluations);
    return std::arg(end) - phi_e;
  };
  double g_lo = g(lo), g_hi = g(hi);
  if (!std::isfinite(lambda_reach) && std::isfinite(g_hi) && (g_hi > 0) == (g_lo > 0)) {
    // No upper end: double hi until the sign changes; a non-finite end direction ends the search.
    BracketSearchOptions bo;
    bo.center = 0.0;
    bo.step = 2;
    bo.growth = 2;
    bo.max_probes = o.bracket_doublings;
    bo.stop_at_failure = true;
    const BracketSearchResult s = search_bracket(g, hi, bo, g_hi);
    if (s.found) lo = s.bracket.lo, g_lo = s.bracket.f_lo, hi = s.bracket.hi, g_hi = s.bracket.f_hi;
    else lo = s.previous_x, g_lo = s.previous_f, hi = s.last_x, g_hi = s.last_f;
  }
  if (!std::isfinite(g_lo) || !std::isfinite(g_hi))
    return fail(Status::numerical_failure,
                "the end direction is not finite at Lambda = " + format_number(std::isfinite(g_lo) ? hi : lo));
  const auto same_sign = [](double a, double b) { return a != 0 && b != 0 && (a > 0) == (b > 0); };
  double x_atol = 0;
  if (same_sign(g_lo, g_hi) && !s_shaped) {
    // C-shaped: the end direction increases with Λ on (0, 1/((1−α)φD)) (docs/hermite.md) and
    // g(0) = φD/2 − φE ≤ 0 after the orientation above; the search covers the margins of [lo, hi].
    if (g_lo > 0) {
      hi = lo, g_hi = g_lo, lo = 0, g_lo = 0.5 * phi_d - phi_e;
      x_atol = kLambdaRtol * hi;  // relative to a root near 0 the bracket never narrows
    } else {
      const double g_limit = g(lambda_reach);
      if (!std::isfinite(g_limit))  // no evidence either way
        return fail(Status::numerical_failure,
                    "the end direction is not finite at the limit Lambda = " + format_number(lambda_reach));
      if (g_limit < 0)
        return finish(Status::no_solution,
                      "no Lambda gives the end direction (C-shaped case, 004 Fig. 2(a): one alpha < 0 segment without "
                      "inflection, its curvature decreasing from the end whose tangent the chord is farther from): the "
                      "end direction increases with Lambda (docs/hermite.md) and is still short of the chord at the "
                      "limit where the curvature reaches 0 at the end");
      lo = hi, g_lo = g_hi, hi = lambda_reach, g_hi = g_limit;
    }
  }
  if (same_sign(g_lo, g_hi))
    return finish(Status::not_converged,
                  "no sign change of the end direction for Lambda in [" + format_number(lo) + ", " + format_number(hi) +
                      "] (004 §2.5 step 4: no loop" +
                      (std::isfinite(lambda_reach) ? ", phi_D reached" : ", upper end doubled " +
                                                                               std::to_string(o.bracket_doublings) + " times") +
                      "); the end direction is not proven monotonic in Lambda here, so a curve may exist");
  // Step 8: converge.
  double lambda = g_lo == 0 ? lo : hi;
  if (g_lo != 0 && g_hi != 0) {
    RootOptions ro;
    ro.x_rtol = kLambdaRtol;
    ro.x_atol = x_atol;
    ro.f_atol = 0;
    ro.max_iterations = o.max_iterations;
    const RootResult rr = find_root(o.solver, g, Bracket{lo, hi, g_lo, g_hi}, ro);
    sum.iterations = rr.iterations;
    if (!usable(rr.status)) return fail(rr.status, "root finder on Lambda: " + rr.message);
    // The bracket's midpoint where the method narrowed it (as 004's bisection), else its best point.
    lambda = detail::width_done(rr.lo, rr.hi, ro) ? 0.5 * (rr.lo + rr.hi) : rr.root;
  }
  const double L = length_at(lambda);
  info.lambda = lambda;
  // The end point by the integrator, as for every trial Λ (the trial path: no second rule for an
  // estimate, which the check below replaces), whatever the budget.
  integrate.set_limit(std::numeric_limits<long>::max());
  const std::complex<double> end = integrate(law, standard_segment(alpha, lambda, L), sum.evaluations);
  if (!std::isfinite(end.real()) || !std::isfinite(end.imag()))
    return finish(Status::numerical_failure, "the integrator failed on the solved curve");
  std::optional<LaSegment> standard;
  try {
    standard.emplace(law, standard_segment(alpha, lambda, L));
  } catch (const InputError& e) {
    return finish(Status::numerical_failure, std::string("the solved curve is not representable: ") + e.what());
  }
  // Similarity onto the user's points: |B − A| / |end| in the normalized frame, times ext.
  const double scale_normalized = std::abs(B - A) / std::abs(end);
  const double scale = ext * scale_normalized;
  const std::complex<double> rotation = dA / std::abs(dA);
  const double length = L * scale;
  // User-unit results must be representable: the length, the curvature (|κ| is largest at an
  // end of the standard form) and every point, which lies within length/2 of the chord's
  // midpoint (the ellipse with foci P0, P3 and major axis `length`).
  const double kappa_max =
      std::max(std::abs(law.kappa_of_q(standard->qa())), std::abs(law.kappa_of_q(standard->qb()))) / scale;
  const std::complex<double> mid = 0.5 * P[0] + 0.5 * P[3];
  const double reach = (std::max(std::abs(mid.real()), std::abs(mid.imag())) + 0.5 * length) * (1 + 1e-9);
  if (!(std::isfinite(length) && scale > 0 && std::isfinite(kappa_max) && std::isfinite(reach)))
    return finish(Status::numerical_failure,
                  "the curve's length, curvature or extent in user units is beyond the double range");
  try {
    LaSegment placed = standard->placed({info.reversed ? P[3] : P[0], scale, rotation});
    if (info.mirrored) placed = placed.mirrored();
    if (info.reversed) placed = placed.reversed(P[0]);
    res.curve = PlanarCurve({placed});
  } catch (const InputError& e) {
    return finish(Status::numerical_failure, std::string("the solved curve is not representable: ") + e.what());
  }
  if (s_shaped) {
    const double s0 = -1.0 / (lambda * alpha) * scale;  // Eq. (12)
    info.inflection_s = info.reversed ? length - s0 : s0;
  }
  // Residuals in the normalized frame (no overflow). Verified, the end point is the independent
  // tanh-sinh one, and the integrator's error is measured against it (its estimate); unverified,
  // the residuals are the integrator's own and it gives no estimate. The end angles come from φ's
  // closed form (004 Eq. 5 in linear-q form) at both ends.
  std::complex<double> z = end;
  if (o.verify) {
    z = detail::integrate_tangent_reference(law, standard->normalized());
    const double deviation = std::abs(end - z);
    if (std::isfinite(deviation)) sum.error_estimate = scale * deviation;
  }
  if (info.mirrored) z = std::conj(z);
  const double residual_position = ext * std::abs(A + rotation * scale_normalized * z - B);
  auto user_theta = [&](double s) {
    double theta = standard->phi_at(s);
    if (info.mirrored) theta = -theta;
    if (info.reversed) theta += kPi;
    return wrap_angle(theta + std::arg(rotation));
  };
  const double theta0 = user_theta(info.reversed ? L : 0.0), theta1 = user_theta(info.reversed ? 0.0 : L);
  const double residual_angle =
      std::max(std::abs(wrap_angle(theta0 - std::arg(d01))), std::abs(wrap_angle(theta1 - std::arg(d23))));
  // A check that cannot be evaluated (e.g. α = −1e-304: the reference integral overflows) leaves
  // the curve unverified: not usable.
  if (!std::isfinite(residual_position) || !std::isfinite(residual_angle))
    return finish(Status::numerical_failure, "the residual check of the end conditions is not a finite number");
  sum.residuals = {residual_position, residual_angle, std::nullopt};
  const double chord = std::abs(d03);
  const double worst = std::max(residual_position / chord, residual_angle);
  sum.error = std::max(worst, sum.error_estimate.value_or(0.0) / chord);
  sum.accept = o.accept;
  if (!(*sum.error <= o.accuracy))
    return finish(Status::tolerance_not_met, std::string(o.verify ? "verified" : "unverified") + " error " +
                                                 format_number(*sum.error) + " above the accuracy target " +
                                                 format_number(o.accuracy));
  return finish(Status::ok, "");
}

}  // namespace lac
