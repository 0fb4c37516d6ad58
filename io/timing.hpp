#pragma once
// Repeated wall-clock timing with median and spread, for timing experiments (benchmarks
// proper use Google Benchmark in bench/). Never used in unit tests.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace lac::io {

struct TimingStats {
  double median = 0;   ///< seconds per call
  double p10 = 0;      ///< 10th percentile
  double p90 = 0;      ///< 90th percentile
  size_t samples = 0;  ///< timed batches
  size_t calls_per_sample = 0;
};

/// Summary of raw per-call seconds.
inline TimingStats summarize(std::vector<double> t, size_t calls_per_sample = 1) {
  TimingStats s;
  if (t.empty()) return s;
  std::sort(t.begin(), t.end());
  auto q = [&](double p) { return t[static_cast<size_t>(p * static_cast<double>(t.size() - 1) + 0.5)]; };
  s.median = q(0.5);
  s.p10 = q(0.1);
  s.p90 = q(0.9);
  s.samples = t.size();
  s.calls_per_sample = calls_per_sample;
  return s;
}

/// Times fn() in batches: each sample runs fn enough times to take about `sample_seconds`,
/// `samples` samples are taken; returns seconds per call. A compiler barrier is the caller's job
/// (return something from fn and accumulate it).
template <class Fn>
TimingStats time_calls(Fn&& fn, size_t samples = 15, double sample_seconds = 0.01) {
  using clock = std::chrono::steady_clock;
  size_t batch = 1;
  for (;;) {  // calibrate the batch size (capped at 2^24 calls)
    const auto t0 = clock::now();
    for (size_t i = 0; i < batch; ++i) fn();
    const double dt = std::chrono::duration<double>(clock::now() - t0).count();
    if (dt >= sample_seconds || batch >= (1u << 24)) break;
    batch *= 2;
  }
  std::vector<double> per_call;
  per_call.reserve(samples);
  for (size_t k = 0; k < samples; ++k) {
    const auto t0 = clock::now();
    for (size_t i = 0; i < batch; ++i) fn();
    per_call.push_back(std::chrono::duration<double>(clock::now() - t0).count() / static_cast<double>(batch));
  }
  return summarize(std::move(per_call), batch);
}

/// Seconds since construction.
class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace lac::io
