#pragma once
// Internals of la_position.hpp: the integrands of the θ- and s-forms, the splitting of long
// pieces, one piece by any method (quadrature or closed form), and the RK4 sweep of a polyline.
#include <algorithm>
#include <cmath>
#include <complex>
#include <concepts>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/curves/curve.hpp"
#include "lac/curves/detail/polyline.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/integrators/quadrature.hpp"

namespace lac {

namespace detail {

// Always inlined: in a unit that instantiates every registered method (the run-time dispatch),
// GCC's growth limits otherwise leave them out of line in the adaptive methods' inner loops.
struct ThetaFormIntegrand {
  const LaCurve* c;
  [[gnu::always_inline]] std::complex<double> operator()(double psi) const {
    return std::polar(std::exp(c->log_rho_at_theta_unchecked(psi)), psi);
  }
};
struct SFormIntegrand {
  const LaCurve* c;
  [[gnu::always_inline]] std::complex<double> operator()(double u) const { return std::polar(1.0, c->theta_at_s_unchecked(u)); }
};

/// e^{iψ} for a run of nearby angles, as an RK4 sweep asks for them: one sincos at a base angle,
/// and for |ψ − base| ≤ 1/64 the base turned by e^{iδ}, δ = ψ − base, from its Taylor polynomial
/// (truncation < 1e-19 there), added to the base as a small correction. Every value is one turn
/// from a sincos, so nothing accumulates: ≤ 0.51 ε absolute against a 113-bit reference (2·10^6
/// random angles; sincos 0.25 ε). On 002's segment (h = 0.001, θ ∈ [0, 1]) about 64 sincos
/// instead of 2001.
class NearbyCis {
 public:
  std::complex<double> operator()(double psi) {
    const double d = psi - base_;
    if (std::abs(d) <= 1.0 / 64) {  // false while base_ is NaN
      const double d2 = d * d;
      const double cos_d_m1 = d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720)));   // cos δ − 1
      const double sin_d = d + d * d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040)));
      return {cos_ + (cos_ * cos_d_m1 - sin_ * sin_d), sin_ + (sin_ * cos_d_m1 + cos_ * sin_d)};  // base + small
    }
    base_ = psi;
    cos_ = std::cos(psi);  // with sin: one sincos
    sin_ = std::sin(psi);
    return {cos_, sin_};
  }

 private:
  double base_ = std::numeric_limits<double>::quiet_NaN(), cos_ = 1, sin_ = 0;
};

/// The integrands as an Rk4Sweep evaluates them (in order, at nearby points): e^{iθ} by
/// NearbyCis, and at a polyline's output point (a piece end, evaluated once) ρ (θ-form) or θ
/// (s-form) taken from that point's frame instead of recomputed (the frame computes it with the
/// same operations, so the value is the same bit for bit). `known` is the point's parameter; NaN
/// (never equal) when the frame's parameter is not the integration variable.
/// `mid`, `mid_value`: the same for a piece's midpoint, whose value polyline_rk4 computes ahead
/// in a pass of its own (value()).
struct ThetaFormSweepIntegrand {
  const LaCurve* c;
  double known = std::numeric_limits<double>::quiet_NaN(), known_rho = 1;
  double mid = std::numeric_limits<double>::quiet_NaN(), mid_value = 1;
  NearbyCis cis{};
  void set_known(const CurvePoint& q) { known = q.theta, known_rho = q.rho; }
  double value(double psi) const { return std::exp(c->log_rho_at_theta_unchecked(psi)); }  // ρ
  std::complex<double> operator()(double psi) {
    return (psi == known ? known_rho : psi == mid ? mid_value : value(psi)) * cis(psi);
  }
};
struct SFormSweepIntegrand {
  const LaCurve* c;
  double known = std::numeric_limits<double>::quiet_NaN(), known_theta = 0;
  double mid = std::numeric_limits<double>::quiet_NaN(), mid_value = 0;
  NearbyCis cis{};
  void set_known(const CurvePoint& q) { known = q.s, known_theta = q.theta; }
  double value(double u) const { return c->theta_at_s_unchecked(u); }  // θ
  std::complex<double> operator()(double u) { return cis(u == known ? known_theta : u == mid ? mid_value : value(u)); }
};

