#include "lac/constructions/g1_hermite.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/constructions/detail/tangent_integral.hpp"
#include "lac/constructions/detail/windings.hpp"
#include "lac/constructions/s_curve.hpp"
#include "lac/constructions/triangle_g1.hpp"
#include "lac/curves/planar/la_segment_kernel.hpp"
#include "lac/integrators/gauss_legendre.hpp"
#include "lac/solvers/bracket.hpp"
#include "lac/solvers/detail/method_registry.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Trial = LaKernelValue;
using Normalized = LaSegmentKernel;
constexpr double kSmallAlpha = kLaKernelSmallAlpha;

// ---- shape guesses ----
// α = −1: the small-angle solution A = 3(φ0 + φ1) of Im∫e^{iφ} ≈ ∫φ = 0 [Bertolazzi–Frego 2015],
// times a correction in s = (φ0 + φ1)/π, d = (φ0 − φ1)/π for ends within (−π, π) (the least
// turning): a least-squares fit to solved clothoids (G1Hermite.ClothoidGuessFit refits it),
// within 1.1e-3 of A there instead of 1.8.
constexpr std::array<double, 10> kClothoidGuessFit{0.999951, -0.0232834, -0.164477, -0.00180186, 0.00432427,
                                                   -0.0119155, 0.000194891, 0.00269847, 0.0101785, -0.000659999};
double clothoid_guess(double phi0, double delta) {
  const double phi1 = phi0 + delta, A = 3 * (phi0 + phi1);
  if (!(std::abs(phi0) < kPi && std::abs(phi1) < kPi)) return A;
  const double s2 = (phi0 + phi1) * (phi0 + phi1) / (kPi * kPi), d2 = (phi0 - phi1) * (phi0 - phi1) / (kPi * kPi);
  const auto& c = kClothoidGuessFit;
  return A * (c[0] + s2 * (c[1] + s2 * (c[3] + s2 * c[6])) + d2 * (c[2] + d2 * (c[5] + d2 * c[9])) +
              s2 * d2 * (c[4] + s2 * c[7] + d2 * c[8]));
}
// α ≠ 0: the clothoid's guess moved to the law by matching the ratio of the end curvatures.
double exponential_guess(double phi0, double delta);
double power_guess(double alpha, double phi0, double delta) {
  if (alpha < 0 && alpha > -kSmallAlpha && delta != 0) {
    // Small |α|: the α = 0 guess b0 = log(κb/κa) carried over, X = log(qb/qa) = −α·b0 and
    // a = Δ·tanh(X/2) (qb/qa = (Δ + a)/(Δ − a)): inside |a| < |Δ|, where near_zero evaluates.
    // (The clothoid's end-curvature ratio is ill-conditioned there: |k|^(−α) ≈ 1.)
    const double b0 = std::clamp(exponential_guess(phi0, delta), -12.0, 12.0);
    return delta * std::tanh(-0.5 * alpha * b0);
  }
  const double A = clothoid_guess(phi0, delta);
  if (alpha == -1) return A;
  const double ka = delta - A, kb = delta + A;
  const auto Q = [&](double k) { return std::copysign(std::pow(std::abs(k), -alpha), k); };
  if (alpha < 0) {
    // Near the antisymmetric S (qa ≈ −qb) the ratio is ill-conditioned for −1 < α < 0 and would put
    // the guess far out, past other roots (curves with loops; at α = −0.1 Newton then wandered for
    // ~40 steps on average); the clamp keeps it within 2|A| + 1 (same roots, 6 steps at α = −0.1).
    const double qa = Q(ka), qb = Q(kb), sum = qa + qb, bound = 2 * std::abs(A) + 1;
    if (!(std::abs(sum) > 1e-12 * (std::abs(qa) + std::abs(qb)))) return A;
    return std::clamp(delta * (qb - qa) / sum, -bound, bound);
  }
  // α > 0: q keeps its sign, a ∈ (−|Δ|, |Δ|); the end curvature ratio of the clothoid, clamped.
  const double r = (ka * kb > 0) ? (Q(kb) - Q(ka)) / (Q(kb) + Q(ka)) : (A > 0 ? 0.9 : -0.9);
  return delta * std::clamp(r, -0.9, 0.9);
}
// α = 0: Im∫e^{iφ} ≈ φ0 + Δ∫E = 0 with ∫E = 1/b − 1/expm1(b) (decreasing from 1 to 0): Newton
// kept in the sign bracket [−800, 800].
double exponential_guess(double phi0, double delta) {
  const double mu = -phi0 / delta;
  if (!(mu > 0 && mu < 1)) return 0;
  const auto fd = [mu](double b) {
    const bool small = std::abs(b) < 1e-4;
    const double em = small ? 0.0 : std::expm1(b);
    return Newton1dSample{(small ? 0.5 - b / 12 : 1 / b - 1 / em) - mu,
                          small ? -1.0 / 12 : -1 / (b * b) + (em + 1) / (em * em)};
  };
  Newton1dOptions o;
  o.x_atol = 1e-12;
  o.x_rtol = 1e-12;
  o.max_iterations = 60;
  o.bracket = Bracket{-800, 800, 1 - mu, -mu};
  o.bisect_slow_steps = false;
  const double b = safeguarded_newton(fd, 12 * (0.5 - mu), o).x;
  return std::isfinite(b) ? b : 0.0;
}


