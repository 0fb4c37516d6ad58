#pragma once
// ∫ e^{iφ(u)} du over a segment in linear-q form (curves/planar/la_law.hpp) with any method of the
// quadrature registry: what the 004 constructions integrate for every trial curve and for the
// returned one. The methods that integrate any integrand go through LaSegment's kernels
// (curves/planar/la_segment.hpp; gauss-legendre through the segment kernel); igf, a closed form of the
// standard form, through the standard-form conversion (curves/planar/standard_form.hpp).
#include <complex>
#include <limits>

#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/curves/planar/la_segment.hpp"
#include "lac/curves/planar/la_segment_igf.hpp"
#include "lac/integrators/registry.hpp"

namespace lac::detail {


/// The integral of trial data (possibly non-finite or not a valid segment) with one method of the
/// registry, chosen once: NaN when the method fails (an unusable status, or data no segment has),
/// which the solvers treat as a failed evaluation. Every method has the fast path's domain: a
/// piece (a side of a zero of q) turning more than kMaxResolvedTurning gives NaN without
/// evaluating the integrand, so the choice of method does not change which trial curves exist.
/// With a limit, a call whose `evaluations` counter has reached it gives NaN at once too (the
/// construction's evaluation budget; the caller reports it). gauss-legendre is LaSegment's
/// GaussLegendre path without its error estimate (its value bit for bit): the segment kernel
/// (curves/planar/la_segment_kernel.hpp), else detail::integrate_tangent. Keeps a pointer
/// to the method: the method must outlive the integrator.
class TrialIntegrator {
 public:
  explicit TrialIntegrator(const AnyQuadrature& method, long limit = std::numeric_limits<long>::max());
  /// `kernel_bound` (optional): the segment kernel's error bound where the value is the kernel's
  /// (segment_integral of curves/planar/la_segment_kernel.hpp, gauss-legendre), else NaN.
  std::complex<double> operator()(const LaLaw& law, const LinearQ& seg, long& evaluations,
                                  double* kernel_bound = nullptr) const {
    if (evaluations >= limit_) {
      if (kernel_bound) *kernel_bound = std::numeric_limits<double>::quiet_NaN();
      return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    }
    return integrate_(method_, law, seg, evaluations, kernel_bound);
  }
  /// Calls whose counter has reached `limit` give NaN (no limit: the largest long).
  void set_limit(long limit) { limit_ = limit; }
  long limit() const { return limit_; }

 private:
  using Integrate = std::complex<double> (*)(const void*, const LaLaw&, const LinearQ&, long&, double*);
  const void* method_ = nullptr;
  Integrate integrate_ = nullptr;
  long limit_ = std::numeric_limits<long>::max();
};

}  // namespace lac::detail