/// Error carried by the integrand values themselves, which no quadrature estimate sees: ρ =
/// exp(log ρ) has relative error ≈ k ε|log ρ| and e^{iθ} absolute error ≈ k ε|θ|, with k the few
/// roundings of log ρ = x·log1p((α − 1)x)/((α − 1)x), x = Λθ (resp. of θ(s)); both integrands have
/// ∫|f| = |Δs|. kRoundingsLogRho = 8, kRoundingsTheta = 4: the measured errors on
/// la_reference.csv reach 3 ε|log ρ| |Δs| (α = 1.01, Λ = 100, θ = 5: log ρ = 179). Added to the
/// quadrature's own estimate.
/// Near ρ → ∞ (y = (α − 1)Λθ → −1) log1p amplifies the rounding of y by |y / ((1 + y) log1p y)|:
/// that condition number multiplies the log ρ term.
inline constexpr double kRoundingsLogRho = 8, kRoundingsTheta = 4;
inline double log_rho_rounding(const LaCurve& c, double theta) {
  const double log_rho = std::abs(c.log_rho_at_theta_unchecked(theta));
  const double y = (c.alpha() - 1.0) * c.lambda() * theta;
  const double cond = std::abs(y) < 1e-8 ? 1.0 : std::abs(y / ((1 + y) * std::log1p(y)));
  return log_rho * (kRoundingsLogRho + (std::isfinite(cond) ? cond : 0.0));
}
inline double integrand_rounding(const LaCurve& c, double theta_a, double theta_b) {
  const double log_rho = std::max(log_rho_rounding(c, theta_a), log_rho_rounding(c, theta_b));
  const double length = std::abs(c.s_at_theta(theta_b) - c.s_at_theta(theta_a));
  return std::numeric_limits<double>::epsilon() *
         (1 + log_rho + kRoundingsTheta * std::max(std::abs(theta_a), std::abs(theta_b))) * length;
}
/// The s-form's limits are arc lengths computed from θ (a position asked at θ): their rounding,
/// |ds| ≈ ρ |dθ| with |dθ| ≈ kRoundingsTheta ε |θ|, moves the position by |ds| (ill-conditioned near
/// an open end, where ρ is huge: α = 0.9, Λ = 100, θ = 0.095 on la_reference.csv).
inline double s_limit_rounding(const LaCurve& c, double theta_a, double theta_b) {
  auto one = [&](double theta) { return std::abs(theta) * std::exp(c.log_rho_at_theta_unchecked(theta)); };
  return kRoundingsTheta * std::numeric_limits<double>::epsilon() * (one(theta_a) + one(theta_b));
}

/// Longest turning given to one quadrature call: a fixed 21-node rule over many turns of
/// e^{iθ} aliases (|K − G| looks small while both are wrong), so longer pieces are split.
inline constexpr double kMaxTurningPerPiece = 64.0;
inline constexpr double kMaxPieces = 1e6;

/// Calls visit(lo, hi) for the consecutive quadrature intervals that make up [a, b] in the
/// variable of `form`: at most kMaxTurningPerPiece of turning each. InputError beyond kMaxPieces.
template <class Visit>
void for_each_subpiece(const LaCurve& c, Form form, double a, double b, Visit&& visit) {
  if (form == Form::theta && std::abs(b - a) <= kMaxTurningPerPiece) {  // the common case: one piece
    visit(a, b);
    return;
  }
  const double theta_a = form == Form::s ? c.theta_at_s(a) : a, theta_b = form == Form::s ? c.theta_at_s(b) : b;
  const double pieces = std::ceil(std::abs(theta_b - theta_a) / kMaxTurningPerPiece);
  if (!(pieces <= kMaxPieces))
    throw_input_error("position", "theta", theta_b,
                      "turning of at most " + format_number(kMaxTurningPerPiece * kMaxPieces) + " rad from the reference point");
  const long n = std::max(1L, static_cast<long>(pieces));
  double lo = a;
  for (long k = 1; k <= n; ++k) {
    const double theta_k = k == n ? theta_b : theta_a + (theta_b - theta_a) * static_cast<double>(k) / static_cast<double>(n);
    const double hi = k == n ? b : (form == Form::s ? c.s_at_theta(theta_k) : theta_k);
    if (!visit(lo, hi)) return;
    lo = hi;
  }
}

