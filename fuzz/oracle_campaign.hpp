#pragma once
// The correctness campaign (docs/robustness.md, "Oracle campaign"): random problems per
// construction, each result checked end to end by the independent long-double oracle of
// fuzz/oracle_check.hpp. Every usable result must meet its conditions within its own accept
// bound (summary.accept, relative to the chord; for positions of eval and quadratic 1e-6 of the
// arc length from the reference point); every no_solution must be backed by the proof's condition
// (recomputed here) within the scope its message states, and no curve may be found by the solver
// itself at another winding inside that scope.
//
// Problem i of construction c with seed S is drawn from its own generator (seeded by S, c, i), so
// the outcome of a problem does not depend on the threads or on the other problems.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "fuzz/oracle_check.hpp"
#include "lac/common/error.hpp"
#include "lac/constructions/chain.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/s_curve.hpp"
#include "lac/constructions/space_drawable_cases.hpp"
#include "lac/constructions/space_segment.hpp"
#include "lac/constructions/triangle_g1.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac::oracle {

constexpr double kPi = std::numbers::pi;
/// The accept bound of positions (eval, quadratic): relative to the arc length from the reference point.
constexpr double kPositionAccept = 1e-6;

/// Campaign-wide settings of the solves (recorded by the campaign's command line).
struct Settings {
  /// > 0: the integrand-evaluation budget of each g2, scurve and compound solve (their options'
  /// max_evaluations) instead of the library's default, and of each quadratic position where it
  /// is below the method's own budget; a call that spends it ends max_iterations (not usable, no
  /// verdict). Bounds the cost of the rare slow calls (a paper solver or a fixed-step rk4 on a
  /// long curve, 003's inverse of κ in a position integral: seconds each) in a long campaign.
  long max_evaluations = 0;
};

inline const std::vector<std::string>& constructions() {
  static const std::vector<std::string> names{"g1", "g2", "scurve", "chain", "compound", "quadratic", "eval", "space"};
  return names;
}

/// What became of one problem.
enum class Outcome {
  verified,          ///< usable, every condition within accept
  wrong_but_usable,  ///< usable, a condition beyond accept (or the wrong α, winding, ...)
  unverified,        ///< usable, but the oracle could not evaluate it (counted, not a verdict)
  no_solution,       ///< no_solution backed by its proof's condition
  false_no_curve,    ///< no_solution without a valid proof, or a curve found inside its scope
  input_error,       ///< InputError (e.g. α outside a solver's range: drawn on purpose)
  other_status,      ///< not usable, not no_solution: not_converged, max_iterations, ...
  exception,         ///< any other exception (a bug either way)
};

struct Record {
  Outcome outcome = Outcome::verified;
  double error = 0;   ///< verified error / accept (usable results)
  std::string status; ///< status name (other_status)
  std::string detail; ///< for findings: the input and what failed
  bool curve_at_other_winding = false;  ///< no_solution, but the solver verifies a curve at another winding in −2…2
  /// no_solution resting (at some winding) on the solver's certified scan of the α ≥ 0 shapes,
  /// which the oracle does not re-derive: counted apart, after every solver failed to refute it.
  bool by_scan = false;
  /// wrong_but_usable and the result's own error (summary.error, or the position's estimate) did
  /// not exceed accept either: nothing in the result tells that it is wrong.
  bool silent = false;
};

struct Example {
  long index = 0;
  std::string text;
};

struct Tally {
  long problems = 0, usable = 0, verified = 0, wrong = 0, unverified = 0, no_solution = 0, false_no_curve = 0,
       input_error = 0, other = 0, exceptions = 0, other_winding = 0, silent = 0, by_scan = 0;
  double worst = 0;  ///< largest verified error / accept
  std::map<std::string, long> statuses;
  std::vector<Example> wrong_examples, false_examples, unverified_examples, exception_examples, other_winding_examples;
  std::vector<Example> all;  ///< every wrong, false no-curve and exception, "kind: detail", by index

  static void keep(std::vector<Example>& v, Example e) {
    v.push_back(std::move(e));
    std::sort(v.begin(), v.end(), [](const Example& a, const Example& b) { return a.index < b.index; });
    if (v.size() > 5) v.resize(5);
  }
  void add(long index, const Record& r) {
    ++problems;
    switch (r.outcome) {
      case Outcome::verified: ++usable, ++verified; break;
      case Outcome::wrong_but_usable: ++usable, ++wrong; keep(wrong_examples, {index, r.detail}); break;
      case Outcome::unverified: ++usable, ++unverified; keep(unverified_examples, {index, r.detail}); break;
      case Outcome::no_solution: ++no_solution; break;
      case Outcome::false_no_curve: ++no_solution, ++false_no_curve; keep(false_examples, {index, r.detail}); break;
      case Outcome::input_error: ++input_error; break;
      case Outcome::other_status: ++other, ++statuses[r.status]; break;
      case Outcome::exception: ++exceptions; keep(exception_examples, {index, r.detail}); break;
    }
    if (r.outcome == Outcome::wrong_but_usable && r.silent) ++silent;
    if (r.outcome == Outcome::no_solution && r.by_scan) ++by_scan;
    if (r.outcome == Outcome::wrong_but_usable || r.outcome == Outcome::false_no_curve || r.outcome == Outcome::exception)
      all.push_back({index, std::string(r.outcome == Outcome::wrong_but_usable ? (r.silent ? "wrong (silent)" : "wrong")
                                        : r.outcome == Outcome::false_no_curve ? "false_no_curve" : "exception") +
                                ": " + r.detail});
    if (r.curve_at_other_winding) {
      ++other_winding;
      keep(other_winding_examples, {index, r.detail});
    }
    if (r.outcome == Outcome::verified || r.outcome == Outcome::wrong_but_usable) worst = std::max(worst, r.error);
  }
  void merge(const Tally& o) {
    problems += o.problems, usable += o.usable, verified += o.verified, wrong += o.wrong, unverified += o.unverified;
    no_solution += o.no_solution, false_no_curve += o.false_no_curve, input_error += o.input_error;
    other += o.other, exceptions += o.exceptions, other_winding += o.other_winding, silent += o.silent;
    by_scan += o.by_scan;
    worst = std::max(worst, o.worst);
    for (const auto& [k, n] : o.statuses) statuses[k] += n;
    all.insert(all.end(), o.all.begin(), o.all.end());
    std::sort(all.begin(), all.end(), [](const Example& a, const Example& b) { return a.index < b.index; });
    for (const auto& e : o.wrong_examples) keep(wrong_examples, e);
    for (const auto& e : o.false_examples) keep(false_examples, e);
    for (const auto& e : o.unverified_examples) keep(unverified_examples, e);
    for (const auto& e : o.exception_examples) keep(exception_examples, e);
    for (const auto& e : o.other_winding_examples) keep(other_winding_examples, e);
  }
};