G1Shape classify_input(double phi0, double phi1, double delta) {
  if (phi0 == 0 && phi1 == 0 && delta == 0) return G1Shape::straight;
  if (std::abs(delta) >= kPi) return G1Shape::other;
  if (phi0 * phi1 > 0) return G1Shape::s_shaped;
  if (phi0 * phi1 < 0) return G1Shape::convex;
  return G1Shape::other;
}

using G1Kind = G1Solver::Kind;
constexpr std::string_view kNoOptions = "";

// auto, the 1-D root registry's rows (names, aliases, descriptions) on the reduced equation, then
// the two paper methods.
std::vector<SolverMethodInfo<G1Solver>> make_g1_solvers() {
  std::vector<SolverMethodInfo<G1Solver>> rows;
  rows.push_back({G1Solver{}, "auto",
                  {},
                  "Newton on the reduced equation with its analytic derivative, safeguarded by a sign bracket (fast path)",
                  kNoOptions});
  for (const RootMethodInfo& m : root_methods())
    rows.push_back({G1Solver{G1Kind::root, m.method}, m.name, m.aliases, m.description, m.options});
  rows.push_back({G1Solver{G1Kind::triangle}, "triangle", {},
                  "001's similar-triangle bisection on the control triangle (tangents on opposite sides, |turning| < pi)",
                  kNoOptions});
  rows.push_back({G1Solver{G1Kind::s_curve}, "s-curve", {}, "004's Lambda search (alpha < 0, tangents on one side of the chord)",
                  kNoOptions});
  return rows;
}

void check_problem(const G1HermiteProblem& pr) {
  require_finite("g1", "p0.x", pr.p0.real());
  require_finite("g1", "p0.y", pr.p0.imag());
  require_finite("g1", "p1.x", pr.p1.real());
  require_finite("g1", "p1.y", pr.p1.imag());
  require_finite("g1", "theta0", pr.theta0);
  require_finite("g1", "theta1", pr.theta1);
  if (!(std::abs(pr.alpha) <= kG1MaxAbsAlpha)) throw_input_error("g1", "alpha", pr.alpha, interval_text(-kG1MaxAbsAlpha, kG1MaxAbsAlpha, true, true));
  const double r = std::abs(pr.p1 - pr.p0);
  if (!std::isfinite(r)) throw_input_error("g1", "p1", "p1 - p0 beyond the double range (|p1 - p0| must be finite)");
  // The problem is similarity-invariant: the chord is compared with the coordinates' own size,
  // so that a tiny configuration solves like its unit-size copy; subnormal chords are refused.
  const double scale = std::max({std::abs(pr.p0.real()), std::abs(pr.p0.imag()), std::abs(pr.p1.real()),
                                 std::abs(pr.p1.imag())});
  if (!(r > 1e-12 * scale) || !(r >= std::numeric_limits<double>::min()))
    throw_input_error("g1", "p1", "coincides with p0 (the chord must have positive length)");
}