/// ∫ over [a, b] in the variable of `form` (θ or s); a closed form always works in θ.
/// A non-finite error estimate makes the result a numerical_failure, never a usable value.
template <class M>
IntegralResult<std::complex<double>> integrate_piece(const LaCurve& c, const M& m, Form form, double a, double b) {
  IntegralResult<std::complex<double>> r;
  if constexpr (LaClosedForm<M>) {
    r = form == Form::s ? m.integrate_theta(c.alpha(), c.lambda(), c.theta_at_s(a), c.theta_at_s(b))
                        : m.integrate_theta(c.alpha(), c.lambda(), a, b);
  } else if constexpr (std::same_as<M, Rk4>) {
    Rk4Sweep<std::complex<double>> sweep(m);
    sweep.reserve(b - a);
    ThetaFormSweepIntegrand ft{&c};
    SFormSweepIntegrand fs{&c};
    if (sweep.status() == Status::ok) for_each_subpiece(c, form, a, b, [&](double lo, double hi) {
      r.value += form == Form::s ? sweep.advance(fs, lo, hi) : sweep.advance(ft, lo, hi);
      return sweep.status() == Status::ok;
    });
    r.evaluations = sweep.evaluations();
    r.status = sweep.status();
    r.message = sweep.message();
    r.error_estimate = r.status == Status::ok ? sweep.error_estimate() : std::numeric_limits<double>::infinity();
    const double theta_a = form == Form::s ? c.theta_at_s(a) : a, theta_b = form == Form::s ? c.theta_at_s(b) : b;
    r.error_estimate += integrand_rounding(c, theta_a, theta_b);
    if (form == Form::s) r.error_estimate += s_limit_rounding(c, theta_a, theta_b);
  } else {
    static_assert(QuadratureMethod<M>, "method must be a QuadratureMethod or an LaClosedForm");
    for_each_subpiece(c, form, a, b, [&](double lo, double hi) {
      if (r.evaluations >= evaluation_budget(m)) {
        r.status = Status::max_iterations;
        r.message = std::string(M::name) + ": evaluation budget " + std::to_string(evaluation_budget(m)) +
                    " of one position call exhausted after " + std::to_string(r.evaluations) +
                    " evaluations, at " + format_number(lo) + " of [" + format_number(a) + ", " + format_number(b) +
                    "] (pieces of " + format_number(kMaxTurningPerPiece) + " rad); raise the method's budget";
        return false;
      }
      add_part(r, form == Form::s ? m.integrate(SFormIntegrand{&c}, lo, hi) : m.integrate(ThetaFormIntegrand{&c}, lo, hi));
      return true;
    });
    const double theta_a = form == Form::s ? c.theta_at_s(a) : a, theta_b = form == Form::s ? c.theta_at_s(b) : b;
    r.error_estimate += integrand_rounding(c, theta_a, theta_b);
    if (form == Form::s) r.error_estimate += s_limit_rounding(c, theta_a, theta_b);
  }
  if (usable(r.status) && !(std::isfinite(r.error_estimate) && std::isfinite(std::abs(r.value)))) {
    r.status = Status::numerical_failure;
    r.message = "non-finite position or error estimate";
  }
  return r;
}

