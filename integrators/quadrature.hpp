#pragma once
// Quadrature methods for integrands t -> V (V = double or std::complex<double>):
//   Rk4          classical RK4 with fixed step h applied to y' = f(t), as 002 uses it;
//   Rk45         adaptive Dormand–Prince 5(4) on y' = f(t);
//   GaussKronrod globally adaptive Gauss–Kronrod G10K21 (Boost.Math nodes and weights).
// Each satisfies QuadratureMethod and returns an IntegralResult with value, error
// estimate, evaluation count and status. `integrate_cumulative` gives the running
// integral at sample points (for polylines).
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <complex>
#include <concepts>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/integrators/ode.hpp"

namespace lac {

template <class V>
struct IntegralResult {
  V value{};
  double error_estimate = 0;  ///< estimate of |value - exact| (absolute)
  long evaluations = 0;       ///< integrand calls
  Status status = Status::ok;
  std::string message;        ///< empty when status is ok
};

template <class F>
concept Integrand = std::invocable<F&, double> && requires(F& f, double t) {
  { std::abs(f(t)) } -> std::convertible_to<double>;
};

template <class F>
using IntegrandValue = std::decay_t<std::invoke_result_t<F&, double>>;

/// An integrand whose values carry a known absolute noise (values computed by an inner solver
/// that is not polished): noise() bounds |f(t) − exact f(t)| over the nodes evaluated so far.
/// Adaptive rules stop refining once their error estimate is down to that noise over the
/// interval (refining cannot lower it) with status tolerance_not_met, instead of spending their
/// budget on it; the caller adds the noise to the estimate.
template <class F>
concept NoisyIntegrand = Integrand<F> && requires(const F& f) {
  { f.noise() } -> std::convertible_to<double>;
};

/// noise() of a NoisyIntegrand, 0 for any other.
template <class F>
double integrand_noise(const F& f) {
  if constexpr (NoisyIntegrand<std::remove_cvref_t<F>>) return f.noise();
  else return 0.0;
}

/// Wraps an integrand and counts its calls (callable as const, as Boost.Math requires).
template <class F>
struct CountingIntegrand {
  F* f;
  long* count;
  auto operator()(double t) const {
    ++*count;
    return (*f)(t);
  }
};

/// Classical RK4 with fixed step on y' = f(t). For an integrand that does not depend on y,
/// k2 = k3 = f(t + h/2) and k4 of one step is k1 of the next, so a step costs two new
/// evaluations (the result equals composite Simpson). The step is h adjusted down so that
/// an integer number n = ceil(|b - a| / h) of steps spans [a, b] (a span within 1e-9 relative of
/// a whole number of steps is not given an extra step). Error estimate: the step-doubling
/// difference |S_h - S_2h| from the same nodes (S_2h uses every other node), plus terms for
/// unresolved steps and rounding; see Rk4Sweep.
/// Budget: at most max_steps steps per call (per sweep for a polyline); a call that needs more
/// is not run and returns status max_iterations (5·10^6 steps = 10^7 evaluations; docs/robustness.md
/// gives its cost).
struct Rk4 {
  static constexpr std::string_view name = "rk4";
  double h = 1e-3;  ///< step in the integration variable (002 uses 0.1, 0.01, 0.001)
  long max_steps = 5'000'000;  ///< step budget per call or sweep (status max_iterations beyond it)

  void validate() const {
    if (!(h > 0) || !std::isfinite(h)) throw_input_error("rk4", "h", h, "(0, inf)");
    if (max_steps < 1) throw_input_error("rk4", "max_steps", static_cast<double>(max_steps), "[1, inf)");
  }