// Builds the result curve from a solved shape; checks it in closed form (angles) and by the
// solver's integral (position), or by options.integrator with `verify`.
void finish(G1HermiteResult& res, const G1HermiteProblem& pr, const G1HermiteOptions& o, const Normalized& nz,
            const Trial& t, double x) {
  Summary& sum = res.summary;
  const Complex d = pr.p1 - pr.p0;
  const double r = std::abs(d);
  const Complex rot = d / r;
  const double L = 1.0 / t.I.real();
  if (!(t.I.real() > 0) || !std::isfinite(L)) {
    res.conclude(Status::not_converged, "g1: the root found runs away from p1 (Re of the end-point integral <= 0)");
    return;
  }
  if (!t.offset && nz.alpha > 0 && nz.delta != 0 && !std::isfinite(std::pow(std::min(std::abs(t.qa), std::abs(t.qb)), -1 / nz.alpha - 2))) {
    // LaLaw's series for K'' (closed-form θ of the segment) overflows there.
    res.conclude(Status::numerical_failure, "g1: the solution's end-curvature ratio (q ratio " +
                                                format_number(std::abs(t.qb / t.qa)) +
                                                ") is beyond what LaSegment evaluates in double precision (e^700 class)");
    return;
  }
  const bool straight_other_law = nz.alpha >= 0 && nz.delta == 0;
  const LaLaw law = straight_other_law ? LaLaw{-1}
                    : t.offset         ? LaLaw{nz.alpha, nz.delta < 0 ? -1.0 : 1.0, true}
                                       : LaLaw{nz.alpha, nz.alpha == 0 && nz.delta < 0 ? -1.0 : 1.0};
  try {
    LaSegment seg(law, 0.0, 1.0, straight_other_law ? 0.0 : t.qa, straight_other_law ? 0.0 : t.qb, nz.phi0,
                  Placement{pr.p0, L * r, rot});
    res.curve = PlanarCurve({seg});
    G1HermiteInfo& info = res.info;
    info.turning = seg.turning();
    info.length = seg.length();
    info.qa = seg.qa();
    info.qb = seg.qb();
    info.x = x;
    info.inflection = seg.inflection_s();
    const double angle = std::max(std::abs(wrap_angle(seg.theta_start() - pr.theta0)), std::abs(wrap_angle(seg.theta_end() - pr.theta1)));
    double position = L * std::abs(t.I.imag()) * r;
    if (o.verify) {
      // Every registry method (igf included) through the construction integrator of the 004 solvers.
      long evaluations = 0;
      const Complex I = detail::TrialIntegrator(o.integrator)(law, seg.normalized(), evaluations);
      sum.evaluations += evaluations;
      if (!std::isfinite(I.real()) || !std::isfinite(I.imag())) {
        res.conclude(Status::numerical_failure, "g1: the integrator could not evaluate the end point of the solution");
        return;
      }
      const Complex end = pr.p0 + seg.scale() * rot * I;
      sum.error_estimate = std::abs(end - (pr.p0 + seg.scale() * rot * t.I));
      position = std::abs(end - pr.p1);
    }
    sum.residuals.position = position;
    sum.residuals.angle = angle;
    if (!std::isfinite(position) || !std::isfinite(info.length) || !std::isfinite(seg.kappa_start()) ||
        !std::isfinite(seg.kappa_end())) {
      // The shape is fine, but scaled to this chord its length, end curvatures or end point
      // leave the double range (a chord near DBL_MIN or coordinates near DBL_MAX).
      res.curve = PlanarCurve{};
      res.conclude(Status::numerical_failure, "g1: the solution's length, end curvatures or end point (chord " +
                                                  format_number(r) + ") are beyond the double range");
      return;
    }
    // Shape of the solution.
    if (t.qa == 0 && t.qb == 0) info.shape = G1Shape::straight;
    else if (std::abs(info.turning) >= kPi || nz.phi0 * (nz.phi0 + nz.delta) == 0) info.shape = G1Shape::other;
    else if (info.inflection) info.shape = nz.phi0 * (nz.phi0 + nz.delta) > 0 ? G1Shape::s_shaped : G1Shape::convex_inflection;
    else info.shape = G1Shape::convex;
    // The achieved error (common/accuracy.hpp): conclude() grades it against accept.
    // The kernel's end point carries its relative accuracy (kLaKernelError of ∫|e^{iφ}| = 1) times
    // the length: a loop thousands of chords long cannot meet the chord to rounding.
    const double kernel_bound = kLaKernelError * info.length / r;
    sum.error = std::max({position / r, angle, sum.error_estimate.value_or(0.0) / r, kernel_bound});
    sum.accept = o.accept;
    const bool good = *sum.error <= o.accuracy;
    res.conclude(good ? Status::ok : Status::tolerance_not_met,
                 good ? "" : "g1: residuals position " + format_number(position / r) + " (chord units), angle " +
                                 format_number(angle) + " above accuracy " + format_number(o.accuracy));
  } catch (const InputError& e) {
    res.conclude(Status::numerical_failure, std::string("g1: the solution has no double-precision segment: ") + e.what());
  }
}

}  // namespace

std::string_view to_string(G1Shape s) {
  switch (s) {
    case G1Shape::straight: return "straight";
    case G1Shape::convex: return "convex";
    case G1Shape::convex_inflection: return "convex-inflection";
    case G1Shape::s_shaped: return "s-shaped";
    case G1Shape::other: return "other";
  }
  return "other";
}

std::span<const SolverMethodInfo<G1Solver>> g1_hermite_solvers() {
  static const std::vector<SolverMethodInfo<G1Solver>> rows = make_g1_solvers();
  return rows;
}
std::string_view to_string(G1Solver s) { return detail::solver_method_name(g1_hermite_solvers(), s); }
G1Solver parse_g1_solver(std::string_view name) {
  return detail::parse_solver_method(g1_hermite_solvers(), name, "g1", "G1 solver");
}

