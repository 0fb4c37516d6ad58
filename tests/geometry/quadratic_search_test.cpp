// geometry/closest_point and intersect_line on arcs of quadratic LA curves (003). Closest point:
// the global minimum of the distance
// over random curves (both signs of γ, through the inflection or not) and spirals turning up to
// 40 rad, with random query points, points near the evolute and points on the arc, against an
// independent computation: dense sampling of the arc (positions by the curve's own
// Gauss–Kronrod evaluator at tolerance 1e-15, chained sample to sample) and Brent polishing of
// every sampled local minimum (positions integrated from the sample before it).
// Lines: every sign change of the signed distance between the same samples, polished by TOMS 748,
// against the list of crossings (random lines, and lines through the arc's points that cross a
// spiral many times).
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

#include "lac/curves/quadratic/quadratic_position.hpp"
#include <boost/math/tools/toms748_solve.hpp>

#include "lac/geometry/closest_point.hpp"
#include "lac/geometry/intersections.hpp"
#include "lac/geometry/transforms.hpp"
#include "curves.hpp"
#include "reference_curve.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/lcg.hpp"

namespace lac {
namespace {

using cplx = std::complex<double>;

using test::Lcg;

const GaussKronrod kTight{1e-15, 500};

struct Sample {
  double s;
  cplx p;
};

// The reference: samples of the arc, then Brent on |p(s) − q|² around each sampled local minimum.
struct Reference {
  const QuadraticLaCurve& c;
  std::vector<Sample> samples;
  // Samples at most L/n apart and turning at most 0.02 rad each (denser where κ is large, e.g.
  // the tight coils of a spiral), each position integrated from the one before; the first one
  // marched the same way from s = 0 (position 0).
  Reference(const QuadraticLaCurve& curve, double s0, double s1, int n) : c(curve) {
    const double h = (s1 - s0) / n;
    const auto step_from = [&](double s, double toward) {
      const double dir = toward > s ? 1.0 : -1.0;
      double step = std::min(h, 0.02 / std::abs(c.kappa_at_s(s)));
      while (std::abs(toward - s) > step && std::abs(c.kappa_at_s(s + dir * step)) * step > 0.02) step *= 0.5;
      return std::abs(toward - s) <= step ? toward : s + dir * step;
    };
    const auto advance = [&](double s, double next) {
      const auto I = detail::integrate_quadratic(c, kTight, s, next, 1'000'000);
      EXPECT_TRUE(usable(I.status)) << I.message;
      return I.value;
    };
    Sample x{0.0, {0.0, 0.0}};
    for (int i = 0; i < 1'000'000 && x.s != s0; ++i) {
      const double next = step_from(x.s, s0);
      x = {next, x.p + advance(x.s, next)};
    }
    samples.push_back(x);
    while (samples.back().s < s1 && samples.size() < 1'000'000) {
      const double next = step_from(samples.back().s, s1);
      samples.push_back({next, samples.back().p + advance(samples.back().s, next)});
    }
  }
  // p(s) from the sample at or below s.
  cplx position(double s) const {
    const auto it = std::upper_bound(samples.begin(), samples.end(), s, [](double x, const Sample& y) { return x < y.s; });
    return at(it == samples.begin() ? 0 : static_cast<size_t>(it - samples.begin()) - 1, s);
  }
  cplx at(size_t i, double s) const {
    const auto I = detail::integrate_quadratic(c, kTight, samples[i].s, s, 1'000'000);
    return samples[i].p + I.value;
  }
  // {distance, s} of the global minimum.
  std::pair<double, double> closest(cplx q) const {
    const size_t n = samples.size();
    std::pair<double, double> best{std::abs(samples[0].p - q), samples[0].s};
    for (size_t i = 0; i < n; ++i) {
      const double d = std::abs(samples[i].p - q);
      if (d < best.first) best = {d, samples[i].s};
      const bool local = (i == 0 || d <= std::abs(samples[i - 1].p - q)) && (i + 1 == n || d <= std::abs(samples[i + 1].p - q));
      if (!local) continue;
      const size_t lo = i == 0 ? 0 : i - 1, hi = std::min(n - 1, i + 1);
      // In t = s − s_lo: Brent's tolerance is relative to |t|, so a minimum near the sample is
      // resolved however large |s| is.
      const double base = samples[lo].s;
      const auto f = [&](double t) { return std::norm(at(lo, base + t) - q); };
      std::uintmax_t it = 200;
      const auto m = boost::math::tools::brent_find_minima(f, 0.0, samples[hi].s - base, 60, it);
      const double dm = std::sqrt(m.second);
      if (dm < best.first) best = {dm, base + m.first};
    }
    return best;
  }
};

// s in (s_lo, s_hi) where θ(s) − θ(s_ref) reaches ±turn (bisection on the closed form), or the
// fraction `keep` of the way to the domain's end when the turning there stays below turn.
double reach(const QuadraticLaCurve& c, double s_ref, double end, double turn) {
  const double t0 = c.theta_at_s(s_ref);
  double a = s_ref, b = s_ref + 0.999 * (end - s_ref);
  if (!std::isfinite(b) || std::abs(b) > 200) b = end > s_ref ? 200 : -200;
  for (int i = 0; i < 200 && std::abs(c.theta_at_s(b) - t0) > turn; ++i) {
    const double m = 0.5 * (a + b);
    if (std::abs(c.theta_at_s(m) - t0) > turn) b = m;
    else a = m;
  }
  return b;
}

// A random arc: every third a spiral (γ > 0, turning 15–45 rad), the others a random part of the
// default range of a random curve (through the inflection or not); within |s| <= 200 (redrawn
// otherwise: for small |γ| the default range can reach 1e22)
struct Arc {
  QuadraticLaCurve c;
  double s0, s1;
  bool spiral;
};

Arc draw_arc(Lcg& rng, bool spiral) {
  QuadraticOptions o;
  double alpha = 0, gamma = 0, lambda = 1, s0 = 0, s1 = 0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    o.through_inflection = !spiral && rng.next() < 0.5;
    alpha = rng.in(-3, 3), gamma = spiral ? rng.in(0.02, 0.3) : rng.in(-0.5, 0.5), lambda = rng.in(0.3, 3);
    const QuadraticLaCurve trial(alpha, gamma, lambda, o);
    if (spiral) {
      const double turn = rng.in(15, 45), side = rng.next();
      s0 = reach(trial, 0.0, trial.s_domain().lo, side * turn);
      s1 = reach(trial, 0.0, trial.s_domain().hi, (1 - side) * turn);
    } else {
      const Interval r = trial.default_range();
      const double x = rng.in(0, 0.4), y = rng.in(0.6, 1);
      s0 = r.lo + x * (r.hi - r.lo);
      s1 = r.lo + y * (r.hi - r.lo);
    }
    // and |κ| <= 1e4 (where a sample step of 0.02 rad is still many ulps of s).
    if (std::max(std::abs(s0), std::abs(s1)) <= 200 &&
        std::max(std::abs(trial.kappa_at_s(s0)), std::abs(trial.kappa_at_s(s1))) <= 1e4)
      break;
  }
  return {QuadraticLaCurve(alpha, gamma, lambda, o), s0, s1, spiral};
}

TEST(GeometryQuadraticClosestPoint, GlobalMinimumMatchesDenseReference) {
  Lcg rng;
  int checked = 0, spirals = 0, through = 0, ok = 0, several = 0;
  double worst = 0, worst_ratio = 0, most_turning = 0;
  long spans = 0, most_spans = 0;
  for (int curve_index = 0; curve_index < 48; ++curve_index) {
    const bool spiral = curve_index % 3 == 0;
    const Arc arc = draw_arc(rng, spiral);
    const QuadraticLaCurve& c = arc.c;
    const double s0 = arc.s0, s1 = arc.s1, alpha = c.alpha(), gamma = c.gamma();
    const QuadraticOptions& o = c.options();
    const double turning = std::abs(c.theta_at_s(s1) - c.theta_at_s(s0));
    if (o.through_inflection && c.has_inflection() && s0 < c.s_at_zero_kappa() && s1 > c.s_at_zero_kappa()) ++through;
    most_turning = std::max(most_turning, turning);
    const int n = 1000;
    const Reference ref(c, s0, s1, n);
    const double L = s1 - s0;
    cplx lo = ref.samples[0].p, hi = lo;
    for (const Sample& x : ref.samples)
      lo = {std::min(lo.real(), x.p.real()), std::min(lo.imag(), x.p.imag())},
      hi = {std::max(hi.real(), x.p.real()), std::max(hi.imag(), x.p.imag())};
    const cplx box = hi - lo;
    std::vector<cplx> queries;
    for (int i = 0; i < 3; ++i)
      queries.push_back(lo - 0.2 * box + cplx(1.4 * box.real() * rng.next(), 1.4 * box.imag() * rng.next()));
    {  // near the evolute and on the arc
      const size_t i = static_cast<size_t>(rng.in(0.1, 0.9) * double(ref.samples.size()));
      const double s = ref.samples[i].s, k = c.kappa_at_s(s);
      const cplx N = cplx(0, 1) * std::polar(1.0, c.theta_at_s(s));
      if (std::abs(k) > 1e-3 / L) queries.push_back(ref.samples[i].p + (1 + 1e-3) / k * N);
      queries.push_back(ref.samples[i].p);
    }
    spirals += spiral;
    for (const cplx q : queries) {
      const ClosestPoint r = closest_point(c, s0, s1, q);
      ASSERT_TRUE(usable(r.status)) << r.message << " alpha " << alpha << " gamma " << gamma << " [" << s0 << ", " << s1 << "]";
      ok += r.status == Status::ok;
      const auto [d_ref, s_ref] = ref.closest(q);
      const double dd = std::abs(r.distance - d_ref);
      // The reference's own rounding: positions of size up to |p| ~ max(|s0|, |s1|) from s = 0.
      const double slack = 1e-13 * std::max({L, std::abs(s0), std::abs(s1)});
      EXPECT_LE(dd, r.error_estimate + slack) << "alpha " << alpha << " gamma " << gamma << " query " << q << " d " << r.distance
                                           << " d_ref " << d_ref << " s " << r.s << " s_ref " << s_ref << " [" << s0 << ", " << s1 << "]";
      EXPECT_LE(dd, 1e-9 * L) << "query " << q;
      EXPECT_GE(r.s, s0);
      EXPECT_LE(r.s, s1);
      // The reported point is the curve's at r.s.
      EXPECT_LE(std::abs(ref.position(r.s) - r.point), 1e-10 * L + slack);
      EXPECT_NEAR(std::abs(r.point - q), r.distance, 1e-14 * L + slack);
      worst = std::max(worst, dd / L);
      if (r.error_estimate > 0) worst_ratio = std::max(worst_ratio, dd / r.error_estimate);
      spans += r.spans, most_spans = std::max(most_spans, r.spans);
      several += std::abs(s_ref - r.s) > 0.01 * L || turning > 6.3;
      ++checked;
    }
  }
  EXPECT_EQ(spirals, 16);
  EXPECT_GE(through, 3);
  EXPECT_GE(most_turning, 30.0);
  EXPECT_GE(ok, checked * 9 / 10);
  std::printf("quadratic closest point: %d queries on 48 arcs (%d spirals, %d through the inflection, most turning %.1f rad), "
              "%d ok; worst |d - d_ref|/L = %.2e, worst |d - d_ref|/error_estimate = %.2e; spans %.0f mean, %ld most\n",
              checked, spirals, through, most_turning, ok, worst, worst_ratio, double(spans) / checked, most_spans);
  (void)several;
}

TEST(GeometryQuadraticIntersectLine, AllCrossingsMatchTheDenseReference) {
  Lcg rng;
  rng.x = 24680;
  int lines = 0, total = 0, most = 0, spirals = 0;
  double worst = 0;
  for (int curve_index = 0; curve_index < 24; ++curve_index) {
    const Arc arc = draw_arc(rng, curve_index % 3 == 0);
    spirals += arc.spiral;
    const QuadraticLaCurve& c = arc.c;
    const double L = arc.s1 - arc.s0;
    const Reference ref(c, arc.s0, arc.s1, 1000);
    const size_t n = ref.samples.size();
    for (int li = 0; li < 4; ++li) {
      // Line 0: through the centre of curvature at the arc's more curved end (across the windings
      // of a spiral); the others through random points near the arc.
      const size_t end = std::abs(c.kappa_at_s(arc.s0)) > std::abs(c.kappa_at_s(arc.s1)) ? 0 : n - 1;
      const size_t pick = li == 0 ? end : static_cast<size_t>(rng.in(0, 1) * double(n - 1));
      const double ks = c.kappa_at_s(ref.samples[pick].s);
      const cplx P = ref.samples[pick].p + (li == 0 ? cplx(0, 1) * std::polar(1.0, c.theta_at_s(ref.samples[pick].s)) / ks
                                                    : cplx(rng.in(-0.01, 0.01), rng.in(-0.01, 0.01)) * L);
      const cplx D = std::polar(1.0, rng.in(0, 6.283185307179586));
      const auto h = [&](cplx p) { return D.real() * (p - P).imag() - D.imag() * (p - P).real(); };
      std::vector<double> expected;
      for (size_t i = 0; i + 1 < n; ++i) {
        const double a = h(ref.samples[i].p), b = h(ref.samples[i + 1].p);
        if (a == 0) expected.push_back(ref.samples[i].s);
        if (!((a < 0 && b > 0) || (a > 0 && b < 0))) continue;
        const double base = ref.samples[i].s;
        const auto f = [&](double t) { return h(ref.at(i, base + t)); };
        std::uintmax_t it = 200;
        const auto r = boost::math::tools::toms748_solve(f, 0.0, ref.samples[i + 1].s - base, a, b,
                                                         boost::math::tools::eps_tolerance<double>(50), it);
        expected.push_back(base + 0.5 * (r.first + r.second));
      }
      const Intersections x = intersect_line(c, arc.s0, arc.s1, P, D);
      ASSERT_TRUE(usable(x.status)) << x.message;
      // Sampling can miss a pair of crossings closer than the sample spacing (and a touch): the
      // library's list holds the reference's, and its extra points come in such close pairs or touches.
      size_t j = 0;
      for (const double se : expected) {
        while (j < x.points.size() && x.points[j].s < se - 1e-7 * L) ++j;
        ASSERT_LT(j, x.points.size()) << "crossing at s = " << se << " missing";
        EXPECT_NEAR(x.points[j].s, se, 1e-7 * L);
        worst = std::max(worst, std::abs(x.points[j].s - se) / L);
        EXPECT_LE(std::abs(h(x.points[j].point)), x.points[j].error_estimate + 1e-12 * L);
        ++j;
      }
      EXPECT_LE(x.points.size(), expected.size() + 2) << "extra points";
      for (size_t i = 1; i < x.points.size(); ++i) EXPECT_LT(x.points[i - 1].s, x.points[i].s);
      total += static_cast<int>(expected.size());
      most = std::max(most, static_cast<int>(expected.size()));
      ++lines;
    }
  }
  EXPECT_EQ(spirals, 8);
  EXPECT_GE(most, 8);
  std::printf("quadratic intersect_line: %d lines on 24 arcs, %d crossings (most %d on one line); worst |s - s_ref|/L = %.2e\n",
              lines, total, most, worst);
}

TEST(GeometryQuadraticIntersectCurves, CrossingsWithAPlanarCurveMatchTheDenseReference) {
  // Arcs against the test curves (curves.hpp) scaled and moved onto the arc's bounding box; the
  // reference: crossings of the arc's samples with the long-double model's polyline
  // (reference_curve.hpp), polished by Newton on both references' positions.
  Lcg rng;
  rng.x = 13579;
  const std::vector<PlanarCurve> others = test::test_curves();
  int pairs = 0, total = 0;
  double worst = 0;
  for (int index = 0; index < 18; ++index) {
    const Arc arc = draw_arc(rng, index % 3 == 0);
    const QuadraticLaCurve& c = arc.c;
    const double L = arc.s1 - arc.s0;
    const Reference ref(c, arc.s0, arc.s1, 1000);
    cplx lo = ref.samples[0].p, hi = lo;
    for (const Sample& x : ref.samples)
      lo = {std::min(lo.real(), x.p.real()), std::min(lo.imag(), x.p.imag())},
      hi = {std::max(hi.real(), x.p.real()), std::max(hi.imag(), x.p.imag())};
    const PlanarCurve& o = others[static_cast<size_t>(index) % others.size()];
    const BoundingBox ob = o.bounding_box();
    const double k = std::abs(hi - lo) / std::abs(ob.hi - ob.lo);
    const PlanarCurve b = translated(scaled(o, k, {0, 0}), 0.5 * (lo + hi) - 0.5 * k * (ob.lo + ob.hi));
    const test::RefCurve rb(b, 500);
    std::vector<std::pair<double, double>> expected;
    for (size_t i = 0; i + 1 < ref.samples.size(); ++i) {
      const cplx a0 = ref.samples[i].p, a1 = ref.samples[i + 1].p;
      for (size_t j = 0; j + 1 < rb.samples.size(); ++j) {
        if (rb.samples[j].seg != rb.samples[j + 1].seg) continue;
        const cplx b0(double(rb.samples[j].p.real()), double(rb.samples[j].p.imag()));
        const cplx b1(double(rb.samples[j + 1].p.real()), double(rb.samples[j + 1].p.imag()));
        const auto cr = [](cplx x, cplx y) { return x.real() * y.imag() - x.imag() * y.real(); };
        const double d = cr(a1 - a0, b1 - b0);
        if (d == 0) continue;
        const double x = cr(b0 - a0, b1 - b0) / d, y = cr(b0 - a0, a1 - a0) / d;
        if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) continue;
        const size_t kb = rb.samples[j].seg;
        const auto& g = rb.segs[kb];
        double s = ref.samples[i].s + x * (ref.samples[i + 1].s - ref.samples[i].s);
        test::ld u = rb.samples[j].u + y * (rb.samples[j + 1].u - rb.samples[j].u);
        for (int it = 0; it < 20; ++it) {
          const test::cld pb = rb.position(kb, u), tb = -g.scale * rb.tangent(kb, u);
          const cplx F = ref.at(i, s) - cplx(double(pb.real()), double(pb.imag()));
          const cplx ta = std::polar(1.0, c.theta_at_s(s)), tbd(double(tb.real()), double(tb.imag()));
          const double det = cr(ta, tbd);
          s += cr(-F, tbd) / det;
          u += cr(ta, -F) / det;
        }
        expected.push_back({s, double(g.s_begin + g.scale * (u - g.ua))});
      }
    }
    std::sort(expected.begin(), expected.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& e : expected)
      if (merged.empty() || std::abs(e.first - merged.back().first) > 1e-9 * L) merged.push_back(e);
    const Intersections r = intersect_curves(c, arc.s0, arc.s1, b);
    ASSERT_TRUE(usable(r.status)) << r.message;
    ASSERT_EQ(r.points.size(), merged.size()) << "arc " << index;
    for (size_t i = 0; i < merged.size(); ++i) {
      EXPECT_NEAR(r.points[i].s, merged[i].first, 1e-9 * L);
      EXPECT_NEAR(r.points[i].t, merged[i].second, 1e-9 * b.length());
      worst = std::max(worst, std::abs(r.points[i].s - merged[i].first) / L);
    }
    total += static_cast<int>(merged.size());
    ++pairs;
  }
  EXPECT_GE(total, 20);
  std::printf("quadratic intersect_curves: %d arc/curve pairs, %d crossings; worst |s - s_ref|/L = %.2e\n", pairs, total, worst);
}

