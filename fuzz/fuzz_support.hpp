#pragma once
// Shared harness of the libFuzzer targets (docs/robustness.md):
//   FuzzInput   turns the fuzz bytes into doubles that favour the hard cases (NaN, ±inf, ±0,
//               denormals, huge and tiny values, exact small integers) and ints in a range;
//   guarded     runs one library call and enforces the error contract: success, or an
//               InputError with a non-empty parameter(); any other exception is a finding;
//   CallTimer   per-call CPU-time bound (LAC_FUZZ_CALL_SECONDS, default 1 s);
//   require_finite_result  no NaN or inf in a successful result.
// Every violation prints one line starting with "LAC_FUZZ_<KIND>:" and aborts, so that
// scripts/fuzz.sh can classify the saved input by replaying it.
#include <time.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <set>
#include <string>

#include "lac/common/error.hpp"

namespace lac::fuzz {

/// Thrown by finding() in continue mode to abandon the current input.
struct FindingRecorded {};

namespace detail {
inline const uint8_t* current_data = nullptr;
inline size_t current_size = 0;
inline std::string current_call;  ///< the guarded call in progress (context of findings)

/// The message with numbers removed: one signature per kind of failure, not per input.
inline std::string signature(const std::string& kind, const std::string& what) {
  std::string sig = kind + " ";
  for (size_t i = 0; i < what.size() && sig.size() < 160; ++i) {
    const char c = what[i];
    if (what.compare(i, 3, "nan") == 0 || what.compare(i, 3, "inf") == 0) {
      i += 2;
      continue;
    }
    const bool numeric = (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' ||
                         ((c == 'e' || c == 'E') && i > 0 && what[i - 1] >= '0' && what[i - 1] <= '9');
    if (!numeric) sig.push_back(c);
  }
  return sig;
}

/// FNV-1a of a byte string (names saved findings; picks rare options from the whole input).
inline uint64_t fnv1a(const uint8_t* data, size_t size) {
  uint64_t hash = 1469598103934665603ull;
  for (size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 1099511628211ull;
  return hash;
}

inline bool continue_mode() {
  static const bool on = [] {
    const char* env = std::getenv("LAC_FUZZ_CONTINUE");
    return env && *env == '1';
  }();
  return on;
}
}  // namespace detail

/// Reports a violated property: one line "LAC_FUZZ_<KIND>: <what>" on stderr. By default it
/// aborts (libFuzzer saves the input). With LAC_FUZZ_CONTINUE=1 (scripts/fuzz.sh) it saves the
/// input once per signature as $LAC_FUZZ_FINDINGS_DIR/<kind>-<hash> and throws FindingRecorded,
/// so that one known failure does not stop the search for others.
inline void report_finding(const char* kind, const std::string& what) {
  const std::string full = detail::current_call.empty() || what.find(detail::current_call) != std::string::npos
                               ? what
                               : what + " in " + detail::current_call;
  std::fprintf(stderr, "LAC_FUZZ_%s: %s\n", kind, full.c_str());
  if (!detail::continue_mode()) {
    std::fflush(stderr);
    std::abort();
  }
  static std::set<std::string> seen;
  const std::string sig = detail::signature(kind, full);
  if (!seen.insert(sig).second) return;
  const uint64_t hash = detail::fnv1a(reinterpret_cast<const uint8_t*>(sig.data()), sig.size());
  const char* dir = std::getenv("LAC_FUZZ_FINDINGS_DIR");
  if (!dir || !detail::current_data) return;
  char name[64];
  std::snprintf(name, sizeof name, "/%s-%016llx", kind, static_cast<unsigned long long>(hash));
  const std::string path = std::string(dir) + name;
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(detail::current_data, 1, detail::current_size, f);
    std::fclose(f);
    std::fprintf(stderr, "LAC_FUZZ_SAVED: %s\n", path.c_str());
  }
}

[[noreturn]] inline void finding(const char* kind, const std::string& what) {
  report_finding(kind, what);
  throw FindingRecorded{};
}

/// Bytes → typed values; reads past the end return zeros, so every input is usable.
class FuzzInput {
 public:
  FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {
    detail::current_data = data;
    detail::current_size = size;
  }

  bool empty() const { return pos_ >= size_; }
  size_t remaining() const { return empty() ? 0 : size_ - pos_; }
  const uint8_t* cursor() const { return data_ + pos_; }
  void skip(size_t n) { pos_ = n >= remaining() ? size_ : pos_ + n; }

  uint8_t byte() { return empty() ? 0 : data_[pos_++]; }

  /// Integer in [lo, hi].
  int int_in(int lo, int hi) {
    const uint32_t span = static_cast<uint32_t>(hi - lo) + 1u;
    uint32_t v = byte();
    v = (v << 8) | byte();
    return lo + static_cast<int>(v % span);
  }

