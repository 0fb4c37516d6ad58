#pragma once
// Offset curves of a PlanarCurve at signed distance d: o(s) = p(s) + d N(s), N = i T the left
// normal (d > 0 offsets toward the centre of curvature where κ > 0). With o'(s) = (1 − dκ(s)) T(s)
// the offset is regular where 1 − dκ ≠ 0, runs backwards where 1 − dκ < 0 and has a cusp where
// 1 − dκ changes sign; its curvature is κ/(1 − dκ) and its arc length ∫|1 − dκ| ds.
// κ is monotonic on each LA segment (q is linear in s and K(q) is monotonic), so the first s
// where 1 − dκ(s) vanishes or changes sign — the offset's first cusp — is found per segment from
// its ends and, inside one, by TOMS 748 on the closed form κ(s): no sampling, nothing missed. At
// a joint where κ jumps across 1/d (a G1 joint) the cusp is at the joint.
//
//   auto o = lac::offset_at(curve, s, 0.1);       // o.position, o.kappa, o.factor = 1 − dκ
//   auto c = lac::first_offset_cusp(curve, 0.1);  // c.s (std::nullopt: regular all along)
#include <complex>
#include <optional>
#include <string>

#include "lac/common/status.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac {

struct OffsetPoint {
  double s = 0, d = 0;
  std::complex<double> position{};  ///< p(s) + d N(s); meaningful only when status is usable
  double error_estimate = 0;        ///< absolute, of the position (that of p(s): N is a closed form)
  double factor = 1;                ///< 1 − dκ(s): ds_offset/ds (negative: the offset runs backwards)
  std::complex<double> tangent{1, 0};  ///< unit tangent of the offset: sign(factor) T(s) (T(s) at a cusp)
  double kappa = 0;                 ///< curvature of the offset, κ/(1 − dκ) (±inf at a cusp)
  long evaluations = 0;
  Status status = Status::ok;
  std::string message;
};

/// At s ∈ [0, length()] (InputError "s"), d finite (InputError "d").
OffsetPoint offset_at(const PlanarCurve& curve, double s, double d, const GaussLegendre& method = {});

struct OffsetCusp {
  /// The first s where 1 − dκ(s) is 0 or changes sign (the offset's first cusp), std::nullopt
  /// when it keeps its sign all along.
  std::optional<double> s;
  bool at_joint = false;            ///< κ jumps across 1/d at a joint there
  bool backwards_at_start = false;  ///< 1 − dκ(0) < 0: the offset runs backwards from its start
  Status status = Status::ok;
  std::string message;
};

/// d finite (InputError "d"). d = 0 has no cusp.
OffsetCusp first_offset_cusp(const PlanarCurve& curve, double d);

}  // namespace lac
