#pragma once
// G2 Hermite interpolation by a triple log-aesthetic curve (004 §3).
// Given end points, tangent angles and signed curvatures and one slope α, three LA segments on
// S ∈ [0, 0.25], [0.25, 0.75], [0.75, 1] (S = s/h, h the length in chord units) with κ and φ
// continuous at the joints meet the data. Each segment is in linear-q form
// (curves/planar/la_law.hpp): q = sgn(κ̃)|κ̃|^(−α) (α ≠ 0) or log|κ̃| (α = 0), κ̃ = κh, linear in
// S; every solver's unknowns reduce to h and q at S1 and S2, i.e. 004's (h, c10, c30).
//
// Solvers (G2Options::solver; names from the N-D registry of solvers/nonlinear.hpp, plus paper):
//   newton   damped Newton on (log h, q1, q2), all three end conditions at once;
//   ceres    Ceres Levenberg–Marquardt on the ten-unknown system (004 Eqs. 20–23, 28–33);
//   simplex  downhill simplex on the max-norm of the three conditions (slow; may stop short);
//   paper    004 §3.3: outer fixed-point iteration h ← r / ∫cos φ dS, inside it bisection on
//            c30 for ∫sin φ dS = 0, inside that Newton on c10 for Eq. (41).
// Initial estimates (G2Options::start): fast (small-angle triple clothoid) or bezier-grid (004
// §3.4: quintic Bézier minimizing J_LAC, Eq. 45, over the 10^4-point leg grid).
// The integrals ∫e^{iφ}dS of every trial curve take G2Options::integrator (any method of
// integrators/registry.hpp; default gauss-legendre); the result is verified by the segment
// kernel with its error bound (curves/planar/la_segment_kernel.hpp), or by tanh-sinh where the
// kernel does not evaluate a segment.
//
// Windings. The turning target is Δ_k = φ1 − φ0 + 2πk, φ0, φ1 the end tangents relative to the
// chord, each in (−π, π] (θ1 is never wrapped silently: every k is a different curve). With
// G2Options::winding only Δ_k; without it every Δ_k with |Δ_k| ≤ max_turning in order of
// increasing |Δ_k| (on a tie the lesser |k|, then the left turn), and the first that solves is returned. A turning is
// excluded by proof where α ≥ 0: κ keeps the sign of κ0 (turnings of the other sign or 0), and a
// convex arc turning at most π has its chord strictly between its end tangents. no_solution only
// when every turning up to max_turning is so excluded ("no curve with total turning <= T"), or for
// every winding when α ≥ 0 and κ0, κ1 are zero or of opposite signs; a turning the solver fails
// on leaves the search incomplete: not_converged.
//
// Supported α ∈ [−5, 5]. Bad input throws InputError.
//
//   lac::G2Options o;
//   o.solver = lac::parse_g2_solver("ceres");
//   o.integrator = lac::make_quadrature("rk45");
//   auto r = lac::solve_g2({{{0, 0}, 0.6, 0.5}, {{4, 0}, -0.6, -0.3}, -0.5}, o);
//   if (r.usable()) { r.curve.sample(200); r.info.coefficients; r.summary.residuals.position; }
#include <array>
#include <complex>
#include <numbers>
#include <optional>
#include <span>
#include <string_view>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/nonlinear_method.hpp"
#include "lac/solvers/method_info.hpp"

