// libFuzzer target: quadratic LA curves (curves/quadratic) fed arbitrary α, γ, Λ and arc
// lengths: constructor (both inverse methods, with and without the inflection continuation),
// domain, s(κ), κ(s), θ(s), frame_at, and positions / polylines with every quadrature by name.
// Properties: see fuzz/fuzz_support.hpp.
#include <algorithm>
#include <optional>
#include <string>

#include "lac/curves/quadratic/quadratic_position.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::require_not_nan;
using lac::fuzz::show;

namespace {

void check_position(const std::string& what, const PositionResult& r) {
  require_finite_result(what + " s", r.point.s);
  require_finite_result(what + " theta", r.point.theta);
  require_finite_result(what + " kappa", r.point.kappa);
  require_not_nan(what + " rho", r.point.rho);  // ±inf at the inflection (documented)
  if (usable(r.status)) require_finite_result(what + " position", r.point.position);
}

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const double alpha = in.number(), gamma = in.number(), lambda = in.number();
  QuadraticOptions o;
  const uint8_t bits = in.byte();
  o.inverse = bits & 1 ? special::ErfInverseMethod::hybrid_003 : special::ErfInverseMethod::ours;
  o.through_inflection = bits & 2;
  if (bits & 4) o.max_iterations = in.int_in(-2, 100);
  const std::string curve_text = "QuadraticLaCurve(" + show(alpha) + ", " + show(gamma) + ", " + show(lambda) + ", " +
                                 std::string(to_string(o.inverse)) + (o.through_inflection ? ", through" : "") + ")";
  std::optional<QuadraticLaCurve> c;
  if (!guarded(curve_text, [&] { c.emplace(alpha, gamma, lambda, o); })) return 0;
  const Interval d = c->s_domain();
  if (std::isnan(d.lo) || std::isnan(d.hi) || !(d.lo < d.hi)) lac::fuzz::finding("NAN", curve_text + ": empty or NaN s_domain");
  require_not_nan(curve_text + " s_at_infinite_kappa", c->s_at_infinite_kappa());
  require_not_nan(curve_text + " s_at_zero_kappa", c->s_at_zero_kappa());

  const double s = in.number(), kappa = in.number(), s1 = in.number();
  const std::string at = curve_text + " at " + show(s);
  guarded(at + " s_at_log_kappa", [&] { require_not_nan("s_at_log_kappa", c->s_at_log_kappa(s)); });
  guarded(curve_text + " s_at_kappa " + show(kappa), [&] { require_not_nan("s_at_kappa", c->s_at_kappa(kappa)); });
  guarded(at + " solve_kappa", [&] {
    const KappaSolution k = c->solve_kappa(s);
    if (usable(k.status)) {
      require_finite_result("kappa", k.kappa);
      require_not_nan("log_kappa", k.log_kappa);  // -inf at the inflection
    }
  });
  guarded(at + " theta_at_s", [&] { require_finite_result("theta_at_s", c->theta_at_s(s)); });

  const auto methods = quadrature_methods();
  const std::string_view name = methods[in.byte() % methods.size()].name;
  AnyQuadrature method;
  if (!guarded(std::string(name), [&] { method = make_quadrature(name); })) return 0;
  // Budgets 200–5000 times below the defaults, so that a sanitized call stays well under the 1 s
  // bound and the 10^6-execution campaign runs at a few hundred executions/s: each integrand value
  // inverts κ(s) (~1 µs unsanitized, ~20 µs with 003's hybrid inverse); budget exhaustion is what
  // is checked.
  if (auto* gk = std::get_if<GaussKronrod>(&method)) gk->max_intervals = 100;
  if (auto* rk45 = std::get_if<Rk45>(&method)) rk45->max_steps = 500;
  if (auto* rk4 = std::get_if<Rk4>(&method)) rk4->max_steps = 1'000;
  // gk-tanh-sinh has no budget of its own but its depth and levels: a 19-point polyline through
  // 003's hybrid inverse took 1.3 s unsanitized at the defaults (4, 12), 0.13 s at (2, 6).
  if (auto* gts = std::get_if<GkTanhSinh>(&method)) {
    gts->gk_max_depth = 2;
    gts->ts_max_levels = 6;
  }
  // rk4 (h = 10^-3) runs |s|/h steps: keep to 10^6 steps, as in fuzz_la_curve.
  if (std::holds_alternative<Rk4>(method) && !(std::max(std::abs(s), std::abs(s1)) <= 1e3)) return 0;
  const int n = in.int_in(-1, 30);
  guarded(at + " " + std::string(name) + " position_at", [&] { check_position("position_at", position_at(*c, s, method)); });
  guarded(at + " .. " + show(s1) + " " + std::string(name) + " polyline " + std::to_string(n), [&] {
    for (const auto& r : polyline(*c, s, s1, n, method)) check_position("polyline", r);
  });
  return 0;
}
