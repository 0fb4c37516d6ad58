// Continuity in α of G1 and G2 Hermite through α = 0 and the special kernels (α = −1, 0, 1, 2):
// at α = k ± 10^−m (m = 3 … 12) the result is usable, meets its end conditions by an independent
// integration (Boost tanh-sinh in u, not the construction's kernel), and its length and end
// curvatures differ from the α = k solution by at most C·10^−m. For G2 the printed segments also
// meet in θ at the joints by an independent integration of κ(s) (Gauss–Kronrod).
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/curves/planar/la_segment.hpp"

namespace lac {
namespace {

constexpr double kEndTol = 1e-9;      // end position (chord units), angles (rad), curvature × chord
constexpr double kJointTol = 1e-9;    // θ at the joints of G2 answers (rad)
constexpr double kSlope = 50;         // C: |d(length, κ·chord)/dα| ≤ C·max(1, |value|) on these problems
constexpr double kFloor = 1e-11;      // the solves' own rounding (tolerance 1e-13 on f / residuals)

const int kSpecial[] = {-1, 0, 1, 2};

double wrap(double a) { return std::remainder(a, 2 * std::numbers::pi); }

// End point of a placed curve by tanh-sinh on every segment (independent of the construction's kernel).
std::complex<double> reference_end(const PlanarCurve& c) {
  std::complex<double> end = c.segments().front().start();
  for (const LaSegment& s : c.segments())
    end += s.scale() * s.rotation() * integrate_tangent_reference(s, s.ua(), s.ub());
  return end;
}

// θ at the end of a segment: θ at its start plus ∫κ ds by Gauss–Kronrod (not the law's F).
double integrated_theta_end(const LaSegment& s) {
  double err = 0;
  const double turn = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      [&](double x) { return s.kappa_at(std::min(x, s.length())); }, 0.0, s.length(), 12, 1e-14, &err);
  return s.theta_start() + turn;
}

struct Values {
  double length, kappa0, kappa1;
};

std::vector<double> alphas_near(int k) {
  std::vector<double> out;
  for (int m = 3; m <= 12; ++m) {
    out.push_back(k + std::pow(10.0, -m));
    out.push_back(k - std::pow(10.0, -m));
  }
  return out;
}

struct G1Case {
  std::complex<double> p0, p1;
  double theta0, theta1;
};

Values check_g1(const G1Case& c, double alpha) {
  const G1HermiteResult r = solve_g1_hermite({c.p0, c.theta0, c.p1, c.theta1, alpha});
  const std::string at = "alpha = " + std::to_string(alpha);
  EXPECT_TRUE(r.usable()) << at << ": " << to_string(r.summary.status) << " " << r.summary.message;
  if (!r.usable()) return {NAN, NAN, NAN};
  const double chord = std::abs(c.p1 - c.p0);
  EXPECT_LE(std::abs(reference_end(r.curve) - c.p1) / chord, kEndTol) << at;
  EXPECT_LE(std::abs(wrap(r.curve.theta_at(0) - c.theta0)), kEndTol) << at;
  EXPECT_LE(std::abs(wrap(r.curve.theta_at(r.curve.length()) - c.theta1)), kEndTol) << at;
  // θ(L) − θ(0) also by integrating κ (the closed-form turning is the law's F).
  const LaSegment& s = r.curve.segments().front();
  EXPECT_NEAR(integrated_theta_end(s), s.theta_end(), kJointTol) << at;
  return {r.curve.length() / chord, r.curve.kappa_at(0) * chord, r.curve.kappa_at(r.curve.length()) * chord};
}

TEST(AlphaContinuity, G1HermiteThroughZeroAndTheSpecialKernels) {
  // Convex data (tangents on opposite sides of the chord, |turning| < π): a curve for every α in
  // [−1, 2] (α > 1: the chord lies between the limit curves' end directions).
  const std::vector<G1Case> cases = {{{0, 0}, {1, 0}, 0.5, -0.3}, {{0, 0}, {1, 0}, 0.4, -0.7}, {{0, 0}, {1, 0}, 0.8, -0.5},
                                     {{1, 2}, {3.5, 1}, 0.1, -1.1}};
  for (const G1Case& c : cases) {
    for (int k : kSpecial) {
      const Values base = check_g1(c, k);
      ASSERT_TRUE(std::isfinite(base.length)) << "alpha = " << k;
      for (double alpha : alphas_near(k)) {
        const Values v = check_g1(c, alpha);
        const auto bound = [&](double value) { return (kSlope * std::abs(alpha - k) + kFloor) * std::max(1.0, std::abs(value)); };
        EXPECT_LE(std::abs(v.length - base.length), bound(base.length)) << "alpha = " << alpha;
        EXPECT_LE(std::abs(v.kappa0 - base.kappa0), bound(base.kappa0)) << "alpha = " << alpha;
        EXPECT_LE(std::abs(v.kappa1 - base.kappa1), bound(base.kappa1)) << "alpha = " << alpha;
      }
    }
  }
}

Values check_g2(const G2Problem& pr) {
  const G2Result r = solve_g2(pr);
  const std::string at = "alpha = " + std::to_string(pr.alpha);
  EXPECT_TRUE(r.usable()) << at << ": " << to_string(r.summary.status) << " " << r.summary.message;
  if (!r.usable()) return {NAN, NAN, NAN};
  const double chord = std::abs(pr.end.position - pr.start.position);
  const PlanarCurve& c = r.curve;
  EXPECT_LE(std::abs(reference_end(c) - pr.end.position) / chord, kEndTol) << at;
  EXPECT_LE(std::abs(wrap(c.theta_at(0) - pr.start.theta)), kEndTol) << at;
  EXPECT_LE(std::abs(wrap(c.theta_at(c.length()) - pr.end.theta)), kEndTol) << at;
  EXPECT_LE(std::abs(c.kappa_at(0) - pr.start.kappa) * chord, kEndTol) << at;
  EXPECT_LE(std::abs(c.kappa_at(c.length()) - pr.end.kappa) * chord, kEndTol) << at;
  // The LA law at the joints: κ continuous, and θ at the end of each segment (θ at its start plus
  // ∫κ ds) equal to θ at the start of the next.
  const auto& segs = c.segments();
  for (size_t j = 0; j < segs.size(); ++j) {
    const double theta_end = integrated_theta_end(segs[j]);
    const double next = j + 1 < segs.size() ? segs[j + 1].theta_start() : pr.end.theta;
    EXPECT_LE(std::abs(wrap(theta_end - next)), kJointTol) << at << ", joint " << j;
    if (j + 1 < segs.size()) {
      EXPECT_LE(std::abs(segs[j].kappa_end() - segs[j + 1].kappa_start()) * chord, kEndTol) << at << ", joint " << j;
    }
  }
  return {c.length() / chord, c.kappa_at(0) * chord, c.kappa_at(c.length()) * chord};
}

TEST(AlphaContinuity, G2HermiteThroughZeroAndTheSpecialKernels) {
  // The first is the reproducer (main: not_converged at α = 1e-9, 1e-12, joints off by 1e-6 …
  // 1e-4 rad near α = 0). κ of one sign and turning of that sign: a triple for α ≥ 0 too.
  const std::vector<G2Problem> cases = {
      {{{0, 0}, 0.0, 1.0}, {{1.5, 1}, 1.2, 0.5}, 0},
      {{{0, 0}, 0.4, -0.8}, {{2, 0}, -0.5, -0.3}, 0},
  };
  for (G2Problem pr : cases) {
    for (int k : kSpecial) {
      pr.alpha = k;
      const Values base = check_g2(pr);
      ASSERT_TRUE(std::isfinite(base.length)) << "alpha = " << k;
      for (double alpha : alphas_near(k)) {
        pr.alpha = alpha;
        const Values v = check_g2(pr);
        const auto bound = [&](double value) { return (kSlope * std::abs(alpha - k) + kFloor) * std::max(1.0, std::abs(value)); };
        EXPECT_LE(std::abs(v.length - base.length), bound(base.length)) << "alpha = " << alpha;
        EXPECT_LE(std::abs(v.kappa0 - base.kappa0), bound(base.kappa0)) << "alpha = " << alpha;
        EXPECT_LE(std::abs(v.kappa1 - base.kappa1), bound(base.kappa1)) << "alpha = " << alpha;
      }
    }
  }
}

}  // namespace
}  // namespace lac