/// Rk4 polyline as one Rk4Sweep from the reference point through every output point (see
/// polyline): the same steps as integrating each piece separately, but the integrand value at a
/// shared end is computed once (2 new evaluations per step), and the error estimate is the
/// sweep's Richardson estimate plus integrand_rounding over the range covered so far.
/// `frames_in_form`: the points' parameter is the integration variable, so f can take ρ or θ at
/// a piece end from its frame (F::set_known). Once the step budget is spent, the remaining points
/// hold the last computed position with status max_iterations (PositionResult). Returns the index
/// of the first point whose running sum is not finite (out.size() if none): the sweep cannot go
/// on from there, polyline continues piece by piece.
template <class F>
size_t polyline_rk4(const LaCurve& c, const Rk4& m, Form form, F f, bool frames_in_form, std::vector<PositionResult>& out) {
  Rk4Sweep<std::complex<double>> sweep(m);
  const double first = form == Form::s ? out.front().point.s : out.front().point.theta;
  const double last = form == Form::s ? out.back().point.s : out.back().point.theta;
  sweep.reserve(std::abs(first) + std::abs(last - first));  // 0 → first → last
  // The integrand at the midpoint of every one-step piece (the sweep's a + step/2 with step =
  // b − a), computed in a pass of its own before the sweep: these calls are independent and
  // overlap, while inside the sweep each waits for the previous step. Same values bit for bit.
  std::vector<double> mids(out.size()), mid_values(out.size());
  double prev = 0.0;
  for (size_t k = 0; k < out.size(); ++k) {
    const double next = form == Form::s ? out[k].point.s : out[k].point.theta;
    const double span = next - prev;
    const bool one_step = span != 0 && std::ceil(std::abs(span) / m.h * (1 - 1e-9)) <= 1.0;
    mids[k] = one_step ? prev + 0.5 * span : std::numeric_limits<double>::quiet_NaN();
    if (one_step) mid_values[k] = f.value(mids[k]);
    prev = next;
  }
  prev = 0.0;
  double prev_s = 0.0, length = 0.0, theta_lo = 0.0, theta_hi = 0.0;
  double log_rho_max = 0.0;  // max |log ρ| over [theta_lo, theta_hi]: log ρ is monotone in θ
  std::complex<double> pos{};
  for (size_t k = 0; k < out.size(); ++k) {
    PositionResult& r = out[k];
    const double next = form == Form::s ? r.point.s : r.point.theta;
    std::complex<double> piece{};
    if (frames_in_form) f.set_known(r.point);
    f.mid = mids[k];
    f.mid_value = mid_values[k];
    if (sweep.status() == Status::ok) for_each_subpiece(c, form, prev, next, [&](double lo, double hi) {
      piece += sweep.advance(f, lo, hi);
      return sweep.status() == Status::ok;
    });
    if (sweep.status() == Status::ok) pos += piece;  // a piece cut short by the budget is not added
    prev = next;
    if (r.point.theta < theta_lo || r.point.theta > theta_hi) {
      theta_lo = std::min(theta_lo, r.point.theta);
      theta_hi = std::max(theta_hi, r.point.theta);
      // |log ρ| ≤ (ilogb(max(ρ, κ)) + 1) ln 2: an upper bound without a log per point
      log_rho_max = std::max(log_rho_max, (std::ilogb(std::max(r.point.rho, r.point.kappa)) + 1) * std::numbers::ln2);
    }
    length += std::abs(r.point.s - prev_s);
    prev_s = r.point.s;
    r.point.position = pos;
    r.evaluations = sweep.evaluations();
    r.form = form;
    r.status = sweep.status();
    if (r.status != Status::ok) r.message = sweep.message();
    r.error_estimate = sweep.status() != Status::ok ? std::numeric_limits<double>::infinity()
                                                    : sweep.error_estimate() + std::numeric_limits<double>::epsilon() *
                                                                                   (1 + kRoundingsLogRho * log_rho_max + kRoundingsTheta * std::max(-theta_lo, theta_hi)) * length;
    if (r.status == Status::ok && !(std::isfinite(r.error_estimate) && std::isfinite(pos.real()) && std::isfinite(pos.imag())))
      return k;
  }
  return out.size();
}

}  // namespace detail

}  // namespace lac
