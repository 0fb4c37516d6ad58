#pragma once
// An independent long-double model of a PlanarCurve for the geometry tests: the closed forms of
// the linear-q law written again from 004 Eqs. 2–8 (plain form, or α = 0) — not the
// library's divided differences — and positions by 30-point Gauss–Legendre (Boost.Math, long
// double) on a fine grid in u, cumulated from each segment's start. Only the segments' defining
// data (law, u range, q at the ends, φa, placement) are read from the library's objects.
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "lac/curves/planar/planar_curve.hpp"

namespace lac::test {

using ld = long double;
using cld = std::complex<ld>;

struct RefSegment {
  ld alpha, sigma, ua, ub, qa, qb, phi_a, scale, angle, s_begin;
  cld start;

  RefSegment(const LaSegment& s, ld s0)
      : alpha(s.law().alpha), sigma(s.law().sigma), ua(s.ua()), ub(s.ub()), qa(s.qa()), qb(s.qb()),
        phi_a(s.phi_a()), scale(s.scale()), angle(std::atan2(ld(s.rotation().imag()), ld(s.rotation().real()))),
        s_begin(s0), start(s.start().real(), s.start().imag()) {}

  ld slope() const { return (qb - qa) / (ub - ua); }
  ld q(ld u) const { return qa + slope() * (u - ua); }
  // κ per unit u, K(q) (004 Eq. 3), and its antiderivative F (Eqs. 5, 7).
  ld K(ld x) const {
    if (alpha == 0) return sigma * std::exp(x);
    return (x < 0 ? -1 : 1) * std::pow(std::abs(x), -1 / alpha);
  }
  ld F(ld x) const {
    if (alpha == 0) return sigma * std::exp(x);
    if (alpha == 1) return std::log(std::abs(x));  // 004 Eq. 8
    return alpha / (alpha - 1) * std::pow(std::abs(x), (alpha - 1) / alpha);
  }
  ld phi(ld u) const {
    const ld c0 = slope();
    if (c0 == 0) return phi_a + K(qa) * (u - ua);
    return phi_a + (F(q(u)) - F(qa)) / c0;
  }
  ld theta(ld u) const { return angle + phi(u); }
  ld kappa(ld u) const { return K(q(u)) / scale; }
  ld u_of(ld s_local) const { return std::min(ub, ua + s_local / scale); }
  ld length() const { return scale * (ub - ua); }
  /// ∫ e^{iθ} ds from u0 to u1 (short: a few hundredths of a radian).
  cld step(ld u0, ld u1) const {
    const auto f = [&](ld u) { return std::polar(ld(1), theta(u)); };
    const auto re = boost::math::quadrature::gauss<ld, 30>::integrate([&](ld u) { return f(u).real(); }, u0, u1);
    const auto im = boost::math::quadrature::gauss<ld, 30>::integrate([&](ld u) { return f(u).imag(); }, u0, u1);
    return scale * cld(re, im);
  }
  ld inflection() const {  // u where q = 0 (α < 0), or NaN
    if (!(alpha < 0) || (qa < 0) == (qb < 0) || qa == 0 || qb == 0) return NAN;
    return ua - qa / slope();
  }
};

/// Dense samples (u, s, position) of every segment, each step turning at most `max_step` rad
/// and at most `min_steps` per segment; a step never straddles an inflection.
struct RefCurve {
  std::vector<RefSegment> segs;
  struct Sample {
    size_t seg;
    ld u, s;
    cld p;
  };
  std::vector<Sample> samples;
  ld length = 0;

