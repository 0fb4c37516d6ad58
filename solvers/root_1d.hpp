#pragma once
// One-dimensional root finding on a bracket [lo, hi] with f(lo)·f(hi) < 0, one registry
// (root_methods(): name, aliases, description, options), selectable by name:
//   bisection  halves the bracket (the method 001 uses for its similar-triangle search);
//   secant     secant steps safeguarded by the bracket (bisection when a step leaves it or the
//              bracket stops shrinking); alias "newton" (Newton with a secant derivative);
//   toms748    Boost.Math tools::toms748_solve (Alefeld–Potra–Shi, cubic interpolation);
//   ceres      Ceres Solver (Levenberg–Marquardt) on the residual f(x), bounded by the bracket.
// Every method is capped by RootOptions::max_iterations and reports the x with the smallest
// |f| it evaluated, the residual there, iterations, evaluations and a Status: ok, max_iterations
// (the cap), numerical_failure (a non-finite f), not_converged (f has the same sign at both
// bracket ends: the bracket proves nothing; ceres: a Ceres failure). Invalid options and a
// malformed bracket (lo ≥ hi, NaN) throw InputError.
//
// Usage:
//   auto f = [](double x) { return x * x - 2; };
//   lac::RootResult r = lac::find_root(lac::RootMethod::toms748, f, lac::make_bracket(f, 0.0, 2.0));
//   // r.root ≈ 1.41421356, r.status == lac::Status::ok, r.iterations, r.evaluations
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/solvers/method_info.hpp"

namespace lac {

enum class RootMethod { bisection, secant, toms748, ceres };

using RootMethodInfo = SolverMethodInfo<RootMethod>;
/// The registry, one row per method in enum order.
std::span<const RootMethodInfo> root_methods();
/// A name or alias of root_methods(); InputError naming "solver" (listing the valid names) otherwise.
RootMethod parse_root_method(std::string_view name);
std::string_view to_string(RootMethod m);

struct RootOptions {
  /// Stop when the bracket [a, b] (or the last step) is narrower than x_atol + x_rtol·min(|a|, |b|)
  /// (Boost.Math's eps_tolerance(bits) is x_atol = 0, x_rtol = max(2^(1−bits), 4·DBL_EPSILON)).
  double x_rtol = 2e-15;  ///< default: a few ulps
  double x_atol = 0;      ///< default: none (pure relative)
  /// Stop as soon as |f(x)| ≤ f_atol (0: only an exact zero stops early).
  double f_atol = 0;
  int max_iterations = 200;  ///< cap on iterations (each costs one evaluation, two for ceres' derivative)

  /// InputError naming the option and its valid range.
  void validate() const {
    if (!(x_rtol >= 0) || !std::isfinite(x_rtol)) throw_input_error("RootOptions", "x_rtol", x_rtol, "[0, inf)");
    if (!(x_atol >= 0) || !std::isfinite(x_atol)) throw_input_error("RootOptions", "x_atol", x_atol, "[0, inf)");
    if (!(x_rtol > 0 || x_atol > 0)) throw_input_error("RootOptions", "x_rtol", x_rtol, "(0, inf) when x_atol = 0");
    if (!(f_atol >= 0) || !std::isfinite(f_atol)) throw_input_error("RootOptions", "f_atol", f_atol, "[0, inf)");
    if (max_iterations < 1 || max_iterations > 100000)
      throw_input_error("RootOptions", "max_iterations", max_iterations, "[1, 100000]");
  }
};

/// A bracket with known end values; lo < hi.
struct Bracket {
  double lo = 0, hi = 0;
  double f_lo = 0, f_hi = 0;
};

struct RootResult {
  double root = std::numeric_limits<double>::quiet_NaN();      ///< evaluated x with the smallest |f|
  double residual = std::numeric_limits<double>::quiet_NaN();  ///< f(root)
  double lo = 0, hi = 0;  ///< final bracket (ceres: the input bracket)
  int iterations = 0;
  long evaluations = 0;   ///< calls of f, including those a method makes for derivatives
  Status status = Status::ok;
  std::string message;    ///< empty when ok
};

/// Evaluates f at both ends (2 evaluations, not counted in the result of a later solve).
template <class F>
Bracket make_bracket(F&& f, double lo, double hi) {
  return Bracket{lo, hi, f(lo), f(hi)};
}

namespace detail {

/// Counts calls, remembers the best point and maps |f| ≤ f_atol to an exact zero so that
/// every method stops there.
template <class F>
struct RootTracker {
  F* f;
  double f_atol;
  long evaluations = 0;
  double best_x = std::numeric_limits<double>::quiet_NaN();
  double best_f = std::numeric_limits<double>::infinity();
  bool non_finite = false;

