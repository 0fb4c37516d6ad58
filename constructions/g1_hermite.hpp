#pragma once
// G1 Hermite interpolation by one LA segment of given slope α: end points P0, P1 and end tangent
// angles θ0, θ1, any configuration (convex, convex with an inflection, S-shaped, parallel or
// anti-parallel tangents, any turning a curve of slope α can make). docs/g1_hermite.md has the
// derivations, the no-solution proofs and the measurements.
//
// Method. In the chord frame (P0 = 0, P1 = 1, angles φ0, φ1 relative to the chord, each in
// (−π, π]) the segment runs over u ∈ [0, 1] (u = s/L) in the linear-q form of
// curves/planar/la_law.hpp, q(u) = m + c(2u − 1). The turning φ(1) − φ(0) = Δ = φ1 − φ0 + 2πk
// (k = G1HermiteOptions::winding) fixes the amplitude of (m, c) in closed form, because K is
// homogeneous (K(λq) = λ^(−1/α) K(q)); what is left is ONE equation in one shape variable x,
//   f(x) = Im ∫₀¹ e^{iφ(u; x)} du = 0,  Re ∫ > 0,  L = |P1 − P0| / Re ∫,
// as [Bertolazzi–Frego 2015] reduce the clothoid to one equation in A. x is
//   α < 0: a ∈ ℝ with (m, c) ∝ (Δ, a) (α = −1: exactly their A, φ = φ0 + (Δ − A)u + Au²);
//   α > 0: a ∈ (−|Δ|, |Δ|) (q keeps its sign);  α = 0: b, κ = κ0 e^{bu}.
// f and f' come from one Gauss–Legendre pass (f' by forward-mode differentiation of the
// integrand), split and graded at the inflection (the zero of q, closed form), geometric panels
// toward an end where κ is steep; Newton from a small-angle guess, safeguarded by a sign bracket.
// Of the curves with turning Δ the one returned is the root of f reached from that guess (no
// internal loop on ordinary data).
//
// Windings. Without `winding` the turnings Δ_k = φ1 − φ0 + 2πk are tried in order of increasing
// |Δ_k| up to `max_turning`, and the first that has a curve is returned (the least-turning curve).
// Each turning is either solved, or excluded by a proof (α ≥ 0: the sign of κ, the convex-arc
// argument for |Δ| ≤ π, the α > 1 limits, or for any Δ a certified scan of every shape x, which
// bounds how far the end point moves between two shapes), or left unresolved (a solver failure).
// no_solution therefore says "no curve with total turning <= T" with the arguments named;
// a search with an unresolved turning and no curve ends not_converged. `winding = k` asks for Δ_k only.
//
//   lac::G1HermiteOptions o;  o.winding = 1;                       // one more left turn
//   auto r = lac::solve_g1_hermite({{0, 0}, 0.3, {1, 0}, -0.4, -1.0}, o);
//   if (r.usable()) { r.curve.length(); r.info.shape; r.info.inflection; r.curve.sample(100); }
#include <complex>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/method_info.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac {

constexpr double kG1MaxAbsAlpha = 5.0;   ///< |α| ≤ 5, as the G2 construction
constexpr double kG1MinAbsAlpha = 0;  ///< every α ∈ [−5, 5]: below |α| = 0.05 the shapes are evaluated in log|κ| (continuous through 0)

struct G1HermiteProblem {
  std::complex<double> p0;
  double theta0 = 0;  ///< tangent angle at p0 (rad)
  std::complex<double> p1;
  double theta1 = 0;  ///< tangent angle at p1 (rad)
  double alpha = -1;  ///< slope of the LCG, [−5, 5]
};

/// straight: κ ≡ 0 (φ0 = φ1 = 0). convex: no inflection, |turning| < π. convex_inflection: an
/// inflection although the tangents lie on opposite sides of the chord. s_shaped: tangents on the
/// same side of the chord (an inflection is needed). other: |turning| ≥ π (loops, windings), a
/// tangent along the chord with the other not. Of a refusal: the input's class.
enum class G1Shape { straight, convex, convex_inflection, s_shaped, other };
std::string_view to_string(G1Shape s);

