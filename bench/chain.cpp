// LA chains (constructions/chain.hpp): a closed G1 chain of 100 segments through 100 points of a
// smooth closed curve with a wavy radius (convex and concave stretches, so the pairs include
// inflections), tangents estimated from the points; the same points as a G2 chain for
// comparison. Each iteration solves the whole chain; the time is per chain.
//   bench_chain --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "lac/constructions/chain.hpp"

namespace {

using namespace lac;

constexpr double kAlphas[] = {-1.0, -0.5, -2.0, 0.5};

/// n points on r(t) = 1 + 0.15 cos(5t), t uniform: a closed curve with five concave stretches.
std::vector<std::complex<double>> wavy_loop(int n) {
  std::vector<std::complex<double>> v;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    v.push_back(std::polar(1 + 0.15 * std::cos(5 * t), t));
  }
  return v;
}

void run(benchmark::State& state, ChainContinuity continuity, int points) {
  const double alpha = kAlphas[state.range(0)];
  const ChainProblem p{.points = wavy_loop(points), .alpha = alpha, .continuity = continuity, .closed = true};
  long usable = 0, calls = 0;
  for (auto _ : state) {
    const ChainResult r = solve_chain(p);
    benchmark::DoNotOptimize(r.curve.length());
    usable += r.usable();
    ++calls;
  }
  state.counters["usable"] = static_cast<double>(usable) / static_cast<double>(calls);
  state.SetLabel("alpha=" + std::to_string(alpha) + " segments=" + std::to_string(points));
}

void BM_ChainG1_100(benchmark::State& s) { run(s, ChainContinuity::g1, 100); }
void BM_ChainG2_100(benchmark::State& s) { run(s, ChainContinuity::g2, 100); }

}  // namespace

BENCHMARK(BM_ChainG1_100)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChainG2_100)->Arg(0)->Unit(benchmark::kMicrosecond);