  explicit RefCurve(const PlanarCurve& c, int min_steps = 2000, ld max_step = 0.02L) {
    for (size_t k = 0; k < c.segments().size(); ++k) segs.emplace_back(c.segments()[k], c.segment_start(k));
    for (size_t k = 0; k < segs.size(); ++k) {
      const RefSegment& g = segs[k];
      std::vector<ld> us;
      const ld ui = g.inflection();
      const auto grid = [&](ld a, ld b) {
        const ld turn = std::abs(g.phi(b) - g.phi(a)) + std::abs(g.phi(0.5L * (a + b)) - g.phi(a));
        const int n = std::max<int>(min_steps, int(std::ceil(turn / max_step)));
        for (int i = 0; i < n; ++i) us.push_back(a + (b - a) * i / n);
      };
      if (std::isfinite(ui)) {
        grid(g.ua, ui);
        grid(ui, g.ub);
      } else {
        grid(g.ua, g.ub);
      }
      us.push_back(g.ub);
      cld p = g.start;
      for (size_t i = 0; i < us.size(); ++i) {
        if (i > 0) p += g.step(us[i - 1], us[i]);
        samples.push_back({k, us[i], g.s_begin + g.scale * (us[i] - g.ua), p});
      }
      length += g.length();
    }
  }
  /// Position at u of segment k, from the nearest sample below.
  cld position(size_t k, ld u) const {
    auto it = std::upper_bound(samples.begin(), samples.end(), std::pair{k, u},
                               [](const std::pair<size_t, ld>& x, const Sample& y) { return x.first < y.seg || (x.first == y.seg && x.second < y.u); });
    --it;
    return it->p + segs[k].step(it->u, u);
  }
  cld tangent(size_t k, ld u) const { return std::polar(ld(1), segs[k].theta(u)); }
};

/// Bisection in long double of f on [a, b] with f(a), f(b) of opposite signs.
template <class F>
ld bisect(F&& f, ld a, ld b) {
  ld fa = f(a);
  for (int i = 0; i < 80; ++i) {
    const ld m = 0.5L * (a + b), fm = f(m);
    if (fm == 0) return m;
    if ((fm < 0) == (fa < 0)) a = m, fa = fm;
    else b = m;
  }
  return 0.5L * (a + b);
}

inline ld cross(cld a, cld b) { return a.real() * b.imag() - a.imag() * b.real(); }
inline ld dot(cld a, cld b) { return a.real() * b.real() + a.imag() * b.imag(); }

/// Global closest point by the dense samples, polished by bisection on (p − q)·T: (s, distance).
/// Also the smallest distance among the other local minima (the margin the test relies on).
struct RefClosest {
  ld s, d, second;
};
inline RefClosest reference_closest(const RefCurve& r, cld q) {
  const auto& S = r.samples;
  std::vector<std::pair<ld, ld>> minima;  // (d, s)
  for (size_t i = 0; i < S.size(); ++i) {
    const ld d = std::abs(S[i].p - q);
    const bool left = i == 0 || S[i - 1].seg != S[i].seg || std::abs(S[i - 1].p - q) >= d;
    const bool right = i + 1 == S.size() || S[i + 1].seg != S[i].seg || std::abs(S[i + 1].p - q) > d;
    if (!(left && right)) continue;
    ld best_s = S[i].s, best_d = d;
    for (int side : {-1, 1}) {  // a root of g between this sample and a neighbour of its segment
      const long j = long(i) + side;
      if (j < 0 || j >= long(S.size()) || S[j].seg != S[i].seg) continue;
      const size_t k = S[i].seg;
      const auto g = [&](ld u) { return dot(r.position(k, u) - q, r.tangent(k, u)); };
      const ld a = std::min(S[i].u, S[j].u), b = std::max(S[i].u, S[j].u);
      if ((g(a) < 0) == (g(b) < 0)) continue;
      const ld u = bisect(g, a, b), dd = std::abs(r.position(k, u) - q);
      if (dd < best_d) best_d = dd, best_s = r.segs[k].s_begin + r.segs[k].scale * (u - r.segs[k].ua);
    }
    minima.push_back({best_d, best_s});
  }
  std::sort(minima.begin(), minima.end());
  RefClosest out{minima[0].second, minima[0].first, INFINITY};
  for (size_t i = 1; i < minima.size(); ++i)
    if (std::abs(minima[i].second - out.s) > 1e-6L * r.length) {
      out.second = minima[i].first;
      break;
    }
  return out;
}

// Crossings of two curves: segment intersections of the dense polylines, polished by Newton in
// long double on p_a(u) − p_b(v) = 0.
struct RefCrossing {
  double s, t;
};
inline std::vector<RefCrossing> reference_curves(const test::RefCurve& A, const test::RefCurve& B) {
  std::vector<RefCrossing> out;
  const auto& SA = A.samples;
  const auto& SB = B.samples;
  for (size_t i = 0; i + 1 < SA.size(); ++i) {
    if (SA[i].seg != SA[i + 1].seg) continue;
    for (size_t j = 0; j + 1 < SB.size(); ++j) {
      if (SB[j].seg != SB[j + 1].seg) continue;
      const cld a0 = SA[i].p, a1 = SA[i + 1].p, b0 = SB[j].p, b1 = SB[j + 1].p;
      const ld d = cross(a1 - a0, b1 - b0);
      if (d == 0) continue;
      const ld x = cross(b0 - a0, b1 - b0) / d, y = cross(b0 - a0, a1 - a0) / d;
      if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) continue;
      const size_t ka = SA[i].seg, kb = SB[j].seg;
      ld u = SA[i].u + x * (SA[i + 1].u - SA[i].u), v = SB[j].u + y * (SB[j + 1].u - SB[j].u);
      for (int it = 0; it < 20; ++it) {
        const cld F = A.position(ka, u) - B.position(kb, v);
        const cld ta = A.segs[ka].scale * A.tangent(ka, u), tb = -B.segs[kb].scale * B.tangent(kb, v);
        const ld det = cross(ta, tb);
        u += cross(-F, tb) / det;
        v += cross(ta, -F) / det;
      }
      out.push_back({double(A.segs[ka].s_begin + A.segs[ka].scale * (u - A.segs[ka].ua)),
                     double(B.segs[kb].s_begin + B.segs[kb].scale * (v - B.segs[kb].ua))});
    }
  }
  std::sort(out.begin(), out.end(), [](auto x, auto y) { return x.s < y.s; });
  std::vector<RefCrossing> merged;  // the same crossing from two neighbouring steps (a joint, a sample)
  for (const RefCrossing& x : out)
    if (merged.empty() || std::abs(x.s - merged.back().s) > 1e-9 * double(A.length) || std::abs(x.t - merged.back().t) > 1e-9 * double(A.length))
      merged.push_back(x);
  return merged;
}

}  // namespace lac::test
