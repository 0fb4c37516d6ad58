// Google Benchmark: quadratic LA curve (003) and the error-function inverses.
// Targets: κ(s) ≤ 200 ns per call; a 1000-point curve ≤ 200 µs.
// Run: build/bench_quadratic [--benchmark_format=json]
#include <benchmark/benchmark.h>

#include <boost/math/special_functions/erf.hpp>
#include <vector>

#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/special/erf_family.hpp"

namespace {

using lac::QuadraticLaCurve;
using lac::QuadraticOptions;
using lac::special::ErfInverseMethod;

// 003 Fig. 3–6 parameter sets: (α, γ, Λ).
constexpr double kSets[][3] = {{-1, -0.5, 1}, {1, 1, 1}, {3, -1, 1}, {1, -30, 0.5}};

std::vector<double> sample_s(const QuadraticLaCurve& c, int n) {
  const auto d = c.s_domain();
  const double lo = std::isfinite(d.lo) ? d.lo : -3.0, hi = std::isfinite(d.hi) ? d.hi : 3.0;
  std::vector<double> s(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) s[static_cast<size_t>(k)] = lo + (hi - lo) * (k + 0.5) / n;
  return s;
}

void BM_KappaOfS(benchmark::State& state) {
  const auto& p = kSets[state.range(0)];
  QuadraticOptions o;
  o.inverse = state.range(1) ? ErfInverseMethod::hybrid_003 : ErfInverseMethod::ours;
  const QuadraticLaCurve c(p[0], p[1], p[2], o);
  const auto s = sample_s(c, 256);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.solve_kappa(s[i++ & 255]));
  }
  state.SetLabel(std::string(to_string(o.inverse)) + " alpha=" + std::to_string(p[0]) + " gamma=" + std::to_string(p[1]));
}
BENCHMARK(BM_KappaOfS)->ArgsProduct({{0, 1, 2, 3}, {0, 1}});

void BM_SOfKappa(benchmark::State& state) {
  const auto& p = kSets[state.range(0)];
  const QuadraticLaCurve c(p[0], p[1], p[2]);
  double u = -2;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.s_at_log_kappa(u));
    u = u > 2 ? -2 : u + 0.013;
  }
}
BENCHMARK(BM_SOfKappa)->DenseRange(0, 3);

void BM_Polyline1000(benchmark::State& state) {
  const auto& p = kSets[state.range(0)];
  const QuadraticLaCurve c(p[0], p[1], p[2]);
  const auto d = c.s_domain();
  const double s0 = std::isfinite(d.lo) ? 0.99 * d.lo : -3.0, s1 = std::isfinite(d.hi) ? 0.99 * d.hi : 3.0;
  const auto method = lac::make_quadrature(state.range(1) == 0 ? "rk4" : "gauss-kronrod",
                                           state.range(1) == 0 ? lac::QuadratureOptions{(s1 - s0) / 999, {}}
                                                               : lac::QuadratureOptions{{}, 1e-10});
  for (auto _ : state) {
    benchmark::DoNotOptimize(lac::polyline(c, s0, s1, 1000, method));
  }
  state.SetLabel(state.range(1) == 0 ? "rk4 one step per segment" : "gauss-kronrod tol 1e-10");
}
BENCHMARK(BM_Polyline1000)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMicrosecond);

void BM_HermitePolyline1000(benchmark::State& state) {
  const auto& p = kSets[state.range(0)];
  const QuadraticLaCurve c(p[0], p[1], p[2]);
  const auto d = c.s_domain();
  const double s0 = std::isfinite(d.lo) ? 0.99 * d.lo : -3.0, s1 = std::isfinite(d.hi) ? 0.99 * d.hi : 3.0;
  for (auto _ : state) benchmark::DoNotOptimize(lac::hermite_polyline(c, s0, s1, 1000));
  state.SetLabel("hermite_polyline");
}
BENCHMARK(BM_HermitePolyline1000)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

void BM_ErfiInverse(benchmark::State& state) {
  const auto method = state.range(0) ? ErfInverseMethod::hybrid_003 : ErfInverseMethod::ours;
  std::vector<double> ys;
  for (double y = 1e-3; y < 1e290; y *= 3.7) ys.push_back(y);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lac::special::erfi_inv_detailed(ys[i], method));
    i = i + 1 == ys.size() ? 0 : i + 1;
  }
  state.SetLabel(std::string(to_string(method)) + ", y log-uniform in [1e-3, 1e290]");
}
BENCHMARK(BM_ErfiInverse)->Arg(0)->Arg(1);

void BM_ErfInverse(benchmark::State& state) {
  std::vector<double> ys;
  for (double y = -0.999999; y < 1; y += 0.0137) ys.push_back(y);
  size_t i = 0;
  for (auto _ : state) {
    if (state.range(0) == 0) benchmark::DoNotOptimize(boost::math::erf_inv(ys[i]));
    else benchmark::DoNotOptimize(lac::special::erf_inv_hybrid_003(ys[i]));
    i = i + 1 == ys.size() ? 0 : i + 1;
  }
  state.SetLabel(state.range(0) == 0 ? "Boost erf_inv" : "hybrid-003");
}
BENCHMARK(BM_ErfInverse)->Arg(0)->Arg(1);

}  // namespace
