#include "lac/constructions/detail/tangent_integral.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/curves/detail/polyline.hpp"
#include "lac/curves/planar/la_segment_kernel.hpp"
#include "lac/curves/planar/standard_form.hpp"

namespace lac::detail {
namespace {

using Complex = std::complex<double>;

// Whether every piece of the segment (each side of a zero of q, where φ is monotonic) turns at most
// kMaxResolvedTurning: the domain of detail::integrate_tangent, applied to every method.
bool resolvable(const LaLaw& law, const LinearQ& seg) {
  const TangentPlan plan = tangent_plan(law, seg);
  for (int i = 0; i < plan.count; ++i) {
    const TangentPiece& p = plan.pieces[static_cast<size_t>(i)];
    const double turning = p.graded ? std::abs(p.delta) * (1.0 - std::pow(p.t0, p.beta))
                                    : std::abs(seg.phi_at(law, p.e) - seg.phi_at(law, p.u0));
    if (!(turning <= kMaxResolvedTurning)) return false;
  }
  return true;
}

template <class M>
Complex trial_integral(const void* method, const LaLaw& law, const LinearQ& seg, long& evaluations, double* bound) {
  const M& m = *static_cast<const M*>(method);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (bound) *bound = kNaN;
  if constexpr (std::is_same_v<M, GaussLegendre>) {
    // The segment kernel (curves/planar/la_segment_kernel.hpp), on the same trial domain as every
    // method; the graded fast path where the kernel does not evaluate the segment.
    if (!resolvable(law, seg)) return {kNaN, kNaN};
    if (const auto k = segment_integral(law, seg, evaluations)) {
      if (bound) *bound = k->error;
      return k->value;
    }
    return integrate_tangent(law, seg, evaluations, m.panels);
  } else {
    // The same trial domain for every method: a piece turning more than the fast path resolves is a
    // failed evaluation here too, not seconds of an adaptive rule on 10^4–10^8 rad (fuzz_hermite:
    // the simplex with gk-tanh-sinh spent 2.7 s on |κ·chord| ~ 1e8).
    if (!resolvable(law, seg)) return {kNaN, kNaN};
    IntegralResult<Complex> r;
    if constexpr (std::is_same_v<M, Igf>) {
      try {
        r = integrate_tangent_igf(law, seg, m);
      } catch (const InputError&) {  // trial data no segment has (e.g. q through 0 for α > 0)
        return {kNaN, kNaN};
      }
    } else {
      r = integrate_tangent_with(law, seg, m);
    }
    evaluations += r.evaluations;
    return usable(r.status) ? r.value : Complex{kNaN, kNaN};
  }
}

}  // namespace

TrialIntegrator::TrialIntegrator(const AnyQuadrature& method, long limit) : limit_(limit) {
  std::visit(
      [this](const auto& m) {
        method_ = &m;
        integrate_ = &trial_integral<std::decay_t<decltype(m)>>;
      },
      method);
}

}  // namespace lac::detail