  template <Integrand F>
  IntegralResult<IntegrandValue<F>> integrate(F&& f, double a, double b) const;
};

/// RK4 (composite Simpson) over consecutive intervals [a0, a1], [a1, a2], … in one sweep: each
/// interval gets its own whole number of steps (as Rk4::integrate would), and the integrand value
/// at a shared end is computed once, so a polyline of N pieces of one step each costs 2N + 1
/// evaluations instead of 4N. The error estimate covers everything swept so far, as
/// Rk4::integrate over the whole range: consecutive steps are paired across interval ends, the
/// pair's coarse value is the 3-point interpolatory rule on its nodes (Simpson for equal widths;
/// a pair whose widths differ in sign or by more than ×2 is not formed), and
///   estimate = Σ |fine − coarse| · steps / paired + 4 ε ∫|f| √steps
/// (a step left unpaired at the end is paired again with the step before it, overlapping the last
/// pair, and adds that difference instead of the factor steps / paired: near a steep end the error
/// gathers in the last steps; step doubling without Richardson's factor 1/15: that factor holds
/// only in the asymptotic regime, and on la_reference.csv the error of h = 0.001 reaches
/// 2.4 × 2|Σ|/15 near a steep start, α = ±100, Λ = 100; the full difference bounds the error
/// whenever halving the step at least halves it. Per pair in absolute value: the pairs' differences of an oscillating
/// integrand cancel in a signed sum while their errors need not, α = 1.5, s-form near ρ → 0)
/// (∫|f| from the Simpson sums of |Re f| + |Im f|, an upper bound),
/// with |Simpson − trapezoid| instead of the Richardson term while only one step exists, plus a
/// term for pairs the steps do not resolve (unresolved_term: the Richardson factor is not a bound
/// there).
/// |v| for real v; |Re v| + |Im v| ≥ |v| for complex v (no hypot: only feeds a rounding bound).
template <class V>
double magnitude_bound(const V& v) {
  if constexpr (std::is_arithmetic_v<V>) {
    return std::abs(v);
  } else {
    return std::abs(v.real()) + std::abs(v.imag());
  }
}

template <class V>
class Rk4Sweep {
 public:
  explicit Rk4Sweep(const Rk4& m) : h_(m.h), max_steps_(m.max_steps) { m.validate(); }

  /// Declares that intervals spanning `total_span` in all will follow: when they need more steps
  /// than the budget has left, the sweep stops now (status max_iterations) instead of after
  /// spending the whole budget. Returns whether the sweep can go on.
  bool reserve(double total_span) {
    const double n_real = std::ceil(std::abs(total_span) / h_ * (1 - 1e-9));
    if (status_ == Status::ok && !(n_real <= static_cast<double>(max_steps_ - steps_))) exhaust(n_real);
    return status_ == Status::ok;
  }

  /// ∫_a^b f; `a` must be the previous call's `b` (its integrand value is reused). After the step
  /// budget is exhausted (status() == max_iterations) returns 0 without evaluating f.
  template <class F>
  V advance(F& f, double a, double b) {
    const double span = b - a;
    if (span == 0 || status_ != Status::ok) return V{};
    const double n_real = std::ceil(std::abs(span) / h_ * (1 - 1e-9));
    if (!(n_real <= static_cast<double>(max_steps_ - steps_))) {
      exhaust(n_real);
      return V{};
    }
    const long n = std::max(1L, static_cast<long>(n_real));
    const double step = span / static_cast<double>(n);
    if (!have_left_) {
      f_left_ = f(a);
      abs_left_ = magnitude_bound(f_left_);
      ++evaluations_;
      have_left_ = true;
    }
    V piece{};
    for (long j = 0; j < n; ++j) {
      const double t = a + static_cast<double>(j) * step;
      const double t_next = (j + 1 == n) ? b : a + static_cast<double>(j + 1) * step;
      const V f_mid = f(t + 0.5 * step);
      const V f_right = f(t_next);
      const V simpson = (step / 6.0) * (f_left_ + 4.0 * f_mid + f_right);
      piece += simpson;
      const double abs_right = magnitude_bound(f_right);
      l1_ += std::abs(step) / 6.0 * (abs_left_ + 4.0 * magnitude_bound(f_mid) + abs_right);
      abs_left_ = abs_right;
      if (steps_ + j == 0) single_ = std::abs(simpson - (step / 2.0) * (f_left_ + f_right));
      pair(step, simpson, f_right);
      f_left_ = f_right;
    }
    evaluations_ += 2 * n;
    steps_ += n;
    return piece;
  }

