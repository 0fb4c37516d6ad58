#include "lac/curves/quadratic/certified_position.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/curves/detail/taylor_frame.hpp"
#include "lac/curves/quadratic/detail/kappa_derivatives.hpp"

namespace lac {
namespace {

constexpr double kEps = DBL_EPSILON;
constexpr int kTerms = detail::kTaylorTerms;

struct Law {
  const QuadraticLaCurve& c;
  std::vector<std::vector<double>> P;  // P_0 … P_kTerms
  double log_lambda;

  /// u = log|κ(s)|, the sign of κ, and a bound on u's error.
  struct At {
    double u, sign, du;
  };
  At at(double s) const {
    const LogKappaSolution sol = c.solve_log_kappa(s);
    const double u = sol.log_kappa;
    // Rounding of the closed form s(u) (relative to 1 + |s|) carried to u by |du/ds|, and of u;
    // 003's hybrid inverse adds its residual's share.
    double du = std::abs(c.dlog_kappa_ds(u)) * 16 * kEps * (1 + std::abs(s)) + 16 * kEps * (1 + std::abs(u));
    if (std::isfinite(u) && u < 700) {
      const KappaSolution k{u, sol.sign * std::exp(u), sol.iterations, sol.status};
      du += c.solution_error(s, k).log_kappa;
    }
    return {u, static_cast<double>(sol.sign), du};
  }

  /// κ_i = κ^(i)(s)/i! · h^(i+1) and their errors.
  detail::FrameSeries series(double s, double h) const {
    const At a = at(s);
    detail::FrameSeries out;
    const double lh = std::log(h);
    for (int i = 0; i < kTerms; ++i) {
      double abs_sum = 0, next_abs = 0;
      const double v = detail::evaluate_polynomial(P[static_cast<size_t>(i)], a.u, &abs_sum);
      detail::evaluate_polynomial(P[static_cast<size_t>(i) + 1], std::abs(a.u) + a.du, &next_abs);
      const double phi = (1 + i * c.alpha()) * a.u - i * c.gamma() * a.u * a.u;
      const double scale = i * log_lambda - std::lgamma(i + 1.0) + (i + 1) * lh;  // log(Λ^i h^(i+1)/i!)
      const double log_value = scale + std::log(std::abs(v)) + phi;
      const double sign = (v < 0 ? -1.0 : 1.0) * (a.sign > 0 ? (i % 2 == 0 ? 1.0 : -1.0) : -1.0);
      out.kappa[i] = v == 0 ? 0.0 : sign * std::exp(log_value);
      // Horner's rounding, u's error (|d(P_i e^φ_i)/du| = |P_(i+1)| e^φ_i, φ_i within the slope times
      // du of its value) and the logarithms' and exponential's rounding.
      const double dphi = std::abs(1 + i * c.alpha() - 2 * i * c.gamma() * a.u) * a.du + std::abs(i * c.gamma()) * a.du * a.du;
      const double size = std::exp(scale + phi);
      out.kappa_error[i] = size * (2 * (i + 2) * kEps * abs_sum + a.du * next_abs * std::exp(dphi)) +
                           std::abs(out.kappa[i]) * 8 * kEps * (std::abs(log_value) + i + 2);
    }
    return out;
  }

  /// Bounds over [s0, s1] (no inflection inside): u covers the interval between its ends' values.
  detail::FrameMajorant majorant(double s0, double s1, double h) const {
    const At a = at(s0), b = at(s1);
    const double lo = std::min(a.u - a.du, b.u - b.du), hi = std::max(a.u + a.du, b.u + b.du);
    detail::FrameMajorant out;
    const double lh = std::log(h);
    for (int i = 0; i < kTerms; ++i) {
      const double p = detail::max_abs_polynomial(P[static_cast<size_t>(i)], lo, hi);
      const double phi = detail::max_quadratic(1 + i * c.alpha(), i * c.gamma(), lo, hi);
      out.kappa[i] = p == 0 ? 0.0 : std::exp(i * log_lambda - std::lgamma(i + 1.0) + (i + 1) * lh + std::log(p) + phi);
    }
    return out;
  }
};

}  // namespace

CertifiedTangentIntegral integrate_quadratic_certified(const QuadraticLaCurve& curve, double s0, double s1) {
  constexpr const char* who = "integrate_quadratic_certified";
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  if (s1 < s0) {
    CertifiedTangentIntegral r = integrate_quadratic_certified(curve, s1, s0);
    r.value = -r.value;
    return r;
  }
  if (s0 == s1) return {};
  const Law law{curve, detail::kappa_derivative_polynomials(curve.alpha(), curve.gamma(), kTerms),
                std::log(curve.lambda())};
  std::optional<detail::TangentZone> zone;
  if (curve.options().through_inflection && curve.has_inflection()) {
    const double si = curve.s_at_zero_kappa();
    const Interval domain = curve.s_domain();
    const auto k_at = [&](double s) { return domain.contains(s) ? std::abs(curve.kappa_at_s(s)) : HUGE_VAL; };
    // κ' grows like e^(|γ|u²) toward the inflection, so Taylor steps cannot get close to it: the
    // zone is as wide as an error of 1e-14 × (1 + arc length) allows.
    const double allowed = 1e-14 * (1 + (s1 - s0));
    double d = 1e-3 * (1 + std::abs(si) + (s1 - s0));
    for (int k = 0; k < 200 && 4 * d * d * std::max(k_at(si - d), k_at(si + d)) > allowed; ++k) d *= 0.5;
    zone = detail::TangentZone{si - d, si + d, std::max(k_at(si - d), k_at(si + d))};
  }
  return detail::integrate_plane_tangent(
      [&](double s, double h) { return law.series(s, h); },
      [&](double a, double b, double h) { return law.majorant(a, b, h); },
      [&](double s, double& error) {
        const double theta = curve.theta_at_s(s, error);
        // θ's own rounding and that of s, moved along the curve by κ.
        error += 8 * kEps * (1 + std::abs(theta)) + std::abs(curve.kappa_at_s(s)) * 16 * kEps * (1 + std::abs(s));
        return theta;
      },
      s0, s1, zone, who);
}

}  // namespace lac
