// Planar LA segment (curves/planar/la_segment.hpp): closed forms against their definitions,
// positions against the mpmath reference (tests/reference/la_segment.csv: through and near
// inflections, α from −3 to 3, both signs of σ at α = 0) with every quadrature method, the
// Gauss–Legendre fast path, mirror and reversal, invalid input.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "lac/curves/planar/la_segment.hpp"
#include "lac/curves/planar/la_segment_kernel.hpp"
#include "lac/integrators/gk_tanh_sinh.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Row {
  int id;
  LaSegment seg;
  double u, s;
  std::complex<double> z;
  double theta, kappa;
};

std::vector<Row> reference_rows() {
  const auto t = test::read_reference_csv("la_segment.csv");
  std::vector<Row> rows;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    auto n = [&](const char* name) { return t.number(r, name); };
    const LaSegment seg(LaLaw{n("alpha"), n("sigma")}, n("ua"), n("ub"), n("qa"), n("qb"), n("phi_a"),
                        Placement{{n("x0"), n("y0")}, n("scale"), {n("rx"), n("ry")}});
    rows.push_back({static_cast<int>(n("id")), seg, n("u"), n("s"), {n("x"), n("y")}, n("theta"), n("kappa")});
  }
  return rows;
}

// Each reference segment once.
std::map<int, LaSegment> reference_segments() {
  std::map<int, LaSegment> segments;
  for (const Row& r : reference_rows()) segments.emplace(r.id, r.seg);
  return segments;
}

std::string describe(const Row& r) {
  const LaSegment& g = r.seg;
  char buf[200];
  std::snprintf(buf, sizeof buf, "case %d alpha %g sigma %g u [%g, %g] q %g -> %g at u = %.17g", r.id, g.law().alpha,
                g.law().sigma, g.ua(), g.ub(), g.qa(), g.qb(), r.u);
  return buf;
}

// The closed forms at the reference points: θ = arg R + φ(u), κ = K(q(u))/ℓ (mpmath from F and K).
TEST(LaSegment, ClosedFormsMatchReference) {
  const auto rows = reference_rows();
  ASSERT_GE(rows.size(), 150u);
  for (const Row& r : rows) {
    SCOPED_TRACE(describe(r));
    const double u_len = r.seg.ub() - r.seg.ua();
    EXPECT_NEAR(r.seg.theta_at(r.s), r.theta, 1e-13 * (1 + std::abs(r.theta)));
    EXPECT_NEAR(r.seg.rotation_angle() + r.seg.phi_at(r.u), r.theta, 1e-13 * (1 + std::abs(r.theta)));
    // κ = K(q): near an inflection q(u) carries a few ε·max|q| of rounding, whose K can exceed |κ|.
    const double q_rounding = 4 * kEps * std::max(std::abs(r.seg.qa()), std::abs(r.seg.qb()));
    const double kappa_rounding = std::abs(r.seg.law().kappa_of_q(q_rounding)) / r.seg.scale();
    EXPECT_NEAR(r.seg.kappa_at(r.s), r.kappa, 1e-13 * std::abs(r.kappa) + kappa_rounding);
    EXPECT_NEAR(r.seg.length(), r.seg.scale() * u_len, 0.0);
    const CurvePoint f = r.seg.frame_at(r.s);
    EXPECT_EQ(f.theta, r.seg.theta_at(r.s));
    EXPECT_EQ(f.kappa, r.seg.kappa_at(r.s));
  }
}

