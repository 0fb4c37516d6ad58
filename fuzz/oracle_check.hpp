#pragma once
// Independent end-to-end checks of lac's results in long double (x87, 64-bit mantissa): the
// oracle of the correctness campaign (fuzz/oracle_campaign.hpp, docs/robustness.md).
//
// Nothing here calls lac's integrators or its law code. A returned planar curve is read only as
// data (each LaSegment's α, σ, ua, ub, qa, qb, φa and placement); the linear-q law is written
// afresh (docs/math.md §1.2; 004 Eqs. 2–8):
//   α ≠ 0: κ = K(q) = sgn(q)|q|^(−1/α),  F(q) = α/(α−1)|q|^((α−1)/α) (α ≠ 1),  log|q| (α = 1)
//   α = 0: κ = σe^q,                      F(q) = σe^q
//   φ(u) = φa + (u − ua)·F[qa, q(u)],  F[a, b] = (F(b) − F(a))/(b − a)
// with the divided difference written without cancellation (log1p/expm1 for equal signs, the
// exact sinh form for α = 0), and ∫e^{iφ}du by Boost's adaptive Gauss–Kronrod (15 points,
// templated on long double) on pieces turning at most ~1.5 rad, cut where the turning reaches
// multiples (F inverted in closed form). Where |q| varies by more than a factor 2 on a piece of
// one sign the integral runs in w = log|q| (du = q dw / c), which resolves steep ends (κ → ∞ just
// beyond an end for α > 0) and the approach to an inflection (α < 0) without bisecting down to
// them.
#include <boost/math/quadrature/gauss_kronrod.hpp>
// Odeint's RKF78 stepper copies members GCC 12 calls maybe-uninitialized (they are written before use).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/space/space_curve.hpp"

