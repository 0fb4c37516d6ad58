#pragma once
// Templates of la_segment.hpp: the tangent integral of an LA segment with any quadrature method.
// (la_segment.hpp includes this file at its end; included alone, it includes la_segment.hpp first.)
#include "lac/curves/planar/la_segment.hpp"

#include <algorithm>
#include <complex>
#include <concepts>
#include <limits>
#include <string>
#include <vector>

#include "lac/curves/detail/polyline.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/integrators/gauss_legendre.hpp"
#include "lac/integrators/quadrature.hpp"

namespace lac {
namespace detail {

/// Most turning given to one call of a method: a fixed 21-node panel over many turns of e^{iφ}
/// aliases (|K − G| looks small while both are wrong), so longer pieces are cut (as for LaCurve).
inline constexpr double kMaxTurningPerPart = 64.0;
inline constexpr double kMaxParts = 1e6;

/// Ends of the parts of one piece of tangent_plan in its variable (u for a plain piece, t for a
/// graded one), each turning at most kMaxTurningPerPart (φ is monotonic on a piece: equal steps
/// of φ through F⁻¹, or of t^β). Empty beyond kMaxParts parts.
std::vector<double> part_ends(const LaLaw& law, const LinearQ& seg, const TangentPiece& piece);

/// Bound on |δφ| from the rounding of q (relative ε in the plain form: ε/|α| on κ; absolute
/// ε(1 + |q|) on log|κ| in the log forms) over φ's total variation on the segment: at small |α| it
/// dwarfs ε·|φ| (at α = −2e-6, 2e-10 rad per radian turned).
double phase_noise(const LaLaw& law, const LinearQ& seg);

/// (ε(1 + max|φ|) + phase_noise)·|ub − ua|: the error of the integrand values themselves (φ
/// rounded), which no quadrature estimate sees.
double tangent_rounding(const LaLaw& law, const LinearQ& seg);

/// The GaussLegendre path: detail::integrate_tangent with the 10-point estimate and the status
/// of GaussLegendre::integrate.
IntegralResult<std::complex<double>> integrate_tangent_gl(const LaLaw& law, const LinearQ& seg, const GaussLegendre& m);

/// Budget of one tangent integral made of several calls of m: the method's per-call budget
/// (Rk4: one sweep's 2 max_steps + 1 evaluations).
template <class M>
long tangent_budget(const M& m) {
  if constexpr (std::same_as<M, Rk4>) return 2 * m.max_steps + 1;
  else return evaluation_budget(m);
}

template <class M>
IntegralResult<std::complex<double>> integrate_tangent_with(const LaLaw& law, const LinearQ& seg, const M& m) {
  IntegralResult<std::complex<double>> r;
  const TangentPlan plan = tangent_plan(law, seg);
  const long budget = tangent_budget(m);
  // No relative tolerance below the integrand's own noise (an adaptive rule would bisect to its
  // budget chasing it); tangent_rounding adds the noise to the estimate.
  M method = m;
  if constexpr (requires { method.tol; }) method.tol = std::max(m.tol, 2 * phase_noise(law, seg));
  const double Ka = law.kappa_of_q(seg.qa), Fa = law.F(seg.qa);
  const auto plain = [&](double u) {
    return std::polar(1.0, seg.phi_a + (u - seg.ua) * law.divided(seg.qa, Ka, Fa, seg.q_at(u)));
  };
  for (int i = 0; i < plan.count; ++i) {
    const TangentPiece& p = plan.pieces[static_cast<size_t>(i)];
    const auto graded = [&p](double t) { return p.du_dt(t) * std::polar(1.0, p.phi(t)); };
    const std::vector<double> ends = part_ends(law, seg, p);
    if (ends.empty()) {
      r.status = Status::max_iterations;
      r.message = std::string(M::name) + ": the segment turns more than " +
                  format_number(kMaxTurningPerPart * kMaxParts) + " rad between the integration limits";
      return r;
    }
    for (size_t k = 0; k + 1 < ends.size(); ++k) {
      if (r.evaluations >= budget) {
        r.status = Status::max_iterations;
        r.message = std::string(M::name) + ": evaluation budget " + std::to_string(budget) +
                    " of one tangent integral exhausted after " + std::to_string(r.evaluations) +
                    " evaluations (parts of " + format_number(kMaxTurningPerPart) + " rad); raise the method's budget";
        return r;
      }
      add_part(r, p.graded ? method.integrate(graded, ends[k], ends[k + 1]) : method.integrate(plain, ends[k], ends[k + 1]),
               p.sign);
    }
  }
  return r;
}

/// The position of the tangent integral I from the segment's start (start + ℓR·I) into r, with its
/// estimate, evaluations and status; a non-finite result is numerical_failure, and a failed one
/// leaves the start point with an infinite estimate (PositionResult).
void place_tangent_integral(const LaSegment& seg, const IntegralResult<std::complex<double>>& I, PositionResult& r);

}  // namespace detail

template <QuadratureMethod M>
IntegralResult<std::complex<double>> integrate_tangent(const LaSegment& seg, double u0, double u1, const M& method) {
  method.validate();
  seg.check_u(u0, "u0");
  seg.check_u(u1, "u1");
  IntegralResult<std::complex<double>> r;
  if (u0 == u1) return r;
  const detail::LinearQ part = u0 < u1 ? seg.part(u0, u1) : seg.part(u1, u0);
  if constexpr (std::same_as<M, GaussLegendre>) {
    r = detail::integrate_tangent_gl(seg.law(), part, method);
  } else {
    r = detail::integrate_tangent_with(seg.law(), part, method);
  }
  if (usable(r.status)) {
    r.error_estimate += detail::tangent_rounding(seg.law(), part);
    if (!(std::isfinite(r.value.real()) && std::isfinite(r.value.imag()) && std::isfinite(r.error_estimate))) {
      r.status = Status::numerical_failure;
      r.message = "non-finite tangent integral or error estimate";
    }
  }
  if (u1 < u0) r.value = -r.value;
  return r;
}

template <QuadratureMethod M>
PositionResult position_at(const LaSegment& seg, double s, const M& method) {
  seg.check_s(s, "s");
  PositionResult r;
  r.form = Form::s;
  r.point = seg.frame_at(s);
  detail::place_tangent_integral(seg, integrate_tangent(seg, seg.ua(), seg.u_at(s), method), r);
  return r;
}

}  // namespace lac
