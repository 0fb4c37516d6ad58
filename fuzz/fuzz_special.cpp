// libFuzzer target: special functions (special/) fed arbitrary doubles: the complex upper
// incomplete gamma function and its scaled / difference forms, the erf family and every
// inverse (erfi⁻¹ by both methods, log-argument inverses, 003's hybrids, Boost erf⁻¹/erfc⁻¹).
// Properties: see fuzz/fuzz_support.hpp. ±inf is accepted only where a header documents it.
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "lac/special/erf_family.hpp"
#include "lac/special/incomplete_gamma.hpp"

using namespace lac;
using lac::fuzz::guarded;
using lac::fuzz::require_finite_result;
using lac::fuzz::require_not_nan;
using lac::fuzz::show;

namespace {

void check_gamma(const std::string& what, const special::GammaIncResult& r) {
  if (usable(r.status) || r.status == Status::max_iterations) require_finite_result(what, r.value);
}

void check_inverse(const std::string& what, const special::InverseResult& r, bool inf_allowed) {
  require_not_nan(what, r.value);
  if (usable(r.status) && !inf_allowed) require_finite_result(what, r.value);
}

}  // namespace

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const int which = in.byte() % 6;
  const double x = in.number(), y = in.number(), u = in.number(), v = in.number();
  const std::string args = "(" + show(x) + ", " + show(y) + ", " + show(u) + ", " + show(v) + ")";
  switch (which) {
    case 0:
      guarded("gamma_inc" + args, [&] { check_gamma("gamma_inc", special::gamma_inc(x, {y, u})); });
      break;
    case 1:
      guarded("gamma_inc_scaled" + args, [&] { check_gamma("gamma_inc_scaled", special::gamma_inc_scaled(x, {y, u})); });
      break;
    case 2: {
      const double w = in.number();
      const std::string a5 = args + " z2.imag " + show(w);
      guarded("gamma_inc_difference" + a5,
              [&] { check_gamma("gamma_inc_difference", special::gamma_inc_difference(x, {y, u}, {v, w})); });
      guarded("gamma_inc_difference_scaled" + a5, [&] {
        check_gamma("gamma_inc_difference_scaled", special::gamma_inc_difference_scaled(x, {y, u}, {v, w}));
      });
      break;
    }
    case 3:  // forward functions: NaN only for NaN input; erfi and erfcx may overflow to +-inf
      if (!std::isnan(x)) {
        guarded("erf" + args, [&] { require_not_nan("erf", special::erf(x)); });
        guarded("erfc" + args, [&] { require_not_nan("erfc", special::erfc(x)); });
        guarded("erfi" + args, [&] { require_not_nan("erfi", special::erfi(x)); });
        guarded("dawson" + args, [&] { require_finite_result("dawson", special::dawson(x)); });
        guarded("erfcx" + args, [&] { require_not_nan("erfcx", special::erfcx(x)); });
      }
      break;
    case 4:
      guarded("erfi_inv_detailed ours" + args, [&] {
        check_inverse("erfi_inv ours", special::erfi_inv_detailed(x, special::ErfInverseMethod::ours), std::isinf(x));
      });
      guarded("erfi_inv_detailed hybrid" + args, [&] {
        check_inverse("erfi_inv hybrid", special::erfi_inv_detailed(x, special::ErfInverseMethod::hybrid_003), std::isinf(x));
      });
      guarded("erfi_inv_hybrid_003" + args,
              [&] { check_inverse("erfi_inv_hybrid_003", special::erfi_inv_hybrid_003(x), false); });
      guarded("erf_inv_hybrid_003" + args, [&] { check_inverse("erf_inv_hybrid_003", special::erf_inv_hybrid_003(x), false); });
      guarded("erf_inv" + args, [&] { require_finite_result("erf_inv", special::erf_inv(x)); });
      guarded("erfc_inv" + args, [&] { require_finite_result("erfc_inv", special::erfc_inv(x)); });
      break;
    case 5:
      guarded("erfi_inv_log" + args,
              [&] { check_inverse("erfi_inv_log", special::erfi_inv_log(x, y < 0 ? -1 : 1), x == INFINITY); });
      // The limits L = +inf (erfi) and L = -inf (erfc: q = 0) map to ±inf, as the code documents.
      guarded("erfc_inv_log" + args, [&] { check_inverse("erfc_inv_log", special::erfc_inv_log(x), x == -INFINITY); });
      break;
  }
  return 0;
}
