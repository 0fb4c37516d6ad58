// G2 Hermite (004 §3) and S-curve (004 §2.5) timings. Targets: G2 ≤ 1 ms median
// including the initial estimate; S-curve ≤ 50 µs. Each iteration solves the next problem of
// a fixed random set (same distribution as experiments/g2_random.cpp), so the time is a mean
// over the set; counters report the share solved. The G2 rows run without the grid fallback
// (a failure costs its capped iterations, not a second ~16 ms attempt); per-call medians are
// in results/g2_random.md.
//   bench_hermite --benchmark_filter=G2 --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <numbers>
#include <random>

#include "lac/constructions/detail/g2_system.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/s_curve.hpp"
#include "lac/integrators/registry.hpp"

namespace {

using namespace lac;

constexpr double kAlphas[] = {-0.5, -1.0, -2.0};

std::vector<G2Problem> g2_set(double alpha) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-std::numbers::pi / 2, std::numbers::pi / 2), curvature(-3, 3);
  std::vector<G2Problem> v(64);
  for (auto& p : v) {
    const double t0 = angle(rng), k0 = curvature(rng), t1 = angle(rng), k1 = curvature(rng);
    p = {{{0, 0}, t0, k0}, {{1, 0}, t1, k1}, alpha};
  }
  return v;
}

void run_g2(benchmark::State& state, G2Solver solver, G2Start start, bool verify,
            const AnyQuadrature& integrator = GaussLegendre{}) {
  const auto set = g2_set(kAlphas[state.range(0)]);
  G2Options o;
  o.solver = solver;
  o.integrator = integrator;
  o.start = start;
  o.verify = verify;
  o.grid_fallback = false;
  size_t i = 0;
  long solved = 0, calls = 0;
  for (auto _ : state) {
    const G2Result r = solve_g2(set[i++ % set.size()], o);
    benchmark::DoNotOptimize(r.info.h);
    solved += r.usable();
    ++calls;
  }
  state.counters["alpha"] = kAlphas[state.range(0)];
  state.counters["solved_share"] = static_cast<double>(solved) / static_cast<double>(calls);
}

void BM_G2_newton_fast(benchmark::State& s) { run_g2(s, G2Solver::newton, G2Start::fast, true); }
void BM_G2_newton_fast_noverify(benchmark::State& s) { run_g2(s, G2Solver::newton, G2Start::fast, false); }
void BM_G2_paper_fast(benchmark::State& s) { run_g2(s, G2Solver::paper, G2Start::fast, true); }
void BM_G2_ceres_fast(benchmark::State& s) { run_g2(s, G2Solver::ceres, G2Start::fast, true); }
void BM_G2_newton_grid(benchmark::State& s) { run_g2(s, G2Solver::newton, G2Start::bezier_grid, true); }
void BM_G2_paper_grid(benchmark::State& s) { run_g2(s, G2Solver::paper, G2Start::bezier_grid, true); }
BENCHMARK(BM_G2_newton_fast)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_G2_newton_fast_noverify)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_G2_paper_fast)->DenseRange(0, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_G2_ceres_fast)->DenseRange(0, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_G2_newton_grid)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_G2_paper_grid)->Arg(0)->Unit(benchmark::kMillisecond);

// Other methods (not in the before/after comparison of scripts/bench_compare.py): the simplex, and
// every quadrature method of the registry in the trial curves (newton, fast start), α = −0.5.
void BM_Methods_G2_simplex(benchmark::State& s) { run_g2(s, G2Solver::simplex, G2Start::fast, true); }
void BM_Methods_G2_integrator(benchmark::State& s, const char* name) {
  run_g2(s, G2Solver::newton, G2Start::fast, true, make_quadrature(name));
}
BENCHMARK(BM_Methods_G2_simplex)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_G2_integrator, rk4, "rk4")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_G2_integrator, rk45, "rk45")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_G2_integrator, gauss_kronrod, "gauss-kronrod")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_G2_integrator, gk_tanh_sinh, "gk-tanh-sinh")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_G2_integrator, igf, "igf")->Arg(0)->Unit(benchmark::kMicrosecond);

