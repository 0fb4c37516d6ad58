#pragma once
// G2 Hermite interpolation by a triple log-aesthetic curve (004 §3; MATH.md §5).
// Given end points, tangent angles and signed curvatures and one slope α, three LA
// segments on S ∈ [0, 0.25], [0.25, 0.75], [0.75, 1] (S = s/h, h the length) with κ and φ
// continuous at the joints meet the data exactly.
//
// Internally each segment is written in "linear q" form (curves/planar/linear_q.hpp):
// q = sgn(κ̃)|κ̃|^(−α) (α ≠ 0) or log|κ̃| (α = 0), κ̃ = κh, is linear in S; the unknowns of
// every solver reduce to the length h and q at S1 and S2, i.e. 004's (h, c10, c30).
//
//   solver "paper"  004 §3.3: outer fixed-point iteration h ← r / ∫cos φ dS, inside it
//                   bisection on c30 for ∫sin φ dS = 0, inside that Newton on c10 for Eq. (41)
//                   with its analytic derivative (bisection when c20 ≈ 0, Appendix A).
//   solver "newton" this project's: damped Newton on (log h, q1, q2) with all three
//                   conditions at once (finite-difference 3×3 Jacobian).
//   solver "ceres"  Ceres Levenberg–Marquardt on the whole 10-unknown system (Eqs. 20–23,
//                   28–33) with c_i2 replaced by the angle at each segment's start.
//   start "bezier-grid"  004 §3.4: quintic Bézier meeting the end data, leg lengths on the
//                   10^4-point grid l_i/h ∈ {0.05, …, 0.5}, minimizing J_LAC (Eq. 45).
//   start "fast"    this project's: the small-angle triple clothoid (∫κ dS = Δφ, ∫φ dS = 0,
//                   linear in the joint curvatures), length from its exact ∫cos φ, two passes.
//
// Supported α ∈ [−5, 5]. For α ≥ 0 the curvature of an LA segment cannot vanish or change
// sign (κ = |q|^(−1/α) or σe^q), so end curvatures of opposite sign or zero have no curve:
// status no_solution. Bad input throws InputError.
#include <array>
#include <complex>
#include <string>
#include <string_view>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"

namespace lac::hermite {

constexpr double kS1 = 0.25;  // 004 §3.1, after Lan et al.
constexpr double kS2 = 0.75;
constexpr double kMaxAbsAlpha = 5.0;  // |α| beyond this overflows q = |κh|^(−α) for ordinary data
/// Smallest nonzero |α|: below it the law's exponents 1/α, (α−1)/α of the linear-q form overflow
/// (found by fuzz_hermite: α = −5e-324 gave NaN polyline points, R18); α = 0 is the exponential law.
constexpr double kMinAbsAlpha = 1e-300;

struct G2Endpoint {
  std::complex<double> position;
  double theta = 0;  ///< tangent angle (rad)
  double kappa = 0;  ///< signed curvature (> 0 turns left)
};

struct G2Problem {
  G2Endpoint start, end;
  double alpha = -1;  ///< slope of the LCG, one for all three segments, [−5, 5]
};

enum class G2Solver { paper, newton, ceres };
enum class G2Start { fast, bezier_grid };
std::string_view to_string(G2Solver s);
std::string_view to_string(G2Start s);
G2Solver parse_g2_solver(std::string_view name);  ///< "paper" | "newton" | "ceres"; InputError otherwise
G2Start parse_g2_start(std::string_view name);    ///< "fast" | "bezier-grid"; InputError otherwise

struct G2Options {
  G2Solver solver = G2Solver::newton;
  G2Start start = G2Start::fast;
  /// When the solver fails from the fast start, retry once from the Bézier-grid start
  /// (status fell_back when that succeeds).
  bool grid_fallback = true;
  double tolerance = 1e-12;        ///< on the normalized residuals (chord = 1, angles in rad)
  int max_iterations = 60;         ///< Newton / LM iterations; outer h iterations for "paper"
  int max_inner_iterations = 200;  ///< "paper": bisection steps on c30 and Newton/bisection steps on c10
  /// Residuals re-evaluated with Boost tanh-sinh quadrature (independent of the solver's
  /// Gauss–Legendre rule); without it they are the solver's own.
  bool verify = true;
  double accept = 1e-10;  ///< largest verified residual (relative to chord, rad, 1/chord) for status ok
  void validate() const;
};

/// One segment in the paper's coefficients (004 Eqs. 2, 3, 5–8, normalized S):
/// α ≠ 0: κ̃ = sgn(q)|q|^(−1/α), q = c0 S + c1;  α = 0: κ̃ = c0 e^(c1 S);  φ = … + c2.
/// κ̃ = κh is the curvature per unit S.
struct SegmentCoefficients {
  double c0 = 0, c1 = 0, c2 = 0;
  double S_begin = 0, S_end = 0;
};

struct CurveSample {
  double S = 0;  ///< normalized arc length
  double s = 0;  ///< arc length (user units)
  std::complex<double> position;
  double theta = 0;  ///< tangent angle (user frame)
  double kappa = 0;  ///< signed curvature (user units)
};

/// The solved curve: three linear-q segments in the normalized frame (start at 0, end at
/// (1, 0)) and the similarity back to the user's frame.
struct TripleLaCurve {
  LaLaw law;
  std::array<lac::detail::LinearQ, 3> segments{};  ///< in S, q of κ̃ = κh
  double h = 1;                                      ///< length in chord units
  std::complex<double> origin;                       ///< user start point
  double chord = 1;                                  ///< |P1 − P0|
  double chord_angle = 0;                            ///< direction of P1 − P0

  double length() const { return h * chord; }
  /// Point at S ∈ [0, 1] (position by Gauss–Legendre from the nearest joint).
  CurveSample at(double S) const;
  /// n ≥ 2 points uniform in S.
  std::vector<CurveSample> polyline(int n) const;
  std::array<SegmentCoefficients, 3> coefficients() const;
};

struct G2Result {
  Status status = Status::no_solution;
  std::string message;
  TripleLaCurve curve;
  double length = 0;
  double residual_position = 0;   ///< |end point − P1| (user units)
  double residual_angle = 0;      ///< max over both ends, rad
  double residual_curvature = 0;  ///< max over both ends (user units)
  int iterations = 0;             ///< solver iterations (paper: outer iterations on h; Ceres: LM iterations)
  long evaluations = 0;           ///< integrand evaluations
  double seconds = 0;             ///< wall time of the whole call
  double start_seconds = 0;       ///< part spent on the initial estimate(s)
  G2Start start_used = G2Start::fast;
};

/// Solves the G2 Hermite problem. Throws InputError for non-finite data, coincident end
/// points, α outside [−5, 5]; every other failure is a status.
G2Result solve_g2(const G2Problem& problem, const G2Options& options = {});

}  // namespace lac::hermite