// θ' = κ and κ' = dκ/ds: θ(s) − θ(0) against Gauss–Kronrod on κ, dκ/ds against a central difference.
TEST(LaSegment, ClosedFormsMatchTheirDefinitions) {
  for (const auto& [id, segment] : reference_segments()) {
    SCOPED_TRACE("case " + std::to_string(id));
    const LaSegment& seg = segment;  // a reference, not a structured binding: lambdas capture it (clang 14)
    const double L = seg.length();
    for (double f : {0.3, 0.7, 1.0}) {
      const double s = f * L;
      // Pieces graded toward both ends of the segment, where κ of small |α| lives in slivers
      // (cases 40, 41) that one adaptive call over [0, s] bisects past.
      std::vector<double> cuts{0.0, s};
      for (int k = 1; k <= 40; ++k)
        for (double c : {std::ldexp(L, -k), L - std::ldexp(L, -k)})
          if (c > 0 && c < s) cuts.push_back(c);
      std::sort(cuts.begin(), cuts.end());
      double turn = 0, turn_error = 0;
      for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const auto part = GaussKronrod{}.integrate([&](double x) { return seg.kappa_at(x); }, cuts[k], cuts[k + 1]);
        turn += part.value;
        turn_error += part.error_estimate;
      }
      const double want = seg.theta_at(s) - seg.theta_at(0.0);
      EXPECT_NEAR(turn, want, 1e-12 * (1 + std::abs(want)) + 2 * turn_error);
      if (f < 1.0) {
        const double h = 1e-5 * L;
        const double fd = (seg.kappa_at(s + h) - seg.kappa_at(s - h)) / (2 * h);
        EXPECT_NEAR(seg.dkappa_ds_at(s), fd, 1e-6 * (std::abs(fd) + std::abs(seg.kappa_at(s)) / L));
      }
    }
    EXPECT_EQ(seg.kappa_start(), seg.kappa_at(0.0));
    EXPECT_EQ(seg.kappa_end(), seg.kappa_at(L));
    EXPECT_EQ(seg.theta_end(), seg.theta_at(L));
  }
}

template <class M>
void check_method(const char* name, const M& method, double tolerance) {
  double worst = 0, worst_ratio = 0;
  long evaluations = 0;
  for (const Row& r : reference_rows()) {
    SCOPED_TRACE(std::string(name) + " " + describe(r));
    const LaSegment& seg = r.seg;
    const double length = seg.length();
    const auto I = integrate_tangent(seg, seg.ua(), r.u, method);
    ASSERT_EQ(I.status, Status::ok) << I.message;
    const std::complex<double> z = seg.start() + (seg.scale() * seg.rotation()) * I.value;
    const double err = std::abs(z - r.z) / length;
    worst = std::max(worst, err);
    EXPECT_LE(err, tolerance);
    // The estimate bounds the true error (to the rounding of the reference's inputs).
    EXPECT_LE(std::abs(z - r.z), 2 * seg.scale() * I.error_estimate + 4 * kEps * (length + std::abs(r.z)));
    worst_ratio = std::max(worst_ratio, std::abs(z - r.z) / (seg.scale() * I.error_estimate));
    evaluations += I.evaluations;
    // position_at at s agrees to the rounding of u = ua + s/ℓ.
    const PositionResult p = position_at(seg, r.s, method);
    ASSERT_TRUE(usable(p.status)) << p.message;
    EXPECT_LE(std::abs(p.point.position - r.z) / length, tolerance + 1e-14);
  }
  std::printf("%-16s worst position error %.2e of the length, worst error/estimate %.2f, %ld evaluations\n", name,
              worst, worst_ratio, evaluations);
}

TEST(LaSegment, PositionsMatchReferenceWithEveryMethod) {
  // The fast path is at 1e-15 except next to a zero of q outside the segment for α > 0 (κ ~ |q|^(−1/α)
  // grows toward it; no graded substitution there): 1.5e-11 on case 37, within its estimate.
  check_method("gauss-legendre", GaussLegendre{}, 1e-10);
  check_method("gauss-kronrod", GaussKronrod{}, 1e-14);
  check_method("rk45", Rk45{}, 1e-11);
  check_method("rk4 h=1e-4", Rk4{.h = 1e-4}, 1e-5);
  check_method("gk-tanh-sinh", GkTanhSinh{}, 1e-13);
}

TEST(LaSegment, TanhSinhReferenceMatchesReference) {
  for (const Row& r : reference_rows()) {
    SCOPED_TRACE(describe(r));
    const auto I = integrate_tangent_reference(r.seg, r.seg.ua(), r.u);
    const std::complex<double> z = r.seg.start() + (r.seg.scale() * r.seg.rotation()) * I;
    EXPECT_LE(std::abs(z - r.z) / r.seg.length(), 1e-13);
  }
}