TEST(GeometryQuadraticIntersectCurves, CrossingsOfTwoArcsMatchTheDenseReference) {
  // Two random arcs (two of three pairs two spirals; every third pair two spirals of nearby
  // parameters, whose coils cross many times). Every quadratic LA curve passes through the origin
  // at s = 0 along the x axis with κ = 1, so two arcs near s = 0 osculate there: b's arc is kept
  // away from s = 0, so the pairs cross transversally. The
  // reference: crossings of the two sample polylines, polished by Newton on both references'
  // positions.
  Lcg rng;
  rng.x = 97531;
  int pairs = 0, total = 0, most = 0, touches = 0;
  double worst = 0;
  const auto cr = [](cplx x, cplx y) { return x.real() * y.imag() - x.imag() * y.real(); };
  for (int index = 0; index < 36; ++index) {
    const Arc a = draw_arc(rng, index % 3 != 2);
    Arc b = draw_arc(rng, index % 3 != 2);
    if (index % 3 == 0) {  // a spiral beside a's: its parameters within 20 %, its inner coils (s < 0)
      const QuadraticLaCurve& c = a.c;
      const QuadraticLaCurve near(c.alpha() * rng.in(0.8, 1.2), c.gamma() * rng.in(0.8, 1.2), c.lambda() * rng.in(0.8, 1.2));
      // Its arc ends at 0.3 s0, away from s = 0, where the two curves osculate (equal κ).
      const double s0 = reach(near, 0.0, near.s_domain().lo, rng.in(10, 30));
      if (s0 < -0.05) b = {near, s0, 0.3 * s0, true};
    }
    // b's arc keeps a distance gap from s = 0, on its side s < 0 where it can (there κ grows: the
    // coils of a spiral); a pair whose b is too short for that is skipped.
    const double gap = std::max(0.05 * (b.s1 - b.s0), 0.05);
    if (b.s0 < gap && b.s1 > -gap) {
      if (b.s0 < -2 * gap) b.s1 = -gap;
      else if (b.s1 > 2 * gap) b.s0 = gap;
      else continue;
    }
    const double La = a.s1 - a.s0, Lb = b.s1 - b.s0;
    const Reference ra(a.c, a.s0, a.s1, 1000), rb(b.c, b.s0, b.s1, 1000);
    std::vector<std::pair<double, double>> expected;
    for (size_t i = 0; i + 1 < ra.samples.size(); ++i) {
      const cplx a0 = ra.samples[i].p, a1 = ra.samples[i + 1].p;
      for (size_t j = 0; j + 1 < rb.samples.size(); ++j) {
        const cplx b0 = rb.samples[j].p, b1 = rb.samples[j + 1].p;
        const double d = cr(a1 - a0, b1 - b0);
        if (d == 0) continue;
        const double x = cr(b0 - a0, b1 - b0) / d, y = cr(b0 - a0, a1 - a0) / d;
        if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) continue;
        double s = ra.samples[i].s + x * (ra.samples[i + 1].s - ra.samples[i].s);
        double t = rb.samples[j].s + y * (rb.samples[j + 1].s - rb.samples[j].s);
        for (int it = 0; it < 20; ++it) {
          const cplx F = ra.at(i, s) - rb.at(j, t);
          const cplx ta = std::polar(1.0, a.c.theta_at_s(s)), tb = -std::polar(1.0, b.c.theta_at_s(t));
          const double det = cr(ta, tb);
          s += cr(-F, tb) / det;
          t += cr(ta, -F) / det;
        }
        // Where the arcs run within a sample's sagitta of each other their polylines can cross
        // without the arcs doing so: Newton then leaves the arcs (toward s = t = 0, where every
        // quadratic LA curve passes); such a crossing is not the arcs'.
        if (!(s >= a.s0 && s <= a.s1 && t >= b.s0 && t <= b.s1 && std::abs(ra.at(i, s) - rb.at(j, t)) <= 1e-13 * std::max(La, Lb)))
          continue;
        expected.push_back({s, t});
      }
    }
    std::sort(expected.begin(), expected.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& e : expected)
      if (merged.empty() || std::abs(e.first - merged.back().first) > 1e-9 * La) merged.push_back(e);
    const Intersections r = intersect_curves(a.c, a.s0, a.s1, b.c, b.s0, b.s1);
    ASSERT_TRUE(usable(r.status)) << r.message;
    // Every reference crossing is found; an extra point may only be a touch within the tolerance
    // (the arcs of nearby spirals can run within tolerance × max(a1 − a0, b1 − b0) of each other).
    std::vector<bool> matched(r.points.size(), false);
    for (const auto& [se, te] : merged) {
      size_t k = 0;
      while (k < r.points.size() && std::abs(r.points[k].s - se) > 1e-9 * La) ++k;
      ASSERT_LT(k, r.points.size()) << "pair " << index << ": crossing at s = " << se << ", t = " << te << " missing";
      matched[k] = true;
      EXPECT_NEAR(r.points[k].t, te, 1e-9 * Lb) << "pair " << index;
      EXPECT_LE(std::abs(r.points[k].point - ra.position(se)), 1e-9 * std::max(La, Lb));
      worst = std::max(worst, std::abs(r.points[k].s - se) / La);
    }
    for (size_t k = 0; k < r.points.size(); ++k) {
      if (matched[k]) continue;
      const Intersection& x = r.points[k];
      ++touches;
      EXPECT_EQ(x.kind, IntersectionKind::tangent) << "pair " << index << ": extra crossing at s = " << x.s;
      EXPECT_LE(std::abs(ra.position(x.s) - rb.position(x.t)), 1e-10 * std::max(La, Lb) + x.error_estimate)
          << "pair " << index << ": extra point at s = " << x.s << " is not within the tolerance";
    }
    total += static_cast<int>(merged.size());
    most = std::max(most, static_cast<int>(merged.size()));
    ++pairs;
  }
  // The draw (fixed seed) gives 45 crossings, up to 11 on a pair (nearby spirals).
  EXPECT_GE(total, 40);
  EXPECT_GE(most, 8);
  std::printf("quadratic x quadratic intersect_curves: %d arc pairs, %d crossings (most %d), %d touches within the "
              "tolerance; worst |s - s_ref|/L = %.2e\n", pairs, total, most, touches, worst);
}