namespace lac::oracle {

using R = long double;
using CR = std::complex<R>;
inline constexpr R kPiL = 3.141592653589793238462643383279502884L;

/// The linear-q law in long double (docs/math.md §1.2).
struct LawL {
  R alpha = -1, sigma = 1;
  R p() const { return (alpha - 1) / alpha; }
  R K(R q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (q == 0) return alpha < 0 ? R(0) : std::copysign(HUGE_VALL, q);
    return std::copysign(std::exp(-std::log(std::fabs(q)) / alpha), q);
  }
  /// dK/dq.
  R dK(R q) const {
    if (alpha == 0) return sigma * std::exp(q);
    const R b = -1 / alpha;
    return b * std::exp((b - 1) * std::log(std::fabs(q)));
  }
  R F(R q) const {
    if (alpha == 0) return sigma * std::exp(q);
    if (alpha == 1) return std::log(std::fabs(q));
    if (q == 0) return alpha < 0 ? R(0) : HUGE_VALL;
    return alpha / (alpha - 1) * std::exp(p() * std::log(std::fabs(q)));
  }
  /// The q of sign `sign` with F(q) = y (NaN where y is not a value of F).
  R F_inverse(R y, R sign) const {
    if (alpha == 0) return std::log(sigma * y);
    if (alpha == 1) return std::copysign(std::exp(y), sign);
    const R z = (alpha - 1) / alpha * y;
    if (!(z > 0)) return z == 0 ? R(0) : std::numeric_limits<R>::quiet_NaN();
    return std::copysign(std::exp(std::log(z) / p()), sign);
  }
  /// F[a, b], the mean of K over q ∈ [a, b].
  R dd(R a, R b) const {
    if (a == b) return K(a);
    const R d = b - a;
    if (alpha == 0) {
      const R h = d / 2;
      return sigma * std::exp(a + h) * (std::fabs(h) < 1e-300L ? R(1) : std::sinh(h) / h);
    }
    if (a != 0 && b != 0 && (a < 0) == (b < 0)) {
      // log(b/a): log1p of the relative step where it is small, else the log of the ratio (a
      // ratio near 0 would lose its digits in 1 + d/a).
      const R x = d / a;
      const R L = std::fabs(x) < 0.5L ? std::log1p(x) : std::log(b / a);
      if (alpha == 1) return L / d;
      return alpha / (alpha - 1) * std::exp(p() * std::log(std::fabs(a))) * std::expm1(p() * L) / d;
    }
    return (F(b) - F(a)) / d;
  }
};

/// A segment's intrinsic data in long double: q linear from (ua, qa) to (ub, qb), φ(ua) = φa.
/// ua > ub is allowed (integrals then run backwards).
struct SegL {
  LawL law;
  R ua = 0, ub = 1, qa = 0, qb = 0, phia = 0;
  R slope() const { return (qb - qa) / (ub - ua); }
  /// q(u) from the nearer end.
  R q_at(R u) const {
    const R t = (u - ua) / (ub - ua);
    return t <= 0.5L ? qa + (qb - qa) * t : qb - (qb - qa) * (1 - t);
  }
  R phi_at(R u) const { return phi_of(u, q_at(u)); }
  R phi_of(R u, R q) const { return phia + (u - ua) * law.dd(qa, q); }
};

struct IntegralL {
  CR value{};
  R error = 0;
  bool ok = true;
  std::string why;
};

namespace detail {

inline constexpr R kPieceTurning = 1.5L;
inline constexpr long kMaxPieces = 20000;
/// Integrand evaluations of one integrate_tangent call before the oracle gives up (no verdict).
inline constexpr long kMaxEvaluations = 400000;
inline thread_local long evaluations = 0;

/// ∫_{u0}^{u1} e^{iφ} du over a part where q keeps one sign (or α = 0); q0, q1 its end values
/// (one may be 0 for α < 0: the inflection).
inline void integrate_side(const SegL& s, R u0, R u1, R q0, R q1, IntegralL& out) {
  if (u0 == u1) return;
  const LawL& law = s.law;
  const R c = (q1 - q0) / (u1 - u0);
  const R sgn = (q0 != 0 ? q0 : q1) < 0 ? R(-1) : R(1);
  // q and φ inside the part, q from the nearer end of the part.
  auto q_in = [&](R u) {
    const R t = (u - u0) / (u1 - u0);
    return t <= 0.5L ? q0 + (q1 - q0) * t : q1 - (q1 - q0) * (1 - t);
  };
  const R phi0 = s.phi_of(u0, q0), phi1 = s.phi_of(u1, q1);
  const R turning = phi1 - phi0;
  if (!std::isfinite(turning) || !std::isfinite(phi0)) {
    out.ok = false;
    out.why = "non-finite turning";
    return;
  }
  long n = static_cast<long>(std::ceil(std::fabs(turning) / kPieceTurning));
  n = std::max(n, 1L);
  if (n > kMaxPieces) {
    out.ok = false;
    out.why = "turning beyond the oracle's piece cap";
    return;
  }
  // Log variable where |q| varies by more than a factor 2 (α ≠ 0, one sign).
  const R qmax = std::max(std::fabs(q0), std::fabs(q1));
  const R qmin_raw = std::min(std::fabs(q0), std::fabs(q1));
  // Also where F ∝ |q|^p is steep on the part (|p| large: small |α|), however little |q| varies:
  // at α = −2e-5, |q| from 1.0002 to 0 turns the whole part within Δlog|q| ≈ 1e-4 of its end.
  const R pe = law.alpha != 0 && law.alpha != 1 ? law.p() : R(0);
  const bool steep = pe != 0 && qmin_raw > 0 && std::fabs(pe) * std::log(qmax / qmin_raw) > 4;
  const bool log_var = law.alpha != 0 && c != 0 && (qmin_raw == 0 || qmax > 2 * qmin_raw || steep);
  const R qfloor = qmax * 1e-24L;  // an inflection end is truncated here: the part lost is ≤ 1e-24 of |q|/|c|
  auto w_of_q = [&](R q) { return std::log(std::max(std::fabs(q), qfloor)); };
  // Cut points: q where φ reaches φ0 + turning·k/n (F inverted), in the integration variable.
  std::vector<R> cuts(static_cast<size_t>(n + 1));
  const R a_var = log_var ? w_of_q(q0) : u0, b_var = log_var ? w_of_q(q1) : u1;
  cuts.front() = a_var;
  cuts.back() = b_var;
  bool monotone = true;
  const R Fqa = law.F(s.qa);
  for (long k = 1; k < n; ++k) {
    const R phik = phi0 + turning * static_cast<R>(k) / static_cast<R>(n);
    const R qk = law.F_inverse(Fqa + s.slope() * (phik - s.phia), sgn);
    R v = log_var ? w_of_q(qk) : u0 + (qk - q0) / c;
    if (!std::isfinite(v)) monotone = false;
    cuts[static_cast<size_t>(k)] = v;
  }
  const bool up = b_var > a_var;
  for (long k = 1; k <= n && monotone; ++k)
    if (up ? !(cuts[k] >= cuts[k - 1]) : !(cuts[k] <= cuts[k - 1])) monotone = false;
  if (!monotone)
    for (long k = 1; k < n; ++k) cuts[k] = a_var + (b_var - a_var) * static_cast<R>(k) / static_cast<R>(n);
  // In w = log|q| the turning concentrates within ~1/|p| of the end where |F| ∝ e^{pw} is largest
  // (the turning cuts above bound each piece's turning, not the width of that layer, which
  // Gauss–Kronrod's bisection can miss): cuts at 2^j/(4|p|) from that end.
  if (log_var && pe != 0) {
    const R steep_end = (pe > 0) == (b_var > a_var) ? b_var : a_var, other = steep_end == b_var ? a_var : b_var;
    const R dir = other > steep_end ? R(1) : R(-1);
    for (R d = 0.25L / std::fabs(pe); d < std::fabs(other - steep_end) && cuts.size() < 4 * kMaxPieces; d *= 2)
      cuts.push_back(steep_end + dir * d);
    std::sort(cuts.begin(), cuts.end(), [up](R x, R y) { return up ? x < y : x > y; });
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    n = static_cast<long>(cuts.size()) - 1;
  }

  // Each piece in its own unit variable: Boost's error estimate on a piece of width ~1e-7 stays
  // ~1e-5 of the value at any depth (measured), while the same piece on [0, 1] converges.
  auto integrate_unit = [](auto& f, R a, R b, R& err) {
    using GK = boost::math::quadrature::gauss_kronrod<R, 15>;
    const CR v = GK::integrate([&](R t) { return f(a + (b - a) * t); }, R(0), R(1), 10, 1e-13L, &err);
    err *= std::fabs(b - a);
    return v * (b - a);
  };
  for (long k = 0; k < n; ++k) {
    const R a = cuts[k], b = cuts[k + 1];
    if (a == b) continue;
    R err = 0;
    CR v;
    if (log_var) {
      auto f = [&](R w) {
        if (++evaluations > kMaxEvaluations) return CR(std::numeric_limits<R>::quiet_NaN(), 0);
        const R q = sgn * std::exp(w);
        const R u = u0 + (q - q0) / c;
        const R ph = s.phia + (q - s.qa) / s.slope() * law.dd(s.qa, q);
        (void)u;
        return CR(std::cos(ph), std::sin(ph)) * (q / c);
      };
      v = integrate_unit(f, a, b, err);
    } else {
      auto f = [&](R u) {
        if (++evaluations > kMaxEvaluations) return CR(std::numeric_limits<R>::quiet_NaN(), 0);
        const R ph = s.phi_of(u, q_in(u));
        return CR(std::cos(ph), std::sin(ph));
      };
      v = integrate_unit(f, a, b, err);
    }
    if (!std::isfinite(v.real()) || !std::isfinite(v.imag()) || !std::isfinite(err)) {
      out.ok = false;
      out.why = detail::evaluations > kMaxEvaluations ? "oracle evaluation budget spent" : "non-finite piece integral";
      return;
    }
    out.value += v;
    out.error += err;
  }
}

}  // namespace detail

/// ∫_{u0}^{u1} e^{iφ(u)} du for u0, u1 in the segment's range (split at an inflection).
inline IntegralL integrate_tangent(const SegL& s, R u0, R u1) {
  IntegralL out;
  if (u0 == u1) return out;
  detail::evaluations = 0;
  R sign = 1;
  if (u0 > u1) {
    std::swap(u0, u1);
    sign = -1;
  }
  const R q0 = s.q_at(u0), q1 = s.q_at(u1);
  if (s.law.alpha < 0 && ((q0 < 0 && q1 > 0) || (q0 > 0 && q1 < 0))) {
    // The zero of q, from the nearer end.
    const R c = s.slope();
    R us = std::fabs(q0) <= std::fabs(q1) ? u0 - q0 / c : u1 - q1 / c;
    us = std::clamp(us, u0, u1);
    detail::integrate_side(s, u0, us, q0, 0, out);
    if (out.ok) detail::integrate_side(s, us, u1, 0, q1, out);
  } else {
    detail::integrate_side(s, u0, u1, q0, q1, out);
  }
  out.value *= sign;
  // The oracle's own error must stay far below any accept bound (1e-6): else no verdict.
  if (out.ok && !(out.error <= 1e-10L * std::fabs(u1 - u0))) {
    out.ok = false;
    out.why = "oracle quadrature error " + std::to_string(static_cast<double>(out.error)) + " of the length " +
              std::to_string(static_cast<double>(std::fabs(u1 - u0)));
  }
  return out;
}

/// A LaSegment of the library read as data.
struct PlacedSegL {
  SegL seg;
  CR start;
  R scale = 1;
  CR rotation{1, 0};
  R rotation_angle = 0;
};

inline PlacedSegL read_segment(const LaSegment& s) {
  PlacedSegL p;
  p.seg.law = {static_cast<R>(s.law().alpha), static_cast<R>(s.law().sigma)};
  p.seg.ua = s.ua();
  p.seg.ub = s.ub();
  p.seg.qa = s.qa();
  p.seg.qb = s.qb();
  if (s.law().offset) {
    // The offset (Box–Cox) form stores q = (t − 1)/(−α), t the plain form's q / σ (la_law.hpp):
    // converted here to the plain form in long double (log|κ| then good to ε_ld/|α|); below
    // |α| = 1e-9 to the α = 0 law in log|κ| = q log1p(−αq)/(−αq) (the law differs by O(|α|)).
    const R a = s.law().alpha, sg = s.law().sigma;
    if (std::fabs(a) >= 1e-9L) {
      p.seg.qa = sg * (1 - a * static_cast<R>(s.qa()));
      p.seg.qb = sg * (1 - a * static_cast<R>(s.qb()));
    } else {
      auto log_kappa = [&](R q) { const R z = -a * q; return z == 0 ? q : q * std::log1p(z) / z; };
      p.seg.law = {0, sg};
      p.seg.qa = log_kappa(s.qa());
      p.seg.qb = log_kappa(s.qb());
    }
  }
  p.seg.phia = s.phi_a();
  p.start = CR(s.start().real(), s.start().imag());
  p.scale = s.scale();
  p.rotation = CR(s.rotation().real(), s.rotation().imag());
  p.rotation_angle = std::atan2(p.rotation.imag(), p.rotation.real());
  return p;
}

/// What the oracle computes of one placed segment.
struct SegmentEnds {
  CR start, end;
  R theta_start = 0, theta_end = 0;  ///< θ continuous within the segment (not wrapped)
  R kappa_start = 0, kappa_end = 0;
  R dkappa_start = 0, dkappa_end = 0;  ///< dκ/ds
  R length = 0;
  R integral_error = 0;
  bool ok = true;
  std::string why;
};

inline SegmentEnds evaluate_segment(const PlacedSegL& p) {
  SegmentEnds e;
  const SegL& s = p.seg;
  e.start = p.start;
  e.theta_start = p.rotation_angle + s.phia;
  e.theta_end = p.rotation_angle + s.phi_at(s.ub);
  e.kappa_start = s.law.K(s.qa) / p.scale;
  e.kappa_end = s.law.K(s.qb) / p.scale;
  const R c = s.slope();
  e.dkappa_start = s.law.dK(s.qa) * c / (p.scale * p.scale);
  e.dkappa_end = s.law.dK(s.qb) * c / (p.scale * p.scale);
  e.length = p.scale * (s.ub - s.ua);
  IntegralL I = integrate_tangent(s, s.ua, s.ub);
  e.ok = I.ok;
  e.why = I.why;
  e.integral_error = I.error * p.scale;
  e.end = p.start + p.scale * p.rotation * I.value;
  return e;
}

/// Angle difference a − b wrapped to (−π, π].
inline R wrap_diff(R a, R b) {
  R d = std::remainder(a - b, 2 * kPiL);
  return d;
}

/// What a planar result must satisfy.
struct PlanarSpec {
  /// A condition at the end of segment `after` (−1: the start of the curve).
  struct Waypoint {
    int after = -1;
    std::complex<double> point;
    std::optional<double> theta, kappa;
  };
  std::vector<Waypoint> waypoints;
  std::vector<double> alphas;  ///< the α each segment must have (empty: not checked)
  int joint_order = 1;         ///< 1: position + tangent, 2: + curvature, 3: + dκ/ds
  std::optional<double> turning;  ///< total θ(L) − θ(0) required (exact, windings included)
  std::vector<double> segment_turnings;  ///< θ(end) − θ(start) of each segment (empty: not checked)
  bool straight_any_alpha = false;  ///< a segment with κ ≡ 0 may carry any α (the line: every α's limit)
  double scale = 1;               ///< chord: position errors are divided by it, curvatures multiplied
};

struct Verdict {
  bool verified = true;   ///< false: the oracle could not evaluate (not a verdict either way)
  double error = 0;       ///< the largest relative error found (chord units, rad, κ × chord)
  /// The oracle's own uncertainty on positions (chord units): its quadrature error estimate plus
  /// the long-double rounding of the integral, scaled by ℓ/chord (a nearly closed loop of huge
  /// ℓ makes the end point a small difference of large numbers).
  double uncertainty = 0;
  std::string worst;      ///< which condition gave it
  std::string why;        ///< when not verified
};

inline void note(Verdict& v, R err, const std::string& what) {
  const double e = std::isnan(static_cast<double>(err)) ? HUGE_VAL : static_cast<double>(err);
  if (e > v.error || (std::isinf(e) && !std::isinf(v.error))) {
    v.error = e;
    v.worst = what;
  }
}

/// Checks a planar curve against its specification: every condition's error, relative.
inline Verdict check_planar(const PlanarCurve& curve, const PlanarSpec& spec) {
  Verdict v;
  const auto& segs = curve.segments();
  if (segs.empty()) {
    v.error = HUGE_VAL;
    v.worst = "empty curve";
    return v;
  }
  const R L = spec.scale;
  std::vector<SegmentEnds> ends;
  ends.reserve(segs.size());
  R total_turning = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    const PlacedSegL p = read_segment(segs[i]);
    SegmentEnds e = evaluate_segment(p);
    {
      const R eps = std::numeric_limits<R>::epsilon();
      const R turn = std::fabs(e.theta_end - e.theta_start);
      const R u = (e.integral_error + 8 * eps * std::fabs(p.scale * (p.seg.ub - p.seg.ua)) * (1 + turn)) / L +
                  8 * eps * std::abs(p.start) / L;
      v.uncertainty = std::max(v.uncertainty, static_cast<double>(u));
    }
    if (!e.ok) {
      v.verified = false;
      v.why = "segment " + std::to_string(i) + ": " + e.why;
      return v;
    }
    const bool straight = segs[i].qa() == 0 && segs[i].qb() == 0 && segs[i].law().alpha < 0;
    if (!spec.alphas.empty() && !(straight && spec.straight_any_alpha)) {
      const double want = spec.alphas[std::min(i, spec.alphas.size() - 1)];
      if (segs[i].law().alpha != want) note(v, HUGE_VALL, "alpha of segment " + std::to_string(i));
    }
    note(v, std::fabs(e.length) > 0 && std::isfinite(e.length) ? R(0) : HUGE_VALL, "length");
    total_turning += e.theta_end - e.theta_start;
    if (i < spec.segment_turnings.size())
      note(v, std::fabs(e.theta_end - e.theta_start - R(spec.segment_turnings[i])), "turning of segment " + std::to_string(i));
    if (i > 0) {
      const SegmentEnds& prev = ends.back();
      const std::string j = "joint " + std::to_string(i);
      note(v, std::abs(e.start - prev.end) / L, j + " position");
      const R dth = wrap_diff(e.theta_start, prev.theta_end);
      note(v, std::fabs(dth), j + " tangent");
      total_turning += dth;
      // Curvature × chord, relative where |κ| × chord > 1 (a joint at κ ~ 1e14/chord agrees to its rounding).
      if (spec.joint_order >= 2)
        note(v, std::fabs(e.kappa_start - prev.kappa_end) * L / std::max<R>(1, std::fabs(e.kappa_start) * L),
             j + " curvature");
      if (spec.joint_order >= 3) {
        const R a = e.dkappa_start * L * L, b = prev.dkappa_end * L * L;
        note(v, std::fabs(a - b) / std::max<R>(1, std::max(std::fabs(a), std::fabs(b))), j + " dkappa/ds");
      }
    }
    ends.push_back(e);
  }
  for (const auto& w : spec.waypoints) {
    const bool at_start = w.after < 0;
    const SegmentEnds& e = ends.at(at_start ? 0 : static_cast<size_t>(w.after));
    const CR pos = at_start ? e.start : e.end;
    const std::string where = at_start ? "start" : "end of segment " + std::to_string(w.after);
    note(v, std::abs(pos - CR(w.point.real(), w.point.imag())) / L, where + " position");
    if (w.theta) note(v, std::fabs(wrap_diff(at_start ? e.theta_start : e.theta_end, *w.theta)), where + " tangent");
    if (w.kappa)
      note(v, std::fabs((at_start ? e.kappa_start : e.kappa_end) - R(*w.kappa)) * L / std::max<R>(1, std::fabs(R(*w.kappa)) * L),
           where + " curvature");
  }
  if (spec.turning) note(v, std::fabs(total_turning - R(*spec.turning)), "total turning");
  return v;
}