// The GaussLegendre path is the segment kernel (la_segment_kernel.hpp) bit for bit where it
// evaluates the segment, else the graded fast kernel, on the whole segment and on a part starting at ua.
TEST(LaSegment, GaussLegendrePathIsTheKernel) {
  int by_kernel = 0;
  for (const Row& r : reference_rows()) {
    SCOPED_TRACE(describe(r));
    const LaSegment& seg = r.seg;
    const detail::LinearQ part{seg.ua(), r.u, seg.qa(), seg.q_at(r.u), seg.phi_a()};
    for (const detail::LinearQ& q : {seg.normalized(), part}) {
      long evaluations = 0;
      const auto got = integrate_tangent(seg, q.ua, q.ub, GaussLegendre{});
      if (const auto kernel = segment_integral(seg.law(), q, evaluations)) {
        EXPECT_EQ(got.value, kernel->value);
        EXPECT_EQ(got.evaluations, evaluations);
        ++by_kernel;
      } else {
        EXPECT_EQ(got.value, detail::integrate_tangent(seg.law(), q, evaluations));
      }
    }
  }
  EXPECT_GT(by_kernel, 0);
}

// Mirror image: q → −q, φ → −φ (σ → −σ): the tangent integral is the exact conjugate.
TEST(LaSegment, MirrorIsExact) {
  for (const Row& r : reference_rows()) {
    SCOPED_TRACE(describe(r));
    const LaSegment m = r.seg.mirrored();
    EXPECT_EQ(integrate_tangent(m, m.ua(), r.u, GaussLegendre{}).value,
              std::conj(integrate_tangent(r.seg, r.seg.ua(), r.u, GaussLegendre{}).value));
    EXPECT_EQ(m.kappa_at(r.s), -r.seg.kappa_at(r.s));
    EXPECT_EQ(m.phi_at(r.u), -r.seg.phi_at(r.u));
    EXPECT_EQ(m.mirrored().qa(), r.seg.qa());
  }
}

// Reversal: the same points, traversed from the end: κ → −κ, θ → θ + π.
TEST(LaSegment, ReversalTraversesTheSameCurve) {
  for (const auto& [id, seg] : reference_segments()) {
    SCOPED_TRACE("case " + std::to_string(id));
    const double L = seg.length();
    const auto end = position_at(seg, L, GaussKronrod{});
    const LaSegment rev = seg.reversed(end.point.position);
    EXPECT_NEAR(rev.length(), L, 4 * kEps * L);
    for (double f : {0.0, 0.25, 0.6, 1.0}) {
      const double s = f * L;
      const auto a = position_at(seg, L - s, GaussKronrod{});
      const auto b = position_at(rev, s, GaussKronrod{});
      EXPECT_LE(std::abs(a.point.position - b.point.position), 1e-13 * (L + std::abs(a.point.position)));
      EXPECT_NEAR(rev.kappa_at(s), -seg.kappa_at(L - s), 1e-13 * std::abs(seg.kappa_at(L - s)) + 1e-300);
      EXPECT_NEAR(std::remainder(rev.theta_at(s) - seg.theta_at(L - s) - std::numbers::pi, 2 * std::numbers::pi), 0.0,
                  1e-13 * (1 + std::abs(seg.theta_at(L - s))));
    }
    const LaSegment back = rev.reversed(seg.start());
    EXPECT_EQ(back.qa(), seg.qa());
    EXPECT_EQ(back.qb(), seg.qb());
    EXPECT_EQ(back.law().sigma, seg.law().sigma);
    EXPECT_EQ(back.start(), seg.start());
  }
}

