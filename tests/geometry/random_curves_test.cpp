// geometry on random G1 chains of one to three LA segments (α ∈ {−2, −1, −0.5, 0, 0.5, 1, 2, 3},
// random q, scale and rotation, turning up to 40 rad): closest points and line intersections
// against the long-double model (reference_curve.hpp), offsets' first cusps against bisection on
// its κ.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>

#include "curves.hpp"
#include "lac/geometry/closest_point.hpp"
#include "lac/geometry/intersections.hpp"
#include "lac/geometry/offset.hpp"
#include "lac/geometry/transforms.hpp"
#include "reference_curve.hpp"

namespace lac {
namespace {

using test::cld;
using test::ld;

struct Rng {
  std::uint64_t x;
  double next() {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(x >> 11) * 0x1.0p-53;
  }
  double in(double a, double b) { return a + (b - a) * next(); }
};

PlanarCurve random_curve(Rng& r) {
  const double alphas[] = {-2, -1, -0.5, 0, 0.5, 1, 2, 3};
  for (;;) {
    const int n = 1 + int(3 * r.next());
    std::vector<test::Part> parts;
    for (int i = 0; i < n; ++i) {
      const double alpha = alphas[int(8 * r.next()) % 8];
      double qa = r.in(-3, 3), qb = r.in(-3, 3);
      if (alpha > 0) {  // one sign, away from 0 (κ = |q|^(−1/α) stays moderate)
        qa = std::copysign(r.in(0.3, 3), qa);
        qb = std::copysign(r.in(0.3, 3), qa);
      }
      parts.push_back({LaLaw{alpha, r.next() < 0.5 ? -1.0 : 1.0}, 0.0, r.in(0.5, 2), qa, qb, r.in(0.5, 3)});
    }
    const PlanarCurve c = test::chain(parts, r.in(-3, 3), {r.in(-2, 2), r.in(-2, 2)}, r.in(-3, 3));
    double turning = 0;
    for (const LaSegment& s : c.segments()) turning += std::abs(s.turning());
    if (turning <= 40 && turning >= 1) return c;
  }
}

TEST(GeometryRandom, ClosestPointsLinesAndCuspsMatchTheModel) {
  Rng r{2026};
  int curves = 0, queries = 0, crossings = 0, cusps = 0;
  double worst_d = 0, worst_s = 0;
  for (int i = 0; i < 24; ++i) {
    const PlanarCurve c = random_curve(r);
    ++curves;
    const test::RefCurve ref(c, 1000, 0.005L);
    const double L = c.length();
    const BoundingBox box = c.bounding_box();
    const std::complex<double> lo = box.lo, span = box.hi - box.lo;
    for (int j = 0; j < 6; ++j) {
      const std::complex<double> q = lo + std::complex<double>(span.real() * r.in(-0.2, 1.2), span.imag() * r.in(-0.2, 1.2));
      const ClosestPoint cp = closest_point(c, q);
      ASSERT_EQ(cp.status, Status::ok) << cp.message;
      const test::RefClosest e = test::reference_closest(ref, cld(q.real(), q.imag()));
      ++queries;
      EXPECT_NEAR(cp.distance, double(e.d), 1e-10 * L) << "curve " << i << " query " << q;
      worst_d = std::max(worst_d, std::abs(cp.distance - double(e.d)) / L);
    }
    for (int j = 0; j < 3; ++j) {
      const std::complex<double> P = lo + std::complex<double>(span.real() * r.next(), span.imag() * r.next());
      const std::complex<double> D = std::polar(1.0, r.in(0, 3.2));
      const Intersections x = intersect_line(c, P, D);
      ASSERT_EQ(x.status, Status::ok) << x.message;
      // Reference: sign changes of D × (p − P) on the dense samples, bisected.
      std::vector<double> e;
      const auto& S = ref.samples;
      const cld Pl(P.real(), P.imag()), Dl(D.real(), D.imag());
      const auto h = [&](cld p) { return test::cross(Dl, p - Pl); };
      for (size_t k = 0; k + 1 < S.size(); ++k) {
        if (S[k].seg != S[k + 1].seg) continue;
        const ld a = h(S[k].p), b = h(S[k + 1].p);
        if (!((a < 0 && b >= 0) || (a > 0 && b <= 0))) continue;
        const size_t g = S[k].seg;
        const ld u = test::bisect([&](ld v) { return h(ref.position(g, v)); }, S[k].u, S[k + 1].u);
        e.push_back(double(ref.segs[g].s_begin + ref.segs[g].scale * (u - ref.segs[g].ua)));
      }
      // A crossing exactly at a joint is one point for the library and may be two sign changes.
      std::vector<double> merged;
      for (double s : e)
        if (merged.empty() || s - merged.back() > 1e-9 * L) merged.push_back(s);
      ASSERT_EQ(x.points.size(), merged.size()) << "curve " << i << " line " << j;
      for (size_t k = 0; k < merged.size(); ++k) {
        EXPECT_NEAR(x.points[k].s, merged[k], 1e-10 * L);
        worst_s = std::max(worst_s, std::abs(x.points[k].s - merged[k]) / L);
      }
      crossings += int(merged.size());
    }
    // The first cusp of the offset at d = 1/κ(s*) for a random s*: at s* or before.
    const double s_star = r.in(0.1, 0.9) * L, k_star = c.kappa_at(s_star);
    if (std::abs(k_star) > 1e-3) {
      const double d = 1 / k_star;
      const OffsetCusp oc = first_offset_cusp(c, d);
      ASSERT_TRUE(oc.s.has_value());
      EXPECT_LE(*oc.s, s_star + 1e-12 * L);
      double first = NAN;  // bisection on the model's κ, segment by segment
      const ld sign = 1 - ld(d) * ref.segs[0].kappa(ref.segs[0].ua) > 0 ? 1 : -1;
      for (const test::RefSegment& g : ref.segs) {
        const auto f = [&](ld u) { return sign * (1 - ld(d) * g.kappa(u)); };
        if (f(g.ua) <= 0) {
          first = double(g.s_begin);
          break;
        }
        if (f(g.ub) > 0) continue;
        first = double(g.s_begin + g.scale * (test::bisect(f, g.ua, g.ub) - g.ua));
        break;
      }
      EXPECT_NEAR(*oc.s, first, 1e-11 * L) << "curve " << i;
      ++cusps;
    }
  }
  std::printf("random curves: %d curves, %d closest points (worst |Δd|/L = %.2e), %d line crossings (worst |Δs|/L = %.2e), "
              "%d cusps\n", curves, queries, worst_d, crossings, worst_s, cusps);
}

TEST(GeometryRandom, CurveCrossingsMatchTheModel) {
  Rng r{7};
  int crossings = 0;
  double worst = 0;
  for (int i = 0; i < 10; ++i) {
    const PlanarCurve a = random_curve(r);
    PlanarCurve b = random_curve(r);
    const BoundingBox ba = a.bounding_box(), bb = b.bounding_box();  // b moved over a
    b = translated(b, 0.5 * (ba.lo + ba.hi - bb.lo - bb.hi) + std::complex<double>(r.in(-0.3, 0.3), r.in(-0.3, 0.3)));
    const Intersections x = intersect_curves(a, b);
    ASSERT_EQ(x.status, Status::ok) << x.message;
    const std::vector<test::RefCrossing> e = test::reference_curves(test::RefCurve(a, 600, 0.01L), test::RefCurve(b, 600, 0.01L));
    ASSERT_EQ(x.points.size(), e.size()) << "pair " << i;
    for (size_t k = 0; k < e.size(); ++k) {
      EXPECT_NEAR(x.points[k].s, e[k].s, 1e-10 * a.length()) << "pair " << i;
      EXPECT_NEAR(x.points[k].t, e[k].t, 1e-10 * a.length()) << "pair " << i;
      worst = std::max({worst, std::abs(x.points[k].s - e[k].s) / a.length(), std::abs(x.points[k].t - e[k].t) / a.length()});
    }
    crossings += int(e.size());
  }
  EXPECT_GE(crossings, 5);
  std::printf("random curve pairs: 10 pairs, %d crossings, worst |Δs|/L = %.2e\n", crossings, worst);
}

}  // namespace
}  // namespace lac
