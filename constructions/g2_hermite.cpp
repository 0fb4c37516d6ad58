#include "lac/constructions/g2_hermite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "lac/common/error.hpp"
#include "lac/constructions/detail/g2_system.hpp"

namespace lac::hermite {
namespace {

constexpr double kPi = std::numbers::pi;

double wrap_angle(double a) { return std::remainder(a, 2.0 * kPi); }  // (−π, π]

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::string_view to_string(G2Solver s) {
  switch (s) {
    case G2Solver::paper:
      return "paper";
    case G2Solver::newton:
      return "newton";
    case G2Solver::ceres:
      return "ceres";
  }
  return "?";
}
std::string_view to_string(G2Start s) { return s == G2Start::fast ? "fast" : "bezier-grid"; }

G2Solver parse_g2_solver(std::string_view name) {
  if (name == "paper") return G2Solver::paper;
  if (name == "newton") return G2Solver::newton;
  if (name == "ceres") return G2Solver::ceres;
  throw_input_error("g2", "solver", "'" + std::string(name) + "' is not one of paper, newton, ceres");
}
G2Start parse_g2_start(std::string_view name) {
  if (name == "fast") return G2Start::fast;
  if (name == "bezier-grid") return G2Start::bezier_grid;
  throw_input_error("g2", "start", "'" + std::string(name) + "' is not one of fast, bezier-grid");
}

void G2Options::validate() const {
  if (!(tolerance >= 1e-16 && tolerance <= 1e-3)) throw_input_error("g2", "tolerance", tolerance, "[1e-16, 1e-3]");
  if (!(accept >= tolerance && accept <= 1)) throw_input_error("g2", "accept", accept, "[tolerance, 1]");
  if (max_iterations < 1 || max_iterations > 100000)
    throw_input_error("g2", "max_iterations", max_iterations, "[1, 100000]");
  if (max_inner_iterations < 1 || max_inner_iterations > 100000)
    throw_input_error("g2", "max_inner_iterations", max_inner_iterations, "[1, 100000]");
}

CurveSample TripleLaCurve::at(double S) const {
  if (!(S >= 0 && S <= 1)) throw_input_error("TripleLaCurve::at", "S", S, "[0, 1]");
  std::complex<double> sum{};
  long evals = 0;
  CurveSample out;
  for (const auto& seg : segments) {
    if (S > seg.ub && &seg != &segments.back()) {
      sum += lac::detail::integrate_tangent(law, seg, evals);
      continue;
    }
    const lac::detail::LinearQ part{seg.ua, S, seg.qa, seg.q_at(S), seg.phi_a};
    if (S > seg.ua) sum += lac::detail::integrate_tangent(law, part, evals);
    out.theta = seg.phi_at(law, S) + chord_angle;
    out.kappa = seg.kappa_at(law, S) / (h * chord);
    break;
  }
  out.S = S;
  out.s = S * h * chord;
  out.position = origin + std::polar(chord * h, chord_angle) * sum;
  return out;
}

std::vector<CurveSample> TripleLaCurve::polyline(int n) const {
  if (n < 2) throw_input_error("TripleLaCurve::polyline", "points", n, "[2, inf)");
  std::vector<CurveSample> out;
  out.reserve(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) out.push_back(at(k + 1 == n ? 1.0 : static_cast<double>(k) / (n - 1)));
  return out;
}

std::array<SegmentCoefficients, 3> TripleLaCurve::coefficients() const {
  std::array<SegmentCoefficients, 3> c;
  const double a = law.alpha;
  for (size_t i = 0; i < 3; ++i) {
    const auto& g = segments[i];
    const double c0 = g.slope(), c1 = g.qa - c0 * g.ua;
    c[i].S_begin = g.ua;
    c[i].S_end = g.ub;
    if (a == 0) {  // 004 Eqs. (3), (7): κ̃ = c0 e^(c1 S), φ = (c0/c1) e^(c1 S) + c2 (arc: c1 = 0)
      const bool arc = std::abs(g.qb - g.qa) <= 1e-8;  // as below: Eq. (7) cancels near c1 = 0
      c[i].c0 = law.sigma * std::exp(arc ? 0.5 * (g.qa + g.qb) : c1);
      c[i].c1 = arc ? 0.0 : c0;
      c[i].c2 = arc ? g.phi_a - c[i].c0 * g.ua : g.phi_a - c[i].c0 / c0 * std::exp(c0 * g.ua);
      continue;
    }
    // Near an arc the Eq. (5) form cancels (c2 ~ |q|^p / c0, Appendix A): below a relative
    // change of q of sqrt(eps) ≈ 1e-8 over the segment the arc of Eq. (6), with q at the
    // segment's middle, is the more accurate of the two (both err by ≲ 1e-8 there).
    const bool arc = std::abs(g.qb - g.qa) <= 1e-8 * std::max(std::abs(g.qa), std::abs(g.qb));
    c[i].c0 = arc ? 0.0 : c0;
    c[i].c1 = arc ? 0.5 * (g.qa + g.qb) : c1;
    if (arc) {
      c[i].c2 = g.phi_a - law.kappa_of_q(c[i].c1) * g.ua;  // 004 Eq. (6)
    } else if (c0 == 0) {
      c[i].c2 = g.phi_a - law.kappa_of_q(c1) * g.ua;  // 004 Eq. (6)
    } else if (a == 1) {
      c[i].c2 = g.phi_a - std::log(std::abs(g.qa)) / c0;  // 004 Eq. (8)
    } else {
      c[i].c2 = g.phi_a - a / ((a - 1.0) * c0) * std::pow(std::abs(g.qa), (a - 1.0) / a);  // 004 Eq. (5)
    }
  }
  return c;
}

G2Result solve_g2(const G2Problem& pr, const G2Options& o) {
  const auto t_begin = std::chrono::steady_clock::now();
  o.validate();
  require_finite("g2", "p0.x", pr.start.position.real());
  require_finite("g2", "p0.y", pr.start.position.imag());
  require_finite("g2", "p1.x", pr.end.position.real());
  require_finite("g2", "p1.y", pr.end.position.imag());
  require_finite("g2", "theta0", pr.start.theta);
  require_finite("g2", "theta1", pr.end.theta);
  require_finite("g2", "kappa0", pr.start.kappa);
  require_finite("g2", "kappa1", pr.end.kappa);
  if (!(std::abs(pr.alpha) <= kMaxAbsAlpha)) throw_input_error("g2", "alpha", pr.alpha, "[-5, 5]");
  if (pr.alpha != 0 && std::abs(pr.alpha) < kMinAbsAlpha)
    throw_input_error("g2", "alpha", pr.alpha, "0 or 1e-300 <= |alpha| <= 5");
  // Finite end points can still be farther apart than the double range (as R10 for S-curves).
  const std::complex<double> d = pr.end.position - pr.start.position;
  const double r = std::abs(d);
  if (!std::isfinite(r)) throw_input_error("g2", "p1", "p1 - p0 beyond the double range (|p1 - p0| must be finite)");
  auto max_coordinate = [](std::complex<double> z) { return std::max(std::abs(z.real()), std::abs(z.imag())); };
  const double scale = std::max({1.0, max_coordinate(pr.start.position), max_coordinate(pr.end.position)});
  if (!(r > 1e-12 * scale)) throw_input_error("g2", "p1", "coincides with p0 (the chord must have positive length)");
  // The solve works on curvatures per chord length (004 §3.2): they must be representable.
  const std::string kappa_range = "[-" + format_number(std::numeric_limits<double>::max() / r) + ", " +
                                  format_number(std::numeric_limits<double>::max() / r) +
                                  "] (kappa times |p1 - p0| must be finite)";
  if (!std::isfinite(pr.start.kappa * r)) throw_input_error("g2", "kappa0", pr.start.kappa, kappa_range);
  if (!std::isfinite(pr.end.kappa * r)) throw_input_error("g2", "kappa1", pr.end.kappa, kappa_range);

  G2Result res;
  detail::NormalizedG2 p;
  p.law.alpha = pr.alpha;
  p.law.sigma = pr.start.kappa < 0 ? -1.0 : 1.0;
  p.phi_s = wrap_angle(pr.start.theta - std::arg(d));
  p.phi_e = wrap_angle(pr.end.theta - std::arg(d));
  p.kappa_s = pr.start.kappa * r;
  p.kappa_e = pr.end.kappa * r;
  res.curve.law = p.law;
  res.curve.origin = pr.start.position;
  res.curve.chord = r;
  res.curve.chord_angle = std::arg(d);
  if (pr.alpha >= 0 && !(pr.start.kappa * pr.end.kappa > 0)) {
    res.status = Status::no_solution;
    res.message =
        "for alpha >= 0 an LA segment's curvature never vanishes nor changes sign, so kappa0 and kappa1 "
        "must be nonzero with equal signs";
    res.seconds = seconds_since(t_begin);
    return res;
  }

  if (pr.alpha >= 0 && !(p.law.sigma * (p.phi_e - p.phi_s) > 0)) {
    res.status = Status::no_solution;
    res.message =
        "for alpha >= 0 the curvature keeps the sign of kappa0, so the turning theta1 - theta0 (measured "
        "from the chord, in (-pi, pi]) must have that sign too";
    res.seconds = seconds_since(t_begin);
    return res;
  }

  auto run = [&](G2Start start) {
    const auto t0 = std::chrono::steady_clock::now();
    const detail::StartEstimate e =
        start == G2Start::fast ? detail::fast_start(p) : detail::bezier_grid_start(p, pr.alpha);
    res.start_seconds += seconds_since(t0);
    res.evaluations += e.evaluations;
    detail::SolverOutcome so;
    switch (o.solver) {
      case G2Solver::newton:
        so = detail::solve_newton(p, e, o);
        break;
      case G2Solver::paper:
        so = detail::solve_paper(p, e, o);
        break;
      case G2Solver::ceres:
        so = detail::solve_ceres(p, e, o);
        break;
    }
    res.iterations += so.iterations;
    res.evaluations += so.evaluations;
    res.start_used = start;
    return so;
  };
  detail::SolverOutcome so = run(o.start);
  bool fell_back = false;
  if (so.status != Status::ok && o.start == G2Start::fast && o.grid_fallback) {
    detail::SolverOutcome retry = run(G2Start::bezier_grid);
    if (retry.status == Status::ok) so = retry, fell_back = true;
  }
  if (so.status != Status::ok) {
    res.status = so.status;
    res.message = so.message;
    res.seconds = seconds_since(t_begin);
    return res;
  }
  res.curve.h = so.h;
  res.curve.segments = detail::build_segments(p, so.h, so.q1, so.q2);
  res.length = res.curve.length();

  // User-unit results must be representable: the length, every point (within length/2 of the
  // chord's midpoint: the ellipse with foci p0, p1 and major axis `length`), the curvature (|κ| is
  // largest at a segment end: |q| is linear along each) and the coefficients.
  double kappa_max = 0;
  for (const auto& seg : res.curve.segments)
    kappa_max = std::max({kappa_max, std::abs(p.law.kappa_of_q(seg.qa)), std::abs(p.law.kappa_of_q(seg.qb))});
  kappa_max /= res.length;
  const double reach =
      (max_coordinate(0.5 * pr.start.position + 0.5 * pr.end.position) + 0.5 * res.length) * (1 + 1e-9);
  bool finite = std::isfinite(res.length) && std::isfinite(reach) && std::isfinite(kappa_max);
  for (const auto& c : res.curve.coefficients())
    finite = finite && std::isfinite(c.c0) && std::isfinite(c.c1) && std::isfinite(c.c2);
  if (!finite) {
    res.length = 0;  // nothing non-finite reaches the caller, usable or not
    res.status = Status::numerical_failure;
    res.message = "the curve's length, curvature, extent or coefficients are beyond the double range";
    res.seconds = seconds_since(t_begin);
    return res;
  }

  // Residuals; the end point's in the normalized frame (end − p1 = (p1 − p0)(h ∫e^{iφ}dS − 1)),
  // which cannot overflow.
  std::complex<double> sum{};
  if (o.verify) {
    for (const auto& seg : res.curve.segments) sum += lac::detail::integrate_tangent_reference(p.law, seg);
  } else {
    for (const auto& seg : res.curve.segments) sum += lac::detail::integrate_tangent(p.law, seg, res.evaluations);
  }
  res.residual_position = r * std::abs(so.h * sum - 1.0);
  const auto& s0 = res.curve.segments.front();
  const auto& s2 = res.curve.segments.back();
  res.residual_angle = std::max(std::abs(wrap_angle(s0.phi_a + res.curve.chord_angle - pr.start.theta)),
                                std::abs(wrap_angle(s2.phi_b(p.law) + res.curve.chord_angle - pr.end.theta)));
  const double hr = so.h * r;
  res.residual_curvature = std::max(std::abs(p.law.kappa_of_q(s0.qa) / hr - pr.start.kappa),
                                    std::abs(p.law.kappa_of_q(s2.qb) / hr - pr.end.kappa));
  const double worst = std::max({res.residual_position / r, res.residual_angle, res.residual_curvature * r});
  if (!std::isfinite(res.residual_position) || !std::isfinite(res.residual_angle) ||
      !std::isfinite(res.residual_curvature)) {
    // A check that cannot be evaluated leaves the curve unverified: not usable, and no NaN returned.
    res.length = 0;
    res.residual_position = res.residual_angle = res.residual_curvature = 0;
    res.status = Status::numerical_failure;
    res.message = "the residual check of the end conditions is not a finite number";
    res.seconds = seconds_since(t_begin);
    return res;
  }
  if (!(worst <= o.accept)) {
    res.status = Status::tolerance_not_met;
    res.message = "verified residual " + format_number(worst) + " above accept " + format_number(o.accept);
  } else {
    res.status = fell_back ? Status::fell_back : Status::ok;
    if (fell_back) res.message = "fast start failed; solved from the Bezier-grid start";
  }
  res.seconds = seconds_since(t_begin);
  return res;
}

}  // namespace lac::hermite
