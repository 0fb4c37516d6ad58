// ns per call of the complex incomplete gamma function Γ(a, z) in each region, and of one LA
// curve endpoint C(θ) by the igf closed form beside Gauss–Kronrod and RK4 on the same endpoint
// (002's timing case α = 2, Λ = 1, θ ∈ [0, 1], plus cases that use the other igf regions).
//   build/bench_special_gamma --benchmark_format=json   (times vary between runs: compare ratios)
#include <benchmark/benchmark.h>

#include <complex>

#include "lac/integrators/igf.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/integrators/igf.hpp"
#include "lac/special/incomplete_gamma.hpp"

namespace {

using cplx = std::complex<double>;

struct GammaCase {
  const char* label;
  double a;
  cplx z;
};
// One argument per region of special/incomplete_gamma.hpp.
const GammaCase kGammaCases[] = {
    {"series a=-2.5 z=-0.5i", -2.5, cplx(0, -0.5)}, {"series a=0 z=1.2i", 0.0, cplx(0, 1.2)},
    {"series a=7.25 z=-3i", 7.25, cplx(0, -3.0)},   {"cf a=2 z=-5i", 2.0, cplx(0, -5.0)},
    {"cf a=-0.5 z=-20i", -0.5, cplx(0, -20.0)},     {"asymptotic a=2 z=-100i", 2.0, cplx(0, -100.0)},
    {"asymptotic a=-5 z=-1e4i", -5.0, cplx(0, -1e4)},
};

void BM_GammaInc(benchmark::State& state) {
  const GammaCase& c = kGammaCases[state.range(0)];
  state.SetLabel(c.label);
  for (auto _ : state) {
    auto r = lac::special::gamma_inc(c.a, c.z);
    benchmark::DoNotOptimize(r.value);
  }
}
BENCHMARK(BM_GammaInc)->DenseRange(0, static_cast<int>(std::size(kGammaCases)) - 1);

void BM_GammaIncDifferenceSmallStep(benchmark::State& state) {
  for (auto _ : state) {
    auto r = lac::special::gamma_inc_difference(2.0, cplx(0, -1.0), cplx(0, -1.0 - 1e-6));
    benchmark::DoNotOptimize(r.value);
  }
}
BENCHMARK(BM_GammaIncDifferenceSmallStep);

struct EndpointCase {
  const char* label;
  double alpha, lambda, theta;
};
const EndpointCase kEndpoints[] = {
    {"002: alpha=2 lambda=1 theta=1 (gamma)", 2.0, 1.0, 1.0},
    {"alpha=0.5 lambda=1 theta=1 (gamma, a=-1)", 0.5, 1.0, 1.0},
    {"alpha=-1 lambda=1 theta=0.4 (gamma)", -1.0, 1.0, 0.4},
    {"alpha=1.001 lambda=1 theta=1 (segment series)", 1.001, 1.0, 1.0},
    {"alpha=2 lambda=100 theta=0.005 (lower series)", 2.0, 100.0, 0.005},
};

void BM_EndpointIgf(benchmark::State& state) {
  const EndpointCase& c = kEndpoints[state.range(0)];
  state.SetLabel(c.label);
  for (auto _ : state) {
    auto r = lac::igf_position_delta(c.alpha, c.lambda, 0.0, c.theta);
    benchmark::DoNotOptimize(r.value);
  }
}
BENCHMARK(BM_EndpointIgf)->DenseRange(0, static_cast<int>(std::size(kEndpoints)) - 1);

void BM_EndpointGaussKronrod(benchmark::State& state) {
  const EndpointCase& c = kEndpoints[state.range(0)];
  state.SetLabel(c.label);
  const lac::LaCurve curve(c.alpha, c.lambda);
  const lac::GaussKronrod gk;  // tol 1e-14
  for (auto _ : state) {
    auto r = lac::position_at(curve, lac::Parameter::theta, c.theta, gk, lac::Form::theta);
    benchmark::DoNotOptimize(r.point.position);
  }
}
BENCHMARK(BM_EndpointGaussKronrod)->DenseRange(0, static_cast<int>(std::size(kEndpoints)) - 1);

void BM_EndpointRk4(benchmark::State& state) {  // 002's method at its finest step
  const EndpointCase& c = kEndpoints[state.range(0)];
  state.SetLabel(c.label);
  const lac::LaCurve curve(c.alpha, c.lambda);
  const lac::Rk4 rk4{.h = 1e-3};
  for (auto _ : state) {
    auto r = lac::position_at(curve, lac::Parameter::theta, c.theta, rk4, lac::Form::theta);
    benchmark::DoNotOptimize(r.point.position);
  }
}
BENCHMARK(BM_EndpointRk4)->Arg(0);

}  // namespace