  double error_estimate() const {
    const double rounding =
        4.0 * std::numeric_limits<double>::epsilon() * l1_ * std::sqrt(static_cast<double>(steps_));
    // The step left unpaired at the end, when the integrand changes by more than a quarter across it.
    double pending = 0;
    if (have_pending_) {
      const double spread = magnitude_bound(f_left_ - f_pair_left_);
      const double size = std::max({size_, magnitude_bound(f_left_), magnitude_bound(f_pair_left_)});
      if (spread > 0.25 * size) pending = std::abs(pending_w_) * spread;
    }
    if (paired_ == 0) return (steps_ > 0 ? single_ : 0.0) + unresolved_ + pending + rounding;
    // The step left unpaired at the end paired again with the step before it (overlapping the last
    // pair): its own difference, not the average of the others, where the error gathers at a steep
    // end (κ → ∞ just past the end of a quadratic curve's range).
    if (have_pending_ && have_last_) {
      const double ratio = pending_w_ / last_w_;
      if (ratio >= 0.5 && ratio <= 2.0)
        return abs_diff_ + std::abs(last_simpson_ + pending_simpson_ -
                                    three_point(last_w_, pending_w_, last_left_, f_pair_left_, f_left_)) +
               unresolved_ + pending + rounding;
    }
    return abs_diff_ * static_cast<double>(steps_) / static_cast<double>(paired_) + unresolved_ + pending + rounding;
  }
  long evaluations() const { return evaluations_; }
  long steps() const { return steps_; }
  Status status() const { return status_; }
  const std::string& message() const { return message_; }

 private:
  void exhaust(double more_steps) {
    status_ = Status::max_iterations;
    message_ = "rk4: step budget max_steps = " + std::to_string(max_steps_) + " exceeded (" +
               format_number(static_cast<double>(steps_) + more_steps) + " steps of h = " + format_number(h_) +
               " needed); raise Rk4::max_steps or h";
  }

  /// Richardson's |S_h − S_2h| / 15 assumes the asymptotic regime, where the integrand is resolved
  /// by the steps. Where it changes by more than a quarter of its size across a pair of steps (a
  /// steep end, ρ ~ (θmax − θ)^(1/(α−1)) near an open end; fast turning in the s-form) the true error
  /// can exceed it many times. Such a pair adds |width| · (largest difference of its node values):
  /// both the exact integral and Simpson's positive-weight sum lie within that of width · f(node)
  /// when f's components are monotone over the pair.
  /// "Its size": the largest |f| met so far in the sweep (not the pair's own, which is small where a
  /// real integrand crosses zero).
  /// A pair counts as unresolved only when its step-doubling difference d is also not negligible
  /// against width · spread (|d| > 1e-3 |width| spread; a resolved pair has |d| ~ width^5 f'''').
  double unresolved_term(double width, const V& f0, const V& f1, const V& f2, double d) {
    const double spread = std::max({magnitude_bound(f1 - f0), magnitude_bound(f2 - f1), magnitude_bound(f2 - f0)});
    size_ = std::max({size_, magnitude_bound(f0), magnitude_bound(f1), magnitude_bound(f2)});
    return spread > 0.25 * size_ && d > 1e-3 * std::abs(width) * spread ? std::abs(width) * spread : 0.0;
  }

  void add_difference(const V& d) { abs_diff_ += std::abs(d); }

  /// The 3-point interpolatory rule on nodes a, a + w1, a + w1 + w (exact for quadratics;
  /// Simpson with step 2w for w1 = w).
  static V three_point(double w1, double w, const V& f0, const V& f1, const V& f2) {
    if (w1 == w) return (w / 3.0) * (f0 + 4.0 * f1 + f2);
    const double sum = w1 + w;
    return (sum / 6.0) * ((2.0 - w / w1) * f0 + (sum * sum / (w1 * w)) * f1 + (2.0 - w1 / w) * f2);
  }

  void pair(double w, const V& simpson, const V& f_right) {
    const double ratio = have_pending_ ? w / pending_w_ : 0.0;
    if (have_pending_ && ratio >= 0.5 && ratio <= 2.0) {
      const V d = pending_simpson_ + simpson - three_point(pending_w_, w, f_pair_left_, f_left_, f_right);
      unresolved_ += unresolved_term(pending_w_ + w, f_pair_left_, f_left_, f_right, std::abs(d));
      add_difference(d);
      paired_ += 2;
      have_pending_ = false;
      have_last_ = true;
      last_w_ = w;
      last_simpson_ = simpson;
      last_left_ = f_left_;
    } else {
      if (have_pending_)  // left unpaired: no difference of its own, judged by its spread alone
        unresolved_ += unresolved_term(pending_w_, f_pair_left_, f_left_, f_left_, std::numeric_limits<double>::infinity());
      have_pending_ = true;
      pending_w_ = w;
      pending_simpson_ = simpson;
      f_pair_left_ = f_left_;
    }
  }

