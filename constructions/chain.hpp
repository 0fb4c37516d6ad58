#pragma once
// LA chains: one PlanarCurve of LA segments (one slope α) through N points, joined G1 or G2.
//   g1  every pair of consecutive points is a G1 Hermite problem (constructions/g1_hermite.hpp):
//       one LA segment per pair, meeting the tangent angles at the points;
//   g2  every pair is a G2 Hermite problem (constructions/g2_hermite.hpp, the triple LA curve of
//       [Miura et al. 2013]): three LA segments per pair, meeting tangent angles and curvatures.
// Tangent angles (and for g2 curvatures) not given are estimated from the points by the circle
// through each point and its two neighbours (estimate_frames below); a closed chain also joins the
// last point to the first, with the neighbours taken cyclically.
//
//   lac::ChainProblem p{.points = {{0, 0}, {1, 1}, {2, 0}, {3, 1}}, .alpha = -1};
//   lac::ChainResult r = lac::solve_chain(p);
//   if (r.usable()) { r.curve.length(); r.info.thetas; r.curve.sample(400); }
#include <complex>
#include <span>
#include <string_view>
#include <vector>

#include "lac/common/summary.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/curves/planar/planar_curve.hpp"

namespace lac {

enum class ChainContinuity { g1, g2 };
std::string_view to_string(ChainContinuity c);
ChainContinuity parse_chain_continuity(std::string_view name);  ///< "g1" | "g2"; InputError "continuity" otherwise

struct ChainProblem {
  std::vector<std::complex<double>> points{};  ///< N ≥ 2 (closed: N ≥ 3), consecutive points distinct
  std::vector<double> thetas{};  ///< tangent angle at each point (rad); empty: estimated
  std::vector<double> kappas{};  ///< signed curvature at each point (g2 only); empty: estimated
  double alpha = -1;
  ChainContinuity continuity = ChainContinuity::g1;
  bool closed = false;  ///< one more segment, from the last point back to the first
};

/// Each pair's turning follows its options: `winding` set, Δ_k = φ1 − φ0 + 2πk only (the same k for
/// every pair); unset, the least-turning curve of each pair up to `max_turning`. The chain's
/// accept bound is the pair options' `accept`.
struct ChainOptions {
  G1HermiteOptions g1;  ///< for each segment of a g1 chain
  G2Options g2;         ///< for each pair of a g2 chain
};

struct ChainInfo {
  std::vector<double> thetas;  ///< tangent angles used at the points (given or estimated)
  std::vector<double> kappas;  ///< curvatures used (g2), or estimated ones for reference (g1)
  bool estimated_thetas = false;
  bool estimated_kappas = false;
  /// How each pair was solved, in order (pair k joins point k and point k+1, cyclically).
  std::vector<Summary> pairs;
  std::vector<int> windings;      ///< k of each pair solved (of a failed pair: its least-turning k)
  std::vector<double> turnings;   ///< the turning of each pair (rad)
  int failed_pair = -1;  ///< the first pair without a usable curve, or −1
};

using ChainResult = Result<PlanarCurve, ChainInfo>;

/// Solves every pair in order and joins the segments into one curve. Status: ok when every pair
/// is ok; otherwise the least usable pair's status with a message naming the pair (unusable:
/// no curve is returned). Summary counters add up over the pairs; residuals and error (each pair's
/// relative to its chord) are the largest.
/// InputError for fewer points than needed, non-finite or repeated consecutive points, thetas or
/// kappas of the wrong count or not finite, α or options the Hermite solvers refuse.
ChainResult solve_chain(const ChainProblem& problem, const ChainOptions& options = {});

/// A tangent angle and signed curvature at a point.
struct PointFrame {
  double theta = 0;
  double kappa = 0;
};

/// The circle through a point and its two neighbours: its tangent angle there (in the direction
/// of travel) and its signed (Menger) curvature 2 (b−a)×(c−b) / (|b−a| |c−b| |c−a|). On a circle
/// the chord between two points has the mean of their tangent angles, so the tangent at b is
/// arg(b−a) + arg((c−b)/(c−a)), exact for points on a circle or a line (then κ = 0). The ends of an
/// open chain take the circle through their three nearest points; two points give the chord.
std::vector<PointFrame> estimate_frames(std::span<const std::complex<double>> points, bool closed);

}  // namespace lac