TEST(GeometryQuadraticIntersectCurves, ArcsOutsideTheDomainAreInputErrors) {
  const QuadraticLaCurve a(-1.0, -0.3, 1.0), b(0.5, 0.2, 1.0);
  const Interval r = a.default_range(), q = b.default_range();
  EXPECT_EQ(test::thrown_parameter([&] { intersect_curves(a, r.hi, r.lo, b, q.lo, q.hi); }), "a1");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_curves(a, r.lo, r.hi, b, q.lo, q.lo); }), "b1");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_curves(a, r.lo, r.hi, b, q.lo, std::nan("")); }), "b1");
}

TEST(GeometryQuadraticClosestPoint, CapsEndWithAStatus) {
  // An arc turning about 28.6 rad needs 58 spans of 0.5 rad: more than max_spans = 16 (no hang,
  // a status that is not usable).
  const QuadraticLaCurve c(0.5, 0.2, 1.0);
  ASSERT_GT(std::abs(c.theta_at_s(3.0) - c.theta_at_s(-3.0)), 28.0);
  GeometryOptions o;
  o.max_spans = 16;
  const ClosestPoint r = closest_point(c, -3.0, 3.0, {0.1, 0.05}, o);
  EXPECT_EQ(r.status, Status::max_iterations);
  EXPECT_NE(r.message.find("max_spans"), std::string::npos) << r.message;
  EXPECT_FALSE(usable(r.status));
  // The line's cap counts monotonic pieces (about 28.6/π here) and points: max_points = 1 of several.
  GeometryOptions one;
  one.max_points = 1;
  ASSERT_GE(intersect_line(c, -3.0, 3.0, {0.1, 0.1}, {1.0, 0.3}).points.size(), 2u);
  const Intersections x = intersect_line(c, -3.0, 3.0, {0.1, 0.1}, {1.0, 0.3}, one);
  EXPECT_EQ(x.status, Status::max_iterations) << x.message;
  EXPECT_NE(x.message.find("max_points"), std::string::npos) << x.message;
  // With the default cap both are ok.
  EXPECT_EQ(closest_point(c, -3.0, 3.0, {0.1, 0.05}).status, Status::ok);
  EXPECT_EQ(intersect_line(c, -3.0, 3.0, {0.1, 0.1}, {1.0, 0.3}).status, Status::ok);
}

TEST(GeometryQuadraticClosestPoint, BadInput) {
  const QuadraticLaCurve c(-1.0, -0.3, 1.0);
  const Interval r = c.default_range();
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, r.lo, r.hi, {NAN, 0}); }), "query");
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, r.hi, r.lo, {0, 0}); }), "s1");
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, c.s_domain().lo - 1, r.hi, {0, 0}); }), "s0");
  GeometryOptions bad;
  bad.tolerance = 0;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, r.lo, r.hi, {0, 0}, bad); }), "tolerance");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_line(c, r.lo, r.hi, {0, 0}, {0, 0}); }), "direction");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_line(c, r.lo, r.hi, {NAN, 0}, {1, 0}); }), "point");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_line(c, r.hi, r.lo, {0, 0}, {1, 0}); }), "s1");
}

}  // namespace
}  // namespace lac