  double h_;
  long max_steps_;
  bool have_left_ = false, have_pending_ = false, have_last_ = false;  // last_: the latest paired step
  V f_left_{}, f_pair_left_{}, pending_simpson_{}, last_simpson_{}, last_left_{};
  double pending_w_ = 0, last_w_ = 0, l1_ = 0, single_ = 0, abs_left_ = 0, unresolved_ = 0, abs_diff_ = 0, size_ = 0;
  long evaluations_ = 0, steps_ = 0, paired_ = 0;
  Status status_ = Status::ok;
  std::string message_;
};

template <Integrand F>
IntegralResult<IntegrandValue<F>> Rk4::integrate(F&& f, double a, double b) const {
  using V = IntegrandValue<F>;
  Rk4Sweep<V> sweep(*this);
  IntegralResult<V> r;
  r.value = sweep.advance(f, a, b);
  r.evaluations = sweep.evaluations();
  r.status = sweep.status();
  r.message = sweep.message();
  r.error_estimate = r.status == Status::ok ? sweep.error_estimate() : std::numeric_limits<double>::infinity();
  if (r.status == Status::ok && !std::isfinite(std::abs(r.value))) {
    r.status = Status::numerical_failure;
    r.message = "rk4: non-finite integrand value";
  }
  return r;
}

/// Adaptive Dormand–Prince 5(4) applied to y' = f(t) (the stages of DormandPrince45::step).
/// Step control for a quadrature: a step of size h is accepted when its local error estimate
/// is at most tol·|h|·max|f| over its stages, so the global error stays below about
/// tol·∫|f| whatever the size of the interval or of the integral. 6 evaluations per step.
/// Budget: max_steps attempted steps per call (10^5 = 6·10^5 evaluations, tens of ms; status
/// max_iterations with the value so far when it is reached).
struct Rk45 {
  static constexpr std::string_view name = "rk45";
  double tol = 1e-12;
  long max_steps = 100'000;  ///< attempted-step budget per call

  void validate() const {
    if (!(tol >= 1e-15) || !std::isfinite(tol)) throw_input_error("rk45", "tol", tol, "[1e-15, inf)");
    if (max_steps < 1) throw_input_error("rk45", "max_steps", static_cast<double>(max_steps), "[1, inf)");
  }

  template <Integrand F>
  IntegralResult<IntegrandValue<F>> integrate(F&& f, double a, double b) const {
    using V = IntegrandValue<F>;
    validate();
    IntegralResult<V> r;
    if (a == b) return r;
    auto rhs = [&f](double t, const V&) -> V { return f(t); };
    const double span = b - a, dir = span > 0 ? 1.0 : -1.0;
    V f0 = f(a);
    r.evaluations = 1;
    double h = std::abs(span) * 0.05, t = a;
    long steps = 0;
    while (dir * (b - t) > 0) {
      if (++steps > max_steps) {
        r.status = Status::max_iterations;
        r.message = "rk45: step budget max_steps = " + std::to_string(max_steps) + " exhausted at t = " +
                    format_number(t) + " of [" + format_number(a) + ", " + format_number(b) + "]; raise Rk45::max_steps";
        break;
      }
      const bool last = std::abs(b - t) <= h * (1 + 1e-12);
      const double hs = last ? b - t : dir * h;
      auto st = DormandPrince45<V>::step(rhs, t, r.value, f0, hs);
      r.evaluations += 6;
      const double local = std::abs(hs) * std::max(std::abs(f0), std::abs(st.f_end)) + std::abs(st.y - r.value);
      const double err = std::abs(st.error) / (tol * local + 1e-300);
      if (!std::isfinite(err)) {
        r.status = Status::numerical_failure;
        r.message = "rk45: non-finite integrand value near t = " + format_number(t);
        break;
      }
      if (err <= 1.0) {
        t = last ? b : t + hs;
        r.value = st.y;
        f0 = st.f_end;
        r.error_estimate += std::abs(st.error);
      }
      h = std::abs(hs) * (err == 0 ? 5.0 : std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0));
      if (h < 1e-15 * std::max(1.0, std::abs(t))) {
        r.status = Status::numerical_failure;
        r.message = "rk45: step size underflow near t = " + format_number(t);
        break;
      }
    }
    return r;
  }
};

