#include "lac/curves/planar/la_segment.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_segment_kernel.hpp"

namespace lac {

namespace {
constexpr const char* kWho = "LaSegment";
}

LaSegment::LaSegment(LaLaw law, double ua, double ub, double qa, double qb, double phi_a, Placement placement)
    : law_(law), q_{ua, ub, qa, qb, phi_a}, placement_(placement) {
  require_finite(kWho, "alpha", law.alpha);
  if (law.log_form() && law.sigma != 1 && law.sigma != -1) throw_input_error(kWho, "sigma", law.sigma, "{-1, 1}");
  require_finite(kWho, "ua", ua);
  require_finite(kWho, "ub", ub);
  if (!(ub > ua)) throw_input_error(kWho, "ub", ub, interval_text(ua, INFINITY) + " (ub > ua)");
  require_finite(kWho, "qa", qa);
  require_finite(kWho, "qb", qb);
  const double ta = law.t_of_q(qa), tb = law.t_of_q(qb);  // the plain form's q
  if (law.alpha > 0 && !((ta > 0 && tb > 0) || (ta < 0 && tb < 0)))
    throw_input_error(kWho, "qb", qb,
                      "values of the sign of qa = " + format_number(qa) +
                          " (for alpha > 0 the curvature cannot reach 0 or infinity: q keeps its sign)");
  if (!std::isfinite(law.kappa_of_q(qa))) throw_input_error(kWho, "qa", qa, "values with a finite curvature K(q)");
  if (!std::isfinite(law.kappa_of_q(qb))) throw_input_error(kWho, "qb", qb, "values with a finite curvature K(q)");
  require_finite(kWho, "phi_a", phi_a);
  if (!std::isfinite(q_.phi_b(law_)))
    throw_input_error(kWho, "qb", qb, "values for which the turning of the segment is a finite double");
  require_finite(kWho, "start.x", placement.start.real());
  require_finite(kWho, "start.y", placement.start.imag());
  if (!(placement.scale > 0) || !std::isfinite(placement.scale))
    throw_input_error(kWho, "scale", placement.scale, "(0, inf)");
  const double r = std::abs(placement.rotation);
  if (!(std::abs(r - 1.0) <= 1e-12))
    throw_input_error(kWho, "rotation", r, "|rotation| = 1 within 1e-12 (a unit complex number)");
  length_ = placement.scale * (ub - ua);
  if (!std::isfinite(length_))
    throw_input_error(kWho, "scale", placement.scale, "values for which the length scale·(ub − ua) is a finite double");
  angle_ = std::arg(placement.rotation);
}

double LaSegment::u_at(double s) const {
  if (s >= length_) return ub();
  return std::min(ub(), ua() + s / scale());
}

detail::LinearQ LaSegment::part(double u0, double u1) const {
  return {u0, u1, u0 == ua() ? qa() : q_at(u0), u1 == ub() ? qb() : q_at(u1), u0 == ua() ? phi_a() : phi_at(u0)};
}

std::optional<double> LaSegment::inflection_u() const {
  if (!(law_.alpha < 0)) return std::nullopt;
  const double ta = law_.t_of_q(qa()), tb = law_.t_of_q(qb());  // zero where κ = 0
  if (ta == 0) return ua();
  if (tb == 0) return ub();
  if ((ta < 0) == (tb < 0)) return std::nullopt;
  return std::clamp(ua() + (ub() - ua()) * ta / (ta - tb), ua(), ub());
}

std::optional<double> LaSegment::inflection_s() const {
  const auto u = inflection_u();
  if (!u) return std::nullopt;
  return *u == ub() ? length_ : std::min(length_, scale() * (*u - ua()));
}

// κ = K(q)/ℓ with q linear in u = ua + s/ℓ: dκ/ds = K'(q) c0/ℓ².
double LaSegment::dkappa_ds_at(double s) const {
  check_s(s, "s");
  return law_.dK(q_at(u_at(s))) * q_.slope() / (scale() * scale());
}

CurvePoint LaSegment::frame_at(double s) const {
  check_s(s, "s");
  CurvePoint c;
  c.s = s;
  const double u = u_at(s);
  c.theta = angle_ + phi_at(u);
  c.kappa = curvature_per_u(u) / scale();
  c.rho = 1.0 / c.kappa;
  c.position = {};
  return c;
}

LaSegment LaSegment::mirrored() const {
  const bool signed_q = !law_.log_form();
  return {law_.mirrored(), ua(), ub(), signed_q ? -qa() : qa(), signed_q ? -qb() : qb(), -phi_a(), placement_};
}

// u' = −u, so q'(u') is q(u) of the opposite curvature (κ → −κ: traversed backwards), φ'(u') = φ(u)
// with the frame turned by π (R → −R), and the start moves to the end point.
LaSegment LaSegment::reversed(std::complex<double> end_point) const {
  const bool signed_q = !law_.log_form();
  return {law_.mirrored(), -ub(), -ua(), signed_q ? -qb() : qb(), signed_q ? -qa() : qa(), phi_b(),
          Placement{end_point, scale(), -rotation()}};
}

void LaSegment::check_s(double s, const char* name) const {
  if (!(s >= 0 && s <= length_)) throw_input_error(kWho, name, s, interval_text(0, length_, true, true));
}

void LaSegment::check_u(double u, const char* name) const {
  if (!(u >= ua() && u <= ub())) throw_input_error(kWho, name, u, interval_text(ua(), ub(), true, true));
}

std::complex<double> integrate_tangent_reference(const LaSegment& seg, double u0, double u1, double tolerance) {
  seg.check_u(u0, "u0");
  seg.check_u(u1, "u1");
  if (u0 == u1) return {};
  const auto value = detail::integrate_tangent_reference(seg.law(), u0 < u1 ? seg.part(u0, u1) : seg.part(u1, u0), tolerance);
  return u0 < u1 ? value : -value;
}

namespace detail {

std::vector<double> part_ends(const LaLaw& law, const LinearQ& seg, const TangentPiece& p) {
  if (p.graded) {
    // φ(t) = φ* + Δ t^β: equal steps of t^β between t0^β and 1.
    const double b0 = std::pow(p.t0, p.beta), turning = std::abs(p.delta) * (1.0 - b0);
    if (!(turning <= kMaxTurningPerPart * kMaxParts)) return {};
    const int n = std::max(1, static_cast<int>(std::ceil(turning / kMaxTurningPerPart)));
    std::vector<double> ends{p.t0};
    for (int k = 1; k < n; ++k) ends.push_back(std::pow(b0 + (1.0 - b0) * k / n, 1.0 / p.beta));
    ends.push_back(1.0);
    // The layer at t = 1 (detail::layer_cuts, in t: t^β = e^{-d}) where β is large (small |α|).
    if (p.beta * (1.0 - p.t0) > 32) {
      for (double d = 0.25; d < 700.0; d *= 2) {
        const double t = std::exp(-d / p.beta);
        if (!(t > p.t0)) break;
        ends.push_back(t);
      }
      std::sort(ends.begin(), ends.end());
      ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    }
    return ends;
  }
  // Plain: φ(u) − φa = (F(q(u)) − F(qa))/c0, so equal steps of φ are equal steps of F(q) while q
  // keeps its sign (α ≠ 0; for α = 0, F is monotonic in q). Only a clothoid's plain piece can
  // pass through q = 0 (F(0) = 0): its turning is then |F(qa)| + |F(qb)| over |c0|, cut in equal
  // steps of u.
  const double c0 = seg.slope(), Fa = law.F(seg.qa), Fb = law.F(seg.qb);
  const double ta = law.t_of_q(seg.qa), tb = law.t_of_q(seg.qb);  // the plain form's q
  const bool crosses = law.alpha != 0 && (ta < 0) != (tb < 0) && ta != 0 && tb != 0;
  const double turning = crosses ? (std::abs(Fa) + std::abs(Fb)) / std::abs(c0) : std::abs(seg.turning(law));
  if (!(turning <= kMaxTurningPerPart * kMaxParts)) return {};
  const int n = std::max(1, static_cast<int>(std::ceil(turning / kMaxTurningPerPart)));
  std::vector<double> ends{seg.ua};
  const bool by_F = c0 != 0 && !crosses;
  const double sign = ta != 0 ? ta : tb;
  for (int k = 1; k < n; ++k) {
    const double uniform = seg.ua + (seg.ub - seg.ua) * k / n;
    double u = uniform;
    if (by_F) u = seg.ua + (law.F_inverse(Fa + (Fb - Fa) * k / n, sign) - seg.qa) / c0;
    // Rounding must not reorder the parts: fall back to equal steps of u.
    ends.push_back(std::isfinite(u) && u > ends.back() && u < seg.ub ? u : std::max(uniform, ends.back()));
  }
  ends.push_back(seg.ub);
  if (!crosses) {
    const std::vector<double> layer = layer_cuts(law, seg, seg.ua, seg.ub);
    if (!layer.empty()) {
      ends.insert(ends.end(), layer.begin(), layer.end());
      std::sort(ends.begin(), ends.end());
      ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    }
  }
  return ends;
}

double phase_noise(const LaLaw& law, const LinearQ& seg) {
  const double c0 = seg.slope(), ta = law.t_of_q(seg.qa), tb = law.t_of_q(seg.qb);
  const bool crosses = law.alpha != 0 && ((ta < 0 && tb > 0) || (ta > 0 && tb < 0));
  // φ's total variation: through a zero of t (F(0) = 0) the two sides' |F|/|c0|.
  const double variation = crosses ? (std::abs(law.F(seg.qa)) + std::abs(law.F(seg.qb))) / std::abs(c0)
                                   : std::abs(seg.turning(law));
  const double per_radian = law.log_form() ? 2 * DBL_EPSILON * (1 + std::max(std::abs(seg.qa), std::abs(seg.qb)))
                                           : 2 * DBL_EPSILON / std::abs(law.alpha);
  return per_radian * variation;
}

double tangent_rounding(const LaLaw& law, const LinearQ& seg) {
  double phi_max = std::max(std::abs(seg.phi_a), std::abs(seg.phi_b(law)));
  const TangentPlan plan = tangent_plan(law, seg);
  if (plan.pieces[0].graded) phi_max = std::max(phi_max, std::abs(plan.pieces[0].phi_zero));  // φ at the inflection
  return (DBL_EPSILON * (1.0 + phi_max) + phase_noise(law, seg)) * (seg.ub - seg.ua);
}

void place_tangent_integral(const LaSegment& seg, const IntegralResult<std::complex<double>>& I, PositionResult& r) {
  r.evaluations = I.evaluations;
  r.status = I.status;
  r.message = I.message;
  if (usable(I.status)) {
    r.point.position = seg.start() + (seg.scale() * seg.rotation()) * I.value;
    r.error_estimate = seg.scale() * I.error_estimate;
    if (!(std::isfinite(r.point.position.real()) && std::isfinite(r.point.position.imag()) &&
          std::isfinite(r.error_estimate))) {
      r.status = Status::numerical_failure;
      r.message = "non-finite position or error estimate";
    }
  }
  if (!usable(r.status)) {
    r.point.position = seg.start();
    r.error_estimate = std::numeric_limits<double>::infinity();
  }
}

IntegralResult<std::complex<double>> integrate_tangent_gl(const LaLaw& law, const LinearQ& seg, const GaussLegendre& m) {
  IntegralResult<std::complex<double>> r;
  // The segment kernel (la_segment_kernel.hpp): Gauss–Legendre panels sized by the phase and
  // closed-form series, within kLaKernelError of the length; the graded panels below where it
  // does not evaluate the segment.
  if (const auto kernel = segment_integral(law, seg, r.evaluations)) {
    r.value = kernel->value;
    r.error_estimate = kernel->error;
    return r;
  }
  std::complex<double> coarse;
  r.value = integrate_tangent(law, seg, r.evaluations, m.panels, &coarse);
  const double l1 = seg.ub - seg.ua;  // |e^{iφ}| = 1
  if (std::isnan(r.value.real())) {
    r.status = Status::max_iterations;
    r.message = "gauss-legendre: a piece of the segment turns more than " + format_number(kMaxResolvedTurning) +
                " rad (64 panels of 16 rad); split the segment or use an adaptive method";
    return r;
  }
  r.error_estimate = std::abs(r.value - coarse) + 2 * DBL_EPSILON * l1;
  if (!std::isfinite(std::abs(r.value)) || !std::isfinite(r.error_estimate)) {
    r.status = Status::numerical_failure;
    r.message = "gauss-legendre: non-finite integrand value";
  } else if (r.error_estimate > m.tol * std::abs(r.value) && r.error_estimate > 100 * DBL_EPSILON * l1) {
    r.status = Status::tolerance_not_met;
    r.message = "gauss-legendre: error estimate " + format_number(r.error_estimate) + " above tolerance with at least " +
                std::to_string(m.panels) + " panels per piece; raise panels";
  }
  return r;
}

}  // namespace detail
}  // namespace lac
