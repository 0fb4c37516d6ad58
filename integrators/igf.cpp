// igf: the incomplete-gamma closed form of the planar LA position, for every α (see igf.hpp).
#include "lac/integrators/igf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "lac/common/error.hpp"
#include "lac/common/numeric.hpp"
#include "lac/special/incomplete_gamma.hpp"

namespace lac {
namespace {

using cplx = std::complex<double>;
constexpr double kEps = std::numeric_limits<double>::epsilon();
const cplx kI(0.0, 1.0);

// Measured worst relative error of special::gamma_inc_scaled / gamma_inc_difference_scaled
// over tests/reference/gamma_inc*.csv is 2.9e-14; the estimates below use 4e-14.
constexpr double kGammaRelativeError = 4e-14;
constexpr double kLowerSeriesRadius = 1.5;  // |z| = U/|k| up to which the U-series is used
constexpr double kShortStep = 4.0;          // Γ segment series when |Δθ| ≤ 4 …
constexpr double kShortRatio = 0.5;         // … and |kΔθ| ≤ 0.5 U0
constexpr double kPieceLength = 2.0;        // segment-series piece: |h| ≤ 2 rad,
constexpr double kPieceRatio = 0.5;         //   |k h| ≤ 0.5 U (radius of convergence 1),
constexpr double kPieceGrowth = 4.0;        //   |Λ h / U| ≤ 4 (ρ changes by at most e^4)
constexpr int kMaxTerms = 400;

/// e^w − 1 without cancellation for small |w| (std has no complex expm1).
cplx expm1c(cplx w) {
  if (std::abs(w.real()) > 0.5 || std::abs(w.imag()) > 0.5) return std::exp(w) - 1.0;
  const double s = std::sin(0.5 * w.imag());
  return {std::expm1(w.real()) * std::cos(w.imag()) - 2.0 * s * s, std::exp(w.real()) * std::sin(w.imag())};
}
cplx expm1c_ratio(cplx w) { return w == cplx(0.0, 0.0) ? cplx(1.0) : expm1c(w) / w; }

bool finite(cplx w) { return std::isfinite(w.real()) && std::isfinite(w.imag()); }

struct Attempt {
  cplx value{};
  double error = std::numeric_limits<double>::infinity();
  long evaluations = 0;
  long pieces = 0;
  bool converged = false;
  bool accepted(double tol) const { return converged && finite(value) && error <= tol * std::abs(value); }
};

struct Curve {
  double alpha, lambda, k, a, p;  // p = a − 1 = 1/(α − 1)
  double u(double theta) const { return 1.0 + k * theta; }
  double log_rho(double theta) const {  // Λθ log1p(kθ)/(kθ), exact limit at kθ = 0
    const double x = k * theta;
    return lambda * theta * (x == 0 ? 1.0 : std::log1p(x) / x);
  }
};

/// |z| ≤ 1.5: C(θ1) − C(θ0) = (e^{−i/k}/k) Σ_n (i/k)^n/n! (U1^{a+n} − U0^{a+n})/(a+n), the
/// difference of the lower-gamma series of both ends taken term by term (docs/math.md §1.1 with
/// γ(a, z) = z^a Σ (−z)^n/(n!(a+n)) and (ik)^a (−iU/k)^a = U^a). Any a, no Γ(a).
Attempt lower_series(const Curve& c, double theta0, double theta1) {
  Attempt r;
  const double u0 = c.u(theta0);
  const double L = std::log1p(c.k * (theta1 - theta0) / u0);  // log(U1/U0)
  const cplx step = kI / c.k;
  cplx factor = 1.0;              // (i/k)^n / n!
  double u0_power = std::pow(u0, c.a);  // U0^{a+n}
  cplx sum = 0.0;
  double magnitude = 0;
  int small = 0;
  for (int n = 0; n < kMaxTerms; ++n) {
    const double b = c.a + n;
    const cplx add = factor * (u0_power * L * expm1_ratio(b * L));
    sum += add;
    magnitude += std::abs(add);
    ++r.evaluations;
    if (std::abs(add) <= 0.5 * kEps * std::abs(sum)) {
      if (++small == 2) {
        r.converged = true;
        break;
      }
    } else {
      small = 0;
    }
    factor *= step / static_cast<double>(n + 1);
    u0_power *= u0;
  }
  const cplx prefactor = std::polar(1.0 / c.k, -1.0 / c.k);
  r.value = prefactor * sum;
  r.error = 8 * kEps * magnitude * std::abs(prefactor);
  return r;
}

/// |a| ≤ 10 through special::gamma_inc_scaled / gamma_inc_step_scaled.
Attempt gamma_form(const Curve& c, double theta0, double theta1, bool& short_step) {
  Attempt r;
  const double u0 = c.u(theta0), u1 = c.u(theta1);
  const cplx z0(0.0, -u0 / c.k), z1(0.0, -u1 / c.k);
  const double delta = theta1 - theta0;
  // U^a e^{iθ}/k: the factor that turns a scaled Γ at z = −iU/k back into C (docs/math.md §1.1).
  auto weight = [&](double u, double theta) { return std::polar(std::pow(u, c.a) / c.k, theta); };
  short_step = std::abs(delta) <= kShortStep && std::abs(c.k * delta) <= kShortRatio * u0;
  if (short_step) {
    // z1 − z0 = −i(U1 − U0)/k = −iΔθ exactly; passing it (not z1) keeps a tiny step exact.
    const special::GammaIncResult d = special::gamma_inc_step_scaled(c.a, z0, cplx(0.0, -delta));
    r.value = weight(u0, theta0) * d.value;
    r.evaluations = d.iterations;
    r.converged = d.status == Status::ok;
    r.error = kGammaRelativeError * std::abs(r.value);
    return r;
  }
  const special::GammaIncResult g0 = special::gamma_inc_scaled(c.a, z0);
  const special::GammaIncResult g1 = special::gamma_inc_scaled(c.a, z1);
  const cplx f0 = weight(u0, theta0) * g0.value, f1 = weight(u1, theta1) * g1.value;
  r.value = f0 - f1;
  r.evaluations = g0.iterations + g1.iterations;
  r.converged = g0.status == Status::ok && g1.status == Status::ok;
  r.error = kGammaRelativeError * (std::abs(f0) + std::abs(f1));
  return r;
}

/// ∫_θ0^θ1 (1 + kψ)^p e^{iψ} dψ (the Γ difference along the ray z = −iU/k, in θ) piece by
/// piece: on [t, t + h], ρ(t) e^{it} ∫_0^h (1 + βx)^p e^{ix} dx with β = k/U(t) and
///   (1 + βx)^p e^{ix} = Σ c_n x^n,  c_0 = 1,  c_{n+1} = ((pβ − nβ + i) c_n + iβ c_{n−1})/(n + 1)
/// (from (1 + βx) f' = (pβ + i(1 + βx)) f). Pieces keep |βh| ≤ 1/2, |h| ≤ 2, |Λh/U| ≤ 4.
Attempt segment_series(const Curve& c, double theta0, double theta1, long max_pieces) {
  Attempt r;
  r.converged = true;
  r.error = 0;
  double t = theta0;
  const double direction = theta1 > theta0 ? 1.0 : -1.0;
  while (t != theta1) {
    if (r.pieces >= max_pieces) {
      r.converged = false;
      return r;
    }
    const double u = c.u(t);
    const double h_max = std::min({kPieceLength, kPieceRatio * u / std::abs(c.k), kPieceGrowth * u / c.lambda});
    const double next = std::abs(theta1 - t) <= h_max ? theta1 : t + direction * h_max;
    const double h = next - t;
    const double beta = c.k / u;
    cplx c_prev = 0.0, c_n = 1.0, sum = 0.0;
    double power = h, magnitude = 0;  // h^{n+1}
    int small = 0;
    bool converged = false;
    for (int n = 0; n < kMaxTerms; ++n) {
      const cplx add = c_n * (power / (n + 1));
      sum += add;
      magnitude += std::abs(add);
      ++r.evaluations;
      if (std::abs(add) <= 0.5 * kEps * std::abs(sum)) {
        if (++small == 3) {
          converged = true;
          break;
        }
      } else {
        small = 0;
      }
      const cplx c_next = ((c.p * beta - n * beta + kI) * c_n + kI * beta * c_prev) / static_cast<double>(n + 1);
      c_prev = c_n;
      c_n = c_next;
      power *= h;
    }
    const double rho = std::exp(c.log_rho(t));
    r.value += std::polar(rho, t) * sum;
    r.error += 4 * kEps * rho * magnitude;
    r.converged = r.converged && converged;
    ++r.pieces;
    t = next;
  }
  return r;
}

void check_theta(const Curve& c, double theta, const char* name) {
  require_finite("igf_position_delta", name, theta);
  if (c.lambda == 0 || c.alpha == 1) return;
  if (!(c.u(theta) > 0)) {
    const double bound = -1.0 / c.k;
    throw_input_error("igf_position_delta", name, theta,
                      c.alpha < 1 ? interval_text(-std::numeric_limits<double>::infinity(), bound)
                                  : interval_text(bound, std::numeric_limits<double>::infinity()));
  }
}

}  // namespace

void IgfOptions::validate() const {
  if (!(tol >= 1e-15 && tol <= 1e-2)) throw_input_error("igf", "tol", tol, "[1e-15, 0.01]");
  if (max_pieces < 1) throw_input_error("igf", "max_pieces", static_cast<double>(max_pieces), "[1, inf)");
}

IgfResult igf_position_delta_detailed(double alpha, double lambda, double theta0, double theta1,
                                      const IgfOptions& options) {
  options.validate();
  require_finite("igf_position_delta", "alpha", alpha);
  require_finite("igf_position_delta", "lambda", lambda);
  if (lambda < 0) throw_input_error("igf_position_delta", "lambda", lambda, "[0, inf)");
  Curve c{alpha, lambda, (alpha - 1.0) * lambda, 0, 0};
  if (alpha != 1) {
    c.a = alpha / (alpha - 1.0);
    c.p = 1.0 / (alpha - 1.0);
  }
  check_theta(c, theta0, "theta0");
  check_theta(c, theta1, "theta1");

  IgfResult out;
  auto& res = out.integral;
  const double delta = theta1 - theta0;
  if (delta == 0) return out;

  if (lambda == 0 || alpha == 1) {  // unit circle; logarithmic spiral (docs/math.md §1.1)
    const cplx w = lambda == 0 ? kI : cplx(lambda, 1.0);
    res.value = std::exp(w * theta0) * delta * expm1c_ratio(w * delta);
    res.error_estimate = 8 * kEps * std::abs(res.value) * (1 + std::abs(w * theta0) + std::abs(w * delta));
    res.evaluations = 1;
    out.region = IgfRegion::elementary;
    if (!finite(res.value)) {
      res.status = Status::numerical_failure;
      res.message = "igf: position overflows double";
    }
    return out;
  }

  // Input conditioning: U = 1 + kθ is rounded, and ρ = U^p moves by |p| ulp(1 + |kθ|)/U relative.
  auto conditioning = [&](double theta) {
    return kEps * (std::abs(c.p) * (1.0 + std::abs(c.k * theta)) / c.u(theta) + std::abs(c.lambda * theta));
  };
  const double input_error = 2 * std::max(conditioning(theta0), conditioning(theta1));
  auto take = [&](const Attempt& a, IgfRegion region) {
    res.value = a.value;
    res.error_estimate = a.error + input_error * std::abs(a.value);
    res.evaluations += a.evaluations;
    out.region = region;
    out.pieces = a.pieces;
    return out;
  };
  const double tol = options.tol;
  long spent = 0;
  std::string why;
  if (std::max(c.u(theta0), c.u(theta1)) / std::abs(c.k) <= kLowerSeriesRadius) {
    const Attempt s = lower_series(c, theta0, theta1);
    if (s.accepted(tol)) return take(s, IgfRegion::lower_series);
    spent += s.evaluations;
  }
  if (c.a >= special::kGammaIncMinOrder && c.a <= special::kGammaIncMaxOrder) {
    bool short_step = false;
    const Attempt g = gamma_form(c, theta0, theta1, short_step);
    if (g.accepted(tol)) {
      res.evaluations = spent;
      return take(g, short_step ? IgfRegion::gamma_segment : IgfRegion::gamma);
    }
    spent += g.evaluations;
  }
  const Attempt t = segment_series(c, theta0, theta1, options.max_pieces);
  if (t.accepted(tol)) {
    res.evaluations = spent;
    return take(t, IgfRegion::segment_series);
  }
  spent += t.evaluations;
  why = t.pieces >= options.max_pieces ? "segment series needs more than max_pieces = " + std::to_string(options.max_pieces) +
                                             " pieces"
                                       : "no closed-form evaluation reached tol = " + format_number(tol) +
                                             " (best estimate " + format_number(t.error / std::abs(t.value)) + ")";

  // Fallback: Gauss–Kronrod on the θ-form integrand ρ(ψ) e^{iψ}.
  GaussKronrod gk;
  gk.tol = std::max(1e-15, 0.1 * tol);
  auto integrand = [&c](double psi) { return std::polar(std::exp(c.log_rho(psi)), psi); };
  IntegralResult<cplx> q = gk.integrate(integrand, theta0, theta1);
  out.region = IgfRegion::gauss_kronrod;
  out.pieces = 0;
  res = q;
  res.error_estimate += input_error * std::abs(q.value);
  res.evaluations += spent;
  if (q.status == Status::ok) res.status = Status::fell_back;
  res.message = "igf: " + why + "; fell back to gauss-kronrod" + (q.message.empty() ? "" : " (" + q.message + ")");
  return out;
}

}  // namespace lac
