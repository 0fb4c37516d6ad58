// libFuzzer target: G2 Hermite interpolation by a triple LA curve and S-shaped input by one LA
// curve (constructions/g2_hermite, s_curve) fed arbitrary end data, slopes, solver and integrator
// choices, and the samples of usable results. Properties: see fuzz/fuzz_support.hpp.
#include <array>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/s_curve.hpp"
#include "lac/integrators/registry.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::show;

namespace {

void check_samples(const std::string& what, const std::vector<PositionResult>& pts) {
  for (const auto& p : pts) {
    const CurvePoint& q = p.point;
    require_finite_result(what + " position", q.position);
    require_finite_result(what + " s", q.s);
    require_finite_result(what + " theta", q.theta);
    require_finite_result(what + " kappa", q.kappa);
  }
}

std::string show_point(std::complex<double> p) { return show(p.real()) + "," + show(p.imag()); }

// A budget well under the library's default (10^8): an adaptive method on a hard integrand costs
// ~10^6 evaluations a trial curve, and the harness bounds each call's CPU time (1 s).
constexpr long kMaxEvaluations = 1'000'000;

// The integrator of the trial curves, by bits of a hash of the whole input (no byte of the saved
// layout): gauss-legendre, the default, for 11 of 16 inputs; each other registry method for 1 in 16
// (rk4 and rk45 are slow on long curves, so rarely).
AnyQuadrature integrator_of(uint64_t input_hash) {
  switch ((input_hash >> 8) % 16) {
    case 0: return Igf{};
    case 1: return GaussKronrod{};
    case 2: return Rk45{};
    case 3: return GkTanhSinh{};
    case 4: return Rk4{};
    default: return GaussLegendre{};
  }
}

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const uint8_t mode = in.byte();
  const int n = in.int_in(-1, 40);
  const uint64_t input_hash = lac::fuzz::detail::fnv1a(lac::fuzz::detail::current_data, lac::fuzz::detail::current_size);
  if (mode % 2 == 0) {
    G2Problem p;
    p.start.position = {in.number(), in.number()};
    p.start.theta = in.number();
    p.start.kappa = in.number();
    p.end.position = {in.number(), in.number()};
    p.end.theta = in.number();
    p.end.kappa = in.number();
    p.alpha = in.number();
    G2Options o;
    // The solver byte keeps its former meaning (paper, newton, ceres); the simplex, slow, for 1 in
    // 16 inputs by the hash.
    constexpr G2Solver kByByte[3] = {G2Solver::paper, G2Solver::newton, G2Solver::ceres};
    o.solver = kByByte[in.byte() % 3];
    if ((input_hash >> 16) % 16 == 0) o.solver = G2Solver::simplex;
    o.integrator = integrator_of(input_hash);
    o.max_evaluations = kMaxEvaluations;
    // The Bezier-grid start scans 10^4 quintics (004 §3.4): allowed, but rarely, to keep the rate up.
    // Chosen by a hash of the whole input, not by one byte: mutants of a grid input keep a byte
    // and the campaign spent half its time in the grid; a hash changes with any mutation.
    in.byte();  // the former selector byte, still read so that saved inputs keep their layout
    o.start = input_hash % 256 == 0 ? G2Start::bezier_grid : G2Start::fast;
    o.grid_fallback = false;
    o.verify = in.byte() % 2;
    const std::string what = "solve_g2 p0 " + show_point(p.start.position) + " theta0 " + show(p.start.theta) +
                             " kappa0 " + show(p.start.kappa) + " p1 " + show_point(p.end.position) + " theta1 " +
                             show(p.end.theta) + " kappa1 " + show(p.end.kappa) + " alpha " + show(p.alpha) +
                             " solver " + std::string(to_string(o.solver)) + " integrator " +
                             std::string(name_of(o.integrator)) + " start " + std::string(to_string(o.start));
    G2Result r;
    if (!guarded(what, [&] { r = solve_g2(p, o); })) return 0;
    if (!r.usable()) return 0;
    const Residuals& e = r.summary.residuals;
    require_finite_result(what + " length", r.curve.length());
    require_finite_result(what + " residual_position", e.position.value_or(NAN));
    require_finite_result(what + " residual_angle", e.angle.value_or(NAN));
    require_finite_result(what + " residual_curvature", e.curvature.value_or(NAN));
    guarded(what + " sample " + std::to_string(n), [&] { check_samples(what, r.curve.sample(n)); });
    return 0;
  }
  std::array<std::complex<double>, 4> control;
  for (auto& c : control) c = {in.number(), in.number()};
  const double alpha = in.number();
  SCurveOptions o;
  o.solver = in.byte() % 2 ? RootMethod::bisection : RootMethod::toms748;
  if ((input_hash >> 16) % 16 == 0) o.solver = RootMethod::secant;
  if ((input_hash >> 16) % 16 == 1) o.solver = RootMethod::ceres;
  o.integrator = integrator_of(input_hash);
  o.max_evaluations = kMaxEvaluations;
  const std::string what = "solve_s_curve " + show_point(control[0]) + " " + show_point(control[1]) + " " +
                           show_point(control[2]) + " " + show_point(control[3]) + " alpha " + show(alpha) +
                           " solver " + std::string(to_string(o.solver)) + " integrator " +
                           std::string(name_of(o.integrator));
  SCurveResult r;
  if (!guarded(what, [&] { r = solve_s_curve(control, alpha, o); })) return 0;
  if (!r.usable()) return 0;
  const Residuals& e = r.summary.residuals;
  require_finite_result(what + " lambda", r.info.lambda);
  require_finite_result(what + " length", r.curve.length());
  require_finite_result(what + " residual_position", e.position.value_or(NAN));
  require_finite_result(what + " residual_angle", e.angle.value_or(NAN));
  guarded(what + " sample " + std::to_string(n), [&] { check_samples(what, r.curve.sample(n)); });
  return 0;
}