// ------------------------------------------------------------------------------------------------
// Drawing.

struct Rng {
  std::mt19937_64 g;
  Rng(unsigned long seed, const std::string& construction, long index) {
    unsigned long h = 1469598103934665603UL;
    for (char ch : construction) h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211UL;
    std::seed_seq seq{static_cast<unsigned>(seed), static_cast<unsigned>(seed >> 32), static_cast<unsigned>(h),
                      static_cast<unsigned>(h >> 32), static_cast<unsigned>(index),
                      static_cast<unsigned>(static_cast<unsigned long>(index) >> 32)};
    g.seed(seq);
  }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(g); }
  bool chance(double p) { return uniform(0, 1) < p; }
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  std::complex<double> point(double r) { return {uniform(-r, r), uniform(-r, r)}; }
};

/// α in [−5, 5]: the special values, uniform draws, and (with `small`) 0 < |α| < 0.1.
inline double draw_alpha(Rng& r, double small_share = 0.05) {
  static const double specials[] = {-5, -3, -2, -1.5, -1, -0.5, -0.3, -0.1, 0, 0.1, 0.3, 0.5, 1, 1.5, 2, 3, 5};
  const double u = r.uniform(0, 1);
  if (u < 0.35) return specials[r.integer(0, static_cast<int>(std::size(specials)) - 1)];
  if (u < 0.35 + small_share) return (r.chance(0.5) ? -1 : 1) * r.log_uniform(1e-6, 0.1);
  return r.chance(0.5) ? -r.uniform(0.1, 5) : r.uniform(0.1, 5);
}

/// LAC_ORACLE_TRACE=1: every problem's input on stderr before it is solved (to find a slow one).
inline bool trace() {
  static const bool on = std::getenv("LAC_ORACLE_TRACE") != nullptr;
  return on;
}
inline void trace_input(const std::string& input) {
  if (trace()) std::fprintf(stderr, "oracle: %s\n", input.c_str());
}

inline std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}
inline std::string pt(std::complex<double> z) { return num(z.real()) + "," + num(z.imag()); }

inline const std::vector<std::string>& quadrature_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& m : quadrature_methods()) v.emplace_back(m.name);
    return v;
  }();
  return names;
}

inline double wrap(double a) {
  double r = std::remainder(a, 2 * kPi);
  return r == -kPi ? kPi : r;
}

/// Grades a usable planar result: verified, wrong or unverified.
inline Record grade(const Verdict& v, const Summary& sum, const std::string& input) {
  const double accept = sum.accept;
  Record r;
  if (!v.verified) {
    r.outcome = Outcome::unverified;
    r.detail = input + " | oracle: " + v.why;
    return r;
  }
  r.error = v.error / accept;
  if (!(v.error <= accept + v.uncertainty)) {
    r.outcome = Outcome::wrong_but_usable;
    r.detail = input + " | " + v.worst + " error " + num(v.error) + " > accept " + num(accept) +
               " (oracle uncertainty " + num(v.uncertainty) + "); status " + std::string(to_string(sum.status)) +
               ", summary.error " + (sum.error ? num(*sum.error) : std::string("unset"));
    r.silent = !(sum.error && *sum.error > accept);
  } else if (v.uncertainty > 0.1 * accept) {
    r.outcome = Outcome::unverified;
    r.error = 0;
    r.detail = input + " | oracle uncertainty " + num(v.uncertainty) + " of the chord (error found " + num(v.error) + ")";
  }
  return r;
}

inline Record not_usable(const Summary& s) {
  Record r;
  r.outcome = Outcome::other_status;
  r.status = std::string(to_string(s.status));
  return r;
}

// ------------------------------------------------------------------------------------------------
// G1 Hermite (constructions/g1_hermite.hpp; proofs: docs/g1_hermite.md "Proofs of no solution").

struct G1Data {
  std::complex<double> p0, p1;
  double theta0 = 0, theta1 = 0, alpha = 0;
  int winding = 0;
};

/// The turning of winding k, recomputed: end tangents relative to the chord in (−π, π].
inline double g1_turning(const G1Data& d, int k) {
  const double chord = std::arg(d.p1 - d.p0);
  return wrap(d.theta1 - chord) - wrap(d.theta0 - chord) + 2 * kPi * k;
}

