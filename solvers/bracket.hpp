#pragma once
// The two 1-D building blocks the constructions share around solvers/root_1d.hpp:
//   search_bracket      probes outward from a start (or geometrically toward / away from a
//                       center) until f changes sign, giving a Bracket for the root registry;
//   safeguarded_newton  Newton with f and f' evaluated together, kept inside a sign bracket
//                       (bisection when a step leaves it), with tolerances in x and f and a cap.
// A probe or iterate whose f is not finite (NaN, ±inf) is a failed evaluation: no curve, no
// value there. Both are templates so that a caller's f inlines (the G1 Hermite fast path).
//
// Usage:
//   auto f = [](double x) { return std::exp(x) - 10; };
//   lac::BracketSearchOptions bo;  // both sides of x0, steps 1, 2, 3, ...
//   lac::BracketSearchResult s = lac::search_bracket(f, 0.0, bo);        // s.bracket = [2, 3]
//   auto fd = [](double x) { return lac::Newton1dSample{std::exp(x) - 10, std::exp(x)}; };
//   lac::Newton1dOptions no;
//   no.f_atol = 1e-14;
//   no.bracket = s.bracket;
//   lac::Newton1dResult r = lac::safeguarded_newton(fd, 2.5, no);         // r.x ≈ log 10
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac {

/// Which sides of x0 the outward probes visit.
enum class BracketSides { both, up, down };

struct BracketSearchOptions {
  /// Probe positions. Outward (no center): x0 ± d_k, d_1 = step and d_{k+1} = d_k + step
  /// (growth = 1, arithmetic) or d_k·growth (growth > 1); with `both` each k probes x0 + d_k
  /// then x0 − d_k (nearest first). Scaled (center set): center + (x0 − center)·q_k with
  /// q_1 = step, q_{k+1} = q_k·growth: a geometric sequence toward the center (growth < 1) or
  /// away from it (growth > 1), on x0's side only (`sides` ignored).
  double step = 1;
  double growth = 1;
  BracketSides sides = BracketSides::both;
  std::optional<double> center;
  /// Open limits: a probe outside (xmin, xmax) is not evaluated and ends its side.
  double xmin = -std::numeric_limits<double>::infinity();
  double xmax = std::numeric_limits<double>::infinity();
  /// Cap on evaluations of f, f(x0) included when it is evaluated here.
  int max_probes = 100;
  /// A failed probe (f not finite) is skipped (false) or ends the search (true).
  bool stop_at_failure = false;
  /// Each probe is compared with f(x0) and the bracket is [x0, probe] (true), or with the
  /// previous finite value on its side and the bracket is the nearest pair (false).
  bool from_start = false;

  /// InputError naming the option and its valid range.
  void validate() const {
    if (!(step > 0) || !std::isfinite(step)) throw_input_error("search_bracket", "step", step, "(0, inf)");
    if (!center && !(growth >= 1 && std::isfinite(growth)))
      throw_input_error("search_bracket", "growth", growth, "[1, inf) for outward steps");
    if (center && !(growth > 0 && growth != 1 && std::isfinite(growth)))
      throw_input_error("search_bracket", "growth", growth, "(0, 1) or (1, inf) about a center");
    if (center && !std::isfinite(*center)) throw_input_error("search_bracket", "center", *center, "finite");
    if (std::isnan(xmin) || std::isnan(xmax) || !(xmin < xmax))
      throw_input_error("search_bracket", "xmin", xmin, "below xmax");
    if (max_probes < 1 || max_probes > 10'000'000)
      throw_input_error("search_bracket", "max_probes", max_probes, "[1, 1e7]");
  }
};

struct BracketSearchResult {
  /// A sign change found: bracket.lo < bracket.hi with f_lo, f_hi of opposite signs, or one of
  /// them exactly 0 (a probe hit a root); lo == hi == x0 when f(x0) is exactly 0.
  bool found = false;
  Bracket bracket;
  int probes = 0;                  ///< evaluations of f
  bool stopped_at_failure = false;  ///< stop_at_failure and the last probe failed
  /// The last probe and its value (not finite when it failed); x0 and f(x0) when none.
  double last_x = std::numeric_limits<double>::quiet_NaN();
  double last_f = std::numeric_limits<double>::quiet_NaN();
  /// The last finite probe before it on its side and its value (x0, f(x0) when none).
  double previous_x = std::numeric_limits<double>::quiet_NaN();
  double previous_f = std::numeric_limits<double>::quiet_NaN();
};

/// Any probe may end a bracket (the default of search_bracket's `closes`).
struct AnyProbeCloses {
  bool operator()(double) const { return true; }
};

/// Looks for a sign change of f from x0 (f0: f(x0) when known, not evaluated again). A sign
/// change is a probe with f = 0 or with (f > 0) ≠ (f_ref > 0), f_ref the comparison value of
/// BracketSearchOptions::from_start, where closes(probe) holds (called right after f at that
/// probe); a finite probe that may not close a bracket still becomes its side's comparison point.
/// Ends at the first sign change, at max_probes, at a failed probe with stop_at_failure, or when
/// every side has left (xmin, xmax). A non-finite f(x0) is replaced on each side by its first
/// finite probe.
template <class F, class Closes = AnyProbeCloses>
BracketSearchResult search_bracket(F&& f, double x0, const BracketSearchOptions& o, std::optional<double> f0 = {},
                                   Closes&& closes = {}) {
  o.validate();
  if (!std::isfinite(x0)) throw_input_error("search_bracket", "x0", x0, "finite");
  BracketSearchResult r;
  double fx0 = 0;
  if (f0) {
    fx0 = *f0;
  } else {
    fx0 = f(x0);
    ++r.probes;
  }
  r.last_x = r.previous_x = x0;
  r.last_f = r.previous_f = fx0;
  if (fx0 == 0) {
    r.found = true;
    r.bracket = {x0, x0, 0.0, 0.0};
    return r;
  }
  // The comparison point of each side: [0] up (x > x0), [1] down.
  double side_x[2] = {x0, x0}, side_f[2] = {fx0, fx0};
  bool open[2] = {o.center || o.sides != BracketSides::down, !o.center && o.sides != BracketSides::up};
  const auto probe = [&](int s, double x) {  // true when the search ends
    if (!(x > o.xmin && x < o.xmax)) {
      open[s] = false;
      return false;
    }
    const double v = f(x);
    ++r.probes;
    r.last_x = x;
    r.last_f = v;
    r.previous_x = side_x[s];
    r.previous_f = side_f[s];
    if (!std::isfinite(v)) {
      if (o.stop_at_failure) {
        r.stopped_at_failure = true;
        return true;
      }
      return false;
    }
    const double ref_x = o.from_start ? x0 : side_x[s], ref_f = o.from_start ? fx0 : side_f[s];
    if (std::isfinite(ref_f) && (v == 0 || (v > 0) != (ref_f > 0)) && closes(x)) {
      r.found = true;
      r.bracket = ref_x < x ? Bracket{ref_x, x, ref_f, v} : Bracket{x, ref_x, v, ref_f};
      return true;
    }
    side_x[s] = x;
    side_f[s] = v;
    return false;
  };
  double d = o.step;
  for (int k = 1; (open[0] || open[1]) && r.probes < o.max_probes; ++k) {
    if (o.center) {
      if (probe(0, *o.center + (x0 - *o.center) * d)) return r;
    } else {
      if (open[0] && probe(0, x0 + d)) return r;
      if (open[1] && r.probes < o.max_probes && probe(1, x0 - d)) return r;
    }
    d = o.growth == 1 && !o.center ? (k + 1) * o.step : d * o.growth;
  }
  return r;
}

/// f and f' at one point. f not finite: a failed evaluation. acceptable = false keeps the
/// iteration going even where |f| ≤ f_atol (e.g. a root that is no curve).
struct Newton1dSample {
  double f = std::numeric_limits<double>::quiet_NaN();
  double df = std::numeric_limits<double>::quiet_NaN();
  bool acceptable = true;
};

struct Newton1dOptions {
  /// Converged when |f| ≤ f_atol at an acceptable point, or when a step from x is at most
  /// x_atol + x_rtol·|x| > 0 (the result is then the new point, not evaluated); with
  /// x_atol = x_rtol = 0 only f decides (a zero step is a stall).
  double f_atol = 0;
  double x_rtol = 0;
  double x_atol = 0;
  int max_iterations = 50;  ///< cap on iterations, one evaluation each
  /// Open domain: a step past a limit goes halfway from x to that limit.
  double xmin = -std::numeric_limits<double>::infinity();
  double xmax = std::numeric_limits<double>::infinity();
  /// A sign bracket known in advance; otherwise the first two iterates of opposite signs form one
  /// when form_bracket (off for an f with poles, where a sign change need not enclose a root).
  std::optional<Bracket> bracket;
  bool form_bracket = true;
  /// A failed evaluation backs off halfway to the previous iterate (false) or ends the
  /// iteration, not_converged (true).
  bool stop_at_failure = false;
  /// Inside a bracket, bisection also when a step is longer than half the step before last
  /// (Numerical Recipes' rtsafe test): the step rule is not converging.
  bool bisect_slow_steps = true;

  void validate() const {
    if (!(f_atol >= 0) || !std::isfinite(f_atol)) throw_input_error("safeguarded_newton", "f_atol", f_atol, "[0, inf)");
    if (!(x_rtol >= 0) || !std::isfinite(x_rtol)) throw_input_error("safeguarded_newton", "x_rtol", x_rtol, "[0, inf)");
    if (!(x_atol >= 0) || !std::isfinite(x_atol)) throw_input_error("safeguarded_newton", "x_atol", x_atol, "[0, inf)");
    if (max_iterations < 1 || max_iterations > 100000)
      throw_input_error("safeguarded_newton", "max_iterations", max_iterations, "[1, 100000]");
    if (std::isnan(xmin) || std::isnan(xmax) || !(xmin < xmax))
      throw_input_error("safeguarded_newton", "xmin", xmin, "below xmax");
  }
};

struct Newton1dResult {
  /// ok (converged), max_iterations (the cap), not_converged (stalled: no usable step, or a
  /// failed evaluation with stop_at_failure or nowhere to back off). x, f: the acceptable evaluated point with the
  /// smallest |f| (the step-converged point when converged by step); NaN when none.
  Status status = Status::not_converged;
  double x = std::numeric_limits<double>::quiet_NaN();
  double f = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  long evaluations = 0;
  bool bracketed = false;  ///< a sign bracket was known at the end
  double lo = 0, hi = 0;   ///< that bracket (lo < hi when bracketed)
};

/// The plain Newton step x − f/f' (the default step rule).
struct Newton1dStep {
  double operator()(double x, const Newton1dSample& s, bool /*bracketed*/) const { return x - s.f / s.df; }
};

/// Newton from x0 on fd(x) → Newton1dSample, each iteration one evaluation:
///   failed evaluation → back off halfway to the previous iterate (the bracket's midpoint when
///     bracketed); no back-off possible → not_converged;
///   |f| ≤ f_atol at an acceptable point → ok;
///   otherwise next = step(x, sample, bracketed) (default x − f/f'), halfway
///   to a domain limit it crosses, and the bracket's midpoint when bracketed and the step
///   leaves the open bracket (or is slow, bisect_slow_steps); not finite → the bracket's
///   midpoint, or not_converged without a bracket; a step within the x tolerance → ok;
///   next == x otherwise → not_converged.
/// A custom step rule may return any proposal; the safeguards above still apply.
template <class FD, class Step = Newton1dStep>
Newton1dResult safeguarded_newton(FD&& fd, double x0, const Newton1dOptions& o, Step&& step = {}) {
  o.validate();
  Newton1dResult r;
  double lo = std::numeric_limits<double>::quiet_NaN(), hi = lo, f_lo = lo;  // lo: an end, not the lower
  if (o.bracket) {
    lo = o.bracket->lo, hi = o.bracket->hi, f_lo = o.bracket->f_lo;
  }
  const auto bracketed = [&] { return std::isfinite(lo); };
  const auto finish = [&](Status s) {
    r.status = s;
    r.bracketed = bracketed();
    if (r.bracketed) r.lo = std::min(lo, hi), r.hi = std::max(lo, hi);
    return r;
  };
  double x = x0, xp = std::numeric_limits<double>::quiet_NaN(), fp = xp;
  double step_one_ago = std::numeric_limits<double>::infinity(), step_two_ago = step_one_ago;
  double best_abs = std::numeric_limits<double>::infinity();
  for (int it = 0; it < o.max_iterations; ++it) {
    ++r.iterations;
    ++r.evaluations;
    const Newton1dSample s = fd(x);
    if (!std::isfinite(s.f)) {  // no value here: back off
      if (o.stop_at_failure) return finish(Status::not_converged);
      const double back = bracketed() ? 0.5 * (lo + hi) : 0.5 * (x + (std::isfinite(xp) ? xp : x0));
      if (back == x) return finish(Status::not_converged);
      x = back;
      continue;
    }
    if (s.acceptable && std::abs(s.f) < best_abs) best_abs = std::abs(s.f), r.x = x, r.f = s.f;
    if (std::abs(s.f) <= o.f_atol && s.acceptable) {
      r.x = x, r.f = s.f;
      return finish(Status::ok);
    }
    if (bracketed()) {
      if ((s.f > 0) == (f_lo > 0)) lo = x, f_lo = s.f;
      else hi = x;
    } else if (o.form_bracket && std::isfinite(fp) && (s.f > 0) != (fp > 0)) {
      lo = xp, f_lo = fp, hi = x;
    }
    xp = x;
    fp = s.f;
    double next = step(x, s, bracketed());
    if (!std::isfinite(next)) {
      if (!bracketed()) return finish(Status::not_converged);
      next = 0.5 * (lo + hi);
    }
    if (!(next > o.xmin && next < o.xmax)) next = 0.5 * (x + (next <= o.xmin ? o.xmin : o.xmax));
    if (bracketed()) {
      const bool slow = o.bisect_slow_steps && std::abs(next - x) > 0.5 * step_two_ago;
      if (slow || !(next > std::min(lo, hi) && next < std::max(lo, hi))) next = 0.5 * (lo + hi);
    }
    const double x_tol = o.x_atol + o.x_rtol * std::abs(x);
    if (x_tol > 0 && std::abs(next - x) <= x_tol) {
      r.x = next;
      r.f = next == x ? s.f : std::numeric_limits<double>::quiet_NaN();  // next not evaluated
      return finish(Status::ok);
    }
    if (next == x) return finish(Status::not_converged);
    step_two_ago = step_one_ago;
    step_one_ago = std::abs(next - x);
    x = next;
  }
  return finish(Status::max_iterations);
}

}  // namespace lac
