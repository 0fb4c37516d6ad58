// bench_p002: Google Benchmark for 002 Appendix A (docs/p002.md).
//   Endpoint/<method>/<row>  C(θ = 1) of each of the 18 Appendix A rows, per method, through the
//                            run-time registry (igf joins when it is registered); counters:
//                            rel_error against the 40-digit reference, evaluations.
//   Segment/...              RK4 with h = 0.001 over θ ∈ [0, 1] on the α = 2, Λ = 1 row:
//                            quadrature endpoint (2 new evaluations per step), the literal RK4 ODE
//                            with an observer collecting the 1001 step points (4 evaluations per
//                            step, as 002's Butcher tableau), the library polyline of 1001 points
//                            (one RK4 sweep, 2 new evaluations per step), and the 1001 frames alone
//                            (as polyline computes them: both ends' domain checked once, then
//                            LaCurve::frames_inside; the polyline's cost that is not
//                            quadrature).
// Targets: best endpoint ≤ 1e-13 relative in ≤ 2 µs median on every row; RK4 h = 0.001
// over a segment ≤ 150 µs median. Run with --benchmark_repetitions=5 for medians; absolute times
// vary between runs, so compare methods within one run.
#include <benchmark/benchmark.h>

#include <complex>
#include <string>
#include <vector>

#include "lac/curves/planar/la_position.hpp"
#include "experiments/p002_data.hpp"
#include "lac/integrators/ode.hpp"

namespace {

struct BenchMethod {
  std::string label;
  std::string name;
  lac::QuadratureOptions options;
};

std::vector<BenchMethod> bench_methods() {
  std::vector<BenchMethod> m = {{"rk4_h=1e-3", "rk4", {1e-3, std::nullopt}},
                                {"gauss-kronrod_tol=1e-14", "gauss-kronrod", {}},
                                {"gauss-kronrod_tol=1e-8", "gauss-kronrod", {std::nullopt, 1e-8}},
                                {"gauss-kronrod_tol=1e-6", "gauss-kronrod", {std::nullopt, 1e-6}},
                                {"rk45_tol=1e-12", "rk45", {}}};
  m.push_back({"igf", "igf", {}});
  return m;
}

void endpoint(benchmark::State& state, lac::p002::ReferenceEnd ref, lac::AnyQuadrature method) {
  const lac::LaCurve curve(ref.alpha, ref.lambda);
  lac::PositionResult r;
  for (auto _ : state) {
    r = lac::position_at(curve, lac::Parameter::theta, ref.theta_end, method);
    benchmark::DoNotOptimize(r.point.position);
  }
  state.counters["rel_error"] = std::abs(r.point.position - ref.c) / ref.abs_c;
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
  state.counters["status_ok"] = r.status == lac::Status::ok ? 1 : 0;
}

void segment_quadrature(benchmark::State& state, lac::p002::ReferenceEnd ref) {
  const lac::LaCurve curve(ref.alpha, ref.lambda);
  const lac::Rk4 rk4{.h = 1e-3};
  lac::PositionResult r;
  for (auto _ : state) {
    r = lac::position_at(curve, lac::Parameter::theta, ref.theta_end, rk4, lac::Form::theta);
    benchmark::DoNotOptimize(r.point.position);
  }
  state.counters["rel_error"] = std::abs(r.point.position - ref.c) / ref.abs_c;
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
}

void segment_ode_observer(benchmark::State& state, lac::p002::ReferenceEnd ref) {
  const lac::LaCurve curve(ref.alpha, ref.lambda);
  auto f = [&curve](double psi, const std::complex<double>&) {
    return std::polar(std::exp(curve.log_rho_at_theta_unchecked(psi)), psi);  // θ-form, 002 Eq. (11)
  };
  std::vector<std::complex<double>> points;
  points.reserve(1001);
  lac::OdeResult<std::complex<double>> r;
  for (auto _ : state) {
    points.clear();
    points.push_back({});
    r = lac::rk4_integrate(f, std::complex<double>{}, 0.0, ref.theta_end, 1e-3, [&](double, const std::complex<double>& y) {
      points.push_back(y);
      return true;
    });
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["rel_error"] = std::abs(r.state - ref.c) / ref.abs_c;
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
  state.counters["points"] = static_cast<double>(points.size());
}

void segment_polyline(benchmark::State& state, lac::p002::ReferenceEnd ref) {
  const lac::LaCurve curve(ref.alpha, ref.lambda);
  const lac::Rk4 rk4{.h = 1e-3};
  std::vector<lac::PositionResult> line;
  for (auto _ : state) {
    line = lac::polyline(curve, lac::Parameter::theta, 0.0, ref.theta_end, 1001, rk4, lac::Form::theta);
    benchmark::DoNotOptimize(line.data());
  }
  state.counters["rel_error"] = std::abs(line.back().point.position - ref.c) / ref.abs_c;
  state.counters["evaluations"] = static_cast<double>(line.back().evaluations);
}

/// The 1001 frames (s, θ, ρ, κ) alone, as polyline computes them before integrating (domain
/// checked at both ends, then LaCurve::frames_inside): the part of the polyline time that is
/// not quadrature.
void segment_frames(benchmark::State& state, lac::p002::ReferenceEnd ref) {
  const lac::LaCurve curve(ref.alpha, ref.lambda);
  std::vector<lac::CurvePoint> frames(1001);
  for (auto _ : state) {
    curve.check(lac::Parameter::theta, 0.0, "theta");
    curve.check(lac::Parameter::theta, ref.theta_end, "theta");
    for (int k = 0; k < 1001; ++k)
      frames[static_cast<size_t>(k)] = lac::CurvePoint{.theta = k == 1000 ? ref.theta_end : ref.theta_end * k / 1000.0};
    curve.frames_inside(lac::Parameter::theta, frames);
    benchmark::DoNotOptimize(frames.data());
  }
}

/// Registers every benchmark before benchmark_main runs.
const bool registered = [] {
  const auto rows = lac::p002::reference_set(lac::p002::read_reference(), "appendix_a");
  for (const auto& bm : bench_methods()) {
    const lac::AnyQuadrature method = lac::make_quadrature(bm.name, bm.options);
    for (const auto& ref : rows) {
      const std::string label = "Endpoint/" + bm.label + "/alpha=" + ref.alpha_text + "/Lambda=" + lac::format_number(ref.lambda);
      benchmark::RegisterBenchmark(label.c_str(), endpoint, ref, method)->Unit(benchmark::kMicrosecond)->MinTime(0.05);
    }
  }
  const auto& row = lac::p002::find_reference(rows, "appendix_a", "2", 1.0);
  benchmark::RegisterBenchmark("Segment/rk4_h=1e-3/quadrature_endpoint/alpha=2/Lambda=1", segment_quadrature, row)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("Segment/rk4_h=1e-3/ode_observer_1001_points/alpha=2/Lambda=1", segment_ode_observer, row)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("Segment/rk4_h=1e-3/library_polyline_1001_points/alpha=2/Lambda=1", segment_polyline, row)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("Segment/frames_only_1001_points/alpha=2/Lambda=1", segment_frames, row)
      ->Unit(benchmark::kMicrosecond);
  return true;
}();

}  // namespace
