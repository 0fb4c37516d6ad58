#include "lac/curves/space/certified_frenet.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

#include "lac/curves/detail/taylor_frame.hpp"

namespace lac {
namespace {

constexpr int kTerms = detail::kTaylorTerms;
constexpr double kEps = DBL_EPSILON;

/// κ_i, τ_i of the law from logarithms so that no factor overflows on its own.
detail::FrameSeries law_series(const LaSpaceCurve& c, double s, double h) {
  detail::FrameSeries out;
  const double lr = c.log_rho(s), lm = c.log_mu(s), lh = std::log(h);
  // κ' = −Λκ^(1+α), τ' = −σΩτ^(1+β) (σ = +1 type 1, −1 type 2): docs/export.md.
  const double sk = -1.0, st = c.type() == TorsionType::type1 ? -1.0 : 1.0;
  const double llam = std::log(c.lambda()), lom = std::log(c.omega());
  double log_ck = 0, log_ct = 0, sign_k = 1, sign_t = 1;  // log(|∏|/i!) and its sign
  double abs_k = 0, abs_t = 0;  // Σ of the absolute values of the logarithms summed into log_ck, log_ct
  for (int i = 0; i < kTerms; ++i) {
    out.kappa[i] = sign_k * std::exp(log_ck - (1 + i * c.alpha()) * lr + (i + 1) * lh);
    out.tau[i] = sign_t * std::exp(log_ct - (1 + i * c.beta()) * lm + (i + 1) * lh);
    // Each exponent's rounding: its terms' ulps, log ρ and log μ to a few ulps of 1 + |·|.
    const double ak = std::abs(1 + i * c.alpha()), at = std::abs(1 + i * c.beta()), ah = (i + 1) * (1 + std::abs(lh));
    const double relative = 8 * kEps * (2 * i + 2 + std::max(abs_k + ak * (1 + std::abs(lr)), abs_t + at * (1 + std::abs(lm))) + ah);
    out.kappa_error[i] = relative * std::abs(out.kappa[i]);
    out.tau_error[i] = relative * std::abs(out.tau[i]);
    const double fk = 1 + i * c.alpha(), ft = 1 + i * c.beta(), lf = std::log(i + 1.0);
    log_ck += llam + std::log(std::abs(fk)) - lf;  // −inf once Λ = 0 or 1 + iα = 0: the rest are 0
    log_ct += lom + std::log(std::abs(ft)) - lf;
    if (std::isfinite(log_ck)) abs_k += std::abs(llam) + std::abs(std::log(std::abs(fk))) + lf;
    if (std::isfinite(log_ct)) abs_t += std::abs(lom) + std::abs(std::log(std::abs(ft))) + lf;
    sign_k *= fk < 0 ? -sk : sk;
    sign_t *= ft < 0 ? -st : st;
  }
  return out;
}

}  // namespace

CertifiedFrame integrate_frenet_certified(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1,
                                          double start_position_error, double start_frame_error) {
  constexpr const char* who = "integrate_frenet_certified";
  detail::check_frenet_input(curve, start, s0, s1, who);
  if (!(start_position_error >= 0) || !std::isfinite(start_position_error))
    throw_input_error(who, "start_position_error", start_position_error, "[0, inf)");
  if (!(start_frame_error >= 0) || !std::isfinite(start_frame_error))
    throw_input_error(who, "start_frame_error", start_frame_error, "[0, inf)");
  Eigen::Matrix3d F;
  F << start.t, start.n, start.b;
  const detail::FrameSeriesFunction series = [&](double s, double h) { return law_series(curve, s, h); };
  const detail::TaylorFrame t = detail::integrate_taylor_frame(series, detail::end_majorant(series), F, start.p, s0, s1, start_position_error,
      start_frame_error, who);
  CertifiedFrame r;
  r.frame = {t.position, t.frame.col(0), t.frame.col(1), t.frame.col(2)};
  r.position_error = t.position_error;
  r.frame_error = t.frame_error;
  r.steps = t.steps;
  r.status = t.status;
  r.message = t.message;
  return r;
}

}  // namespace lac
