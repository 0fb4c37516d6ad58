#pragma once
// cos and sin of a batch of angles at once: the e^{iφ} of a quadrature panel's nodes
// (curves/planar/la_segment_kernel.cpp). By glibc's vector math library libmvec where the build
// found it (LAC_HAVE_LIBMVEC, x86-64): four at a time on CPUs with AVX2 and FMA, two at a time
// (SSE) otherwise; std::cos/std::sin elsewhere. libmvec is within 4 ulp (glibc's manual);
// tests/common/unit_phasors_test.cpp measures it against long double. The last bits of a result
// can differ between these three methods, hence between CPUs (docs/kernel.md).
#include <cstddef>
#include <string_view>

namespace lac::detail {

/// c[k] = cos(phi[k]), s[k] = sin(phi[k]) for k < n.
void unit_phasors(const double* phi, std::size_t n, double* c, double* s);

/// The method this process uses: "libmvec-avx2", "libmvec-sse" or "libm".
std::string_view unit_phasors_method();

}  // namespace lac::detail
