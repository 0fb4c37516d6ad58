#include "lac/curves/planar/la_segment_igf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_segment.hpp"
#include "lac/curves/planar/standard_form.hpp"

namespace lac::detail {
namespace {

using Complex = std::complex<double>;

// Adds a part: value, estimate, evaluations, and the worse of the two statuses.
void add(IntegralResult<Complex>& total, const IntegralResult<Complex>& part) {
  total.value += part.value;
  total.error_estimate += part.error_estimate;
  total.evaluations += part.evaluations;
  if (severity(part.status) > severity(total.status)) {
    total.status = part.status;
    total.message = part.message;
  }
}

// One part without a zero of q inside, anchored (U = 1) at a nonzero q: the closed form in θ of its
// standard-form pieces.
IntegralResult<Complex> igf_part(const std::vector<StandardPiece>& pieces, const Igf& m) {
  IntegralResult<Complex> r;
  for (const StandardPiece& piece : pieces) {
    const auto [theta0, theta1] = theta_range(piece);
    IntegralResult<Complex> c = m.integrate_theta(piece.curve.alpha(), piece.curve.lambda(), theta0, theta1);
    // The piece's similarity without its offset: the difference of two placed points.
    const Similarity& f = piece.to_user;
    c.value = f.factor * (f.mirror ? std::conj(c.value) : c.value);
    c.error_estimate *= std::abs(f.factor);
    add(r, c);
  }
  return r;
}

}  // namespace

IntegralResult<Complex> integrate_tangent_igf(const LaLaw& law, const LinearQ& seg, const Igf& m) {
  if (law.offset && law.alpha != 0) {
    // The standard form is written in the plain q (la_law.hpp): t = σ(1 − αq) (t carries log|κ|
    // to ε/|α| only, which bounds igf's accuracy for small |α|).
    const LinearQ plain{seg.ua, seg.ub, law.t_of_q(seg.qa), law.t_of_q(seg.qb), seg.phi_a};
    return integrate_tangent_igf(LaLaw{law.alpha, 1.0}, plain, m);
  }
  IntegralResult<Complex> r;
  if (law.alpha < 0 && seg.qa == 0 && seg.qb == 0) {  // κ ≡ 0: a straight segment, no standard form
    r.value = seg.length() * std::polar(1.0, seg.phi_a);
    return r;
  }
  const auto part = [&](double x, double y, double qx, double qy) {
    return LinearQ{x, y, qx, qy, x == seg.ua ? seg.phi_a : seg.phi_at(law, x)};
  };
  // τ = |q|/|q_anchor| where U = kIgfMinU (|q| ∝ ρ^α = U^(α/(α−1)) with U = 1 at the anchor).
  const double tau = law.alpha < 0 ? std::pow(kIgfMinU, law.alpha / (law.alpha - 1.0)) : 0.0;
  // An empty part (a zero of q within rounding of an end) contributes nothing.
  const auto graded = [&](const LinearQ& p) {
    if (p.ub > p.ua) add(r, integrate_tangent_gl(law, p, GaussLegendre{}));
  };
  // A part whose standard form does not exist in double precision (|q| at its anchor so small, e.g.
  // a subnormal end curvature, that ρ overflows) is integrated by the graded rule as well.
  const auto closed = [&](const LinearQ& p) {
    if (!(p.ub > p.ua)) return;
    const LaSegment segment(law, p);  // InputError for data no segment has
    std::vector<StandardPiece> pieces;
    try {
      pieces = to_standard_pieces(segment, Complex{});
    } catch (const InputError&) {
      graded(p);
      return;
    }
    add(r, igf_part(pieces, m));
  };
  // One side of a zero of q: anchored at x unless q(x) = 0 (then at y, as to_standard_pieces does).
  const auto side = [&](double x, double y, double qx, double qy) {
    const bool at_x = qx != 0;
    const double q_anchor = at_x ? qx : qy, q_far = at_x ? qy : qx;
    if (!(std::abs(q_far) < tau * std::abs(q_anchor))) {
      closed(part(x, y, qx, qy));
      return;
    }
    // Stop the closed form where |q| = τ|q_anchor|; the rest, next to the zero, by Gauss–Legendre.
    const double zero = x - qx * (y - x) / (qy - qx), anchor = at_x ? x : y;
    const double c = zero + tau * (anchor - zero), qc = seg.q_at(c);
    closed(at_x ? part(x, c, qx, qc) : part(c, y, qc, qy));
    graded(at_x ? part(c, y, qc, qy) : part(x, c, qx, qc));
  };
  const bool crosses = law.alpha < 0 && seg.qa != 0 && seg.qb != 0 && (seg.qa < 0) != (seg.qb < 0);
  if (crosses) {
    const double zero = std::clamp(seg.ua - seg.qa / seg.slope(), seg.ua, seg.ub);
    side(seg.ua, zero, seg.qa, 0.0);
    side(zero, seg.ub, 0.0, seg.qb);
  } else {
    side(seg.ua, seg.ub, seg.qa, seg.qb);
  }
  return r;
}

}  // namespace lac::detail

namespace lac {

PositionResult position_at(const LaSegment& seg, double s, const Igf& method) {
  method.validate();
  seg.check_s(s, "s");
  PositionResult r;
  r.form = Form::s;
  r.point = seg.frame_at(s);
  r.point.position = seg.start();
  const double u = seg.u_at(s);
  if (u == seg.ua()) return r;
  detail::place_tangent_integral(seg, detail::integrate_tangent_igf(seg.law(), seg.part(seg.ua(), u), method), r);
  return r;
}

}  // namespace lac