/// Globally adaptive Gauss–Kronrod (21-point Kronrod, 10-point Gauss; nodes and weights from
/// Boost.Math). The interval with the largest error estimate |K − G| is bisected until the sum
/// of estimates is at most tol·|integral|, or at the rounding floor 50·ε·∫|f|. Caps (status
/// tolerance_not_met when they stop it): max_intervals pieces, and no piece split more than
/// max_depth times (Boost's meaning of max_depth). The driver is ours because Boost 1.74's
/// recursive driver reports each piece's error unscaled by the piece's half-width, so short
/// intervals never converge (θ = 1e-3 took 1.4 million evaluations at tol 1e-14).
/// The reported estimate adds the rounding term 2·ε·∫|f|.
struct GaussKronrod {
  static constexpr std::string_view name = "gauss-kronrod";
  double tol = 1e-14;
  long max_intervals = 20'000;  ///< interval budget per call (≤ 8.4·10^5 evaluations, status tolerance_not_met)
  unsigned max_depth = 40;

  void validate() const {
    if (!(tol >= 1e-16) || !std::isfinite(tol)) throw_input_error("gauss-kronrod", "tol", tol, "[1e-16, inf)");
    if (max_depth < 1 || max_depth > 60) throw_input_error("gauss-kronrod", "max_depth", max_depth, "[1, 60]");
    if (max_intervals < 1 || max_intervals > 10'000'000)
      throw_input_error("gauss-kronrod", "max_intervals", static_cast<double>(max_intervals), "[1, 1e7]");
  }

  template <Integrand F>
  IntegralResult<IntegrandValue<F>> integrate(F&& f, double a, double b) const {
    using V = IntegrandValue<F>;
    validate();
    IntegralResult<V> r;
    if (a == b) return r;
    struct Piece {
      double a, b;
      V value;
      double error, l1;
      unsigned depth;
    };
    auto rule = [&](double lo, double hi, unsigned depth) {
      using Kronrod = boost::math::quadrature::gauss_kronrod<double, 21>;
      using Gauss = boost::math::quadrature::gauss<double, 10>;
      const auto& x = Kronrod::abscissa();
      const auto& wk = Kronrod::weights();
      const auto& wg = Gauss::weights();
      const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
      const V f0 = f(mid);
      V k = wk[0] * f0, g{};
      double l1 = wk[0] * std::abs(f0);
      for (size_t i = 1; i < x.size(); ++i) {  // odd i: Gauss nodes (10-point rule has no centre)
        const V fp = f(mid + half * x[i]), fm = f(mid - half * x[i]);
        k += wk[i] * (fp + fm);
        l1 += wk[i] * (std::abs(fp) + std::abs(fm));
        if (i % 2 == 1) g += wg[i / 2] * (fp + fm);
      }
      r.evaluations += static_cast<long>(2 * x.size() - 1);
      return Piece{lo, hi, half * k, std::abs(half * (k - g)), std::abs(half) * l1, depth};
    };
    auto by_error = [](const Piece& p, const Piece& q) { return p.error < q.error; };
    std::vector<Piece> heap{rule(a, b, 0)}, frozen;  // frozen: at max_depth or unsplittable
    V total = heap[0].value;
    double error = heap[0].error, l1 = heap[0].l1;
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    constexpr size_t kResumAll = 512;
    int splits_since_resum = 0;
    // Floor: rounding (50 ε times ∫|f|), or the integrand's noise (NoisyIntegrand), which the
    // difference of the two rules sees on every piece: 4 × noise × |b − a| (twice the noise per rule).
    auto floor = [&] { return std::max(50 * kEps * l1, 4.0 * integrand_noise(f) * std::abs(b - a)); };
    while (error > tol * std::abs(total) && error > floor() && std::isfinite(error) && !heap.empty()) {
      if (static_cast<long>(heap.size() + frozen.size()) >= max_intervals) {
        r.status = Status::tolerance_not_met;
        r.message = "gauss-kronrod: interval budget max_intervals = " + std::to_string(max_intervals) +
                    " exhausted with error estimate " + format_number(error) + " above tolerance; raise "
                    "GaussKronrod::max_intervals";
        break;
      }
      std::pop_heap(heap.begin(), heap.end(), by_error);
      const Piece worst = heap.back();
      heap.pop_back();
      const double m = 0.5 * (worst.a + worst.b);
      if (worst.depth >= max_depth || m == worst.a || m == worst.b) {
        frozen.push_back(worst);
        continue;
      }
      const Piece left = rule(worst.a, m, worst.depth + 1), right = rule(m, worst.b, worst.depth + 1);
      total += left.value + right.value - worst.value;
      l1 += left.l1 + right.l1 - worst.l1;
      for (const Piece& p : {left, right}) {
        heap.push_back(p);
        std::push_heap(heap.begin(), heap.end(), by_error);
      }
      // Exact re-sum (no drift from repeated subtraction) while it is cheap; beyond kResumAll pieces
      // (the re-sum made long runs quadratic) update in place and re-sum every 64 splits and
      // whenever the updated sum says converged, so stopping is always decided on an exact sum.
      error += left.error + right.error - worst.error;
      const bool converged = !(error > tol * std::abs(total) && error > floor());
      if (heap.size() + frozen.size() <= kResumAll || ++splits_since_resum >= 64 || converged) {
        splits_since_resum = 0;
        error = 0;
        for (const Piece& p : heap) error += p.error;
        for (const Piece& p : frozen) error += p.error;
      }
    }
    error = 0;  // exact sum for the report (the loop may stop on an updated one at the budget)
    for (const Piece& p : heap) error += p.error;
    for (const Piece& p : frozen) error += p.error;
    if (r.status == Status::ok && error > tol * std::abs(total) && error > 50 * kEps * l1) {
      r.status = Status::tolerance_not_met;
      r.message = error > floor() ? "gauss-kronrod: error estimate " + format_number(error) +
                                        " above tolerance at max_depth " + std::to_string(max_depth)
                                  : "gauss-kronrod: error estimate " + format_number(error) +
                                        " above tolerance, at the integrand's noise " +
                                        format_number(integrand_noise(f)) + " (refining cannot lower it)";
    }
    r.value = total;
    r.error_estimate = error + 2.0 * kEps * l1;
    if (!std::isfinite(std::abs(r.value)) || !std::isfinite(r.error_estimate)) {
      r.status = Status::numerical_failure;
      r.message = "gauss-kronrod: non-finite integrand value or error estimate";
    }
    return r;
  }
};