// ---------------------------------------------------------------------------------------------
// Standard-form LA curve (docs/math.md §1): ρ = 1, θ = 0, position 0 at s = 0; ρ^α = 1 + αΛs
// (α ≠ 0), log ρ = Λs (α = 0). In linear-q form: q = ρ^α (α ≠ 0) or q = log κ = −Λs (α = 0, σ = 1),
// slope αΛ or −Λ, φ(0) = 0.

/// 1 + a·b·t with error-free products (fmal): near the open end of the standard form's domain
/// (αΛs → −1) the rounded product would leave 1 + αΛs only ε_ld/|1 + αΛs| relative accuracy.
inline R one_plus_product(R a, R b, R t) {
  const R p = b * t, p_err = std::fmal(b, t, -p);
  const R q = a * p, q_err = std::fmal(a, p, -q) + a * p_err;
  return (1 + q) + q_err;  // 1 + q is exact where it cancels (Sterbenz)
}

inline SegL standard_form(double alpha, double lambda, R s_end) {
  SegL s;
  s.law = {static_cast<R>(alpha), 1};
  s.ua = 0;
  s.ub = s_end;
  s.qa = alpha == 0 ? R(0) : R(1);
  s.qb = alpha == 0 ? -R(lambda) * s_end : one_plus_product(alpha, lambda, s_end);
  s.phia = 0;
  return s;
}

