#pragma once
// `gk-tanh-sinh`, the default position quadrature of the segment solvers: Boost Gauss–Kronrod (G10K21) with a
// shallow recursion, falling back to Boost tanh-sinh when Gauss–Kronrod does not meet its
// tolerance. The similar-triangle search draws trial curves up to the ends of the LA domain,
// where ρ → 0 or ∞ at an end of the integration interval and the integrand has an algebraic
// endpoint singularity (θ-form: ρ ~ (θmax − θ)^(1/(α−1)); s-form: θ(s) loses smoothness at the
// inflection). Gauss–Kronrod converges slowly there; tanh-sinh converges exponentially.
// Satisfies QuadratureMethod, so position_at / polyline accept it.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <algorithm>
#include <array>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <string_view>

#include "lac/integrators/quadrature.hpp"

namespace lac {

struct GkTanhSinh {
  static constexpr std::string_view name = "gk-tanh-sinh";
  double tol = 1e-13;             ///< relative tolerance of both rules
  unsigned gk_max_depth = 4;      ///< Gauss–Kronrod bisection depth before falling back
  std::size_t ts_max_levels = 12; ///< tanh-sinh refinement levels (Boost default 15)

  void validate() const {
    if (!(tol >= 1e-16) || !std::isfinite(tol)) throw_input_error(name, "tol", tol, "[1e-16, inf)");
    if (gk_max_depth < 1 || gk_max_depth > 30) throw_input_error(name, "gk_max_depth", gk_max_depth, "[1, 30]");
    if (ts_max_levels < 4 || ts_max_levels > 20) throw_input_error(name, "ts_max_levels", static_cast<double>(ts_max_levels), "[4, 20]");
  }

  /// The tanh-sinh rule with `levels` refinement levels (its abscissa tables): one per thread and
  /// level count, as Boost 1.74 declares integrate() non-const.
  static boost::math::quadrature::tanh_sinh<double>& tanh_sinh_rule(std::size_t levels) {
    thread_local std::array<std::unique_ptr<boost::math::quadrature::tanh_sinh<double>>, 21> rules;
    auto& rule = rules.at(levels);
    if (!rule) rule = std::make_unique<boost::math::quadrature::tanh_sinh<double>>(levels);
    return *rule;
  }

  template <Integrand F>
  IntegralResult<IntegrandValue<F>> integrate(F&& f, double a, double b) const {
    using V = IntegrandValue<F>;
    IntegralResult<V> r;
    if (a == b) return r;
    // Gauss–Kronrod on [−1, 1]: Boost 1.74's recursive_adaptive_integrate compares the
    // unscaled panel error with a scaled tolerance, so on a short [a, b] it would always
    // recurse to max_depth. On [−1, 1] the top panel's test is exact.
    {
      const double mean = 0.5 * (a + b), half = 0.5 * (b - a);
      long count = 0;
      auto g = [&](double t) {
        ++count;
        return f(mean + half * t);
      };
      double err = 0, l1 = 0;
      const V unit = boost::math::quadrature::gauss_kronrod<double, 21>::integrate(g, -1.0, 1.0, gk_max_depth, tol, &err, &l1);
      r.value = half * unit;
      r.error_estimate = std::abs(half) * err;
      r.evaluations = count;
      if (!std::isfinite(std::abs(unit))) {
        r.status = Status::numerical_failure;
        r.message = "gauss-kronrod: non-finite value";
      } else if (err > tol * std::abs(unit) && err > 100 * std::numeric_limits<double>::epsilon() * l1) {
        r.status = Status::tolerance_not_met;
        r.message = "gauss-kronrod: error estimate above tolerance";
      }
    }
    if (r.status == Status::ok) return r;
    boost::math::quadrature::tanh_sinh<double>& rule = tanh_sinh_rule(ts_max_levels);
    long count = 0;
    CountingIntegrand<std::remove_reference_t<F>> counted{&f, &count};
    double err = 0, l1 = 0;
    std::size_t levels = 0;
    const double lo = std::min(a, b), hi = std::max(a, b);
    V value{};
    try {
      value = rule.integrate(counted, lo, hi, tol, &err, &l1, &levels);
    } catch (const std::exception& e) {  // Boost raises on a non-finite integrand value
      r.status = Status::numerical_failure;
      r.message = std::string("tanh-sinh: ") + e.what();
      r.evaluations += count;
      return r;
    }
    if (b < a) value = -value;
    const long gk_evaluations = r.evaluations;
    IntegralResult<V> t;
    t.value = value;
    t.error_estimate = err;
    t.evaluations = gk_evaluations + count;
    if (!std::isfinite(std::abs(value))) {
      t.status = Status::numerical_failure;
      t.message = "tanh-sinh: non-finite value";
    } else if (err > 10 * tol * l1) {
      // Neither rule converged. Each estimate is a difference of its own refinements, which can
      // both be small where the integrand has an interior kink neither resolves (a quadratic LA
      // curve whose θ(s) levels off within a tiny arc); the two rules are independent, so the
      // value keeps the smaller estimate but never less than their disagreement.
      const double disagreement = std::abs(t.value - r.value);
      IntegralResult<V>& kept = r.error_estimate < err ? r : t;
      kept.error_estimate = std::max(kept.error_estimate, disagreement);
      kept.evaluations = t.evaluations;
      kept.status = Status::tolerance_not_met;
      kept.message = std::string(&kept == &r ? "gauss-kronrod" : "tanh-sinh") + ": error estimate " +
                     format_number(kept.error_estimate) + " above tolerance (the two rules differ by " +
                     format_number(disagreement) + ")";
      return kept;
    }
    return t;
  }
};

static_assert(QuadratureMethod<GkTanhSinh>);

}  // namespace lac
