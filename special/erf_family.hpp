#pragma once
// Error-function family for the quadratic LA curves (docs/math.md §4; 003 §2).
//   erfi, Dawson D(x) = (√π/2) e^(−x²) erfi(x), erfcx(x) = e^(x²) erfc(x): libcerf;
//   erf, erfc, erf⁻¹, erfc⁻¹: Boost.Math;
//   erfi⁻¹ (two methods, selectable) and log-argument inverses: written here, because neither
//   library has them. The log forms accept targets far beyond double range
//   (erfi(x) = ±e^L, erfc(x) = e^L), which is what the scaled quadratic-curve formulas need.
#include <string_view>

#include "lac/common/status.hpp"

namespace lac::special {

double erf(double x);     ///< Boost.Math
double erfc(double x);    ///< Boost.Math
double erfi(double x);    ///< libcerf; ±inf beyond |x| ≈ 26.64
double dawson(double x);  ///< libcerf
double erfcx(double x);   ///< libcerf; e^(x²) erfc(x), +inf for x < −26.6

/// Boost.Math erf⁻¹. InputError unless |y| < 1 (NaN included).
double erf_inv(double y);
/// Boost.Math erfc⁻¹. InputError unless 0 < q < 2.
double erfc_inv(double q);

/// Result of an iterative inverse: value, iterations (function evaluations in the loop), status.
struct InverseResult {
  double value = 0;
  int iterations = 0;
  Status status = Status::ok;
};

/// Which erfi⁻¹ / erf⁻¹ algorithm to use.
enum class ErfInverseMethod {
  ours,        ///< asymptotic initial guess + Halley with a bracket safeguard (whole double range)
  hybrid_003,  ///< 003 §4: Newton near 0, bisection on [−26, 26] (erfi) or [−5, 5] (erf) elsewhere
};
constexpr std::string_view to_string(ErfInverseMethod m) { return m == ErfInverseMethod::ours ? "ours" : "hybrid-003"; }
/// "ours" | "hybrid-003"; InputError otherwise.
ErfInverseMethod parse_erf_inverse_method(std::string_view name);

/// Caps shared by the iterative inverses.
inline constexpr int kMaxInverseIterations = 100;

/// erfi⁻¹(y) for every double y (±inf → ±inf; NaN → InputError). Relative error ≤ 1e-14
/// (tests/special_erf). Status max_iterations only if the cap is hit (never observed).
InverseResult erfi_inv_detailed(double y, ErfInverseMethod method = ErfInverseMethod::ours);
double erfi_inv(double y);

/// Solves erfi(x) = sign · e^L for x (sign = ±1), for any finite L: the inverse of
/// log|erfi| with no overflow for arguments beyond double range (x up to √(L + …)).
InverseResult erfi_inv_log(double log_abs_y, int sign);

/// Solves log erfc(x) = L for x, L < log 2 (any L below, e.g. −1e6): the inverse of erfc
/// for values below the smallest double. InputError for L ≥ log 2 or NaN.
InverseResult erfc_inv_log(double log_q);

/// 003's hybrid erf⁻¹ (for comparison): Newton near 0, bisection on [−5, 5] elsewhere.
/// |y| > erf(5) has no answer there: status no_solution, value clamped to ±5.
InverseResult erf_inv_hybrid_003(double y);
/// 003's hybrid erfi⁻¹: |y| > erfi(26) gives status no_solution, value clamped to ±26.
InverseResult erfi_inv_hybrid_003(double y);

}  // namespace lac::special
