#include "lac/curves/planar/certified_position.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/curves/detail/taylor_frame.hpp"

namespace lac {
namespace {

constexpr double kEps = DBL_EPSILON;
constexpr int kTerms = detail::kTaylorTerms;

/// log|k|, sgn k, log|g|, sgn g (g = k'/k) at u, and D = d log|k|/dq (for the rounding of q):
/// header comment.
struct LogCurvature {
  double log_k, sign_k, log_g, sign_g, dlogk_dq;
};

LogCurvature log_curvature(const LaLaw& law, double q, double dq_du) {
  const double a = law.alpha;
  LogCurvature c{};
  double log_d = 0, sign_d = 1;  // D = d log|K|/dq
  if (a == 0) {
    c.log_k = q, c.sign_k = law.sigma;
  } else if (law.offset) {
    const double z = -a * q, t1 = 1.0 + z;  // 1 − αq = σt
    if (t1 > 0) {
      c.log_k = q * LaLaw::log1p_ratio(z), c.sign_k = law.sigma;
    } else {
      c.log_k = -std::log(-t1) / a, c.sign_k = -law.sigma;
    }
    log_d = -std::log(std::abs(t1)), sign_d = t1 > 0 ? 1 : -1;
  } else {
    c.log_k = -std::log(std::abs(q)) / a, c.sign_k = q > 0 ? 1 : -1;
    log_d = -std::log(std::abs(a * q)), sign_d = a * q > 0 ? -1 : 1;
  }
  c.log_g = std::log(std::abs(dq_du)) + log_d;
  c.sign_g = (dq_du < 0 ? -1 : 1) * sign_d;
  c.dlogk_dq = a == 0 ? 1.0 : std::exp(log_d);
  return c;
}

/// κ_i = k^(i)(u)/i! · h^(i+1), from logarithms (no factor overflows on its own), and their
/// relative rounding, including that of q(u) itself.
detail::FrameSeries planar_series(const LaSegment& seg, double u, double h) {
  const LaLaw& law = seg.law();
  const detail::LinearQ& lq = seg.normalized();
  // q(u) from the nearer end, with its rounding relative to the distance from that end (so that q
  // keeps its relative accuracy where it nears a zero just beyond an end).
  const double dq = lq.slope();
  const bool from_a = u - lq.ua <= lq.ub - u;
  const double delta_u = from_a ? u - lq.ua : lq.ub - u;
  const double q = from_a ? lq.qa + dq * delta_u : lq.qb - dq * delta_u;
  const LogCurvature c = log_curvature(law, q, dq);
  const double delta_q = 2 * kEps * (std::abs(q) + std::abs(from_a ? lq.qa : lq.qb)) + 6 * kEps * std::abs(dq * delta_u);
  const double lh = std::log(h);
  detail::FrameSeries out;
  double log_prod = 0, abs_log_prod = 0, sign = c.sign_k, log_fact = 0;
  for (int i = 0; i < kTerms; ++i) {
    if (std::isinf(log_prod) && log_prod < 0) break;  // a factor 1 + lα = 0: the rest are 0
    const double gi = i == 0 ? 0.0 : i * c.log_g;   // g = 0 (constant κ): only κ_0
    if (i > 0 && dq == 0) break;
    const double exponent = c.log_k + gi + log_prod - log_fact + (i + 1) * lh;
    out.kappa[i] = sign * std::exp(exponent);
    // d log|k^(i)|/dq = D(1 + iα) (both forms): zero where k^(i) does not depend on q (α = −1, i = 1).
    const double e = std::abs(c.dlogk_dq * (1 + i * law.alpha)) * delta_q +
                     4 * kEps * (std::abs(c.log_k) + std::abs(gi) + abs_log_prod + log_fact + (i + 1) * (1 + std::abs(lh)) + i + 1);
    out.kappa_error[i] = (std::expm1(e) + 4 * kEps) * std::abs(out.kappa[i]);
    const double f = 1.0 + i * law.alpha;
    log_prod += std::log(std::abs(f));
    abs_log_prod += std::abs(std::log(std::abs(f)));
    log_fact += std::log(i + 1.0);
    sign *= c.sign_g * (f < 0 ? -1 : 1);
  }
  return out;
}

/// Bound on the error of the closed-form φ(u) (la_law.hpp's divided difference: a few ulps of its
/// terms).
double phi_error(const LaSegment& seg, double phi) {
  return 8 * kEps * (1 + std::abs(seg.phi_a()) + std::abs(phi - seg.phi_a()));
}

}  // namespace

CertifiedTangentIntegral integrate_tangent_certified(const LaSegment& seg, double u0, double u1) {
  constexpr const char* who = "integrate_tangent_certified";
  seg.check_u(u0, "u0");
  seg.check_u(u1, "u1");
  if (!(u0 <= u1)) throw_input_error(who, "u1", u1, "[u0, ub]");
  if (u0 == u1) return {};
  const LaLaw& law = seg.law();
  // Taylor steps away from an inflection, one tangent step across its zone.
  std::optional<detail::TangentZone> zone;
  const double ta = law.t_of_q(seg.qa()), tb = law.t_of_q(seg.qb());
  if (law.alpha < 0 && ta != tb) {
    const double ui = seg.ua() + (seg.ub() - seg.ua()) * ta / (ta - tb);  // t = 0 (possibly outside)
    const double p = -1.0 / law.alpha, dt_du = std::abs((tb - ta) / (seg.ub() - seg.ua()));
    double d = std::exp((std::log(kEps / 32) - p * std::log(dt_du)) / (p + 1));
    const auto k_at = [&](double u) { return std::abs(law.kappa_of_q(seg.normalized().q_at(u))); };
    for (int k = 0; k < 200 && d * std::max(k_at(ui - d), k_at(ui + d)) > kEps / 16; ++k) d *= 0.5;
    zone = detail::TangentZone{ui - d, ui + d, std::max(k_at(ui - d), k_at(ui + d))};
  }
  const detail::FrameSeriesFunction series = [&](double u, double h) { return planar_series(seg, u, h); };
  return detail::integrate_plane_tangent(
      series, detail::end_majorant(series),
      [&](double u, double& error) {
        const double phi = seg.phi_at(u);
        error = phi_error(seg, phi);
        return phi;
      },
      u0, u1, zone, who);
}

CertifiedPoint position_certified(const LaSegment& seg, double u0, std::complex<double> p0, double p0_error,
                                  double u1) {
  const CertifiedTangentIntegral i = integrate_tangent_certified(seg, u0, u1);
  CertifiedPoint r{p0, p0_error, i.steps, i.status, i.message};
  if (i.status != Status::ok) {
    r.error = HUGE_VAL;
    return r;
  }
  const std::complex<double> moved = seg.scale() * seg.rotation() * i.value;
  r.position = p0 + moved;
  // The similarity's rounding: a few ulps of each term.
  r.error = p0_error + seg.scale() * std::abs(seg.rotation()) * i.error +
            4 * kEps * (std::abs(p0) + 2 * std::abs(moved));
  return r;
}

CertifiedPoint position_certified(const LaSegment& seg, double s) {
  seg.check_s(s, "s");
  return position_certified(seg, seg.ua(), seg.start(), 0.0, seg.u_at(s));
}

}  // namespace lac