TEST(LaSegment, InflectionArcLength) {
  const LaSegment through(LaLaw{-2.0}, 0.0, 1.0, 1.0, -3.0, 0.0, Placement{{}, 2.0, {1, 0}});
  ASSERT_TRUE(through.inflection_s());
  EXPECT_DOUBLE_EQ(*through.inflection_s(), 0.5);
  EXPECT_EQ(through.kappa_at(0.5), 0.0);
  EXPECT_FALSE(LaSegment(LaLaw{-2.0}, 0.0, 1.0, 1.0, 3.0, 0.0).inflection_s());
  EXPECT_FALSE(LaSegment(LaLaw{2.0}, 0.0, 1.0, 1.0, 3.0, 0.0).inflection_s());
  EXPECT_FALSE(LaSegment(LaLaw{0.0, -1.0}, 0.0, 1.0, 1.0, -3.0, 0.0).inflection_s());
  EXPECT_EQ(*LaSegment(LaLaw{-1.0}, 0.0, 1.0, 0.0, 3.0, 0.0).inflection_s(), 0.0);
  EXPECT_EQ(*LaSegment(LaLaw{-1.0}, 0.0, 1.0, 2.0, 0.0, 0.0, Placement{{}, 3.0, {1, 0}}).inflection_s(), 3.0);
}

// A piece turning beyond 1024 rad: GaussLegendre reports max_iterations (no NaN position); an
// adaptive method gets through by parts of at most 64 rad.
TEST(LaSegment, TurningCapOfTheFastPath) {
  const LaSegment spiral(LaLaw{0.0, 1.0}, 0.0, 1.0, 9.5, 0.0, 0.0);  // κ̃ from e^9.5: ~1400 rad
  ASSERT_GT(spiral.turning(), detail::kMaxResolvedTurning);
  const auto gl = position_at(spiral, 1.0, GaussLegendre{});
  EXPECT_EQ(gl.status, Status::max_iterations);
  EXPECT_EQ(gl.point.position, spiral.start());
  EXPECT_TRUE(std::isinf(gl.error_estimate));
  const auto rk45 = position_at(spiral, 1.0, Rk45{});
  const auto gk = position_at(spiral, 1.0, GaussKronrod{.tol = 1e-10});
  EXPECT_EQ(rk45.status, Status::ok) << rk45.message;
  EXPECT_EQ(gk.status, Status::ok) << gk.message;
  EXPECT_LE(std::abs(rk45.point.position - gk.point.position), 1e-10);
}

template <class Fn>
void expect_input_error(Fn&& fn, const std::string& parameter) {
  try {
    fn();
    ADD_FAILURE() << "no InputError for " << parameter;
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
  }
}

TEST(LaSegment, InvalidInputNamesTheParameter) {
  const double nan = std::nan("");
  expect_input_error([&] { LaSegment(LaLaw{nan}, 0, 1, 1, 2, 0); }, "alpha");
  expect_input_error([] { LaSegment(LaLaw{0.0, 0.5}, 0, 1, 1, 2, 0); }, "sigma");
  expect_input_error([] { LaSegment(LaLaw{-1.0}, 1, 1, 1, 2, 0); }, "ub");
  expect_input_error([&] { LaSegment(LaLaw{-1.0}, 0, 1, nan, 2, 0); }, "qa");
  expect_input_error([] { LaSegment(LaLaw{2.0}, 0, 1, 1, -2, 0); }, "qb");  // α > 0: q keeps its sign
  expect_input_error([] { LaSegment(LaLaw{2.0}, 0, 1, 0, 2, 0); }, "qb");
  expect_input_error([] { LaSegment(LaLaw{-1.0}, 0, 1, 1, 2, INFINITY); }, "phi_a");
  expect_input_error([] { LaSegment(LaLaw{-1.0}, 0, 1, 1, 2, 0, Placement{{}, 0.0, {1, 0}}); }, "scale");
  expect_input_error([] { LaSegment(LaLaw{-1.0}, 0, 1, 1, 2, 0, Placement{{}, 1.0, {1, 1}}); }, "rotation");
  expect_input_error([] { LaSegment(LaLaw{-1.0}, 0, 1, 1, 2, 0, Placement{{INFINITY, 0}, 1.0, {1, 0}}); }, "start.x");
  const LaSegment seg(LaLaw{-1.0}, 0, 1, 1, 2, 0, Placement{{}, 2.0, {1, 0}});
  expect_input_error([&] { seg.frame_at(2.5); }, "s");
  expect_input_error([&] { position_at(seg, -0.1); }, "s");
  expect_input_error([&] { integrate_tangent(seg, 0.0, 1.5, GaussKronrod{}); }, "u1");
}

}  // namespace
}  // namespace lac

