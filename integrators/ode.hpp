#pragma once
// Explicit Runge–Kutta integration of y' = f(t, y) over any OdeState (integrators/state.hpp):
// fixed-step classical RK4 (as 002 uses it) and adaptive Dormand–Prince 5(4).
// Hand-written rather than Boost.Odeint so that every call reports evaluations, an error
// estimate and a Status the same way as the quadrature methods, and so that callers get
// single exact steps (`DormandPrince45::step`) for event location (the space-curve cone).
#include <algorithm>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/integrators/state.hpp"

namespace lac {

template <class S>
struct OdeResult {
  S state{};                    ///< y(t_end)
  double t_end = 0;             ///< where integration stopped (t1, or earlier if the observer stopped it)
  double error_estimate = 0;    ///< sum of local error estimates (adaptive) or Richardson estimate (RK4)
  long evaluations = 0;         ///< calls of f
  long steps = 0;               ///< accepted steps
  Status status = Status::ok;
  bool stopped_by_observer = false;
};

/// One classical RK4 step: 4 evaluations of f.
template <OdeState S, class F>
S rk4_step(F& f, double t, const S& y, double h) {
  const S k1 = f(t, y);
  const S k2 = f(t + 0.5 * h, y + (0.5 * h) * k1);
  const S k3 = f(t + 0.5 * h, y + (0.5 * h) * k2);
  const S k4 = f(t + h, y + h * k3);
  return y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// Fixed-step RK4 from t0 to t1 with n = ceil(|t1 - t0| / h) equal steps. The observer
/// `bool(double t, const S& y)` sees every step end; returning false stops early.
/// Error estimate: none is computed here (0) — callers wanting one compare with step 2h.
template <OdeState S, class F, class Observer>
OdeResult<S> rk4_integrate(F&& f, S y, double t0, double t1, double h, Observer&& observer) {
  if (!(h > 0) || !std::isfinite(h)) throw_input_error("rk4_integrate", "h", h, "(0, inf)");
  const double span = t1 - t0;
  const double n_real = std::ceil(std::abs(span) / h);
  constexpr long kMaxSteps = 100'000'000;
  if (!(n_real <= kMaxSteps)) throw_input_error("rk4_integrate", "h", h, "large enough for at most 1e8 steps");
  const long n = std::max(1L, static_cast<long>(n_real));
  const double step = span / static_cast<double>(n);
  OdeResult<S> r;
  for (long j = 0; j < n; ++j) {
    const double t = t0 + static_cast<double>(j) * step;
    y = rk4_step(f, t, y, step);
    r.evaluations += 4;
    ++r.steps;
    const double t_next = (j + 1 == n) ? t1 : t0 + static_cast<double>(j + 1) * step;
    if (!observer(t_next, y)) {
      r.stopped_by_observer = true;
      r.t_end = t_next;
      r.state = y;
      return r;
    }
  }
  r.t_end = t1;
  r.state = y;
  return r;
}

struct AdaptiveOptions {
  double rtol = 1e-10;          ///< relative tolerance per step
  double atol = 1e-12;          ///< absolute tolerance per step
  double initial_step = 0;      ///< 0: chosen from the first derivative
  double max_step = 0;          ///< 0: unlimited (|t1 - t0|)
  long max_steps = 1'000'000;   ///< cap on attempted steps (status max_iterations when hit)
  void validate(const char* who) const {
    if (!(rtol >= 0) || !(atol >= 0) || !(rtol + atol > 0) || !std::isfinite(rtol) || !std::isfinite(atol))
      throw_input_error(who, "tol", rtol, "rtol >= 0, atol >= 0, not both 0, finite");
    if (!(rtol == 0 || rtol >= 1e-15))
      throw_input_error(who, "rtol", rtol, "0 or [1e-15, inf): tighter than double precision cannot be met");
    if (!(initial_step >= 0) || !(max_step >= 0)) throw_input_error(who, "step", initial_step, "[0, inf)");
    if (max_steps < 1) throw_input_error(who, "max_steps", static_cast<double>(max_steps), "[1, inf)");
  }
};

/// Dormand–Prince 5(4) with FSAL (6 new evaluations per step), local extrapolation
/// (the 5th-order solution is propagated) and the standard PI-free step controller.
template <OdeState S>
class DormandPrince45 {
 public:
  struct Step {
    S y;        ///< 5th-order solution at t + h
    S f_end;    ///< f(t + h, y), reused as the next step's first stage
    S error;    ///< y5 - y4
  };

  /// One step of size h from (t, y) with f0 = f(t, y) known. 6 evaluations.
  template <class F>
  static Step step(F& f, double t, const S& y, const S& f0, double h) {
    const S k1 = f0;
    const S k2 = f(t + h / 5.0, y + h * ((1.0 / 5.0) * k1));
    const S k3 = f(t + 3.0 * h / 10.0, y + h * ((3.0 / 40.0) * k1 + (9.0 / 40.0) * k2));
    const S k4 = f(t + 4.0 * h / 5.0, y + h * ((44.0 / 45.0) * k1 + (-56.0 / 15.0) * k2 + (32.0 / 9.0) * k3));
    const S k5 = f(t + 8.0 * h / 9.0, y + h * ((19372.0 / 6561.0) * k1 + (-25360.0 / 2187.0) * k2 +
                                             (64448.0 / 6561.0) * k3 + (-212.0 / 729.0) * k4));
    const S k6 = f(t + h, y + h * ((9017.0 / 3168.0) * k1 + (-355.0 / 33.0) * k2 + (46732.0 / 5247.0) * k3 +
                                   (49.0 / 176.0) * k4 + (-5103.0 / 18656.0) * k5));
    const S y5 = y + h * ((35.0 / 384.0) * k1 + (500.0 / 1113.0) * k3 + (125.0 / 192.0) * k4 +
                          (-2187.0 / 6784.0) * k5 + (11.0 / 84.0) * k6);
    const S k7 = f(t + h, y5);
    const S err = h * ((71.0 / 57600.0) * k1 + (-71.0 / 16695.0) * k3 + (71.0 / 1920.0) * k4 +
                       (-17253.0 / 339200.0) * k5 + (22.0 / 525.0) * k6 + (-1.0 / 40.0) * k7);
    return {y5, k7, err};
  }

  /// Adaptive integration from t0 to t1 (either direction). The observer
  /// `bool(double t, const S& y)` sees every accepted step; returning false stops there.
  template <class F, class Observer>
  static OdeResult<S> integrate(F&& f, S y, double t0, double t1, const AdaptiveOptions& opt, Observer&& observer) {
    opt.validate("DormandPrince45");
    OdeResult<S> r;
    r.t_end = t0;
    const double span = t1 - t0;
    if (span == 0) {
      r.state = y;
      return r;
    }
    const double dir = span > 0 ? 1.0 : -1.0;
    const double max_step = opt.max_step > 0 ? opt.max_step : std::abs(span);
    S f0 = f(t0, y);
    r.evaluations = 1;
    double h = opt.initial_step;
    if (h <= 0) {  // Hairer's simple starting-step heuristic for order 5
      const double d0 = max_abs(y), d1 = max_abs(f0);
      const double tol = opt.atol + opt.rtol * d0;
      h = (d1 > 1e-300) ? 0.5 * std::pow(tol, 0.2) * std::max(d0, 1.0) / d1 : 1e-3 * std::abs(span);
      h = std::clamp(h, 1e-12 * std::abs(span), std::abs(span));
    }
    h = std::min(h, max_step);
    double t = t0;
    long attempts = 0;
    while (dir * (t1 - t) > 0) {
      if (++attempts > opt.max_steps) {
        r.status = Status::max_iterations;
        break;
      }
      const bool last = std::abs(t1 - t) <= h * (1 + 1e-12);
      const double hs = last ? (t1 - t) : dir * h;
      Step st = step(f, t, y, f0, hs);
      r.evaluations += 6;
      const double err = scaled_error(st.error, y, st.y, opt.atol, opt.rtol);
      if (!std::isfinite(err)) {
        if (std::abs(hs) < 1e-14 * std::abs(span)) {
          r.status = Status::numerical_failure;
          break;
        }
        h *= 0.1;
        continue;
      }
      if (err <= 1.0) {
        t = last ? t1 : t + hs;
        y = st.y;
        f0 = st.f_end;
        r.error_estimate += max_abs(st.error);
        ++r.steps;
        if (!observer(t, y)) {
          r.stopped_by_observer = true;
          break;
        }
      }
      const double factor = err == 0 ? 5.0 : std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
      h = std::min(std::abs(hs) * factor, max_step);
      if (h < 1e-15 * std::max(1.0, std::abs(t))) {
        r.status = Status::numerical_failure;
        break;
      }
    }
    r.t_end = t;
    r.state = y;
    return r;
  }
};

/// Observer that never stops integration.
struct NoObserver {
  template <class S>
  bool operator()(double, const S&) const noexcept {
    return true;
  }
};

}  // namespace lac