// The initial estimates alone (normalized problems of the same set).
void run_start(benchmark::State& state, bool grid) {
  const auto set = g2_set(kAlphas[state.range(0)]);
  const AnyQuadrature method = GaussLegendre{};  // the estimates integrate with their own rule; unused
  std::vector<detail::G2System> norm;
  for (const auto& p : set) {
    norm.push_back({{p.alpha, p.start.kappa < 0 ? -1.0 : 1.0},
                    p.start.theta,
                    p.end.theta,
                    p.start.kappa,
                    p.end.kappa,
                    detail::TrialIntegrator(method)});
  }
  size_t i = 0;
  for (auto _ : state) {
    const auto& n = norm[i++ % norm.size()];
    const auto e = grid ? detail::g2_bezier_grid_start(n) : detail::g2_fast_start(n);
    benchmark::DoNotOptimize(e.h);
  }
}
void BM_Start_fast(benchmark::State& s) { run_start(s, false); }
void BM_Start_bezier_grid(benchmark::State& s) { run_start(s, true); }
BENCHMARK(BM_Start_fast)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Start_bezier_grid)->Arg(0)->Unit(benchmark::kMillisecond);

// S-shaped inputs only: P0 = (0,0), P3 = (1,0), tangent legs 1/3 at random angles.
std::vector<std::array<std::complex<double>, 4>> s_set() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-std::numbers::pi / 2, std::numbers::pi / 2);
  std::vector<std::array<std::complex<double>, 4>> v;
  while (v.size() < 64) {
    const double a = angle(rng), b = angle(rng);
    const std::array<std::complex<double>, 4> P{std::complex<double>(0, 0), std::polar(1.0 / 3, a),
                                                std::complex<double>(1, 0) - std::polar(1.0 / 3, b),
                                                std::complex<double>(1, 0)};
    const auto r = solve_s_curve(P, -1.0);
    if (r.info.shape == SCurveShape::s_shaped && r.summary.status == Status::ok) v.push_back(P);
  }
  return v;
}

// S-curve slopes: the G2 ones, then both ends of the range 004 §2.5 illustrates (Fig. 3).
constexpr double kSAlphas[] = {-0.5, -1.0, -2.0, -0.25, -4.0};

void run_s(benchmark::State& state, RootMethod m, bool verify, const AnyQuadrature& integrator = GaussLegendre{}) {
  static const auto set = s_set();
  const double alpha = kSAlphas[state.range(0)];
  SCurveOptions o;
  o.solver = m;
  o.integrator = integrator;
  o.verify = verify;
  size_t i = 0;
  long solved = 0, calls = 0;
  for (auto _ : state) {
    const SCurveResult r = solve_s_curve(set[i++ % set.size()], alpha, o);
    benchmark::DoNotOptimize(r.info.lambda);
    solved += r.summary.status == Status::ok;
    ++calls;
  }
  state.counters["alpha"] = alpha;
  state.counters["solved_share"] = static_cast<double>(solved) / static_cast<double>(calls);
}
void BM_SCurve_toms748(benchmark::State& s) { run_s(s, RootMethod::toms748, true); }
void BM_SCurve_toms748_noverify(benchmark::State& s) { run_s(s, RootMethod::toms748, false); }
void BM_SCurve_bisection(benchmark::State& s) { run_s(s, RootMethod::bisection, true); }
BENCHMARK(BM_SCurve_toms748)->DenseRange(0, 4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SCurve_toms748_noverify)->DenseRange(0, 4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SCurve_bisection)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

// Other methods for the S-curve (not compared by scripts/bench_compare.py), α = −0.5: the 1-D
// registry's secant and ceres, and every quadrature method with toms748.
void BM_Methods_SCurve_root(benchmark::State& s, RootMethod m) { run_s(s, m, true); }
void BM_Methods_SCurve_integrator(benchmark::State& s, const char* name) {
  run_s(s, RootMethod::toms748, true, make_quadrature(name));
}
BENCHMARK_CAPTURE(BM_Methods_SCurve_root, secant, RootMethod::secant)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_SCurve_root, ceres, RootMethod::ceres)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_SCurve_integrator, rk4, "rk4")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_SCurve_integrator, rk45, "rk45")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_SCurve_integrator, gauss_kronrod, "gauss-kronrod")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_SCurve_integrator, gk_tanh_sinh, "gk-tanh-sinh")->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Methods_SCurve_integrator, igf, "igf")->Arg(0)->Unit(benchmark::kMicrosecond);

}  // namespace