/// The G1 solver. automatic: safeguarded Newton on the reduced equation f with its analytic
/// derivative (the fast path). root: that method of the 1-D root registry (solvers/root_1d.hpp)
/// on f in the sign bracket found around the guess. triangle: 001's similar-triangle search
/// (constructions/triangle_g1.hpp), tangents on opposite sides of the chord, |turning| < π only.
/// s_curve: 004's Λ search (constructions/s_curve.hpp), α < 0 and tangents on one side only.
struct G1Solver {
  enum class Kind { automatic, root, triangle, s_curve } kind = Kind::automatic;
  RootMethod root = RootMethod::toms748;  ///< the method of Kind::root (toms748 otherwise)
  friend bool operator==(const G1Solver&, const G1Solver&) = default;
};
/// auto, the root registry's methods with their aliases (bisection, secant (newton), toms748,
/// ceres), triangle, s-curve.
std::span<const SolverMethodInfo<G1Solver>> g1_hermite_solvers();
std::string_view to_string(G1Solver s);
G1Solver parse_g1_solver(std::string_view name);  ///< a name or alias of g1_hermite_solvers(); InputError "solver" otherwise

struct G1HermiteOptions {
  G1Solver solver{};  ///< default: automatic
  /// Used to verify the returned curve's end point when `verify` is set (summary.residuals and
  /// error_estimate; also the trial integrals of "triangle" and "s-curve"). The solve itself always
  /// runs on the built-in Gauss–Legendre kernel, which differentiates f.
  AnyQuadrature integrator = GaussLegendre{};
  bool verify = false;
  /// Only the turning Δ_k = φ1 − φ0 + 2πk (φ0, φ1 relative to the chord, each in (−π, π]),
  /// k ∈ [−100, 100]. Unset: every k with |Δ_k| ≤ max_turning, least |Δ_k| first.
  std::optional<int> winding;
  /// Largest total turning |Δ| (rad) searched without `winding`, [π, 200π]; the default covers at
  /// least 3π beyond the least turning (which is at most π).
  double max_turning = 4 * std::numbers::pi;
  double tolerance = 1e-13;   ///< on |f| (end point off the chord, chord units), [1e-16, 1e-3]
  int max_iterations = 60;    ///< Newton / root-finder steps, [1, 10000]
  /// Trial points of the bracket search (α < 0) or of the certified scan of one turning (α ≥ 0),
  /// [1, 100000].
  int max_bracket_steps = 400;
  /// Kernel evaluations (quadrature nodes and series terms) of one call for α < 0, [1000, 1e9]:
  /// S-shaped data at 0 < −α ≪ 1 need pieces of up to 4096 panels (the curvature gathers within
  /// e^(−1/|α|) of the ends); the call ends not_converged once they are spent.
  long max_evaluations = 500'000;
  double accuracy = 1e-10;    ///< target: largest residual (chord units, rad) for status ok, [tolerance, 1]
  double accept = kDefaultAccept;  ///< usable bound on the achieved error (relative), (0, 0.1]
  void validate() const;      ///< InputError naming the option
};

struct G1HermiteInfo {
  G1Shape shape = G1Shape::convex;
  double turning = 0;                ///< Δ = θ(L) − θ(0) (rad)
  std::optional<double> inflection;  ///< arc length of the inflection, if any
  double phi0 = 0, phi1 = 0;         ///< end tangents relative to the chord, in (−π, π]
  double qa = 0, qb = 0;             ///< the segment's q at u = 0 and u = 1 (u = s/L)
  double length = 0;                 ///< L (user units)
  double x = 0;                      ///< the shape variable at the solution (a or b, above)
  int winding = 0;                   ///< k of the returned curve (of a refusal: the least-turning k)
  /// Without `winding`: T, every turning |Δ| ≤ T was searched (0 with an explicit winding).
  double max_turning = 0;
};

using G1HermiteResult = Result<PlanarCurve, G1HermiteInfo>;

/// The curve: one LaSegment on u ∈ [0, 1] placed at p0 with scale L and the chord's direction (a
/// straight line for α ≥ 0 is a segment of α = −1 with κ ≡ 0: the common limit of every α).
/// Summary: iterations, evaluations (integrand calls), constructions (trial shapes), residuals
/// position (user units) and angle; error (position / chord, angle, error estimate / chord) and
/// accept. Throws InputError for non-finite data, coincident points, α outside its range, bad
/// options; no_solution only with a proof in the message, which states its scope.
G1HermiteResult solve_g1_hermite(const G1HermiteProblem& problem, const G1HermiteOptions& options = {});

}  // namespace lac
