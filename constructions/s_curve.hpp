#pragma once
// S-shaped G1 input by one LA curve with α < 0 (004 §2.4–2.5; MATH.md §5).
// Four control points: start P0 with tangent P1 − P0, end P3 with tangent P3 − P2.
// After moving P0 to the origin with tangent +x, φD is the end tangent angle and φE the
// direction of P3. The Fig. 2 decision: the curve is S-shaped unless φE lies strictly
// between 0 and φD (then it fits inside the triangle of the end points and the tangents'
// intersection, Fig. 2(a)). In standard form (κ = 1 at the start, 004 Eq. 9–10) the
// inflection is at s0 = −1/(Λα) (Eq. 12) and, past it, the end angle φD is reached after
// s1 = −(1 + (α−1)ΛφD)^(α/(α−1))/(Λα) (Eq. 15); Λ is found so that the end point's
// direction equals φE, and a similarity maps the curve onto P0 and P3.
// The non-S (C-shaped) case uses the same search without the inflection (s = Eq. 11),
// oriented so that the curvature decreases from the start (the curve is reversed when the
// chord is closer to the start tangent than to the end tangent).
#include <array>
#include <complex>
#include <string>
#include <string_view>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/curves/planar/detail/linear_q.hpp"
#include "lac/constructions/g2_hermite.hpp"

namespace lac::hermite {

enum class RootMethod { bisection, toms748 };
std::string_view to_string(RootMethod m);
RootMethod parse_root_method(std::string_view name);  ///< "bisection" | "toms748"

struct SCurveOptions {
  RootMethod root = RootMethod::toms748;  ///< 004 uses bisection
  int max_iterations = 200;               ///< root-finder iterations on Λ
  int bracket_doublings = 200;            ///< growth steps of Λ's upper end when it is unbounded
  /// Residuals from an independent tanh-sinh evaluation of the end point; without it they
  /// come from the search's own Gauss–Legendre rule.
  bool verify = true;
  void validate() const;
};

enum class SCurveShape { s_shaped, c_shaped, straight };
std::string_view to_string(SCurveShape s);

struct SCurveResult {
  Status status = Status::no_solution;
  std::string message;
  SCurveShape shape = SCurveShape::s_shaped;
  double alpha = -1;
  double lambda = 0;             ///< Λ of the standard form (κ = 1 at its start)
  double length = 0;             ///< user units
  double inflection_s = -1;      ///< arc length of the inflection from the (user) start; −1 if none
  double residual_position = 0;  ///< |end point − P3|
  double residual_angle = 0;     ///< end tangent vs P3 − P2 (rad)
  int iterations = 0;
  long evaluations = 0;
  double seconds = 0;

  // Geometry: the standard-form segment (variable s, from 0 to its length) and the
  // similarity onto the user's points.
  LaLaw law;
  lac::detail::LinearQ standard;
  bool mirrored = false;                ///< y → −y applied in the normalized frame
  bool reversed = false;                ///< the standard form runs from P3 to P0
  std::complex<double> origin;          ///< user point where the standard form starts
  std::complex<double> rotation{1, 0};  ///< unit complex: normalized → user direction
  double scale = 1;

  /// Point at normalized arc length t ∈ [0, 1] from P0 (user frame).
  CurveSample at(double t) const;
  std::vector<CurveSample> polyline(int n) const;
};

/// α ∈ [−5, 0). Throws InputError for non-finite points, P1 = P0, P3 = P2, P3 = P0 or α
/// out of range; "no curve" (e.g. loops needed) is a status.
SCurveResult solve_s_curve(const std::array<std::complex<double>, 4>& control, double alpha,
                           const SCurveOptions& options = {});

}  // namespace lac::hermite
