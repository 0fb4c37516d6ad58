// G1 Hermite by one LA segment (constructions/g1_hermite.hpp) on the shared 2000-problem set
// (tests/support/g1_problem_set.hpp). Targets: α = −1 ≤ 1.3 µs per solve; any α ∈ [−3, 3] median
// ≤ 5 µs, p90 ≤ 10 µs; a proven refusal ≤ 0.5 µs. Each iteration solves the next problem of the
// set and times it alone (steady_clock, ~20 ns overhead), so the counters give the per-problem
// median and p90 over the set: all problems, and the solved ones only (refusals are much cheaper).
//   bench_g1_hermite --benchmark_min_time=2s
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "lac/constructions/g1_hermite.hpp"
#include "tests/support/g1_problem_set.hpp"

namespace {

using namespace lac;

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

// range(0): α × 100. range(1) = 1: only the data that need an inflection at turnings of at most π
// (α ≥ 0: the winding search finds most a curve winding round); 2: the same at winding 0 (the
// proven refusal of that turning).
void g1(benchmark::State& state) {
  const double alpha = static_cast<double>(state.range(0)) / 100;
  const bool refusals_only = state.range(1) >= 1;
  G1HermiteOptions options;
  if (state.range(1) == 2) options.winding = 0;
  std::vector<G1HermiteProblem> set;
  for (const auto& a : test::g1_problem_set())
    if (!refusals_only || a.theta0 * a.theta1 > 0) set.push_back({{0, 0}, a.theta0, {1, 0}, a.theta1, alpha});
  std::vector<double> all(set.size()), solved_time(set.size(), -1);
  size_t k = 0;
  long solved = 0, refused = 0, calls = 0;
  for (auto _ : state) {
    const G1HermiteProblem& p = set[k];
    const auto t0 = std::chrono::steady_clock::now();
    G1HermiteResult r = solve_g1_hermite(p, options);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    benchmark::DoNotOptimize(r);
    all[k] = all[k] == 0 ? t : std::min(all[k], t);  // the best of the passes over the set
    if (r.usable()) solved_time[k] = all[k], ++solved;
    if (r.summary.status == Status::no_solution) ++refused;
    ++calls;
    k = (k + 1) % set.size();
  }
  std::vector<double> ok;
  for (double t : solved_time)
    if (t >= 0) ok.push_back(t);
  state.counters["median_us"] = quantile(all, 0.5) * 1e6;
  state.counters["p90_us"] = quantile(all, 0.9) * 1e6;
  state.counters["solved_median_us"] = quantile(ok, 0.5) * 1e6;
  state.counters["solved_p90_us"] = quantile(ok, 0.9) * 1e6;
  state.counters["solved"] = static_cast<double>(solved) / static_cast<double>(calls);
  state.counters["refused"] = static_cast<double>(refused) / static_cast<double>(calls);
}

BENCHMARK(g1)
    ->ArgsProduct({{-100, -300, -250, -200, -150, -50, -30, -10, 0, 10, 30, 50, 100, 150, 200, 250, 300}, {0}})
    ->Args({50, 1})
    ->Args({200, 1})
    ->Args({50, 2})
    ->Args({200, 2})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(1.0);

}  // namespace
