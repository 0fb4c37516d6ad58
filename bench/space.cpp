// Google Benchmark: G1 and compound-rhythm LA space segments (000 §2.2, §4.3).
// Targets: compound segment ≤ 1 ms median, monotonic (G1) segment ≤ 0.5 ms median.
// BM_*_random cycle through 64 random drawable configurations (constructions/space_drawable_cases.hpp,
// fixed seed; time per segment is the mean over them); BM_*_fig5a solve one fixed configuration
// (000 Fig. 5a parameters, endpoints of experiments/space_figures.cpp). Run with
// --benchmark_repetitions=5 --benchmark_report_aggregates_only=true for medians.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "lac/constructions/space_drawable_cases.hpp"

namespace {

const std::vector<lac::DrawableCase>& random_cases(bool compound) {
  static const auto make = [](bool c) {
    std::mt19937_64 rng(c ? 777 : 555);
    std::vector<lac::DrawableCase> v;
    for (int i = 0; i < 64; ++i) v.push_back(lac::random_drawable_case(rng, c));
    return v;
  };
  static const std::vector<lac::DrawableCase> g1 = make(false), comp = make(true);
  return compound ? comp : g1;
}

lac::Result<lac::SpaceCurve, lac::SpaceInfo> solve(const lac::DrawableCase& c, const lac::SpaceSegmentOptions& o) {
  return c.compound ? lac::solve_compound_space_segment(c.ends, c.spec, o) : lac::solve_g1_space_segment(c.ends, c.g1(), o);
}

void run_random(benchmark::State& state, bool compound, lac::NonlinearMethod solver) {
  const auto& cases = random_cases(compound);
  lac::SpaceSegmentOptions o;
  o.solver = solver;
  size_t i = 0, ok = 0, n = 0;
  long constructions = 0;
  for (auto _ : state) {
    const auto r = solve(cases[i++ % cases.size()], o);
    benchmark::DoNotOptimize(r.curve.length());
    ok += r.summary.status == lac::Status::ok;
    constructions += r.summary.constructions;
    ++n;
  }
  state.counters["success"] = static_cast<double>(ok) / static_cast<double>(n);
  state.counters["constructions"] = static_cast<double>(constructions) / static_cast<double>(n);
}

void run_fig5a(benchmark::State& state, bool compound, lac::NonlinearMethod solver) {
  const lac::CompoundSpaceSpec spec{-1, 1, -1, 1, 0.1, 0.5, lac::TorsionType::type1};
  const lac::SpaceEndpoints e = lac::drawable_endpoints(spec, compound, 0.2, 2.5, 1.2).info.ends;
  lac::DrawableCase c{e, spec, compound, 0.2, 2.5, 1.2};
  lac::SpaceSegmentOptions o;
  o.solver = solver;
  long constructions = 0, n = 0;
  for (auto _ : state) {
    const auto r = solve(c, o);
    benchmark::DoNotOptimize(r.curve.length());
    if (r.summary.status != lac::Status::ok) state.SkipWithError("not solved");
    constructions += r.summary.constructions;
    ++n;
  }
  state.counters["constructions"] = static_cast<double>(constructions) / static_cast<double>(std::max(1L, n));
}

void BM_g1_random_newton(benchmark::State& s) { run_random(s, false, lac::NonlinearMethod::newton); }
void BM_g1_random_ceres(benchmark::State& s) { run_random(s, false, lac::NonlinearMethod::ceres); }
void BM_g1_random_simplex(benchmark::State& s) { run_random(s, false, lac::NonlinearMethod::simplex); }
void BM_compound_random_newton(benchmark::State& s) { run_random(s, true, lac::NonlinearMethod::newton); }
void BM_compound_random_ceres(benchmark::State& s) { run_random(s, true, lac::NonlinearMethod::ceres); }
void BM_compound_random_simplex(benchmark::State& s) { run_random(s, true, lac::NonlinearMethod::simplex); }
void BM_g1_fig5a_newton(benchmark::State& s) { run_fig5a(s, false, lac::NonlinearMethod::newton); }
void BM_compound_fig5a_newton(benchmark::State& s) { run_fig5a(s, true, lac::NonlinearMethod::newton); }
void BM_compound_fig5a_simplex(benchmark::State& s) { run_fig5a(s, true, lac::NonlinearMethod::simplex); }

BENCHMARK(BM_g1_random_newton)->Unit(benchmark::kMillisecond)->Iterations(640);
BENCHMARK(BM_g1_random_ceres)->Unit(benchmark::kMillisecond)->Iterations(192);
BENCHMARK(BM_g1_random_simplex)->Unit(benchmark::kMillisecond)->Iterations(128);
BENCHMARK(BM_compound_random_newton)->Unit(benchmark::kMillisecond)->Iterations(640);
BENCHMARK(BM_compound_random_ceres)->Unit(benchmark::kMillisecond)->Iterations(192);
BENCHMARK(BM_compound_random_simplex)->Unit(benchmark::kMillisecond)->Iterations(128);
BENCHMARK(BM_g1_fig5a_newton)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_compound_fig5a_newton)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_compound_fig5a_simplex)->Unit(benchmark::kMillisecond);

}  // namespace
