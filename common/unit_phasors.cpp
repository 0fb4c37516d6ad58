#include "lac/common/detail/unit_phasors.hpp"

#include <cmath>

#if defined(LAC_HAVE_LIBMVEC) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define LAC_UNIT_PHASORS_LIBMVEC 1
// glibc's libmvec, x86-64 vector function ABI: 'b' = SSE (2 lanes), 'd' = AVX2 (4 lanes),
// v = one vector argument.
extern "C" __m128d _ZGVbN2v_cos(__m128d);
extern "C" __m128d _ZGVbN2v_sin(__m128d);
extern "C" __attribute__((target("avx2,fma"))) __m256d _ZGVdN4v_cos(__m256d);
extern "C" __attribute__((target("avx2,fma"))) __m256d _ZGVdN4v_sin(__m256d);
#endif

namespace lac::detail {
namespace {

#ifdef LAC_UNIT_PHASORS_LIBMVEC
// Lane-wise functions: a value's result does not depend on its neighbours, so the last group is
// padded with copies of its first value.
__attribute__((target("avx2,fma"))) void phasors_avx2(const double* phi, std::size_t n, double* c, double* s) {
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m256d v = _mm256_loadu_pd(phi + k);
    _mm256_storeu_pd(c + k, _ZGVdN4v_cos(v));
    _mm256_storeu_pd(s + k, _ZGVdN4v_sin(v));
  }
  if (k < n) {
    double x[4], cv[4], sv[4];
    for (std::size_t j = 0; j < 4; ++j) x[j] = phi[k + j < n ? k + j : k];
    const __m256d v = _mm256_loadu_pd(x);
    _mm256_storeu_pd(cv, _ZGVdN4v_cos(v));
    _mm256_storeu_pd(sv, _ZGVdN4v_sin(v));
    for (std::size_t j = 0; k + j < n; ++j) c[k + j] = cv[j], s[k + j] = sv[j];
  }
}
void phasors_sse(const double* phi, std::size_t n, double* c, double* s) {
  for (std::size_t k = 0; k < n; k += 2) {
    const __m128d v = _mm_set_pd(phi[k + 1 < n ? k + 1 : k], phi[k]);
    double cv[2], sv[2];
    _mm_storeu_pd(cv, _ZGVbN2v_cos(v));
    _mm_storeu_pd(sv, _ZGVbN2v_sin(v));
    c[k] = cv[0], s[k] = sv[0];
    if (k + 1 < n) c[k + 1] = cv[1], s[k + 1] = sv[1];
  }
}
#else
void phasors_scalar(const double* phi, std::size_t n, double* c, double* s) {
  for (std::size_t k = 0; k < n; ++k) {
    c[k] = std::cos(phi[k]);
    s[k] = std::sin(phi[k]);
  }
}
#endif

using Phasors = void (*)(const double*, std::size_t, double*, double*);
struct Choice {
  Phasors f;
  const char* name;
};
Choice choose() {
#ifdef LAC_UNIT_PHASORS_LIBMVEC
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return {phasors_avx2, "libmvec-avx2"};
  return {phasors_sse, "libmvec-sse"};
#else
  return {phasors_scalar, "libm"};
#endif
}
const Choice& choice() {
  static const Choice c = choose();
  return c;
}

}  // namespace

void unit_phasors(const double* phi, std::size_t n, double* c, double* s) { choice().f(phi, n, c, s); }

std::string_view unit_phasors_method() { return choice().name; }

}  // namespace lac::detail