/// s at tangent angle θ of the standard form: F inverted, then Newton on θ(s) (dθ/ds = κ).
inline std::optional<R> standard_s_at_theta(double alpha, double lambda, R theta) {
  if (lambda == 0) return theta;
  const LawL law{static_cast<R>(alpha), 1};
  const R q0 = alpha == 0 ? R(0) : R(1);
  const R c = alpha == 0 ? -R(lambda) : R(alpha) * R(lambda);
  const R q = law.F_inverse(law.F(q0) + c * theta, 1);
  R s = std::isfinite(q) ? (q - q0) / c : theta;
  if (!std::isfinite(s)) return std::nullopt;
  for (int it = 0; it < 8; ++it) {
    const R qs = alpha == 0 ? c * s : one_plus_product(alpha, lambda, s);
    if (alpha > 0 && !(qs > 0)) return std::nullopt;
    const R th = s * law.dd(q0, qs);
    const R k = law.K(qs);
    if (!(k > 0) || !std::isfinite(th)) return std::nullopt;
    const R step = (th - theta) / k;
    s -= step;
    if (std::fabs(step) <= 1e-19L * std::max<R>(1, std::fabs(s))) break;
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// Quadratic LA curve (003; docs/math.md §4): in u = log κ, ds/du = −e^{γu² − αu}/Λ, so along s
//   du/ds = −Λ e^{−(γu² − αu)},  dθ/ds = e^u,  dx/ds = cos θ,  dy/ds = sin θ,
// from u = θ = x = y = 0 at s = 0: an ODE in s integrated by Boost.Odeint's Runge–Kutta–
// Fehlberg 7(8) in long double (no closed form, no inverse function of lac's). Each step turns at
// most kQuadraticStepTurn rad: RKF78's embedded estimate misses the error of x and y (integrals of
// cos θ, sin θ), e.g. 1.5e-4 at α = 1.75, γ = 0.38, Λ = 0.42, s = −8.27 (κ = 228, θ = −934) in
// 342 free steps, 6e-16 against mpmath with the cap.

struct QuadraticPoint {
  R log_kappa = 0, theta = 0;
  CR position;
  bool ok = true;
};

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
inline constexpr R kQuadraticStepTurn = 0.25L;
inline QuadraticPoint quadratic_point(double alpha, double gamma, double lambda, R s_end) {
  using State = std::array<R, 4>;
  namespace ode = boost::numeric::odeint;
  const R a = alpha, g = gamma, l = lambda;
  auto rhs = [&](const State& y, State& dy, R) {
    const R u = y[0];
    dy[0] = -l * std::exp(-(g * u * u - a * u));
    dy[1] = std::exp(u);
    dy[2] = std::cos(y[1]);
    dy[3] = std::sin(y[1]);
  };
  QuadraticPoint out;
  if (s_end == 0) return out;
  State y{0, 0, 0, 0};
  auto stepper = ode::make_controlled(R(1e-16), R(1e-16), ode::runge_kutta_fehlberg78<State, R>());
  R t = 0, dt = s_end / 64;
  long steps = 0;
  const bool fwd = s_end > 0;
  while (fwd ? t < s_end : t > s_end) {
    if (++steps > 200000) {
      out.ok = false;
      return out;
    }
    const R turn_cap = kQuadraticStepTurn / std::exp(y[0]);  // dθ/ds = κ = e^u
    if (std::fabs(dt) > turn_cap) dt = fwd ? turn_cap : -turn_cap;
    if (fwd ? t + dt > s_end : t + dt < s_end) dt = s_end - t;
    if (stepper.try_step(rhs, y, t, dt) == ode::fail) {
      if (std::fabs(dt) < 1e-300L) {
        out.ok = false;
        return out;
      }
    }
    for (R c : y)
      if (!std::isfinite(c)) {
        out.ok = false;
        return out;
      }
  }
  out.log_kappa = y[0];
  out.theta = y[1];
  out.position = CR(y[2], y[3]);
  return out;
}
#pragma GCC diagnostic pop

// ---------------------------------------------------------------------------------------------
// LA space curves (000 §2; docs/math.md §3): the laws written afresh in the standard form,
//   ρ(s) = e^{Λs} (α = 0) or (1 + αΛs)^{1/α};  μ(s) = ν e^{σΩs} (β = 0) or (σΩβs + ν^β)^{1/β},
// σ = +1 for type 1 (μ increasing), −1 for type 2; κ = 1/ρ, τ = 1/μ, and the Frenet–Serret
// equations P' = T, T' = κN, N' = −κT + τB, B' = −τN integrated in long double by Boost.Odeint's
// RKF78, each step turning the frame by at most kSpaceStepTurn rad (√(κ² + τ²) h), from each
// piece's start frame (no ODE method of lac's).

inline constexpr R kSpaceStepTurn = 0.25L;

struct SpaceLawL {
  R alpha, beta, lambda, omega, nu, sigma;
  R rho(R s) const { return alpha == 0 ? std::exp(lambda * s) : std::pow(1 + alpha * lambda * s, 1 / alpha); }
  R mu(R s) const { return beta == 0 ? nu * std::exp(sigma * omega * s) : std::pow(sigma * omega * beta * s + std::pow(nu, beta), 1 / beta); }
};

struct FrameL {
  std::array<R, 3> p{}, t{}, n{}, b{};
  bool ok = true;
};

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
/// The standard-form frame at s1 from `start` at s0 (s1 ≥ s0).
inline FrameL space_frame(const SpaceLawL& law, const FrameL& start, R s0, R s1) {
  using State = std::array<R, 12>;
  namespace ode = boost::numeric::odeint;
  State y;
  for (int i = 0; i < 3; ++i) y[i] = start.p[i], y[3 + i] = start.t[i], y[6 + i] = start.n[i], y[9 + i] = start.b[i];
  auto rhs = [&](const State& x, State& dx, R s) {
    const R k = 1 / law.rho(s), tau = 1 / law.mu(s);
    for (int i = 0; i < 3; ++i) {
      dx[i] = x[3 + i];
      dx[3 + i] = k * x[6 + i];
      dx[6 + i] = -k * x[3 + i] + tau * x[9 + i];
      dx[9 + i] = -tau * x[6 + i];
    }
  };
  FrameL out = start;
  auto stepper = ode::make_controlled(R(1e-17), R(1e-17), ode::runge_kutta_fehlberg78<State, R>());
  R s = s0, dt = (s1 - s0) / 16;
  long steps = 0;
  while (s < s1) {
    if (++steps > 400000 || !(dt > 0)) {
      out.ok = false;
      return out;
    }
    const R rate = std::hypot(1 / law.rho(s), 1 / law.mu(s));
    if (dt * rate > kSpaceStepTurn) dt = kSpaceStepTurn / rate;
    if (s + dt > s1) dt = s1 - s;
    stepper.try_step(rhs, y, s, dt);
    for (R c : y)
      if (!std::isfinite(c)) {
        out.ok = false;
        return out;
      }
  }
  for (int i = 0; i < 3; ++i) out.p[i] = y[i], out.t[i] = y[3 + i], out.n[i] = y[6 + i], out.b[i] = y[9 + i];
  return out;
}
#pragma GCC diagnostic pop

/// What a space construction promised: its end points, directions and laws.
struct SpaceSpec {
  Vec3 p0, v0, p1, v1;
  std::vector<std::array<double, 2>> slopes;  ///< (α, β) of each piece
  bool joint_continuity = false;              ///< compound: κ, τ and the frame continuous at the joint
};

/// Checks a space curve: start and end point (relative to |p1 − p0|), start and end tangent
/// (rad), each piece's slopes, and for a compound segment the joint (frame, κ and τ relative).
inline Verdict check_space(const SpaceCurve& curve, const SpaceSpec& spec) {
  Verdict v;
  const auto& pieces = curve.pieces();
  if (pieces.empty() || (!spec.slopes.empty() && pieces.size() != spec.slopes.size())) {
    v.error = HUGE_VAL;
    v.worst = "piece count";
    return v;
  }
  const SpacePlacement& pl = curve.placement();
  const R chord = (spec.p1 - spec.p0).norm();
  auto user_point = [&](const std::array<R, 3>& q) {
    std::array<R, 3> u;
    for (int i = 0; i < 3; ++i) u[i] = pl.origin[i] + pl.matrix(i, 0) * q[0] + pl.matrix(i, 1) * q[1] + pl.matrix(i, 2) * q[2];
    return u;
  };
  auto user_dir = [&](const std::array<R, 3>& q) {
    std::array<R, 3> u;
    for (int i = 0; i < 3; ++i) u[i] = pl.matrix(i, 0) * q[0] + pl.matrix(i, 1) * q[1] + pl.matrix(i, 2) * q[2];
    const R n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (R& c : u) c /= n;
    return u;
  };
  auto distance = [](const std::array<R, 3>& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  auto angle = [](const std::array<R, 3>& a, const Vec3& b) {  // a unit, b any length
    const Vec3 bn = b.normalized();
    const R c0 = a[1] * bn[2] - a[2] * bn[1], c1 = a[2] * bn[0] - a[0] * bn[2], c2 = a[0] * bn[1] - a[1] * bn[0];
    return std::atan2(std::sqrt(c0 * c0 + c1 * c1 + c2 * c2), a[0] * bn[0] + a[1] * bn[1] + a[2] * bn[2]);
  };
  auto to_l = [](const Frame3& f) {
    FrameL o;
    for (int i = 0; i < 3; ++i) o.p[i] = f.p[i], o.t[i] = f.t[i], o.n[i] = f.n[i], o.b[i] = f.b[i];
    return o;
  };
  FrameL prev_end;
  R prev_kappa = 0, prev_tau = 0;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const SpacePiece& pc = pieces[k];
    const LaSpaceCurve& law = pc.law;
    if (!spec.slopes.empty() && (law.alpha() != spec.slopes[k][0] || law.beta() != spec.slopes[k][1]))
      note(v, HUGE_VALL, "slopes of piece " + std::to_string(k));
    const SpaceLawL L{law.alpha(), law.beta(), law.lambda(), law.omega(), law.nu(), law.type() == TorsionType::type1 ? R(1) : R(-1)};
    const FrameL start = to_l(pc.start);
    const std::string name = "piece " + std::to_string(k);
    if (k == 0) {
      note(v, distance(user_point(start.p), spec.p0) / chord, "start position");
      note(v, angle(user_dir(start.t), spec.v0), "start tangent");
    } else if (spec.joint_continuity) {
      // The joint: this piece's start frame against the oracle's end of the previous piece, and
      // κ, τ of both laws there (relative).
      R dp = 0, dt = 0;
      for (int i = 0; i < 3; ++i) {
        dp = std::max(dp, std::fabs(start.p[i] - prev_end.p[i]));
        dt = std::max({dt, std::fabs(start.t[i] - prev_end.t[i]), std::fabs(start.n[i] - prev_end.n[i]), std::fabs(start.b[i] - prev_end.b[i])});
      }
      note(v, dp * pl.scale / chord, "joint position");
      note(v, dt, "joint frame");
      const R kap = 1 / L.rho(pc.s_begin), tau = 1 / L.mu(pc.s_begin);
      note(v, std::fabs(kap - prev_kappa) / std::max(kap, prev_kappa), "joint curvature");
      note(v, std::fabs(tau - prev_tau) / std::max(tau, prev_tau), "joint torsion");
    }
    const FrameL end = space_frame(L, start, pc.s_begin, pc.s_end);
    if (!end.ok) {
      v.verified = false;
      v.why = name + ": the oracle's integration failed";
      return v;
    }
    v.uncertainty = std::max(v.uncertainty, static_cast<double>(1e-14L * (1 + (pc.s_end - pc.s_begin) * pl.scale / chord)));
    prev_end = end;
    prev_kappa = 1 / L.rho(pc.s_end);
    prev_tau = 1 / L.mu(pc.s_end);
    if (k + 1 == pieces.size()) {
      note(v, distance(user_point(end.p), spec.p1) / chord, "end position");
      note(v, angle(user_dir(end.t), spec.v1), "end tangent");
    }
  }
  return v;
}

}  // namespace lac::oracle