  /// A double: one selector byte chooses a special value, raw IEEE bits, or a moderate value
  /// (most library domains are a few units wide, so moderate values reach the deep code).
  double number() {
    const uint8_t sel = byte();
    switch (sel % 8) {
      case 0: return special(sel / 8);
      case 1: return raw();
      case 2: return std::ldexp(moderate(), int_in(-60, 60));  // any scale, few mantissa bits
      default: return moderate();
    }
  }
  /// A double that is finite and positive more often (scales, tolerances, lambdas).
  double positive() {
    const double v = number();
    return std::isnan(v) ? v : std::abs(v);
  }

  static double special(int k) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    static const double table[] = {std::numeric_limits<double>::quiet_NaN(),
                                   inf,
                                   -inf,
                                   0.0,
                                   -0.0,
                                   std::numeric_limits<double>::denorm_min(),
                                   -std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::epsilon(),
                                   1e-300,
                                   1e300,
                                   -1e300,
                                   1.0,
                                   -1.0,
                                   0.5,
                                   2.0,
                                   1.0 + 1e-15,
                                   1.0 - 1e-16,
                                   M_PI,
                                   -M_PI,
                                   M_PI / 2,
                                   1e-8,
                                   -1e-8,
                                   26.64,
                                   -26.64,
                                   10.0,
                                   -10.0,
                                   5.0,
                                   -5.0,
                                   std::numeric_limits<double>::signaling_NaN()};
    return table[static_cast<size_t>(k) % (sizeof table / sizeof table[0])];
  }

 private:
  double raw() {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = (bits << 8) | byte();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  /// A value in [−8, 8] with 1/4096 resolution.
  double moderate() {
    const int v = (static_cast<int>(byte()) << 8) | byte();
    return (v - 32768) / 4096.0;
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

inline std::string show(double v) { return format_number(v); }

/// Reports a hang when the call that started at construction used more than the bound in CPU
/// time (process CPU time, so that other processes on the machine do not make false hangs; calls that
/// never return are caught by libFuzzer's wall-clock -timeout).
class CallTimer {
 public:
  explicit CallTimer(std::string what) : what_(std::move(what)), start_(cpu_seconds()) {}
  ~CallTimer() {
    const double seconds = cpu_seconds() - start_;
    if (seconds > limit()) report_finding("HANG", what_ + " took " + std::to_string(seconds) + " s CPU");
  }
  static double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
  static double limit() {
    static const double value = [] {
      const char* env = std::getenv("LAC_FUZZ_CALL_SECONDS");
      const double v = env ? std::atof(env) : 0.0;
      return v > 0 ? v : 1.0;
    }();
    return value;
  }

 private:
  std::string what_;
  double start_;
};

/// Runs `call` under the time bound; true on success, false on an InputError that names its
/// parameter. Any other exception, or an InputError with an empty parameter, is a finding.
template <class Call>
bool guarded(const std::string& what, Call&& call) {
  struct CallContext {
    std::string saved = detail::current_call;
    ~CallContext() { detail::current_call = saved; }
  } context;
  detail::current_call = what;
  static const bool trace = std::getenv("LAC_FUZZ_TRACE") != nullptr;  // replaying a finding: print each call
  if (trace) std::fprintf(stderr, "call: %s\n", what.c_str());
  CallTimer timer(what);
  try {
    call();
    return true;
  } catch (const FindingRecorded&) {
    throw;
  } catch (const InputError& e) {
    if (e.parameter().empty()) finding("EMPTY_PARAMETER", what + ": " + e.what());
    return false;
  } catch (const std::exception& e) {
    finding("EXCEPTION", what + ": unexpected exception (not InputError): " + e.what());
  } catch (...) {
    finding("EXCEPTION", what + ": unexpected non-std exception");
  }
}

inline void require_finite_result(const std::string& what, double v) {
  if (!std::isfinite(v)) finding("NAN", what + " = " + show(v) + " in a successful result");
}
inline void require_finite_result(const std::string& what, std::complex<double> v) {
  require_finite_result(what + ".real", v.real());
  require_finite_result(what + ".imag", v.imag());
}
/// NaN is never acceptable; ±inf only where the function documents it.
inline void require_not_nan(const std::string& what, double v) {
  if (std::isnan(v)) finding("NAN", what + " = nan in a successful result");
}

/// Each target defines this; the entry point below ends an input at a recorded finding.
int fuzz_one(FuzzInput& in);

}  // namespace lac::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lac::fuzz::FuzzInput in(data, size);
  try {
    return lac::fuzz::fuzz_one(in);
  } catch (const lac::fuzz::FindingRecorded&) {
    return 0;
  }
}
