// geometry/closest_point on arcs of quadratic LA curves (003): the global minimum of the distance
// over random curves (both signs of γ, through the inflection or not) and spirals turning up to
// 40 rad, with random query points, points near the evolute and points on the arc, against an
// independent computation: dense sampling of the arc (positions by the curve's own
// Gauss–Kronrod evaluator at tolerance 1e-15, chained sample to sample) and Brent polishing of
// every sampled local minimum (positions integrated from the sample before it).
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/geometry/closest_point.hpp"
#include "tests/support/input_error.hpp"

namespace lac {
namespace {

using cplx = std::complex<double>;

struct Lcg {
  std::uint64_t x = 987654321;
  double next() {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(x >> 11) * 0x1.0p-53;
  }
  double in(double a, double b) { return a + (b - a) * next(); }
};

const GaussKronrod kTight{1e-15};

struct Sample {
  double s;
  cplx p;
};

// The reference: samples of the arc, then Brent on |p(s) − q|² around each sampled local minimum.
struct Reference {
  const QuadraticLaCurve& c;
  std::vector<Sample> samples;
  Reference(const QuadraticLaCurve& curve, double s0, double s1, int n) : c(curve) {
    const std::vector<PositionResult> pts = polyline(c, s0, s1, n, kTight);
    for (const PositionResult& r : pts) {
      EXPECT_TRUE(usable(r.status)) << r.message;
      samples.push_back({r.point.s, r.point.position});
    }
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

TEST(GeometryQuadraticClosestPoint, GlobalMinimumMatchesDenseReference) {
  Lcg rng;
  int checked = 0, spirals = 0, through = 0, ok = 0, several = 0;
  double worst = 0, worst_ratio = 0, most_turning = 0;
  long spans = 0, most_spans = 0;
  for (int curve_index = 0; curve_index < 48; ++curve_index) {
    const bool spiral = curve_index % 3 == 0;
    // Arcs within |s| <= 200 (redrawn otherwise: for small |γ| the default range can reach 1e22).
    QuadraticOptions o;
    double alpha = 0, gamma = 0, lambda = 1, s0 = 0, s1 = 0;
    for (int attempt = 0; attempt < 100; ++attempt) {
      o.through_inflection = !spiral && rng.next() < 0.5;
      alpha = rng.in(-3, 3), gamma = spiral ? rng.in(0.02, 0.3) : rng.in(-0.5, 0.5), lambda = rng.in(0.3, 3);
      const QuadraticLaCurve trial(alpha, gamma, lambda, o);
      if (spiral) {  // γ > 0: θ is unbounded both ways; an arc turning 10–40 rad
        const double turn = rng.in(15, 45), side = rng.next();
        s0 = reach(trial, 0.0, trial.s_domain().lo, side * turn);
        s1 = reach(trial, 0.0, trial.s_domain().hi, (1 - side) * turn);
      } else {
        const Interval r = trial.default_range();
        const double a = rng.in(0, 0.4), b = rng.in(0.6, 1);
        s0 = r.lo + a * (r.hi - r.lo);
        s1 = r.lo + b * (r.hi - r.lo);
      }
      if (std::max(std::abs(s0), std::abs(s1)) <= 200) break;
    }
    const QuadraticLaCurve c(alpha, gamma, lambda, o);
    const double turning = std::abs(c.theta_at_s(s1) - c.theta_at_s(s0));
    if (o.through_inflection && c.has_inflection() && s0 < c.s_at_zero_kappa() && s1 > c.s_at_zero_kappa()) ++through;
    most_turning = std::max(most_turning, turning);
    const int n = static_cast<int>(std::min(20000.0, 300 + 100 * turning));
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
      const PositionResult p = position_at(c, r.s, kTight);
      EXPECT_LE(std::abs(p.point.position - r.point), 1e-10 * L + slack);
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

TEST(GeometryQuadraticClosestPoint, BadInput) {
  const QuadraticLaCurve c(-1.0, -0.3, 1.0);
  const Interval r = c.default_range();
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, r.lo, r.hi, {NAN, 0}); }), "query");
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, r.hi, r.lo, {0, 0}); }), "s1");
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, c.s_domain().lo - 1, r.hi, {0, 0}); }), "s0");
  GeometryOptions bad;
  bad.tolerance = 0;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, r.lo, r.hi, {0, 0}, bad); }), "tolerance");
}

}  // namespace
}  // namespace lac
