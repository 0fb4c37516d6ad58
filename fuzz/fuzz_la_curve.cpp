// libFuzzer target: the planar LA curve (curves/planar) fed arbitrary doubles — constructor,
// closed-form conversions, frame_at, position_at and polyline with every integrator by name
// (every method of the quadrature registry) and every form — and the igf closed form directly.
// Properties: see fuzz/fuzz_support.hpp.
#include <algorithm>
#include <string>

#include "lac/curves/planar/la_position.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::show;

namespace {

void check_point(const std::string& what, const CurvePoint& q) {
  require_finite_result(what + ".s", q.s);
  require_finite_result(what + ".theta", q.theta);
  require_finite_result(what + ".rho", q.rho);
  require_finite_result(what + ".kappa", q.kappa);
}

void check_position(const std::string& what, const PositionResult& r) {
  check_point(what, r.point);
  if (!usable(r.status)) return;
  require_finite_result(what + ".position", r.point.position);
  require_finite_result(what + ".error_estimate", r.error_estimate);
}

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const double alpha = in.number(), lambda = in.number();
  const std::string curve_text = "LaCurve(" + show(alpha) + ", " + show(lambda) + ")";
  LaCurve* curve = nullptr;
  alignas(LaCurve) unsigned char storage[sizeof(LaCurve)];
  if (!guarded(curve_text, [&] { curve = new (storage) LaCurve(alpha, lambda); })) {
    // The closed form validates the same parameters on its own.
    const double t0 = in.number(), t1 = in.number();
    guarded("igf_position_delta(" + show(alpha) + ", " + show(lambda) + ", " + show(t0) + ", " + show(t1) + ")", [&] {
      auto r = igf_position_delta(alpha, lambda, t0, t1);
      if (usable(r.status)) require_finite_result("igf value", r.value);
    });
    return 0;
  }
  const LaCurve& c = *curve;

  // Domains and closed-form conversions.
  const Interval th = c.theta_domain(), sd = c.s_domain();
  if (std::isnan(th.lo) || std::isnan(th.hi) || std::isnan(sd.lo) || std::isnan(sd.hi) || !(th.lo < th.hi) ||
      !(sd.lo < sd.hi))
    lac::fuzz::finding("NAN", curve_text + ": empty or NaN domain");
  const double t = in.number();
  const std::string at = curve_text + " at " + show(t);
  guarded(at + " rho_at_theta", [&] { lac::fuzz::require_not_nan("rho_at_theta", c.rho_at_theta(t)); });
  guarded(at + " s_at_theta", [&] { lac::fuzz::require_not_nan("s_at_theta", c.s_at_theta(t)); });
  guarded(at + " theta_at_s", [&] { lac::fuzz::require_not_nan("theta_at_s", c.theta_at_s(t)); });
  guarded(at + " kappa_at_s", [&] { lac::fuzz::require_not_nan("kappa_at_s", c.kappa_at_s(t)); });
  guarded(at + " theta_at_log_rho", [&] { lac::fuzz::require_not_nan("theta_at_log_rho", c.theta_at_log_rho(t)); });
  guarded(at + " s_at_log_rho", [&] { lac::fuzz::require_not_nan("s_at_log_rho", c.s_at_log_rho(t)); });
  const Parameter p = in.byte() % 2 ? Parameter::s : Parameter::theta;
  guarded(at + " frame_at", [&] { check_point("frame_at", c.frame_at(p, t)); });

  // Positions with an integrator chosen by name and options from the input.
  const auto methods = quadrature_methods();
  const std::string_view name = methods[in.byte() % methods.size()].name;
  QuadratureOptions options;
  const uint8_t option_bits = in.byte();
  if (option_bits & 1) options.h = in.number();
  if (option_bits & 2) options.tol = in.number();
  if (option_bits & 16) options.panels = in.int_in(-1, 100);
  const Form form = option_bits & 4 ? Form::theta : option_bits & 8 ? Form::s : Form::automatic;
  AnyQuadrature method;
  if (!guarded(std::string(name) + " options", [&] { method = make_quadrature(name, options); })) return 0;

  // Budgets 40 times below the defaults: budget exhaustion is what is checked, and a long
  // integration at the default budget (up to 8.4·10^5 GK evaluations) would hold the 10^6-execution
  // campaign to ~250 executions/s.
  if (auto* gk = std::get_if<GaussKronrod>(&method)) gk->max_intervals = 500;
  if (auto* rk45 = std::get_if<Rk45>(&method)) rk45->max_steps = 2'500;
  if (auto* igf = std::get_if<Igf>(&method)) igf->max_pieces = 2'500;
  const double t1 = in.number();
  const int n = in.int_in(2, 40);
  // rk4 runs |Δ|/h steps, capped at 5·10^6 (seconds under the sanitizers): keep the fuzzer to
  // problems of at most 10^6 steps so that its time bound catches real hangs only. gauss-legendre
  // and gk-tanh-sinh have no budget of their own to lower (a call stops at Gauss–Kronrod's default
  // 8.4·10^5 evaluations): keep them to at most 64 pieces of 64 rad.
  const Rk4* rk4 = std::get_if<Rk4>(&method);
  const bool default_budget = std::holds_alternative<GaussLegendre>(method) || std::holds_alternative<GkTanhSinh>(method);
  if (rk4 || default_budget) {
    double span = 0;
    for (double end : {t, t1}) {
      try {
        const CurvePoint q = c.frame_at(p, end);
        span = std::max({span, std::abs(q.s), std::abs(q.theta)});
      } catch (const InputError&) {  // position_at throws the same error quickly
      }
    }
    if (rk4 && !(span / rk4->h <= 1e6)) return 0;
    if (default_budget && !(span <= 64.0 * lac::detail::kMaxTurningPerPiece)) return 0;
  }
  const std::string call = curve_text + " " + std::string(name) + " form " + std::string(to_string(form)) +
                           (p == Parameter::s ? " s " : " theta ");
  guarded(call + "position_at " + show(t), [&] { check_position("position_at", position_at(c, p, t, method, form)); });
  guarded(call + "polyline " + show(t) + " .. " + show(t1) + " n " + std::to_string(n), [&] {
    for (const auto& r : polyline(c, p, t, t1, n, method, form)) check_position("polyline", r);
  });
  return 0;
}