void G1HermiteOptions::validate() const {
  bool known = false;
  for (const SolverMethodInfo<G1Solver>& row : g1_hermite_solvers()) known = known || row.method == solver;
  if (!known) throw_input_error("g1", "solver", "not a choice of g1_hermite_solvers() (parse_g1_solver gives one)");
  if (winding && (*winding < -100 || *winding > 100)) throw_input_error("g1", "winding", *winding, "[-100, 100]");
  if (!(max_turning >= kPi && max_turning <= 200 * kPi))
    throw_input_error("g1", "max_turning", max_turning, "[pi, 200 pi]");
  if (!(tolerance >= 1e-16 && tolerance <= 1e-3)) throw_input_error("g1", "tolerance", tolerance, "[1e-16, 1e-3]");
  if (!(accuracy >= tolerance && accuracy <= 1)) throw_input_error("g1", "accuracy", accuracy, "[tolerance, 1]");
  validate_accept("g1", accept);
  if (max_iterations < 1 || max_iterations > 10000) throw_input_error("g1", "max_iterations", max_iterations, "[1, 10000]");
  if (max_bracket_steps < 1 || max_bracket_steps > 100000)
    throw_input_error("g1", "max_bracket_steps", max_bracket_steps, "[1, 100000]");
  if (max_evaluations < 1000 || max_evaluations > 1'000'000'000)
    throw_input_error("g1", "max_evaluations", static_cast<double>(max_evaluations), "[1000, 1e9]");
  std::visit([](const auto& m) { m.validate(); }, integrator);
}

namespace {

// ---- one turning Δ_k, and the search over windings (docs/g1_hermite.md, "Windings") ----

// For α ≥ 0 the shapes of one turning are φ(u; x) = φ0 + Δ·G(u; x) with G(·; x) the distribution
// function of the curvature density |κ(u)| on [0, 1]: κ ∝ (1 + (e^x − 1)u)^(−1/α) (x = log(qb/qa))
// or e^{bu} (α = 0). Both families have a monotone likelihood ratio in u, so G(u; x) is monotonic
// in x for every u, and for two shapes |I(x2) − I(x1)| ≤ |Δ| ∫|G(u; x2) − G(u; x1)| du =
// |Δ| |E(x2) − E(x1)| with E(x) the mean of u under the density. E in closed form:
double expm1_over(double c, double x) { return c == 0 ? x : std::expm1(c * x) / c; }
double mean_u_power(double alpha, double x) {  // α > 0; E(−x) = 1 − E(x) (the mirror u ↦ 1 − u)
  if (x < 0) return 1 - mean_u_power(alpha, -x);
  const double b = -1 / alpha, p = 1 + b, t = std::expm1(x);
  if (t <= 0.25) {  // Σ C(b, n) tⁿ/(n + 2) over Σ C(b, n) tⁿ/(n + 1)
    double c = 1, tn = 1, D = 0, N = 0;
    for (int n = 0; n < 400; ++n) {
      const double term = c * tn;
      D += term / (n + 1);
      N += term / (n + 2);
      if (n > -b && std::abs(term) < 1e-18 * std::abs(D)) break;
      c *= (b - n) / (n + 1);
      tn *= t;
    }
    return N / D;
  }
  // E = (Φ(p + 1)/Φ(p) − 1)/t with Φ(c) = ∫₀^x e^{cw}dw = expm1(cx)/c; scaled by e^(−(p+1)x) for p > 0.
  if (p > 0) return p / (p + 1) * std::expm1(-(p + 1) * x) / std::expm1(-p * x) / -std::expm1(-x) - 1 / t;
  return (expm1_over(p + 1, x) / expm1_over(p, x) - 1) / t;
}
double mean_u_exponential(double b) {  // α = 0: 1/(1 − e^(−b)) − 1/b
  if (b < 0) return 1 - mean_u_exponential(-b);
  if (b < 1e-2) {
    const double b2 = b * b;
    return 0.5 + b / 12 * (1 - b2 / 60 * (1 - b2 / 42));
  }
  return -1 / std::expm1(-b) - 1 / b;
}

// The shapes x → ±∞ (all turning at one end; α > 1: κ = ∞ at one end): ∫e^{iφ} and E.
struct ShapeLimits {
  Complex I_lo, I_hi;
  double E_lo = 0, E_hi = 0;
};
ShapeLimits shape_limits(Normalized& nz) {
  const Complex a = std::polar(1.0, nz.phi0), b = std::polar(1.0, nz.phi0 + nz.delta);
  if (nz.alpha == 0) return {b, a, 0, 1};  // b → −∞: turning at the start
  if (nz.alpha <= 1) return {a, b, 1, 0};  // x → −∞: κ = ∞ at the end
  const double p = 1 - 1 / nz.alpha;
  // Past the kernel's panel cap the limits stay NaN: the intervals next to them are never excluded.
  const Complex J = power_limit_integral(nz.delta, p, nz.evaluations).value_or(Complex(kNaN, kNaN));
  return {b * std::conj(J), a * J, 1 / (p + 1), p / (p + 1)};
}

// Every shape of one turning (α ≥ 0) between −∞ and ∞: an interval [x1, x2] holds no solution when
// dist(I(x1)) + dist(I(x2)) > |Δ|·|E(x2) − E(x1)| (dist: to the ray [0, ∞) of the chord; the end
// point must travel to the ray and back). Intervals not excluded are split; a sign change of f
// with Re ∫ > 0 at both ends is returned as a bracket.
struct Scan {
  enum Kind { bracket, none, inconclusive } kind = inconclusive;
  double lo = 0, hi = 0, flo = 0, fhi = 0;
  std::string why;
};
Scan certified_scan(Normalized& nz, const ShapeLimits& lim, int budget, int& used) {
  struct Point {
    double x;
    Complex I;
    double E;
  };
  const double adelta = std::abs(nz.delta), limit = 700;
  const auto mean = [&](double x) { return nz.alpha == 0 ? mean_u_exponential(x) : mean_u_power(nz.alpha, x); };
  const auto dist = [](Complex z) { return z.real() >= 0 ? std::abs(z.imag()) : std::abs(z); };
  const auto eval = [&](double x, Point& out) {
    const Trial t = nz.evaluate(x);
    ++used;
    if (!t.ok) return false;
    out = {x, t.I, mean(x)};
    return true;
  };
  const auto fail = [](std::string why) { return Scan{Scan::inconclusive, 0, 0, 0, 0, std::move(why)}; };
  std::vector<Point> nodes{{-HUGE_VAL, lim.I_lo, lim.E_lo}};
  for (double x : {-512.0, -128.0, -32.0, -8.0, -2.0, 0.0, 2.0, 8.0, 32.0, 128.0, 512.0}) {
    Point p;
    if (eval(x, p)) nodes.push_back(p);
  }
  nodes.push_back({HUGE_VAL, lim.I_hi, lim.E_hi});
  std::vector<std::pair<Point, Point>> stack;
  for (size_t i = nodes.size() - 1; i > 0; --i) stack.emplace_back(nodes[i - 1], nodes[i]);
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    for (const Point& e : {a, b})
      if (std::isfinite(e.x) && e.I.imag() == 0 && e.I.real() > 0) return {Scan::bracket, e.x, e.x, 0, 0, ""};
    if (std::isfinite(a.x) && std::isfinite(b.x) && (a.I.imag() > 0) != (b.I.imag() > 0) && a.I.real() > 0 &&
        b.I.real() > 0)
      return {Scan::bracket, a.x, b.x, a.I.imag(), b.I.imag(), ""};
    // The kernel's ∫ is good to ~1e-14; E to ~1e-13 relative.
    const double reach = adelta * (std::abs(b.E - a.E) * (1 + 1e-9) + 1e-12) + 1e-12;
    if (dist(a.I) + dist(b.I) > reach) continue;  // no shape in [a, b] ends on the chord
    if (used >= budget)
      return fail("the certified scan of the shapes did not settle [" + format_number(a.x) + ", " + format_number(b.x) +
                  "] within max_bracket_steps = " + std::to_string(budget));
    double m;
    if (!std::isfinite(a.x)) m = std::max(-limit, b.x - std::max(1.0, std::abs(b.x)));
    else if (!std::isfinite(b.x)) m = std::min(limit, a.x + std::max(1.0, std::abs(a.x)));
    else m = 0.5 * (a.x + b.x);
    if (m == a.x || m == b.x)
      return fail("the end point of the shapes near x = " + format_number(m) +
                  " touches the chord (or needs an end-curvature ratio beyond e^700): not separated");
    Point pm;
    if (!eval(m, pm)) return fail("the shape x = " + format_number(m) + " has no double-precision evaluation");
    stack.push_back({pm, b});
    stack.push_back({a, pm});
  }
  return {Scan::none, 0, 0, 0, 0, ""};
}

// One turning: a curve, a proof that there is none, or a failure.
struct Attempt {
  enum Kind { found, none, failed } kind = failed;
  std::string why;
  Trial t;
  double x = 0;
};

constexpr const char* kProofTurnsZero =
    "alpha >= 0: kappa cannot vanish or change sign, so every curve of this slope turns (turning 0 excluded)";
constexpr const char* kProofConvexArc =
    "alpha >= 0: the data need an inflection at turnings of at most pi (tangents on the same side of the chord, or one "
    "along it) and kappa cannot change sign: a convex curve turning at most pi has its chord strictly between its end "
    "tangents";
constexpr const char* kProofLimits =
    "alpha > 1: the chord direction is outside the range of end-point directions of the curves of this slope and "
    "turning (at most pi; the end direction is monotonic in the shape and its limits, the curves with infinite "
    "curvature at one end, lie on one side of the chord)";
constexpr const char* kProofScan =
    "alpha >= 0: a certified scan of every shape finds none ending on the chord (between two shapes the end point "
    "moves by at most |turning| times the shift of the mean position of the curvature, docs/g1_hermite.md)";

Attempt attempt_turning(const G1HermiteProblem& pr, const G1HermiteOptions& o, Normalized& nz, Summary& sum) {
  Attempt out;
  const auto none = [&](std::string why) {
    out.kind = Attempt::none;
    out.why = std::move(why);
    return out;
  };
  // α ≥ 0: κ keeps its sign, so φ is strictly monotonic and the turning is not 0.
  if (pr.alpha >= 0) {
    if (nz.delta == 0) return none(kProofTurnsZero);
    // A convex arc turning |Δ| ≤ π has its chord strictly between its end tangents.
    const double phi1k = nz.phi0 + nz.delta;
    if (std::abs(nz.delta) <= kPi && !(nz.delta > 0 ? (nz.phi0 < 0 && phi1k > 0) : (nz.phi0 > 0 && phi1k < 0)))
      return none(kProofConvexArc);
  }

  // The reduced equation f(x) = 0: domain and guess.
  double xmin = -HUGE_VAL, xmax = HUGE_VAL, x0 = 0, step = 0.5;
  // α ≥ 0: f at the two limits of x (all turning at one end); NaN where not known.
  double f_at_xmin = kNaN, f_at_xmax = kNaN;
  if (pr.alpha == 0) {
    xmin = -700;
    xmax = 700;
    x0 = exponential_guess(nz.phi0, nz.delta);
    step = 1;
    // b → ∞ gathers the turning at the end (the chord tends to the start tangent), b → −∞ at the start.
    f_at_xmax = std::sin(nz.phi0);
    f_at_xmin = std::sin(nz.phi0 + nz.delta);
  } else if (pr.alpha > 0) {
    xmin = -700;
    xmax = 700;
    // log(qb/qa) = −α log(κb/κa); the small-angle b0 beyond |b| = 12 (turning gathered within 1/12
    // of an end) lands in the flat tail of f, where Newton creeps (α = 0.5: up to 15 steps).
    x0 = -pr.alpha * std::clamp(exponential_guess(nz.phi0, nz.delta), -12.0, 12.0);
    step = 1;
    if (pr.alpha <= 1) {  // x → −∞: κ = ∞ at the end, x → ∞: at the start
      f_at_xmin = std::sin(nz.phi0);
      f_at_xmax = std::sin(nz.phi0 + nz.delta);
    }
    if (pr.alpha > 1 && std::abs(nz.delta) <= kPi) {
      // The shapes run from κ = ∞ at the start (x → ∞, φ = φ0 + Δu^p) to κ = ∞ at the end; their
      // end-point direction is monotonic in x (docs/g1_hermite.md), so f must change sign
      // between the two limits.
      const double p = 1 - 1 / pr.alpha;
      const Complex J = *power_limit_integral(nz.delta, p, nz.evaluations);  // |Δ| ≤ π: inside the cap
      const double f_start = (std::polar(1.0, nz.phi0) * J).imag();
      const double f_end = (std::polar(1.0, nz.phi0 + nz.delta) * std::conj(J)).imag();
      f_at_xmax = f_start;
      f_at_xmin = f_end;
      if ((f_start > 1e-12 && f_end > 1e-12) || (f_start < -1e-12 && f_end < -1e-12)) return none(kProofLimits);
    }
  } else {
    x0 = power_guess(pr.alpha, nz.phi0, nz.delta);
  }

  Trial best;
  double xbest = x0;
  bool converged = false;
  // α = 0 and α > 1 beyond half a turn: the certified scan straight away (it brackets every root
  // it meets; at α > 1 Newton from the guess fails more often than not, at α = 0 it can end on
  // shapes whose far-end curvature underflows). For 0 < α ≤ 1 Newton first, the scan only if it
  // fails: the same curves on the G1 set with 38–56 % of the trial shapes (docs/g1_hermite.md).
  const bool scan_first = (pr.alpha == 0 || pr.alpha > 1) && std::abs(nz.delta) > kPi;
  if (o.solver.kind == G1Kind::automatic && !scan_first) {
    // Newton (solvers/bracket.hpp), each step limited to 2π in x and kept inside the domain; once
    // two iterates have opposite signs of f the step is kept inside their bracket (bisection otherwise).
    // α ≥ 0: f increases with x when Δ > 0 (x → ∞ puts the turning at the start, so the chord
    // tends to the end tangent, f → |I| sin φ1), decreases when Δ < 0: a step the derivative gets
    // wrong (flat tails) is replaced by a doubling step toward the root.
    // α = 0: x = b = log(κb/κa) runs the other way.
    const double rising = pr.alpha == 0 ? (nz.delta > 0 ? -1.0 : 1.0) : pr.alpha > 0 ? (nz.delta > 0 ? 1.0 : -1.0) : 0.0;
    // f runs from f_lo to f_hi (its limits) like a sigmoid: in each tail it approaches its limit
    // geometrically in x, where plain Newton creeps. Newton on the logit
    // g = log((f − f_lo)/(f_hi − f)), linear in both tails, has the same root (g = log(−f_lo/f_hi)).
    const double f_lo = rising > 0 ? f_at_xmin : f_at_xmax, f_hi = rising > 0 ? f_at_xmax : f_at_xmin;
    const bool logit = rising != 0 && f_lo < 0 && f_hi > 0;
    const double g_root = logit ? std::log(-f_lo / f_hi) : 0;
    double jump = 1;
    const auto step_rule = [&](double x, const Newton1dSample& s, bool bracketed) {
      double next = x - s.f / s.df;
      if (logit && s.f > f_lo && s.f < f_hi && s.df * rising > 0) {
        const double a = s.f - f_lo, b = f_hi - s.f;
        next = x - (std::log(a / b) - g_root) / (s.df * (1 / a + 1 / b));
      }
      if (!std::isfinite(next)) next = x + (s.f > 0 ? -step : step);
      if (rising != 0 && !bracketed && (s.df * rising <= 0 || std::abs(next - x) > 2 * kPi)) {
        next = x - (s.f > 0 ? 1.0 : -1.0) * rising * jump;
        jump *= 2;
        return next;
      }
      return std::clamp(next, x - 2 * kPi, x + 2 * kPi);
    };
    // A trial without a curve (e.g. beyond the turning the kernel resolves) is a failed
    // evaluation (Newton backs off); a root with Re ∫ <= 0 runs away from p1 and is not accepted.
    const auto fd = [&](double x) {
      const Trial t = nz.evaluate(x);
      if (!t.ok) return Newton1dSample{};
      if (!best.ok || std::abs(t.f) < std::abs(best.f)) best = t, xbest = x;
      return Newton1dSample{t.f, t.df, t.I.real() > 0};
    };
    Newton1dOptions no;
    no.f_atol = o.tolerance;
    no.max_iterations = o.max_iterations;
    no.xmin = xmin;
    no.xmax = xmax;
    no.bisect_slow_steps = false;  // the step rule above handles the tails
    const Newton1dResult nr = safeguarded_newton(fd, x0, no, step_rule);
    sum.iterations += nr.iterations;
    converged = nr.status == Status::ok;
  }
  std::string failure;
  if (!converged) {
    // A sign bracket (α ≥ 0: from the certified scan, which may also prove that there is none;
    // α < 0: around the guess), then the chosen root method (auto: TOMS 748).
    int used = 0;
    std::optional<Bracket> b;
    if (pr.alpha >= 0) {
      const Scan s = certified_scan(nz, shape_limits(nz), o.max_bracket_steps, used);
      sum.iterations += used;
      if (s.kind == Scan::none) return none(kProofScan);
      if (s.kind == Scan::bracket) b = Bracket{s.lo, s.hi, s.flo, s.fhi};
      else failure = s.why;
    } else {
      // Steps of `step` on both sides of the guess, nearest first; a trial without a curve is a
      // failed probe, and one with Re ∫ <= 0 (running away from p1) may not close a bracket but
      // is its side's next comparison point.
      BracketSearchOptions bo;
      bo.step = step;
      bo.xmin = xmin;
      bo.xmax = xmax;
      bo.max_probes = o.max_bracket_steps;
      bool toward_p1 = false;  // Re ∫ > 0 at the last probe
      const BracketSearchResult s = search_bracket(
          [&](double x) {
            const Trial t = nz.evaluate(x);
            toward_p1 = t.ok && t.I.real() > 0;
            return t.ok ? t.f : kNaN;
          },
          x0, bo, std::nullopt, [&](double) { return toward_p1; });
      sum.iterations += s.probes;
      if (s.found) b = s.bracket;
      else failure = "no sign change of the reduced equation within max_bracket_steps of the guess";
      if (nz.exhausted()) failure = "evaluation budget max_evaluations = " + std::to_string(o.max_evaluations) + " spent";
    }
    if (b && b->lo == b->hi) {  // the scan or the search met a root exactly
      const Trial t = nz.evaluate(b->lo);
      if (t.ok) best = t, xbest = b->lo, converged = std::abs(t.f) <= o.tolerance && t.I.real() > 0;
    } else if (b) {
      const RootMethod m = o.solver.root;  // toms748 for auto
      RootOptions ro;
      ro.x_rtol = 1e-15;
      ro.x_atol = 1e-300;
      ro.f_atol = o.tolerance;
      ro.max_iterations = o.max_iterations;
      auto f = [&](double x) {
        const Trial t = nz.evaluate(x);
        return t.ok ? t.f : kNaN;
      };
      const RootResult rr = find_root(m, f, *b, ro);
      sum.iterations += rr.iterations;
      if (std::isfinite(rr.root)) {
        const Trial t = nz.evaluate(rr.root);
        if (t.ok) {
          best = t;
          xbest = rr.root;
          converged = std::abs(t.f) <= std::max(o.tolerance, 1e-3 * o.accuracy) && t.I.real() > 0;
        }
      }
      if (!converged) failure = "the root method did not converge in the sign bracket";
    }
  }
  // The end point is off by L|f| = |f|/Re∫ chords: where Re∫ is small (long loops) and that exceeds
  // a tenth of `accuracy`, a few Newton steps more.
  for (int it = 0; it < 4 && best.ok && best.I.real() > 0 && std::abs(best.f) > 0.1 * o.accuracy * best.I.real();
       ++it) {
    const double x = xbest - best.f / best.df;
    if (!std::isfinite(x)) break;
    const Trial t = nz.evaluate(x);
    ++sum.iterations;
    if (!t.ok || !(std::abs(t.f) < std::abs(best.f)) || !(t.I.real() > 0)) break;
    best = t;
    xbest = x;
  }
  // Not converged but within accept: finish() grades it (tolerance_not_met).
  if (converged || (best.ok && std::abs(best.f) <= o.accept && best.I.real() > 0)) {
    out.kind = Attempt::found;
    out.t = best;
    out.x = xbest;
    return out;
  }
  out.why = "no root of the reduced equation found (best |f| = " + format_number(best.ok ? std::abs(best.f) : kNaN) +
            (failure.empty() ? "" : "; " + failure) + ")";
  if (pr.alpha >= 0 && failure.empty()) out.why += "; for alpha >= 0 the root may need an end-curvature ratio beyond e^700";
  return out;
}

std::string turning_text(double delta) { return "turning " + format_number(delta) + " rad"; }

}  // namespace