  void note(double x, double v) {
    if (std::abs(v) < std::abs(best_f)) {
      best_x = x;
      best_f = v;
    }
  }
  double operator()(double x) {
    ++evaluations;
    const double v = (*f)(x);
    if (!std::isfinite(v)) {
      non_finite = true;
      return v;
    }
    note(x, v);
    return std::abs(v) <= f_atol ? 0.0 : v;
  }
};

inline bool width_done(double a, double b, const RootOptions& o) {
  return std::abs(b - a) <= o.x_atol + o.x_rtol * std::min(std::abs(a), std::abs(b));
}

/// Checks the bracket; returns false (with r filled) when solving is unnecessary or impossible.
template <class F>
bool start(const Bracket& b, const RootOptions& o, RootTracker<F>& t, RootResult& r, std::string_view method) {
  o.validate();
  if (!std::isfinite(b.lo) || !std::isfinite(b.hi) || !(b.lo < b.hi))
    throw_input_error(method, "bracket", "needs finite lo < hi (got [" + format_number(b.lo) + ", " + format_number(b.hi) + "])");
  r.lo = b.lo;
  r.hi = b.hi;
  t.note(b.lo, b.f_lo);
  t.note(b.hi, b.f_hi);
  if (!std::isfinite(b.f_lo) || !std::isfinite(b.f_hi)) {
    r.status = Status::numerical_failure;
    r.message = std::string(method) + ": f is not finite at a bracket end";
  } else if (std::abs(b.f_lo) <= o.f_atol || std::abs(b.f_hi) <= o.f_atol) {
    r.status = Status::ok;  // a bracket end is already a root
  } else if ((b.f_lo > 0) == (b.f_hi > 0)) {
    r.status = Status::not_converged;  // no proof that f has no root in the bracket
    r.message = std::string(method) + ": f has the same sign at both bracket ends (" + format_number(b.f_lo) + ", " +
                format_number(b.f_hi) + ")";
  } else {
    return true;
  }
  r.root = t.best_x;
  r.residual = t.best_f;
  return false;
}

template <class F>
void finish(RootTracker<F>& t, RootResult& r, bool converged, std::string_view method) {
  r.root = t.best_x;
  r.residual = t.best_f;
  r.evaluations = t.evaluations;
  if (t.non_finite) {
    r.status = Status::numerical_failure;
    r.message = std::string(method) + ": f returned a non-finite value inside the bracket";
  } else if (!converged) {
    r.status = Status::max_iterations;
    r.message = std::string(method) + ": bracket still wider than the tolerance after " + std::to_string(r.iterations) + " iterations";
  }
}

}  // namespace detail

/// Bisection (001 §4). Written here rather than Boost's tools::bisect because that re-evaluates
/// both ends, which callers of this header usually know already. Same midpoints as tools::bisect;
/// iterations count midpoints only (tools::bisect reports midpoints + 3 and caps midpoints at
/// max_iter − 3), and no midpoint is evaluated once no double lies between the ends.
template <class F>
RootResult bisection(F&& f, const Bracket& b, const RootOptions& o = {}) {
  RootResult r;
  detail::RootTracker<std::remove_reference_t<F>> t{&f, o.f_atol};
  if (!detail::start(b, o, t, r, "bisection")) return r;
  double lo = b.lo, hi = b.hi, f_lo = b.f_lo;
  bool converged = false;
  while (r.iterations < o.max_iterations) {
    if (detail::width_done(lo, hi, o)) {
      converged = true;
      break;
    }
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) {  // no double left between the ends
      converged = true;
      break;
    }
    ++r.iterations;
    const double fm = t(mid);
    if (!std::isfinite(fm)) break;
    if (fm == 0) {
      lo = hi = mid;
      converged = true;
      break;
    }
    if ((fm > 0) == (f_lo > 0)) {
      lo = mid;
      f_lo = fm;
    } else {
      hi = mid;
    }
  }
  r.lo = lo;
  r.hi = hi;
  if (!converged && detail::width_done(lo, hi, o)) converged = true;
  detail::finish(t, r, converged, "bisection");
  return r;
}