namespace lac {

constexpr double kG2S1 = 0.25;  // joints in S, 004 §3.1 after Lan et al.
constexpr double kG2S2 = 0.75;
constexpr double kG2MaxAbsAlpha = 5.0;  // |α| beyond this overflows q = |κh|^(−α) for ordinary data
/// Smallest nonzero |α|: below it the law's exponents 1/α, (α−1)/α of the linear-q form overflow
/// (found by fuzz_hermite: α = −5e-324 gave NaN polyline points, R18); α = 0 is the exponential law.
constexpr double kG2MinAbsAlpha = 1e-300;

struct G2Endpoint {
  std::complex<double> position;
  double theta = 0;  ///< tangent angle (rad)
  double kappa = 0;  ///< signed curvature (> 0 turns left)
};

struct G2Problem {
  G2Endpoint start, end;
  double alpha = -1;  ///< slope of the LCG, one for all three segments, [−5, 5]
};

/// The G2 solver: a method of the N-D registry (solvers/nonlinear.hpp) on the six conditions, or
/// 004's own iteration (section 3.3). G2Solver::newton, ::ceres, ::simplex, ::paper name them.
struct G2Solver {
  enum class Kind { nonlinear, paper } kind = Kind::nonlinear;
  NonlinearMethod method = NonlinearMethod::newton;  ///< of Kind::nonlinear (newton for paper)
  static const G2Solver newton, ceres, simplex, paper;
  friend bool operator==(const G2Solver&, const G2Solver&) = default;
};
inline constexpr G2Solver G2Solver::newton{Kind::nonlinear, NonlinearMethod::newton};
inline constexpr G2Solver G2Solver::ceres{Kind::nonlinear, NonlinearMethod::ceres};
inline constexpr G2Solver G2Solver::simplex{Kind::nonlinear, NonlinearMethod::simplex};
inline constexpr G2Solver G2Solver::paper{Kind::paper, NonlinearMethod::newton};
/// newton, ceres, simplex (with the N-D registry's aliases and descriptions), paper.
std::span<const SolverMethodInfo<G2Solver>> g2_solvers();
std::string_view to_string(G2Solver s);
G2Solver parse_g2_solver(std::string_view name);  ///< a name or alias of g2_solvers(); InputError "solver" otherwise

enum class G2Start { fast, bezier_grid };
std::string_view to_string(G2Start s);
G2Start parse_g2_start(std::string_view name);  ///< "fast" | "bezier-grid"; InputError otherwise

struct G2Options {
  G2Solver solver = G2Solver::newton;
  /// ∫e^{iφ} of every trial curve and of the result's joints.
  AnyQuadrature integrator = GaussLegendre{};
  G2Start start = G2Start::fast;
  /// When the solver fails from the fast start, retry once from the Bézier-grid start (status
  /// fell_back when that succeeds).
  bool grid_fallback = true;
  /// Where neither start gives a curve with 004's joints (S = 1/4, 3/4), retry from the fast
  /// start with the joints at 1/8, 7/8 and then 1/16, 15/16 (a longer middle segment; newton,
  /// simplex, ceres — `paper` keeps 004's joints). false: 004's joints only.
  bool free_joints = true;
  double tolerance = 1e-12;  ///< on the normalized residuals (chord = 1, angles in rad), max-norm
  /// newton, ceres: iterations; paper: outer iterations on h; simplex: 100× this many moves.
  int max_iterations = 60;
  /// newton: a run whose max-norm residual has not fallen by 1 % over this many iterations
  /// stops (not_converged) and the next start or turning is tried; 0: only max_iterations stops it.
  int stagnation_window = 10;
  int max_inner_iterations = 200;  ///< paper: bisection steps on c30 and on c10
  /// Integrand evaluations of the whole call (starts, solves, fallback): once spent, trial curves
  /// fail and the solve ends max_iterations. An adaptive method on a hard integrand can cost ~10^6
  /// evaluations a trial curve; the default is ~4× what the slowest combination (simplex with rk4:
  /// 2.6·10^7) needs on ordinary data, seconds of CPU at most.
  long max_evaluations = 100'000'000;
  /// Residuals re-evaluated by the segment kernel, whose error bound is added to the position
  /// residual (Boost tanh-sinh where the kernel does not evaluate a segment), and the integrator's
  /// deviation from that plus the bound reported as summary.error_estimate; without it the
  /// residuals are the integrator's own (no error estimate).
  bool verify = true;
  double accuracy = 1e-10;  ///< target: largest verified residual (relative to chord, rad, 1/chord) for status ok
  double accept = kDefaultAccept;  ///< usable bound on the achieved error (relative), (0, 0.1]
  /// Only the turning Δ_k = φ1 − φ0 + 2πk (above), k ∈ [−100, 100]; unset: the search.
  std::optional<int> winding;
  /// Largest total turning |Δ| (rad) searched without `winding`, [π, 200π] (default: at least 3π
  /// beyond the least turning, which is at most π).
  double max_turning = 4 * std::numbers::pi;
  void validate() const;  ///< InputError naming the option (the integrator's own check included)
};

/// One segment in the paper's coefficients (004 Eqs. 2, 3, 5–8, normalized S):
/// α ≠ 0: κ̃ = sgn(q)|q|^(−1/α), q = c0 S + c1;  α = 0: κ̃ = c0 e^(c1 S);  φ = … + c2 (relative to
/// the chord). κ̃ = κh is the curvature per unit S.
struct SegmentCoefficients {
  double c0 = 0, c1 = 0, c2 = 0;
  double S_begin = 0, S_end = 0;
};

/// What is specific to the 004 triple.
struct G2Info {
  G2Start start_used = G2Start::fast;  ///< the initial estimate of the run that gave the result
  double start_seconds = 0;            ///< part of summary.seconds spent on initial estimates
  double h = 0;                        ///< length in chord units (S = s / (h·chord))
  std::array<double, 2> joints{kG2S1, kG2S2};  ///< S of the joints of the returned curve
  int winding = 0;                     ///< k of the returned curve (of a refusal: the least-turning k)
  double turning = 0;                  ///< Δ_k of the returned curve (of a refusal: the least turning)
  double max_turning = 0;              ///< without `winding`: every |Δ| ≤ this was searched (else 0)
  std::array<SegmentCoefficients, 3> coefficients{};  ///< of a usable result
};

using G2Result = Result<PlanarCurve, G2Info>;

/// Solves the G2 Hermite problem. The curve: three LaSegments in S (q of κ̃ per unit S), placed
/// with scale h·chord and the chord's direction, each starting where the previous one ends (by
/// the tanh-sinh check with `verify`, else by the integrator). Summary: iterations (summed over the fast and the fallback run), evaluations
/// (integrand calls, initial estimates included), constructions (trial curves whose end
/// conditions were evaluated), residuals position / angle / curvature (user units), with `verify`
/// error_estimate = the integrator's error of the end point against tanh-sinh. Throws
/// InputError for non-finite data, coincident end points, α outside [−5, 5], invalid options; every
/// other failure is a status.
G2Result solve_g2(const G2Problem& problem, const G2Options& options = {});

}  // namespace lac