namespace lac {
namespace {

// The offset form (la_law.hpp) at α = ±1e-12 is the α = 0 segment to rounding: same q (log|κ| to
// rounding), κ, θ and positions; the plain form at that α holds log|κ| only to ε/|α|.
TEST(LaSegment, OffsetFormIsContinuousThroughAlphaZero) {
  const double qa = std::log(3.0), qb = std::log(0.2);
  const LaSegment zero(LaLaw{0.0, 1.0}, 0.0, 1.0, qa, qb, 0.3);
  for (double alpha : {1e-12, -1e-12, 1e-9, -1e-9}) {
    const LaLaw law{alpha, 1.0, true};
    const LaSegment seg(law, 0.0, 1.0, law.q_of_kappa(3.0), law.q_of_kappa(0.2), 0.3);
    const double tol = 1e-13 + 10 * std::abs(alpha);
    for (double s : {0.0, 0.25, 0.5, 1.0}) {
      EXPECT_NEAR(seg.kappa_at(s), zero.kappa_at(s), tol * 3) << alpha << " " << s;
      EXPECT_NEAR(seg.theta_at(s), zero.theta_at(s), tol) << alpha << " " << s;
      EXPECT_LE(std::abs(position_at(seg, s).point.position - position_at(zero, s).point.position), tol) << alpha << " " << s;
    }
  }
}

// The Gauss–Legendre path's error estimate bounds its actual error (against tanh-sinh) on segments
// near and through an inflection for small |α| < 0 (plain form) and on offset-form segments, and an
// ok status means the value is within its tolerance.
TEST(LaSegment, ErrorEstimateBoundsTheErrorForSmallAlpha) {
  int checked = 0;
  for (double alpha : {-0.3, -0.1, -0.05}) {
    for (double qa : {-1.0, -0.3, 0.2, 0.9}) {
      for (double qb : {-0.8, 0.5, 1.0}) {
        const LaSegment seg(LaLaw{alpha}, 0.0, 1.0, qa, qb, 0.1);
        const auto r = integrate_tangent(seg, 0.0, 1.0, GaussLegendre{});
        const auto ref = integrate_tangent_reference(seg, 0.0, 1.0);
        if (!usable(r.status) || !std::isfinite(ref.real())) continue;
        ++checked;
        const double err = std::abs(r.value - ref);
        EXPECT_LE(err, r.error_estimate + 1e-13) << alpha << " " << qa << " " << qb << " " << to_string(r.status);
      }
    }
  }
  for (double alpha : {-0.01, -1e-6, 1e-6, 0.01}) {
    const LaLaw law{alpha, 1.0, true};
    for (double la : {-2.0, 0.5, 2.0})  // turning ≤ ~10 rad: tanh-sinh (the reference) misses at ~100 rad
      for (double lb : {-5.0, 1.0, 3.0}) {
        const LaSegment seg(law, 0.0, 1.0, law.q_of_kappa(std::exp(la)), law.q_of_kappa(std::exp(lb)), -0.2);
        const auto r = integrate_tangent(seg, 0.0, 1.0, GaussLegendre{});
        const auto ref = integrate_tangent_reference(seg, 0.0, 1.0);
        ASSERT_TRUE(usable(r.status)) << r.message;
        ++checked;
        EXPECT_LE(std::abs(r.value - ref), r.error_estimate + 1e-13) << alpha << " " << la << " " << lb;
        EXPECT_LE(std::abs(r.value - ref), 1e-12) << alpha << " " << la << " " << lb;
      }
  }
  EXPECT_GE(checked, 40);
}

}  // namespace
}  // namespace lac