/// Whether a proof of "no G1 curve of slope α ≥ 0 with winding k" applies: Δ = 0, or |Δ| ≤ π
/// with the chord not strictly between the end tangents, or α > 1, |Δ| ≤ π and both limit shapes
/// (κ = ∞ at one end: φ = φ0 + Δu^p, p = 1 − 1/α, and its mirror) end on the same side of the
/// chord (the end direction is monotonic between them). The limits by the oracle's quadrature.
inline bool g1_no_curve_proven(const G1Data& d, int k) {
  if (d.alpha < 0) return false;
  const double chord = std::arg(d.p1 - d.p0);
  const double phi0 = wrap(d.theta0 - chord), phi1 = wrap(d.theta1 - chord);
  const double delta = phi1 - phi0 + 2 * kPi * k;
  if (delta == 0) return true;
  if (std::abs(delta) > kPi) return false;
  const bool between = delta > 0 ? (phi0 < 0 && phi1 + 2 * kPi * k > 0) : (phi0 > 0 && phi1 + 2 * kPi * k < 0);
  if (!between) return true;
  if (d.alpha > 1) {
    // φ = φ0 + Δ u^p as a segment: q linear from 0 (κ = ∞) to 1, α > 1 (F(0) = 0).
    const R p = 1 - 1 / R(d.alpha);
    using GK = boost::math::quadrature::gauss_kronrod<R, 15>;
    auto at_start = [&](R u) { const R ph = phi0 + delta * std::pow(u, p); return CR(std::cos(ph), std::sin(ph)); };
    auto at_end = [&](R u) {
      const R ph = phi0 + delta * (1 - std::pow(1 - u, p));
      return CR(std::cos(ph), std::sin(ph));
    };
    // u = t^m makes the start smooth (m p ≥ 4).
    const R m = std::ceil(4 / p);
    auto smooth_start = [&](R t) { return at_start(std::pow(t, m)) * (m * std::pow(t, m - 1)); };
    auto smooth_end = [&](R t) { return at_end(1 - std::pow(t, m)) * (m * std::pow(t, m - 1)); };
    R e1 = 0, e2 = 0;
    const CR J1 = GK::integrate(smooth_start, R(0), R(1), 20, 1e-15L, &e1);
    const CR J2 = GK::integrate(smooth_end, R(0), R(1), 20, 1e-15L, &e2);
    const R f1 = J1.imag(), f2 = J2.imag();
    // Same side of the chord at both limits, by more than the oracle's error: proven.
    return (f1 > 1e-12L && f2 > 1e-12L) || (f1 < -1e-12L && f2 < -1e-12L);
  }
  return false;
}

/// The windings a no_solution message covers: "every winding" → all of −2…2, "turning <= T" →
/// those with |Δ| ≤ T, otherwise the asked winding only.
inline std::vector<int> g1_scope(const G1Data& d, const std::string& message) {
  std::vector<int> ks;
  if (message.find("every winding") != std::string::npos || message.find("all windings") != std::string::npos) {
    for (int k = -2; k <= 2; ++k) ks.push_back(k);
    return ks;
  }
  const auto pos = message.find("turning <= ");
  if (pos != std::string::npos) {
    const double T = std::strtod(message.c_str() + pos + 11, nullptr);
    for (int k = -2; k <= 2; ++k)
      if (std::abs(g1_turning(d, k)) <= T) ks.push_back(k);
    return ks;
  }
  ks.push_back(d.winding);
  return ks;
}

inline std::string g1_input(const G1Data& d, const std::string& solver, bool verify) {
  return "solve_g1_hermite p0 " + pt(d.p0) + " theta0 " + num(d.theta0) + " p1 " + pt(d.p1) + " theta1 " +
         num(d.theta1) + " alpha " + num(d.alpha) + " winding " + std::to_string(d.winding) + " solver " + solver +
         (verify ? " verify" : "");
}

inline PlanarSpec g1_spec(const G1Data& d, int k) {
  PlanarSpec spec;
  spec.waypoints = {{-1, d.p0, d.theta0, {}}, {0, d.p1, d.theta1, {}}};
  spec.alphas = {d.alpha};
  spec.straight_any_alpha = true;
  spec.turning = g1_turning(d, k);
  spec.scale = std::abs(d.p1 - d.p0);
  return spec;
}

/// Whether the solver itself, with winding k (and `solver`), returns a curve the oracle verifies.
inline bool g1_curve_verified(const G1Data& d, int k, const char* solver = "auto") {
  G1HermiteOptions o;
  o.winding = k;
  o.solver = parse_g1_solver(solver);
  try {
    const G1HermiteResult r = solve_g1_hermite({d.p0, d.theta0, d.p1, d.theta1, d.alpha}, o);
    if (!r.usable()) return false;
    const Verdict v = check_planar(r.curve, g1_spec(d, k));
    return v.verified && v.error <= r.summary.accept;
  } catch (const InputError&) {
    return false;
  }
}

/// Checks a G1 no_solution: a proof for every winding of its scope, and no verified curve there.
inline Record g1_check_no_solution(const G1Data& d, const std::string& message, const std::string& input) {
  Record r;
  r.outcome = Outcome::no_solution;
  for (int k : g1_scope(d, message)) {
    // The certified scan (docs/g1_hermite.md) is not re-derived here: every root method tries to
    // refute it (a verified curve at that winding is a false no-curve).
    if (!g1_no_curve_proven(d, k) && message.find("certified scan") != std::string::npos && d.alpha >= 0 &&
        !g1_curve_verified(d, k) && !g1_curve_verified(d, k, "toms748") && !g1_curve_verified(d, k, "bisection")) {
      r.by_scan = true;
      continue;
    }
    if (!g1_no_curve_proven(d, k)) {
      r.outcome = Outcome::false_no_curve;
      r.detail = input + " | no proof applies at winding " + std::to_string(k) + " (turning " +
                 num(g1_turning(d, k)) + "; solver auto " + (g1_curve_verified(d, k) ? "verifies a curve" : "finds none") +
                 "): " + message;
      return r;
    }
    if (k != d.winding && g1_curve_verified(d, k)) {
      r.outcome = Outcome::false_no_curve;
      r.detail = input + " | the solver verifies a curve at winding " + std::to_string(k) + ": " + message;
      return r;
    }
  }
  for (int k = -2; k <= 2; ++k)
    if (k != d.winding && g1_curve_verified(d, k)) {
      r.curve_at_other_winding = true;
      r.detail = input + " | curve at winding " + std::to_string(k) + " outside the message's scope: " + message;
      break;
    }
  return r;
}

