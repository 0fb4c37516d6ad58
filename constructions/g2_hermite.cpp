#include "lac/constructions/g2_hermite.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/common/numeric.hpp"
#include "lac/constructions/detail/g2_system.hpp"
#include "lac/constructions/detail/windings.hpp"
#include "lac/curves/planar/la_segment_kernel.hpp"
#include "lac/solvers/detail/method_registry.hpp"

namespace lac {
namespace {

constexpr std::string_view kPaperDescription =
    "004 section 3.3: outer fixed-point iteration on the length h, bisection on c30 for Eq. (33), Newton on c10 "
    "for Eq. (41) with its analytic derivative";
constexpr std::string_view kPaperOptions = "tolerance, max_iterations (outer), max_inner_iterations";

// The N-D registry's rows (names, aliases, descriptions) as G2 solvers, then paper.
std::vector<SolverMethodInfo<G2Solver>> make_g2_solvers() {
  std::vector<SolverMethodInfo<G2Solver>> rows;
  for (const NonlinearMethodInfo& m : nonlinear_methods())
    rows.push_back({G2Solver{G2Solver::Kind::nonlinear, m.method}, m.name, m.aliases, m.description, m.options});
  rows.push_back({G2Solver::paper, "paper", {}, kPaperDescription, kPaperOptions});
  return rows;
}

// 004's coefficients of each segment (Eqs. 2, 3, 5–8) from its linear-q data in S.
std::array<SegmentCoefficients, 3> coefficients(const LaLaw& law, const std::array<detail::LinearQ, 3>& segments) {
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
      c[i].c2 = g.phi_a - a / ((a - 1.0) * c0) * power(std::abs(g.qa), (a - 1.0) / a);  // 004 Eq. (5)
    }
  }
  return c;
}

double max_coordinate(std::complex<double> z) { return std::max(std::abs(z.real()), std::abs(z.imag())); }

void check_problem(const G2Problem& pr) {
  require_finite("g2", "p0.x", pr.start.position.real());
  require_finite("g2", "p0.y", pr.start.position.imag());
  require_finite("g2", "p1.x", pr.end.position.real());
  require_finite("g2", "p1.y", pr.end.position.imag());
  require_finite("g2", "theta0", pr.start.theta);
  require_finite("g2", "theta1", pr.end.theta);
  require_finite("g2", "kappa0", pr.start.kappa);
  require_finite("g2", "kappa1", pr.end.kappa);
  if (!(std::abs(pr.alpha) <= kG2MaxAbsAlpha)) throw_input_error("g2", "alpha", pr.alpha, interval_text(-kG2MaxAbsAlpha, kG2MaxAbsAlpha, true, true));
  if (pr.alpha != 0 && std::abs(pr.alpha) < kG2MinAbsAlpha)
    throw_input_error("g2", "alpha", pr.alpha, "0 or 1e-300 <= |alpha| <= 5");
  // Finite end points can still be farther apart than the double range (as R10 for S-curves).
  const double r = std::abs(pr.end.position - pr.start.position);
  if (!std::isfinite(r)) throw_input_error("g2", "p1", "p1 - p0 beyond the double range (|p1 - p0| must be finite)");
  const double scale = std::max({1.0, max_coordinate(pr.start.position), max_coordinate(pr.end.position)});
  if (!(r > 1e-12 * scale)) throw_input_error("g2", "p1", "coincides with p0 (the chord must have positive length)");
  // The solve works on curvatures per chord length (004 §3.2): they must be representable.
  const auto kappa_range = [r] {  // built only for the error
    return "[-" + format_number(std::numeric_limits<double>::max() / r) + ", " +
           format_number(std::numeric_limits<double>::max() / r) + "] (kappa times |p1 - p0| must be finite)";
  };
  if (!std::isfinite(pr.start.kappa * r)) throw_input_error("g2", "kappa0", pr.start.kappa, kappa_range());
  if (!std::isfinite(pr.end.kappa * r)) throw_input_error("g2", "kappa1", pr.end.kappa, kappa_range());
}

}  // namespace

std::span<const SolverMethodInfo<G2Solver>> g2_solvers() {
  static const std::vector<SolverMethodInfo<G2Solver>> rows = make_g2_solvers();
  return rows;
}
std::string_view to_string(G2Solver s) { return detail::solver_method_name(g2_solvers(), s); }
G2Solver parse_g2_solver(std::string_view name) {
  return detail::parse_solver_method(g2_solvers(), name, "g2", "G2 solver");
}