template <class M>
concept QuadratureMethod = requires(const M& m, double (*f)(double)) {
  { m.integrate(f, 0.0, 1.0) } -> std::same_as<IntegralResult<double>>;
  { m.validate() };
  { M::name } -> std::convertible_to<std::string_view>;
};

/// A closed-form position method of the planar LA curve in standard form (α, Λ): C(θ1) − C(θ0),
/// e.g. Igf.
template <class M>
concept LaClosedForm = requires(const M& m, double alpha, double lambda) {
  { m.integrate_theta(alpha, lambda, 0.0, 1.0) } -> std::same_as<IntegralResult<std::complex<double>>>;
  { m.validate() };
  { M::name } -> std::convertible_to<std::string_view>;
};

/// Running integral ∫_{ts[0]}^{ts[k]} f for every k, piece by piece; counts and error
/// estimates accumulate. ts must be monotonic (either direction). Rk4 runs as one Rk4Sweep
/// (shared end values; the estimate is the sweep's, not a sum of per-piece estimates).
template <QuadratureMethod M, Integrand F>
std::vector<IntegralResult<IntegrandValue<F>>> integrate_cumulative(const M& method, F&& f, std::span<const double> ts) {
  using V = IntegrandValue<F>;
  std::vector<IntegralResult<V>> out(ts.size());
  if constexpr (std::same_as<M, Rk4>) {
    Rk4Sweep<V> sweep(method);
    for (size_t k = 1; k < ts.size(); ++k) {
      const long before = sweep.evaluations();
      out[k].value = out[k - 1].value + sweep.advance(f, ts[k - 1], ts[k]);
      out[k].evaluations = sweep.evaluations() - before;  // per piece, as below
      out[k].status = sweep.status();
      out[k].message = sweep.message();
      out[k].error_estimate =
          sweep.status() == Status::ok ? sweep.error_estimate() : std::numeric_limits<double>::infinity();
    }
    return out;
  }
  for (size_t k = 1; k < ts.size(); ++k) {
    IntegralResult<V> piece = method.integrate(f, ts[k - 1], ts[k]);
    out[k] = out[k - 1];
    out[k].value += piece.value;
    out[k].error_estimate += piece.error_estimate;
    out[k].evaluations = piece.evaluations;  // per piece; callers sum if they need totals
    if (piece.status != Status::ok) {
      out[k].status = piece.status;
      out[k].message = piece.message;
    }
  }
  return out;
}

static_assert(QuadratureMethod<Rk4>);
static_assert(QuadratureMethod<Rk45>);
static_assert(QuadratureMethod<GaussKronrod>);

}  // namespace lac