/// Secant steps kept inside the bracket; a bisection step replaces a secant step that falls
/// outside it or when two steps have not halved the bracket. Hand-written: Boost.Math's
/// Newton iterations need an analytic derivative. Stops when the bracket or the step is
/// below the tolerance.
template <class F>
RootResult secant(F&& f, const Bracket& b, const RootOptions& o = {}) {
  RootResult r;
  detail::RootTracker<std::remove_reference_t<F>> t{&f, o.f_atol};
  if (!detail::start(b, o, t, r, "secant")) return r;
  double lo = b.lo, hi = b.hi, f_lo = b.f_lo, f_hi = b.f_hi;
  double x0 = lo, f0 = f_lo, x1 = hi, f1 = f_hi;  // the two latest iterates
  double width_two_ago = hi - lo, width_one_ago = hi - lo;
  bool converged = false;
  while (r.iterations < o.max_iterations) {
    if (detail::width_done(lo, hi, o)) {
      converged = true;
      break;
    }
    double x = f1 != f0 ? x1 - f1 * (x1 - x0) / (f1 - f0) : 0.5 * (lo + hi);
    const bool stalled = (hi - lo) > 0.5 * width_two_ago;
    if (!(x > lo && x < hi) || stalled) x = 0.5 * (lo + hi);
    if (x <= lo || x >= hi) {
      converged = true;
      break;
    }
    ++r.iterations;
    const double fx = t(x);
    if (!std::isfinite(fx)) break;
    const double step = std::abs(x - x1);
    x0 = x1;
    f0 = f1;
    x1 = x;
    f1 = fx;
    if (fx == 0) {
      lo = hi = x;
      converged = true;
      break;
    }
    if ((fx > 0) == (f_lo > 0)) {
      lo = x;
      f_lo = fx;
    } else {
      hi = x;
      f_hi = fx;
    }
    width_two_ago = width_one_ago;
    width_one_ago = hi - lo;
    if (step <= o.x_atol + o.x_rtol * std::abs(x)) {
      converged = true;
      break;
    }
  }
  r.lo = lo;
  r.hi = hi;
  detail::finish(t, r, converged, "secant");
  return r;
}

/// Boost.Math TOMS 748 (Alefeld, Potra, Shi 1995) on the bracket.
template <class F>
RootResult toms748(F&& f, const Bracket& b, const RootOptions& o = {}) {
  RootResult r;
  detail::RootTracker<std::remove_reference_t<F>> t{&f, o.f_atol};
  if (!detail::start(b, o, t, r, "toms748")) return r;
  using Policy = boost::math::policies::policy<boost::math::policies::evaluation_error<boost::math::policies::ignore_error>>;
  std::uintmax_t iterations = static_cast<std::uintmax_t>(o.max_iterations);
  auto tol = [&o](double a, double c) { return detail::width_done(a, c, o); };
  // A non-finite value inside the bracket ends the search (recorded by the tracker).
  auto g = [&t](double x) {
    const double v = t(x);
    return std::isfinite(v) ? v : 0.0;
  };
  const auto ends = boost::math::tools::toms748_solve(g, b.lo, b.hi, b.f_lo, b.f_hi, tol, iterations, Policy());
  r.iterations = static_cast<int>(iterations);
  r.lo = ends.first;
  r.hi = ends.second;
  const bool converged = ends.first == ends.second || detail::width_done(ends.first, ends.second, o) ||
                         std::abs(t.best_f) <= o.f_atol;
  detail::finish(t, r, converged, "toms748");
  return r;
}

/// Ceres Solver on the 1-D residual f(x) with bounds [lo, hi] and a finite-difference derivative
/// that stays inside the bracket (central, one-sided at the ends); starts at the regula-falsi point of the bracket. Stops at Ceres' convergence
/// tests (parameter tolerance x_rtol, function tolerance) or when |f| ≤ f_atol.
RootResult ceres_root(const std::function<double(double)>& f, const Bracket& b, const RootOptions& o = {});

/// Dispatch by method (the name registry's target).
template <class F>
RootResult find_root(RootMethod m, F&& f, const Bracket& b, const RootOptions& o = {}) {
  switch (m) {
    case RootMethod::bisection: return bisection(f, b, o);
    case RootMethod::secant: return secant(f, b, o);
    case RootMethod::toms748: return toms748(f, b, o);
    case RootMethod::ceres: return ceres_root(std::function<double(double)>(std::ref(f)), b, o);
  }
  return bisection(f, b, o);
}

}  // namespace lac