std::string_view to_string(G2Start s) { return s == G2Start::fast ? "fast" : "bezier-grid"; }
G2Start parse_g2_start(std::string_view name) {
  if (name == "fast") return G2Start::fast;
  if (name == "bezier-grid") return G2Start::bezier_grid;
  std::string message(1, '\'');  // built step by step: GCC 12 warns (-Wrestrict) on "'" + std::string
  message.append(name).append("' is not one of fast, bezier-grid");
  throw_input_error("g2", "start", message);
}

void G2Options::validate() const {
  if (!(tolerance >= 1e-16 && tolerance <= 1e-3)) throw_input_error("g2", "tolerance", tolerance, "[1e-16, 1e-3]");
  if (!(accuracy >= tolerance && accuracy <= 1)) throw_input_error("g2", "accuracy", accuracy, "[tolerance, 1]");
  validate_accept("g2", accept);
  if (winding && (*winding < -100 || *winding > 100)) throw_input_error("g2", "winding", *winding, "[-100, 100]");
  if (!(max_turning >= std::numbers::pi && max_turning <= 200 * std::numbers::pi))
    throw_input_error("g2", "max_turning", max_turning, "[pi, 200 pi]");
  if (max_iterations < 1 || max_iterations > 100000)
    throw_input_error("g2", "max_iterations", max_iterations, "[1, 100000]");
  if (stagnation_window < 0 || stagnation_window > 100000)
    throw_input_error("g2", "stagnation_window", stagnation_window, "[0, 100000] (0: never)");
  if (max_inner_iterations < 1 || max_inner_iterations > 100000)
    throw_input_error("g2", "max_inner_iterations", max_inner_iterations, "[1, 100000]");
  if (max_evaluations < 1) throw_input_error("g2", "max_evaluations", static_cast<double>(max_evaluations), "[1, inf)");
  bool known = false;
  for (const SolverMethodInfo<G2Solver>& row : g2_solvers()) known = known || row.method == solver;
  if (!known) throw_input_error("g2", "solver", "not a choice of g2_solvers() (parse_g2_solver gives one)");
  std::visit([](const auto& m) { m.validate(); }, integrator);
}