inline Record run_g1(Rng& rng) {
  G1Data d;
  d.alpha = draw_alpha(rng);
  d.p0 = rng.point(10);
  const double psi = rng.uniform(-kPi, kPi);
  d.p1 = d.p0 + std::polar(std::pow(10.0, rng.uniform(-3, 3)), psi);
  d.theta0 = psi + rng.uniform(-kPi, kPi);
  d.theta1 = psi + rng.uniform(-kPi, kPi);
  const double u = rng.uniform(0, 1);
  if (u < 0.04) d.theta0 = psi;                       // start tangent along the chord
  else if (u < 0.08) d.theta1 = d.theta0;             // parallel tangents
  else if (u < 0.12) d.theta1 = d.theta0 + kPi;       // anti-parallel
  else if (u < 0.15) d.theta1 = 2 * psi - d.theta0;   // symmetric
  d.winding = rng.chance(0.7) ? 0 : rng.integer(-2, 2);
  static const char* solvers[] = {"bisection", "secant", "toms748", "ceres", "triangle", "s-curve"};
  const std::string solver = rng.chance(0.8) ? "auto" : solvers[rng.integer(0, 5)];
  const bool verify = rng.chance(0.5);
  const std::string integrator = quadrature_names()[static_cast<size_t>(rng.integer(0, static_cast<int>(quadrature_names().size()) - 1))];
  const std::string input = g1_input(d, solver, verify) + " integrator " + integrator;
  trace_input(input);
  G1HermiteOptions o;
  o.solver = parse_g1_solver(solver);
  o.winding = d.winding;
  o.verify = verify;
  G1HermiteResult res;
  try {
    o.integrator = make_quadrature(integrator);
    res = solve_g1_hermite({d.p0, d.theta0, d.p1, d.theta1, d.alpha}, o);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
  if (res.usable()) return grade(check_planar(res.curve, g1_spec(d, d.winding)), res.summary, input);
  if (res.summary.status == Status::no_solution) return g1_check_no_solution(d, res.summary.message, input);
  return not_usable(res.summary);
}

// ------------------------------------------------------------------------------------------------
// G2 Hermite (constructions/g2_hermite.hpp).

/// The sign rules of α ≥ 0 (κ keeps one sign): κ0 κ1 > 0 and the turning (chord-relative, in
/// (−π, π]) of κ0's sign are needed.
inline bool g2_no_curve_proven(const G2Problem& p) {
  if (p.alpha < 0) return false;
  if (!(p.start.kappa * p.end.kappa > 0)) return true;
  const double chord = std::arg(p.end.position - p.start.position);
  const double sigma = p.start.kappa < 0 ? -1 : 1;
  return !(sigma * (wrap(p.end.theta - chord) - wrap(p.start.theta - chord)) > 0);
}

inline std::string g2_input(const G2Problem& p) {
  return "solve_g2 p0 " + pt(p.start.position) + " theta0 " + num(p.start.theta) + " kappa0 " + num(p.start.kappa) +
         " p1 " + pt(p.end.position) + " theta1 " + num(p.end.theta) + " kappa1 " + num(p.end.kappa) + " alpha " +
         num(p.alpha);
}

inline PlanarSpec g2_spec(const G2Problem& p) {
  PlanarSpec spec;
  spec.waypoints = {{-1, p.start.position, p.start.theta, p.start.kappa}, {2, p.end.position, p.end.theta, p.end.kappa}};
  spec.alphas = {p.alpha};
  spec.joint_order = 2;
  spec.scale = std::abs(p.end.position - p.start.position);
  return spec;
}

inline Record run_g2(Rng& rng, const Settings& settings) {
  G2Problem p;
  p.alpha = draw_alpha(rng, 0.02);
  p.start.position = rng.point(10);
  const double psi = rng.uniform(-kPi, kPi);
  const double chord = std::pow(10.0, rng.uniform(-2, 2));
  p.end.position = p.start.position + std::polar(chord, psi);
  p.start.theta = psi + rng.uniform(-kPi / 2, kPi / 2);
  p.end.theta = psi + rng.uniform(-kPi / 2, kPi / 2);
  p.start.kappa = rng.uniform(-4, 4) / chord;
  p.end.kappa = rng.uniform(-4, 4) / chord;
  if (rng.chance(0.05)) p.start.kappa = 0;
  if (rng.chance(0.3)) p.end.kappa = std::copysign(p.end.kappa, p.start.kappa);
  G2Options o;
  if (settings.max_evaluations > 0) o.max_evaluations = settings.max_evaluations;
  const double u = rng.uniform(0, 1);
  o.solver = u < 0.85 ? G2Solver::newton : u < 0.95 ? G2Solver::ceres : u < 0.99 ? G2Solver::paper : G2Solver::simplex;
  o.grid_fallback = rng.chance(0.2);
  const std::string integrator = rng.chance(0.8) ? "gauss-legendre" : quadrature_names()[static_cast<size_t>(rng.integer(0, 4))];
  const std::string input = g2_input(p) + " solver " + std::string(to_string(o.solver)) + " integrator " + integrator +
                            (o.grid_fallback ? " grid_fallback" : "");
  trace_input(input);
  G2Result res;
  try {
    o.integrator = make_quadrature(integrator);
    res = solve_g2(p, o);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
  if (res.usable()) return grade(check_planar(res.curve, g2_spec(p)), res.summary, input);
  if (res.summary.status == Status::no_solution) {
    Record r;
    r.outcome = g2_no_curve_proven(p) ? Outcome::no_solution : Outcome::false_no_curve;
    if (r.outcome == Outcome::false_no_curve) r.detail = input + " | no sign rule applies: " + res.summary.message;
    return r;
  }
  return not_usable(res.summary);
}

// ------------------------------------------------------------------------------------------------
// S-curve (constructions/s_curve.hpp).

inline Record run_scurve(Rng& rng, const Settings& settings) {
  const double alpha = rng.chance(0.3) ? -std::array{5.0, 3.0, 2.0, 1.0, 0.5, 0.1}[static_cast<size_t>(rng.integer(0, 5))]
                                       : -rng.uniform(1e-3, 5);
  const std::complex<double> P0 = rng.point(10);
  const double psi = rng.uniform(-kPi, kPi);
  const double chord = std::pow(10.0, rng.uniform(-2, 2));
  const std::complex<double> P3 = P0 + std::polar(chord, psi);
  const double t0 = psi + rng.uniform(-kPi * 0.9, kPi * 0.9), t1 = psi + rng.uniform(-kPi * 0.9, kPi * 0.9);
  const std::complex<double> P1 = P0 + std::polar(chord * rng.uniform(0.1, 0.6), t0);
  const std::complex<double> P2 = P3 - std::polar(chord * rng.uniform(0.1, 0.6), t1);
  SCurveOptions o;
  if (settings.max_evaluations > 0) o.max_evaluations = settings.max_evaluations;
  o.solver = rng.chance(0.7) ? RootMethod::toms748 : RootMethod::bisection;
  const std::string integrator = rng.chance(0.7) ? "gauss-legendre" : quadrature_names()[static_cast<size_t>(rng.integer(0, 4))];
  const std::string input = "solve_s_curve P " + pt(P0) + " " + pt(P1) + " " + pt(P2) + " " + pt(P3) + " alpha " +
                            num(alpha) + " solver " + (o.solver == RootMethod::toms748 ? "toms748" : "bisection") +
                            " integrator " + integrator;
  trace_input(input);
  SCurveResult res;
  const double th0 = std::arg(P1 - P0), th1 = std::arg(P3 - P2);
  try {
    o.integrator = make_quadrature(integrator);
    res = solve_s_curve({P0, P1, P2, P3}, alpha, o);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
  if (res.usable()) {
    PlanarSpec spec;
    spec.waypoints = {{-1, P0, th0, {}}, {0, P3, th1, {}}};
    spec.alphas = {alpha};
    spec.straight_any_alpha = true;
    spec.scale = chord;
    return grade(check_planar(res.curve, spec), res.summary, input);
  }
  if (res.summary.status == Status::no_solution) {
    // Scope: "straight" (any curve) or the C-shaped family: no inflection, |κ| largest at the
    // end whose tangent the chord is farther from. The G1 Hermite solver on the same data
    // (winding 0) must not verify a curve of that scope.
    Record r;
    r.outcome = Outcome::no_solution;
    const std::string& m = res.summary.message;
    const bool c_shaped = m.find("C-shaped") != std::string::npos;
    const bool straight = m.find("straight") != std::string::npos;
    if (!c_shaped && !straight) {
      r.outcome = Outcome::false_no_curve;
      r.detail = input + " | unrecognised no_solution scope: " + m;
      return r;
    }
    G1Data d{P0, P3, th0, th1, alpha, 0};
    try {
      const G1HermiteResult g = solve_g1_hermite({P0, th0, P3, th1, alpha});
      if (g.usable()) {
        const Verdict v = check_planar(g.curve, g1_spec(d, 0));
        if (v.verified && v.error <= g.summary.accept) {
          const LaSegment& seg = g.curve.segments().front();
          const bool inflection = seg.inflection_u().has_value() && seg.qa() != 0 && seg.qb() != 0;
          const double chord_angle = std::arg(P3 - P0);
          const bool start_farther = std::abs(wrap(th0 - chord_angle)) > std::abs(wrap(th1 - chord_angle));
          const bool kappa_larger_at_start = std::abs(seg.kappa_start()) > std::abs(seg.kappa_end());
          const bool in_scope = straight || (!inflection && start_farther == kappa_larger_at_start);
          if (in_scope) {
            r.outcome = Outcome::false_no_curve;
            r.detail = input + " | solve_g1_hermite verifies a curve within the message's scope: " + m;
          }
        }
      }
    } catch (const InputError&) {
    }
    return r;
  }
  return not_usable(res.summary);
}

// ------------------------------------------------------------------------------------------------
// Chains (constructions/chain.hpp).

inline Record run_chain(Rng& rng) {
  ChainProblem p;
  const int n = rng.integer(3, 8);
  p.alpha = draw_alpha(rng, 0.02);
  p.continuity = rng.chance(0.6) ? ChainContinuity::g1 : ChainContinuity::g2;
  p.closed = rng.chance(0.2);
  std::complex<double> z = rng.point(10);
  double dir = rng.uniform(-kPi, kPi);
  for (int i = 0; i < n; ++i) {
    p.points.push_back(z);
    dir += rng.uniform(-2, 2);
    z += std::polar(std::pow(10.0, rng.uniform(-1, 1)), dir);
  }
  if (rng.chance(0.4)) {
    for (int i = 0; i < n; ++i) {
      const auto a = p.points[static_cast<size_t>(std::max(0, i - 1))], b = p.points[static_cast<size_t>(std::min(n - 1, i + 1))];
      p.thetas.push_back(std::arg(b - a) + rng.uniform(-1, 1));
    }
    if (p.continuity == ChainContinuity::g2 && rng.chance(0.5))
      for (int i = 0; i < n; ++i) p.kappas.push_back(rng.uniform(-1, 1));
  }
  std::string input = "solve_chain alpha " + num(p.alpha) + (p.continuity == ChainContinuity::g1 ? " g1" : " g2") +
                      (p.closed ? " closed" : "") + " points";
  for (auto q : p.points) input += " " + pt(q);
  if (!p.thetas.empty()) {
    input += " thetas";
    for (double t : p.thetas) input += " " + num(t);
  }
  if (!p.kappas.empty()) {
    input += " kappas";
    for (double k : p.kappas) input += " " + num(k);
  }
  trace_input(input);
  ChainResult res;
  try {
    res = solve_chain(p);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
  const size_t pairs = p.closed ? p.points.size() : p.points.size() - 1;
  const bool g2 = p.continuity == ChainContinuity::g2;
  auto point = [&](size_t k) { return p.points[k % p.points.size()]; };
  if (res.usable()) {
    const size_t m = g2 ? 3 : 1;
    if (res.curve.segments().size() != pairs * m) {
      Record r;
      r.outcome = Outcome::wrong_but_usable;
      r.detail = input + " | " + std::to_string(res.curve.segments().size()) + " segments for " + std::to_string(pairs) + " pairs";
      return r;
    }
    // Each pair is graded against its own chord, as the chain grades it (summary.error is the
    // largest pair's error relative to that pair's chord): the pair's segments as one curve, its
    // end points, tangents (and curvatures) as waypoints. Consecutive pairs meet at the given
    // points, so the waypoints also check the joints between pairs.
    auto kappa_at = [&](size_t k) -> std::optional<double> {
      if (!g2) return std::nullopt;
      return res.info.kappas.at(k % p.points.size());
    };
    Verdict all;
    const auto& segs = res.curve.segments();
    for (size_t k = 0; k < pairs; ++k) {
      PlanarSpec spec;
      spec.scale = std::abs(point(k + 1) - point(k));
      spec.waypoints.push_back({-1, point(k), res.info.thetas.at(k), kappa_at(k)});
      spec.waypoints.push_back({static_cast<int>(m - 1), point(k + 1), res.info.thetas.at((k + 1) % p.points.size()), kappa_at(k + 1)});
      spec.alphas = {p.alpha};
      spec.straight_any_alpha = true;
      spec.joint_order = g2 ? 2 : 1;
      const std::vector<LaSegment> part(segs.begin() + static_cast<long>(k * m), segs.begin() + static_cast<long>((k + 1) * m));
      Verdict v = check_planar(PlanarCurve(part), spec);
      all.uncertainty = std::max(all.uncertainty, v.uncertainty);
      if (!v.verified) {
        v.why = "pair " + std::to_string(k) + ": " + v.why;
        v.uncertainty = all.uncertainty;
        all = v;
        break;
      }
      if (v.error > all.error || (std::isinf(v.error) && !std::isinf(all.error))) {
        all.error = v.error;
        all.worst = "pair " + std::to_string(k) + ": " + v.worst;
      }
    }
    return grade(all, res.summary, input);
  }
  if (res.summary.status == Status::no_solution) {
    Record r;
    r.outcome = Outcome::no_solution;
    const int k = res.info.failed_pair;
    bool proven = false;
    if (k >= 0 && static_cast<size_t>(k) < pairs && res.info.thetas.size() == p.points.size()) {
      const size_t a = static_cast<size_t>(k), b = (a + 1) % p.points.size();
      if (!g2) {
        // The failed pair is a G1 Hermite problem: its no_solution is checked as the g1 campaign
        // checks one, over the scope its message states (the certified scan included).
        const G1Data d{p.points[a], p.points[b], res.info.thetas[a], res.info.thetas[b], p.alpha, 0};
        return g1_check_no_solution(d, res.summary.message, input + " | failed pair " + std::to_string(k));
      } else if (res.info.kappas.size() == p.points.size()) {
        proven = g2_no_curve_proven({{p.points[a], res.info.thetas[a], res.info.kappas[a]},
                                     {p.points[b], res.info.thetas[b], res.info.kappas[b]}, p.alpha});
      }
    }
    if (!proven) {
      r.outcome = Outcome::false_no_curve;
      r.detail = input + " | failed pair " + std::to_string(k) + ": no proof applies: " + res.summary.message;
    }
    return r;
  }
  return not_usable(res.summary);
}

// ------------------------------------------------------------------------------------------------
// Control-triangle G1 and compound segments (constructions/triangle_g1.hpp).

inline Record run_compound(Rng& rng, const Settings& settings) {
  const std::complex<double> a0 = rng.point(10);
  const double psi = rng.uniform(-kPi, kPi);
  const double leg0 = std::pow(10.0, rng.uniform(-2, 2)), leg1 = leg0 * std::pow(10.0, rng.uniform(-1.5, 1.5));
  double tau = rng.uniform(0.01, kPi - 0.01);
  if (rng.chance(0.5)) tau = -tau;
  const std::complex<double> a1 = a0 + std::polar(leg0, psi), a2 = a1 + std::polar(leg1, psi + tau);
  const bool monotone = rng.chance(0.25);
  const double alpha0 = draw_alpha(rng, 0), alpha1 = monotone ? alpha0 : draw_alpha(rng, 0);
  const double r = rng.uniform(0.02, 0.98);
  TriangleOptions o;
  if (settings.max_evaluations > 0) o.max_evaluations = settings.max_evaluations;
  const std::string integrator = quadrature_names()[static_cast<size_t>(rng.integer(0, static_cast<int>(quadrature_names().size()) - 1))];
  const auto& roots = root_methods();
  const std::string solver(roots[static_cast<size_t>(rng.integer(0, static_cast<int>(roots.size()) - 1))].name);
  std::string input = std::string(monotone ? "solve_g1" : "solve_compound") + " a0 " + pt(a0) + " a1 " + pt(a1) + " a2 " +
                      pt(a2) + " alpha " + num(alpha0);
  if (!monotone) input += " alpha1 " + num(alpha1) + " r " + num(r);
  input += " integrator " + integrator + " solver " + solver;
  trace_input(input);
  TriangleResult res;
  try {
    o.integrator = make_quadrature(integrator);
    o.solver = parse_root_method(solver);
    res = monotone ? solve_g1({a0, a1, a2}, alpha0, o) : solve_compound({a0, a1, a2}, alpha0, alpha1, r, o);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
  if (res.usable()) {
    PlanarSpec spec;
    const double turning = std::arg((a2 - a1) / (a1 - a0));
    spec.waypoints = {{-1, a0, std::arg(a1 - a0), {}}, {static_cast<int>(res.curve.segments().size()) - 1, a2, std::arg(a2 - a1), {}}};
    spec.turning = turning;
    spec.scale = std::abs(a2 - a0);
    // Segment 0 of 001 is at the small-ρ end, the end of the shorter control leg.
    const bool seg0_at_a0 = leg0 <= leg1;
    if (monotone) {
      spec.alphas = {alpha0};
      if (res.curve.segments().size() != 1) spec.alphas = {NAN};
    } else {
      spec.joint_order = 3;
      if (leg0 != leg1) {
        spec.alphas = seg0_at_a0 ? std::vector{alpha0, alpha1} : std::vector{alpha1, alpha0};
        spec.segment_turnings = seg0_at_a0 ? std::vector{r * turning, (1 - r) * turning}
                                           : std::vector{(1 - r) * turning, r * turning};
      }
      if (res.curve.segments().size() != 2) spec.alphas = {NAN};
    }
    return grade(check_planar(res.curve, spec), res.summary, input);
  }
  if (res.summary.status == Status::no_solution) {
    Record rec;
    rec.outcome = Outcome::no_solution;  // proof condition not recomputed (see docs/robustness.md)
    return rec;
  }
  return not_usable(res.summary);
}

// ------------------------------------------------------------------------------------------------
// Positions on a standard-form LA curve (curves/planar/la_position.hpp), every method.

inline Record position_grade(const PositionResult& p, CR pos, R theta, R kappa, R s, const std::string& input) {
  Record r;
  const double scale = std::max(static_cast<double>(std::fabs(s)), 1e-300);
  const double e_pos = static_cast<double>(std::abs(CR(p.point.position.real(), p.point.position.imag()) - pos)) / scale;
  const double e_theta = static_cast<double>(std::fabs(R(p.point.theta) - theta));
  const double e_kappa = static_cast<double>(std::fabs(R(p.point.kappa) - kappa) / std::max<R>(std::fabs(kappa), 1e-300L));
  const double e = std::max({e_pos, e_theta, e_kappa});
  r.error = e / kPositionAccept;
  if (!(e <= kPositionAccept)) {
    r.outcome = Outcome::wrong_but_usable;
    r.silent = !(p.error_estimate > kPositionAccept * scale);
    r.detail = input + " | status " + std::string(to_string(p.status)) + " error: position " + num(e_pos) +
               " (of the arc length " + num(static_cast<double>(s)) + "), theta " + num(e_theta) + ", kappa " + num(e_kappa) +
               "; estimate " + num(p.error_estimate);
  }
  return r;
}

inline Record run_eval(Rng& rng) {
  const double alpha = draw_alpha(rng, 0.05);
  const double lambda = rng.chance(0.05) ? 0.0 : rng.log_uniform(1e-3, 1e2);
  const bool by_theta = rng.chance(0.5);
  const std::string integrator = quadrature_names()[static_cast<size_t>(rng.integer(0, static_cast<int>(quadrature_names().size()) - 1))];
  std::string input = "position_at LaCurve alpha " + num(alpha) + " lambda " + num(lambda) + (by_theta ? " theta " : " s ");
  try {
    const LaCurve c(alpha, lambda);
    // θ in [−20, 20] inside the domain (the turning bounds the work of every method); for the s
    // form its arc length (the oracle's inversion of θ(s)).
    const Interval dom = c.theta_domain();
    const double lo = std::max(dom.lo, -20.0), hi = std::min(dom.hi, 20.0);
    double t = lo + (hi - lo) * rng.uniform(0, 1);
    if (!by_theta) {
      const auto s_of_t = standard_s_at_theta(alpha, lambda, t);
      if (!s_of_t || !std::isfinite(static_cast<double>(*s_of_t))) return {Outcome::input_error, 0, {}, {}, false};
      t = static_cast<double>(*s_of_t);
    }
    input += num(t) + " integrator " + integrator;
    trace_input(input);
    const AnyQuadrature m = make_quadrature(integrator);
    const PositionResult p = position_at(c, by_theta ? Parameter::theta : Parameter::s, t, m);
    if (!usable(p.status)) {
      Record r;
      r.outcome = Outcome::other_status;
      r.status = std::string(to_string(p.status));
      return r;
    }
    std::optional<R> s = by_theta ? standard_s_at_theta(alpha, lambda, t) : std::optional<R>(t);
    if (!s) return {Outcome::unverified, 0, "", input + " | oracle: s(theta) not found", false};
    const SegL seg = standard_form(alpha, lambda, *s);
    // The inversion must reproduce θ (Newton from F⁻¹ can fail where F is nearly flat, α → 1).
    if (by_theta && !(std::fabs(seg.phi_at(*s) - R(t)) <= 1e-13L * (1 + std::fabs(R(t)))))
      return {Outcome::unverified, 0, "", input + " | oracle: s(theta) inversion not accurate", false};
    const IntegralL I = integrate_tangent(seg, 0, *s);
    if (!I.ok) return {Outcome::unverified, 0, "", input + " | oracle: " + I.why, false};
    return position_grade(p, I.value, seg.phi_at(*s), seg.law.K(seg.qb), *s, input);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
}

// ------------------------------------------------------------------------------------------------
// Positions on a quadratic LA curve (curves/quadratic/quadratic_position.hpp), every method
// that integrates any integrand.

inline Record run_quadratic(Rng& rng, const Settings& settings) {
  const double alpha = rng.uniform(-5, 5);
  const double gamma = rng.chance(0.1) ? 0.0 : rng.uniform(-2, 2);
  const double lambda = rng.log_uniform(1e-2, 1e1);
  QuadraticOptions qo;
  if (rng.chance(0.2)) qo.inverse = special::ErfInverseMethod::hybrid_003;
  std::vector<std::string> names;
  for (const auto& n : quadrature_names())
    if (n != "igf") names.push_back(n);
  const std::string integrator = names[static_cast<size_t>(rng.integer(0, static_cast<int>(names.size()) - 1))];
  std::string input = "position_at QuadraticLaCurve alpha " + num(alpha) + " gamma " + num(gamma) + " lambda " + num(lambda) +
                      (qo.inverse == special::ErfInverseMethod::hybrid_003 ? " inverse hybrid_003" : "");
  try {
    const QuadraticLaCurve c(alpha, gamma, lambda, qo);
    const Interval dom = c.s_domain();
    const double lo = std::max(dom.lo, -10.0), hi = std::min(dom.hi, 10.0);
    const double s = lo + (hi - lo) * rng.uniform(0, 1);
    input += " s " + num(s) + " integrator " + integrator;
    trace_input(input);
    const AnyQuadrature m = make_quadrature(integrator);
    PositionResult p;
    std::visit(
        [&](const auto& method) {
          if constexpr (QuadratureMethod<std::decay_t<decltype(method)>>) {
            const long own = position_budget(method);
            p = position_at(c, s, method, kDefaultAccept,
                            settings.max_evaluations > 0 ? std::min(own, settings.max_evaluations) : own);
          }
        },
        m);
    if (!usable(p.status)) {
      Record r;
      r.outcome = Outcome::other_status;
      r.status = std::string(to_string(p.status));
      return r;
    }
    const QuadraticPoint q = quadratic_point(alpha, gamma, lambda, s);
    if (!q.ok) return {Outcome::unverified, 0, "", input + " | oracle: ODE failed", false};
    return position_grade(p, q.position, q.theta, std::exp(q.log_kappa), s, input);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
}

// ------------------------------------------------------------------------------------------------

// ------------------------------------------------------------------------------------------------
// LA space segments (constructions/space_segment.hpp): G1 and compound-rhythm, half of the problems
// drawable by construction (constructions/space_drawable_cases.hpp), half random end data. The
// construction never claims that no curve exists (a failed solve is not_converged or
// max_iterations), so only usable results are checked.

inline std::string vec(const Vec3& x) { return num(x[0]) + "," + num(x[1]) + "," + num(x[2]); }

inline Record run_space(Rng& rng) {
  const bool compound = rng.chance(0.4);
  DrawableCase c;
  if (rng.chance(0.5)) {
    std::mt19937_64 engine(rng.g());
    c = random_drawable_case(engine, compound);
  } else {
    auto v3 = [&](double r) { return Vec3(rng.uniform(-r, r), rng.uniform(-r, r), rng.uniform(-r, r)); };
    c.compound = compound;
    c.ends = {v3(5), v3(1), v3(5), v3(1)};
    c.spec.alpha0 = rng.uniform(-1, 2);
    c.spec.alpha1 = rng.uniform(-1, 2);
    c.spec.beta0 = rng.uniform(-1, 2);
    c.spec.beta1 = rng.uniform(-1, 2);
    c.spec.omega0 = rng.uniform(0.05, 0.6);
    c.spec.r_theta = rng.uniform(0.3, 0.7);
    c.spec.type = rng.chance(0.5) ? TorsionType::type1 : TorsionType::type2;
  }
  SpaceSegmentOptions o;
  const auto& solvers = nonlinear_methods();
  const auto& solver = solvers[static_cast<size_t>(rng.integer(0, static_cast<int>(solvers.size()) - 1))];
  o.solver = parse_nonlinear_method(solver.name);
  const bool rk45 = rng.chance(0.3);
  if (rk45) o.integrator = OdeOptions{OdeMethod::rk45, 1e-10, 1e-11};
  std::string input = std::string(compound ? "solve_compound_space_segment" : "solve_g1_space_segment") + " p0 " +
                      vec(c.ends.p0) + " v0 " + vec(c.ends.v0) + " p1 " + vec(c.ends.p1) + " v1 " + vec(c.ends.v1) +
                      " alpha " + num(c.spec.alpha0) + " beta " + num(c.spec.beta0) + " omega " + num(c.spec.omega0) +
                      (c.spec.type == TorsionType::type1 ? " type1" : " type2");
  if (compound) input += " alpha1 " + num(c.spec.alpha1) + " beta1 " + num(c.spec.beta1) + " r_theta " + num(c.spec.r_theta);
  input += std::string(" solver ") + std::string(solver.name) + (rk45 ? " integrator rk45" : " integrator magnus6");
  trace_input(input);
  Result<SpaceCurve, SpaceInfo> res;
  try {
    res = compound ? solve_compound_space_segment(c.ends, c.spec, o) : solve_g1_space_segment(c.ends, c.g1(), o);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  }
  if (res.usable()) {
    SpaceSpec spec{c.ends.p0, c.ends.v0, c.ends.p1, c.ends.v1, {}, compound};
    if (compound) spec.slopes = {{c.spec.alpha0, c.spec.beta0}, {c.spec.alpha1, c.spec.beta1}};
    else spec.slopes = {{c.spec.alpha0, c.spec.beta0}};
    return grade(check_space(res.curve, spec), res.summary, input);
  }
  if (res.summary.status == Status::no_solution) {
    Record r;
    r.outcome = Outcome::false_no_curve;  // no proof of no curve exists for space segments
    r.detail = input + " | no_solution: " + res.summary.message;
    return r;
  }
  return not_usable(res.summary);
}

inline Record run_one(const std::string& construction, unsigned long seed, long index, const Settings& settings = {}) {
  Rng rng(seed, construction, index);
  try {
    if (construction == "g1") return run_g1(rng);
    if (construction == "g2") return run_g2(rng, settings);
    if (construction == "scurve") return run_scurve(rng, settings);
    if (construction == "chain") return run_chain(rng);
    if (construction == "compound") return run_compound(rng, settings);
    if (construction == "eval") return run_eval(rng);
    if (construction == "quadratic") return run_quadratic(rng, settings);
    if (construction == "space") return run_space(rng);
  } catch (const InputError&) {
    return {Outcome::input_error, 0, {}, {}, false};
  } catch (const std::exception& e) {
    return {Outcome::exception, 0, "", construction + " problem " + std::to_string(index) + ": " + e.what(), false};
  }
  throw_input_error("oracle", "construction", "'" + construction + "' is not one of g1 g2 scurve chain compound quadratic eval space");
}

/// Runs problems [first, first + count) of one construction (in parallel under the caller's
/// TBB settings) and tallies them.
inline Tally run_campaign(const std::string& construction, long first, long count, unsigned long seed,
                          const Settings& settings = {}) {
  return tbb::parallel_reduce(
      tbb::blocked_range<long>(first, first + count, 16), Tally{},
      [&](const tbb::blocked_range<long>& r, Tally t) {
        for (long i = r.begin(); i != r.end(); ++i) t.add(i, run_one(construction, seed, i, settings));
        return t;
      },
      [](Tally a, const Tally& b) {
        a.merge(b);
        return a;
      });
}

}  // namespace lac::oracle