G1HermiteResult solve_g1_hermite(const G1HermiteProblem& pr, const G1HermiteOptions& o) {
  const auto t_begin = std::chrono::steady_clock::now();
  o.validate();
  check_problem(pr);
  G1HermiteResult res;
  Summary& sum = res.summary;
  sum.solver = std::string(to_string(o.solver));
  sum.integrator = std::string(name_of(o.integrator));
  sum.accept = o.accept;
  const Complex d = pr.p1 - pr.p0;
  const double chord_angle = std::arg(d);
  const double phi0 = wrap_angle(pr.theta0 - chord_angle);
  const double phi1 = wrap_angle(pr.theta1 - chord_angle);
  const double base = phi1 - phi0;  // Δ_0; Δ_k = base + 2πk
  const auto turning_of = [&](int k) { return base + 2 * kPi * k; };

  const detail::Windings windings = detail::windings_to_try(base, o.winding, o.max_turning);
  const int first = windings.front();
  res.info.phi0 = phi0;
  res.info.phi1 = phi1;
  res.info.winding = first;
  res.info.turning = turning_of(first);
  res.info.max_turning = o.winding ? 0.0 : o.max_turning;
  res.info.shape = classify_input(phi0, phi1, turning_of(first));
  Normalized nz;
  nz.budget = o.max_evaluations;
  nz.alpha = pr.alpha;
  nz.phi0 = phi0;
  nz.delta = turning_of(first);
  auto done = [&]() -> G1HermiteResult& {
    sum.evaluations += nz.evaluations;
    sum.constructions += nz.constructions;
    sum.seconds = seconds_since(t_begin);
    return res;
  };

  // Straight data: the line (κ ≡ 0), for every α.
  if (phi0 == 0 && phi1 == 0 && first == 0) {
    Trial t;
    t.ok = true;
    t.I = 1.0;
    finish(res, pr, o, nz, t, 0);
    return done();
  }

  // The paper methods (turnings of at most π: the given winding, else winding 0).
  if (o.solver.kind == G1Kind::triangle || o.solver.kind == G1Kind::s_curve) {
    const int k = o.winding.value_or(0);
    nz.delta = turning_of(k);
    res.info.winding = k;
    res.info.turning = nz.delta;
    res.info.shape = classify_input(phi0, phi1, nz.delta);
    const bool convex = res.info.shape == G1Shape::convex && k == 0;
    const bool s = res.info.shape == G1Shape::s_shaped && k == 0 && pr.alpha < 0;
    if (o.solver.kind == G1Kind::triangle && !convex)
      throw_input_error("g1", "solver", "'triangle' (001) handles tangents on opposite sides of the chord with "
                                        "|turning| < pi and winding 0 only; use 'auto'");
    if (o.solver.kind == G1Kind::s_curve && !s)
      throw_input_error("g1", "solver", "'s-curve' (004) handles alpha < 0 with both tangents on the same side of the "
                                        "chord and winding 0 only; use 'auto'");
    const Complex t0 = std::polar(1.0, pr.theta0), t1 = std::polar(1.0, pr.theta1);
    PlanarCurve curve;
    Summary paper;
    if (o.solver.kind == G1Kind::triangle) {
      // Tangent intersection a1 = p0 + μ t0 = p1 − ν t1 (μ, ν > 0 for convex data).
      const double cross = (std::conj(t0) * t1).imag();
      const double mu = (std::conj(d) * t1).imag() / cross;
      TriangleOptions to;  // 001's search on its own default integrator unless one was asked for
      if (o.verify) to.integrator = o.integrator;
      to.accept = o.accept;
      TriangleResult tr = solve_g1({pr.p0, pr.p0 + mu * t0, pr.p1}, pr.alpha, to);
      curve = tr.curve;
      paper = tr.summary;
    } else {
      const double r = std::abs(d) / 3;
      SCurveOptions so;
      if (o.verify) so.integrator = o.integrator;
      so.accept = o.accept;
      SCurveResult sr = solve_s_curve({pr.p0, pr.p0 + r * t0, pr.p1 - r * t1, pr.p1}, pr.alpha, so);
      curve = sr.curve;
      paper = sr.summary;
    }
    const std::string solver = sum.solver, integrator = sum.integrator;
    sum = paper;
    sum.solver = solver;
    sum.integrator = integrator;
    // A paper method proves "no curve" only within its family (001: no inflection; 004: 004's
    // S-family); a G1 curve of another shape may exist, so for the G1 problem it is no proof.
    if (paper.status == Status::no_solution)
      sum.message = "g1: the '" + solver + "' method found no curve in its family (" +
                    (o.solver.kind == G1Kind::triangle ? "001's, without inflection" : "004's S-curves") +
                    "), which is no proof for every G1 curve ('auto' searches every shape): " + sum.message,
      sum.status = Status::not_converged;
    if (paper.usable()) {
      res.curve = curve;
      res.info.length = curve.length();
      res.info.turning = curve.theta_at(curve.length()) - curve.theta_at(0);
      for (const LaSegment& seg : curve.segments())
        if (auto s_in = seg.inflection_s()) res.info.inflection = *s_in;
    }
    sum.seconds = seconds_since(t_begin);
    return res;
  }

  // Each turning in order: the first curve found is returned.
  std::vector<std::pair<double, std::string>> proofs, failures;  // (turning, why)
  for (int k : windings) {
    nz.delta = turning_of(k);
    const Attempt a = attempt_turning(pr, o, nz, sum);
    if (a.kind == Attempt::none) {
      proofs.emplace_back(nz.delta, a.why);
      continue;
    }
    if (a.kind == Attempt::found) {
      finish(res, pr, o, nz, a.t, a.x);
      if (res.usable()) {
        res.info.winding = k;
        if (!failures.empty() && sum.message.empty())
          sum.message = "g1: not proven the least-turning curve: " + turning_text(failures.front().first) +
                        " unresolved (" + failures.front().second + ")";
        return done();
      }
      failures.emplace_back(nz.delta, sum.message);
      res.info.turning = turning_of(first);
      continue;
    }
    failures.emplace_back(nz.delta, a.why);
  }
  res.info.turning = turning_of(first);
  res.info.winding = first;
  res.curve = PlanarCurve{};
  // (With a winding the turning is info.turning; the message stays cheap to build.)
  const std::string scope = o.winding ? "g1: no curve of winding " + std::to_string(first)
                                      : "g1: no curve with total turning <= " + format_number(o.max_turning) +
                                            " rad (max_turning)";
  if (!failures.empty()) {
    std::string m = scope + " found, but the search is not complete: " + turning_text(failures.front().first) + ": " +
                    failures.front().second;
    if (failures.size() > 1) m += " (and " + std::to_string(failures.size() - 1) + " more turnings unresolved)";
    res.conclude(Status::not_converged, m);
    return done();
  }
  // Every turning excluded by a proof: group the turnings by argument.
  if (o.winding) {
    res.conclude(Status::no_solution, scope + ": " + proofs.front().second);
    return done();
  }
  const std::string m = scope + ":" + detail::proofs_text(proofs);
  res.conclude(Status::no_solution, m);
  return done();
}

}  // namespace lac