namespace {

// One turning: the system p (its phi_e = φ0 + Δ_k) solved and the curve built and checked into res
// (status set; counters added to res.summary). `spent`: integrand evaluations of earlier turnings.
// `grid`: the Bézier-grid start, computed at its first use and kept for the call (it depends on the
// end tangents' directions only, the same for every turning).
void solve_turning(G2Result& res, const G2Problem& pr, const G2Options& o, detail::G2System& p, double chord_angle,
                   std::optional<detail::G2StartEstimate>& grid) {
  Summary& sum = res.summary;
  const std::complex<double> d = pr.end.position - pr.start.position;
  const double r = std::abs(d);
  auto finish = [&](Status status, std::string message) { res.conclude(status, std::move(message)); };

  const auto grid_start = [&]() -> const detail::G2StartEstimate& {
    if (!grid) {
      const auto t0 = std::chrono::steady_clock::now();
      grid = detail::g2_bezier_grid_start(p);
      res.info.start_seconds += seconds_since(t0);
      sum.evaluations += grid->evaluations;
    }
    return *grid;
  };
  auto run = [&](G2Start start) {
    detail::G2StartEstimate e;
    if (start == G2Start::fast) {
      const auto t0 = std::chrono::steady_clock::now();
      e = detail::g2_fast_start(p);
      res.info.start_seconds += seconds_since(t0);
      sum.evaluations += e.evaluations;
    } else {
      e = grid_start();
    }
    // The run's trial curves fail once the call's budget is spent (the run counts from 0).
    p.integrate.set_limit(std::max(0L, o.max_evaluations - sum.evaluations));
    detail::G2SolverOutcome so = o.solver == G2Solver::paper
                                     ? detail::solve_g2_paper(p, e, o)
                                     : detail::solve_g2_nonlinear(o.solver.method, p, e, o);
    if (so.status != Status::ok && so.evaluations >= p.integrate.limit()) {
      so.status = Status::max_iterations;
      so.message = "integrand evaluation budget max_evaluations = " + std::to_string(o.max_evaluations) +
                   " spent (" + so.message + ")";
    }
    sum.iterations += so.iterations;
    sum.evaluations += so.evaluations;
    sum.constructions += so.constructions;
    res.info.start_used = start;
    return so;
  };
  // 004's joints, from the fast start and then the Bézier grid; freed (o.free_joints) only where
  // neither finds a curve with them.
  const auto at_joints = [&p](double s1) { p.s1 = s1, p.s2 = 1 - s1; };
  at_joints(kG2S1);
  detail::G2SolverOutcome so = run(o.start);
  double solved_s1 = kG2S1;
  bool fell_back = false;
  if (so.status != Status::ok && o.start == G2Start::fast && o.grid_fallback && sum.evaluations < o.max_evaluations) {
    detail::G2SolverOutcome retry = run(G2Start::bezier_grid);
    if (retry.status == Status::ok) so = retry, fell_back = true;
  }
  if (o.free_joints && o.solver != G2Solver::paper) {
    for (const double s1 : {0.125, 0.0625}) {
      if (so.status == Status::ok || sum.evaluations >= o.max_evaluations) break;
      at_joints(s1);
      detail::G2SolverOutcome retry = run(G2Start::fast);
      if (retry.status == Status::ok) so = retry, solved_s1 = s1;
    }
  }
  if (so.status != Status::ok) return finish(so.status, so.message);
  at_joints(solved_s1);
  res.info.joints = {p.s1, p.s2};
  const std::array<detail::LinearQ, 3> segments = detail::g2_segments(p, so.h, so.q1, so.q2);
  res.info.h = so.h;
  res.info.coefficients = coefficients({p.law.alpha, p.law.sigma}, detail::plain_form(p.law, segments));

  // User-unit results must be representable: the length, every point (within length/2 of the
  // chord's midpoint: the ellipse with foci p0, p1 and major axis `length`), the curvature (|κ| is
  // largest at a segment end: |q| is linear along each) and the coefficients.
  const double length = so.h * r;
  double kappa_max = 0;
  for (const auto& seg : segments)
    kappa_max = std::max({kappa_max, std::abs(p.law.kappa_of_q(seg.qa)), std::abs(p.law.kappa_of_q(seg.qb))});
  kappa_max /= length;
  const double reach = (max_coordinate(0.5 * pr.start.position + 0.5 * pr.end.position) + 0.5 * length) * (1 + 1e-9);
  bool finite = std::isfinite(length) && std::isfinite(reach) && std::isfinite(kappa_max);
  for (const auto& c : res.info.coefficients) finite = finite && std::isfinite(c.c0) && std::isfinite(c.c1) && std::isfinite(c.c2);
  if (!finite)
    return finish(Status::numerical_failure,
                  "the curve's length, curvature, extent or coefficients are beyond the double range");

  // Per segment ∫e^{iφ}dS. Verified: by the segment kernel with its error bound
  // (curves/planar/la_segment_kernel.hpp), else, where the kernel does not evaluate a segment, by
  // the independent tanh-sinh evaluation; the integrator's error is its end point at the solution,
  // which the solver evaluated, against those, plus the kernel's bound. Unverified: by the
  // integrator (residuals its own, no estimate).
  std::array<std::complex<double>, 3> parts{};
  std::complex<double> integral{};
  double kernel_bound = 0;  // Σ of the kernel's bounds on ∫ over the chord-normalized segments
  p.integrate.set_limit(std::numeric_limits<long>::max());  // the result is integrated whatever the budget
  for (size_t k = 0; k < 3; ++k) {
    if (!o.verify) {
      parts[k] = p.integrate(p.law, segments[k], sum.evaluations);
    } else if (so.kernel_parts) {  // the kernel's, from the solver's last evaluation (the same segments)
      parts[k] = (*so.kernel_parts)[k].value;
      kernel_bound += (*so.kernel_parts)[k].error;
    } else if (const auto v = segment_integral(p.law, segments[k], sum.evaluations)) {
      parts[k] = v->value;
      kernel_bound += v->error;
    } else {
      parts[k] = detail::integrate_tangent_reference(p.law, segments[k]);
    }
    integral += parts[k];
  }
  if (!std::isfinite(integral.real()) || !std::isfinite(integral.imag()))
    return finish(Status::numerical_failure, o.verify ? "the residual check of the end conditions is not a finite number"
                                                      : "the integrator failed on the solved curve");
  if (o.verify && so.end) sum.error_estimate = r * (std::abs(*so.end - so.h * integral) + so.h * kernel_bound);
  // The curve: segment k + 1 starts where segment k ends.
  const std::complex<double> rotation = std::polar(1.0, chord_angle);
  try {
    std::vector<LaSegment> placed;
    std::complex<double> start{};
    for (size_t k = 0; k < 3; ++k) {
      placed.emplace_back(p.law, segments[k], Placement{pr.start.position + length * rotation * start, length, rotation});
      start += parts[k];
    }
    res.curve = PlanarCurve(std::move(placed));
  } catch (const InputError& e) {
    return finish(Status::numerical_failure, std::string("the solved curve is not representable: ") + e.what());
  }

  // Residuals; the end point's in the normalized frame (end − p1 = (p1 − p0)(h ∫e^{iφ}dS − 1)),
  // which cannot overflow.
  const double residual_position = r * std::abs(so.h * integral - 1.0);
  const auto& s0 = segments.front();
  const auto& s2 = segments.back();
  const double residual_angle = std::max(std::abs(wrap_angle(s0.phi_a + chord_angle - pr.start.theta)),
                                         std::abs(wrap_angle(s2.phi_b(p.law) + chord_angle - pr.end.theta)));
  const double hr = so.h * r;
  const double residual_curvature = std::max(std::abs(p.law.kappa_of_q(s0.qa) / hr - pr.start.kappa),
                                             std::abs(p.law.kappa_of_q(s2.qb) / hr - pr.end.kappa));
  if (!std::isfinite(residual_position) || !std::isfinite(residual_angle) || !std::isfinite(residual_curvature))
    // A check that cannot be evaluated leaves the curve unverified: not usable, and no NaN returned.
    return finish(Status::numerical_failure, "the residual check of the end conditions is not a finite number");
  sum.residuals = {residual_position, residual_angle, residual_curvature};
  // The position residual is the kernel's to within h·kernel_bound (chord units).
  const double worst = std::max({residual_position / r + so.h * kernel_bound, residual_angle, residual_curvature * r});
  // The achieved error (common/accuracy.hpp): conclude() grades it against accept.
  sum.error = std::max(worst, sum.error_estimate.value_or(0.0) / r);
  if (!(*sum.error <= o.accuracy))
    return finish(Status::tolerance_not_met, std::string(o.verify ? "verified" : "unverified") + " residual " +
                                                 format_number(*sum.error) + " above accuracy " +
                                                 format_number(o.accuracy));
  if (fell_back) return finish(Status::fell_back, "fast start failed; solved from the Bezier-grid start");
  return finish(Status::ok, "");
}

std::string turning_text(double delta) { return "turning " + format_number(delta) + " rad"; }

}  // namespace

