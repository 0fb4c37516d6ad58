// Google Benchmark: the global geometry queries of geometry/ on a clothoid spiral turning 31 rad
// (5 turns, the test curve of tests/geometry): closest point for 64 query points (fixed seed) in
// and around the spiral, all crossings with 64 lines through it, and all crossings with a rotated
// copy of it.
// Run: build/bench_geometry --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <complex>
#include <random>
#include <vector>

#include "lac/geometry/closest_point.hpp"
#include "lac/geometry/intersections.hpp"
#include "lac/geometry/transforms.hpp"

namespace {

using namespace lac;

PlanarCurve spiral() {
  return PlanarCurve({LaSegment(LaLaw{-1.0}, 0.0, 1.0, 2.0, 60.0, 0.3, {{1, -2}, 10.0, std::polar(1.0, 0.7)})});
}

std::vector<std::complex<double>> points(const PlanarCurve& c, int n) {
  const BoundingBox b = c.bounding_box();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<std::complex<double>> out;
  for (int i = 0; i < n; ++i)
    out.emplace_back(b.lo.real() + u(rng) * (b.hi - b.lo).real(), b.lo.imag() + u(rng) * (b.hi - b.lo).imag());
  return out;
}

void BM_ClosestPoint(benchmark::State& state) {
  const PlanarCurve c = spiral();
  const auto qs = points(c, 64);
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(closest_point(c, qs[i++ % qs.size()]).distance);
}
BENCHMARK(BM_ClosestPoint)->Unit(benchmark::kMicrosecond);

void BM_IntersectLine(benchmark::State& state) {
  const PlanarCurve c = spiral();
  const auto ps = points(c, 64);
  size_t i = 0;
  for (auto _ : state) {
    const std::complex<double> P = ps[i % ps.size()], D = std::polar(1.0, 0.1 * static_cast<double>(i % 31));
    ++i;
    benchmark::DoNotOptimize(intersect_line(c, P, D).points.size());
  }
}
BENCHMARK(BM_IntersectLine)->Unit(benchmark::kMicrosecond);

void BM_IntersectCurves(benchmark::State& state) {
  const PlanarCurve c = spiral();
  const PlanarCurve d = rotated(c, 0.9, {0.5, 0.5});
  for (auto _ : state) benchmark::DoNotOptimize(intersect_curves(c, d).points.size());
}
BENCHMARK(BM_IntersectCurves)->Unit(benchmark::kMillisecond);

}  // namespace
