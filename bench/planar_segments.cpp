// Google Benchmark: planar G1 (monotonic) and compound-rhythm segments from control points.
// Targets: monotonic ≤ 20 µs median, compound ≤ 100 µs median per solve.
// BM_Monotonic / BM_Compound cycle through 64 drawable control triangles (fixed seed, base angles in
// [0.2, 1.2] rad, random orientation and scale) so that the time is a mix over shapes.
// Run: build/bench_planar_segments --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "lac/constructions/triangle_g1.hpp"

namespace {

using namespace lac;

struct Case {
  ControlTriangle t;
  double alpha0, alpha1, r;
};

std::vector<Case> drawable_cases(bool compound, int n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  const double alphas[] = {-1.5, -1, -0.5, 0, 0.5, 1, 1.5, 2, 3};
  std::vector<Case> out;
  while (static_cast<int>(out.size()) < n) {
    const double b0 = 0.2 + u(rng), b2 = 0.2 + u(rng);
    const double h = std::sin(b0) * std::sin(b2) / std::sin(b0 + b2);
    const Point2 rot = std::polar(std::pow(10.0, 2 * u(rng) - 1), 2 * std::numbers::pi * u(rng));
    const ControlTriangle t{0, Point2{h / std::tan(b0), h} * rot, rot};
    Case c{t, alphas[rng() % 9], alphas[rng() % 9], 0.2 + 0.6 * u(rng)};
    const TriangleResult g = compound ? solve_compound(c.t, c.alpha0, c.alpha1, c.r) : solve_g1(c.t, c.alpha0);
    if (g.summary.status == Status::ok) out.push_back(c);
  }
  return out;
}

void BM_Monotonic(benchmark::State& state, RootMethod solver) {
  static const std::vector<Case> cases = drawable_cases(false, 64);
  TriangleOptions o;
  o.solver = solver;
  size_t k = 0, failures = 0;
  for (auto _ : state) {
    const Case& c = cases[k++ % cases.size()];
    const TriangleResult g = solve_g1(c.t, c.alpha0, o);
    failures += g.summary.status != Status::ok;
    benchmark::DoNotOptimize(g.curve.length());
  }
  state.counters["failures"] = static_cast<double>(failures);
}

void BM_Compound(benchmark::State& state, RootMethod solver) {
  static const std::vector<Case> cases = drawable_cases(true, 64);
  TriangleOptions o;
  o.solver = solver;
  size_t k = 0, failures = 0;
  for (auto _ : state) {
    const Case& c = cases[k++ % cases.size()];
    const TriangleResult g = solve_compound(c.t, c.alpha0, c.alpha1, c.r, o);
    failures += g.summary.status != Status::ok;
    benchmark::DoNotOptimize(g.curve.length());
  }
  state.counters["failures"] = static_cast<double>(failures);
}

// One fixed, moderate shape (a0 = (0,0), a1 = (1,0), a2 = (2,1)): the per-shape cost without the
// tail of near-singular shapes that the 64-shape mix above averages in (Google Benchmark reports
// the mean over the loop, i.e. over the mix).
void BM_MonotonicOneShape(benchmark::State& state) {
  const ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  for (auto _ : state) benchmark::DoNotOptimize(solve_g1(t, static_cast<double>(state.range(0)) / 2).curve.length());
}
void BM_CompoundOneShape(benchmark::State& state) {
  const ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  for (auto _ : state) benchmark::DoNotOptimize(solve_compound(t, -1, 1.5, 0.4).curve.length());
}
BENCHMARK(BM_MonotonicOneShape)->Arg(-2)->Arg(0)->Arg(2)->Arg(4)->Unit(benchmark::kMicrosecond);  // α = -1, 0, 1, 2
BENCHMARK(BM_CompoundOneShape)->Unit(benchmark::kMicrosecond);

BENCHMARK_CAPTURE(BM_Monotonic, toms748, RootMethod::toms748)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Monotonic, secant, RootMethod::secant)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Monotonic, bisection, RootMethod::bisection)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Monotonic, ceres, RootMethod::ceres)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Compound, toms748, RootMethod::toms748)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Compound, secant, RootMethod::secant)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Compound, bisection, RootMethod::bisection)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Compound, ceres, RootMethod::ceres)->Unit(benchmark::kMicrosecond);

}  // namespace