G2Result solve_g2(const G2Problem& pr, const G2Options& o) {
  const auto t_begin = std::chrono::steady_clock::now();
  o.validate();
  check_problem(pr);
  const std::complex<double> d = pr.end.position - pr.start.position;
  const double r = std::abs(d), chord_angle = std::arg(d);
  constexpr double kPi = std::numbers::pi;

  G2Result res;
  Summary& sum = res.summary;
  sum.integrator = std::string(name_of(o.integrator));
  sum.solver = std::string(to_string(o.solver));
  sum.accept = o.accept;
  auto finish = [&](Status status, std::string message) {
    res.conclude(status, std::move(message));
    sum.seconds = seconds_since(t_begin);
    return res;
  };

  // The turning target: Δ_k = φ1 − φ0 + 2πk with φ0, φ1 relative to the chord in (−π, π].
  const double phi0 = wrap_angle(pr.start.theta - chord_angle), phi1 = wrap_angle(pr.end.theta - chord_angle);
  const double base = phi1 - phi0;
  const auto turning_of = [&](int k) { return base + 2 * kPi * k; };
  if (pr.alpha >= 0 && !(pr.start.kappa * pr.end.kappa > 0)) {  // before any search: stays sub-µs
    res.info.winding = o.winding.value_or(static_cast<int>(std::lround(-base / (2 * kPi))));
    res.info.turning = turning_of(res.info.winding);
    res.info.max_turning = o.winding ? 0.0 : o.max_turning;
    return finish(Status::no_solution,
                  "no curve of any winding: for alpha >= 0 an LA segment's curvature never vanishes nor changes sign, "
                  "so kappa0 and kappa1 must be nonzero with equal signs");
  }
  const detail::Windings windings = detail::windings_to_try(base, o.winding, o.max_turning);
  res.info.winding = windings.front();
  res.info.turning = turning_of(windings.front());
  res.info.max_turning = o.winding ? 0.0 : o.max_turning;

  const double sigma = pr.start.kappa < 0 ? -1.0 : 1.0;

  detail::G2System p{detail::g2_law(pr.alpha, sigma), phi0, phi1, pr.start.kappa * r, pr.end.kappa * r,
                     detail::TrialIntegrator(o.integrator)};
  std::vector<std::pair<double, std::string>> proofs, failures;  // (turning, why)
  std::optional<detail::G2StartEstimate> grid;
  Status failed_status = Status::not_converged;
  for (int k : windings) {
    const double delta = turning_of(k);
    if (pr.alpha >= 0 && !(sigma * delta > 0)) {
      proofs.emplace_back(delta, "for alpha >= 0 the curvature keeps the sign of kappa0, and the turning must have "
                                 "that sign too");
      continue;
    }
    if (pr.alpha >= 0 && std::abs(delta) <= kPi && !(delta > 0 ? (phi0 < 0 && phi0 + delta > 0) : (phi0 > 0 && phi0 + delta < 0))) {
      proofs.emplace_back(delta, "for alpha >= 0 the data need an inflection at turnings of at most pi (tangents on the "
                                 "same side of the chord, or one along it): a convex curve turning at most pi has its "
                                 "chord strictly between its end tangents");
      continue;
    }
    p.phi_e = phi0 + delta;
    G2Result attempt;
    attempt.summary = sum;  // counters (and the call's evaluation budget) carry over
    attempt.info.start_seconds = res.info.start_seconds;
    solve_turning(attempt, pr, o, p, chord_angle, grid);
    attempt.info.winding = k;
    attempt.info.turning = delta;
    attempt.info.max_turning = res.info.max_turning;
    if (attempt.usable()) {
      res = std::move(attempt);
      if (!failures.empty() && sum.status == Status::ok && sum.message.empty())
        sum.message = "not proven the least-turning curve: " + turning_text(failures.front().first) + " unresolved (" +
                      failures.front().second + ")";
      sum.seconds = seconds_since(t_begin);
      return res;
    }
    if (o.winding) {  // the one turning asked for: its own status
      res = std::move(attempt);
      sum.seconds = seconds_since(t_begin);
      return res;
    }
    sum.iterations = attempt.summary.iterations;
    sum.evaluations = attempt.summary.evaluations;
    sum.constructions = attempt.summary.constructions;
    res.info.start_seconds = attempt.info.start_seconds;
    failures.emplace_back(delta, std::string(to_string(attempt.summary.status)) + ": " + attempt.summary.message);
    if (attempt.summary.status == Status::max_iterations && sum.evaluations >= o.max_evaluations) {
      failed_status = Status::max_iterations;  // the call's budget is spent: no further turning can be tried
      break;
    }
  }
  const std::string scope = o.winding ? "no curve of " + turning_text(turning_of(windings.front())) + " (winding " +
                                            std::to_string(windings.front()) + ")"
                                      : "no curve with total turning <= " + format_number(o.max_turning) +
                                            " rad (max_turning)";
  if (!failures.empty()) {
    std::string m = scope + " found, but the search is not complete: " + turning_text(failures.front().first) + ": " +
                    failures.front().second;
    if (failures.size() > 1) m += " (and " + std::to_string(failures.size() - 1) + " more turnings unresolved)";
    if (failed_status == Status::max_iterations && failures.size() > 1)  // the budget stopped a later turning
      m += "; stopped at " + turning_text(failures.back().first) + ": " + failures.back().second;
    return finish(failed_status, m);
  }
  if (o.winding) return finish(Status::no_solution, scope + ": " + proofs.front().second);
  const std::string m = scope + ":" + detail::proofs_text(proofs);
  return finish(Status::no_solution, m);
}

}  // namespace lac
