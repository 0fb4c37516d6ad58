// G1 Hermite (constructions/g1_hermite.hpp) checked by code that shares nothing with the solver:
//  * every solution on the test set, at nine α, integrated end to end in quadruple precision
//    (Boost.Multiprecision cpp_bin_float_quad, Boost tanh-sinh, the law's closed forms written out
//    here again): start and end point, start and end tangent;
//  * every "no curve" answer on the set checked by a complete scan of the shapes with the
//    required turning: no sign change of the chord condition Im ∫e^{iφ} = 0 (with Re ∫ > 0) over
//    a dense grid of the shape variable, in double precision with Boost tanh-sinh.
// LAC_G1_FULL=1 runs all 2000 problems (default: every 20th for the solutions, every 25th for the
// refusals).
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <numbers>
#include <string>
#include <vector>

#include "lac/constructions/g1_hermite.hpp"
#include "tests/support/g1_problem_set.hpp"

namespace lac {
namespace {

using Quad = boost::multiprecision::cpp_bin_float_quad;
constexpr double kPi = std::numbers::pi;
constexpr double kAlphas[] = {-3, -2, -1, -0.5, 0, 0.5, 1, 2, 3};

bool full_run() {
  const char* v = std::getenv("LAC_G1_FULL");
  return v && std::string(v) == "1";
}

double wrap(double a) { return std::remainder(a, 2 * kPi); }

// The law in quadruple precision: K(q) = sgn(q)|q|^(−1/α) (α ≠ 0), σe^q (α = 0), and its
// antiderivative F (α/(α−1)|q|^((α−1)/α), log|q| at α = 1, σe^q at α = 0).
struct QuadLaw {
  Quad alpha, sigma;
  Quad K(const Quad& q) const {
    if (alpha == 0) return sigma * exp(q);
    if (q == 0) return Quad(0);
    const Quad m = pow(abs(q), -1 / alpha);
    return q < 0 ? Quad(-m) : m;
  }
  Quad F(const Quad& q) const {
    if (alpha == 0) return sigma * exp(q);
    if (alpha == 1) return log(abs(q));
    return alpha / (alpha - 1) * pow(abs(q), (alpha - 1) / alpha);
  }
};

// φ(u) − φa of a segment (q linear from qa at ua to qb at ub): ∫ K(q) du = (F(q(u)) − F(qa)) / q'.
struct QuadSegment {
  QuadLaw law;
  Quad ua, ub, qa, qb;
  Quad slope() const { return (qb - qa) / (ub - ua); }
  // From the nearer end: q at one end may be ~1e-70 of the other (α = 1 near a tangent), below
  // what qa + slope·(ub − ua) resolves even in quadruple precision.
  Quad q(const Quad& u) const { return u - ua <= ub - u ? Quad(qa + slope() * (u - ua)) : Quad(qb - slope() * (ub - u)); }
  Quad turn(const Quad& u) const {
    const Quad d = q(u) - qa;
    if (abs(d) < Quad(1e-25) * (1 + abs(qa))) return law.K((qa + q(u)) / 2) * (u - ua);
    return (law.F(q(u)) - law.F(qa)) / slope();
  }
};

// ∫_{ua}^{ub} e^{i(φ(u) − φa)} du, split at the zero of q (an inflection for α < 0).
std::complex<Quad> quad_tangent_integral(const QuadSegment& s) {
  boost::math::quadrature::tanh_sinh<Quad> ts;
  std::vector<Quad> cuts{s.ua};
  if (s.qa * s.qb < 0) cuts.push_back(s.ua - s.qa / s.slope());
  cuts.push_back(s.ub);
  Quad re = 0, im = 0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    re += ts.integrate([&](const Quad& u) { return Quad(cos(s.turn(u))); }, cuts[k], cuts[k + 1]);
    im += ts.integrate([&](const Quad& u) { return Quad(sin(s.turn(u))); }, cuts[k], cuts[k + 1]);
  }
  return {re, im};
}

// The end-to-end check of one solution: "" when it passes, else what is off.
std::string check_end_to_end(const G1HermiteProblem& p, const G1HermiteResult& r) {
  const LaSegment& seg = r.curve.segments()[0];
  const QuadSegment qs{{seg.law().alpha, seg.law().sigma}, seg.ua(), seg.ub(), seg.qa(), seg.qb()};
  const std::complex<Quad> I = quad_tangent_integral(qs);
  const Quad c = cos(Quad(seg.rotation_angle()) + seg.phi_a()), s = sin(Quad(seg.rotation_angle()) + seg.phi_a());
  const Quad ex = seg.start().real() + seg.scale() * (c * I.real() - s * I.imag());
  const Quad ey = seg.start().imag() + seg.scale() * (s * I.real() + c * I.imag());
  const double end_error = std::hypot(static_cast<double>(ex - Quad(p.p1.real())), static_cast<double>(ey - Quad(p.p1.imag())));
  const double theta_end = static_cast<double>(Quad(seg.rotation_angle()) + seg.phi_a() + qs.turn(qs.ub));
  const double angle0 = std::abs(wrap(seg.rotation_angle() + seg.phi_a() - p.theta0));
  const double angle1 = std::abs(wrap(theta_end - p.theta1));
  if (end_error <= 1e-10 && std::abs(seg.start() - p.p0) <= 1e-15 && angle0 <= 1e-10 && angle1 <= 1e-10) return "";
  return "alpha " + std::to_string(p.alpha) + " theta0 " + std::to_string(p.theta0) + " theta1 " + std::to_string(p.theta1) +
         ": end " + std::to_string(end_error) + " angles " + std::to_string(angle0) + " " + std::to_string(angle1);
}

// Beyond the test set: tangents anywhere in (−π, π), windings −1, 0, 1 (turnings up to ~3π), and α
// near the ends of the range, where the kernels' pieces turn most and the law is steepest.
TEST(G1HermiteIndependent, RandomDataWithWindingsEndToEnd) {
  constexpr double kMore[] = {-5, -0.3, -0.1, 0.1, 0.3, 1.5, 5};
  const auto angles = test::g1_problem_set(full_run() ? 2000 : 120, 20261124);
  for (double alpha : kMore) {
    std::atomic<int> checked = 0;
    std::mutex m;
    std::vector<std::string> failures;
    tbb::parallel_for(size_t{0}, angles.size(), [&](size_t i) {
      const G1HermiteProblem p{{0, 0}, 2 * angles[i].theta0, {1, 0}, 2 * angles[i].theta1, alpha};
      G1HermiteOptions o;
      o.winding = static_cast<int>(i % 3) - 1;
      const G1HermiteResult r = solve_g1_hermite(p, o);
      if (!r.usable()) return;
      ++checked;
      if (std::string f = check_end_to_end(p, r); !f.empty()) {
        std::lock_guard lock(m);
        failures.push_back(f + " winding " + std::to_string(*o.winding));
      }
    });
    EXPECT_TRUE(failures.empty()) << failures.size() << " failures, first: " << failures[0];
    EXPECT_GE(checked.load(), static_cast<int>(angles.size() / 10)) << "alpha " << alpha;  // α = 5: 15 of 120
  }
}

TEST(G1HermiteIndependent, SolutionsEndToEndInQuadruplePrecision) {
  const auto set = test::g1_problem_set();
  const size_t stride = full_run() ? 1 : 20;
  for (double alpha : kAlphas) {
    std::atomic<int> checked = 0;
    std::mutex m;
    std::vector<std::string> failures;
    tbb::parallel_for(size_t{0}, set.size() / stride, [&](size_t i) {
      const test::G1Angles a = set[i * stride];
      const G1HermiteProblem p{{0, 0}, a.theta0, {1, 0}, a.theta1, alpha};
      const G1HermiteResult r = solve_g1_hermite(p);
      if (!r.usable()) return;
      ++checked;
      if (std::string f = check_end_to_end(p, r); !f.empty()) {
        std::lock_guard lock(m);
        failures.push_back(f);
      }
    });
    EXPECT_TRUE(failures.empty()) << "alpha " << alpha << ": " << failures.size() << " failures, first: " << failures[0];
    EXPECT_GT(checked.load(), 0) << "alpha " << alpha;
    if (alpha < 0) {
      EXPECT_EQ(checked.load(), static_cast<int>(set.size() / stride)) << "alpha " << alpha << ": every problem has a curve";
    }
  }
}

// The chord condition of a shape with turning Δ from φ0 (chord along x), by tanh-sinh in double:
//   α > 0:  q̂(u) linear from ta = 1/(1 + e^(−z)) to tb = 1/(1 + e^z) (z ∈ ℝ; ta + tb = 1, each
//           without cancellation, so end-q ratios up to e^700 are reached), G(u) = ∫₀^u K(q̂),
//           φ = φ0 + Δ G(u)/G(1) (K homogeneous: scaling q̂ only rescales the turning, fixed to Δ);
//   α = 0:  κ ∝ e^{bu} (b ∈ ℝ), G(u) = (e^{bu} − 1)/b, the same φ.
// ∫₀¹ e^{iφ} is integrated in the distance v from the steep end (the smaller q̂), which tanh-sinh
// resolves down to the double range; the value is the same in either direction.
// The sign of κ is the sign of Δ (a curve without inflection turns the way its curvature points).
struct ShapeScan {
  double alpha, phi0, delta;
  std::complex<double> integral(double shape) const {
    boost::math::quadrature::tanh_sinh<double> ts;
    constexpr double tol = 1e-9;  // the sign of Im ∫ is all the scan needs
    std::function<double(double)> phi;
    if (alpha == 0) {
      const auto G = [&](double u) { return std::abs(shape) < 1e-12 ? u : std::expm1(shape * u) / shape; };
      phi = [=, p0 = phi0, d = delta](double u) { return p0 + d * G(u) / G(1); };
    } else {
      const double ta = 1 / (1 + std::exp(-shape)), tb = 1 / (1 + std::exp(shape)), slope = tb - ta;
      const bool end_steep = tb < ta;
      const double a = alpha;
      const auto F = [a](double q) { return a == 1 ? std::log(q) : a / (a - 1) * std::pow(q, (a - 1) / a); };
      const auto G = [=](double v) {  // G at u = v, or u = 1 − v when the end is steep
        if (std::abs(slope) < 1e-9) return (end_steep ? 1 - v : v) * std::pow(0.5, -1 / a);
        return (F(end_steep ? tb - slope * v : ta + slope * v) - F(ta)) / slope;
      };
      const double g1 = end_steep ? G(0) : G(1);
      phi = [=, p0 = phi0, d = delta](double v) { return p0 + d * G(v) / g1; };
    }
    return {ts.integrate([&](double v) { return std::cos(phi(v)); }, 0.0, 1.0, tol),
            ts.integrate([&](double v) { return std::sin(phi(v)); }, 0.0, 1.0, tol)};
  }
  /// The grid: α > 0, z = 700 sinh(7.25x)/sinh(7.25) at 4001 points x ∈ [−1, 1] (steps of 0.004
  /// near the arc, end-q ratios up to e^700); α = 0, b = sinh of 4001 points in [−7, 7] (|b| up to
  /// 550, κ ratios up to e^550 at the ends).
  std::vector<double> grid() const {
    std::vector<double> v;
    for (int k = 0; k <= 4000; ++k) {
      const double x = -1 + 2.0 * k / 4000;
      v.push_back(alpha == 0 ? std::sinh(7 * x) : 700 * std::sinh(7.25 * x) / std::sinh(7.25));
    }
    return v;
  }
};

/// Whether the scan finds a shape whose chord condition changes sign with Re ∫ > 0 (a curve).
bool scan_finds_a_curve(const ShapeScan& scan) {
  double prev_im = NAN, prev_re = NAN;
  for (double shape : scan.grid()) {
    const std::complex<double> I = scan.integral(shape);
    if (prev_re > 0 && I.real() > 0 && std::signbit(prev_im) != std::signbit(I.imag())) return true;
    prev_im = I.imag();
    prev_re = I.real();
  }
  return false;
}

TEST(G1HermiteIndependent, EveryRefusalConfirmedByACompleteShapeScan) {
  const auto set = test::g1_problem_set();
  const size_t stride = full_run() ? 1 : 25;
  for (double alpha : kAlphas) {
    if (alpha < 0) continue;  // every problem of the set has a curve (the test above)
    std::atomic<int> refusals = 0, solved_found = 0, solved_scanned = 0;
    std::mutex m;
    std::vector<std::string> counterexamples;
    tbb::parallel_for(size_t{0}, set.size() / stride, [&](size_t i) {
      const test::G1Angles a = set[i * stride];
      // Winding 0 (the scan's turning θ1 − θ0): the refusals of turnings of at most π.
      G1HermiteOptions w0;
      w0.winding = 0;
      const G1HermiteResult r = solve_g1_hermite({{0, 0}, a.theta0, {1, 0}, a.theta1, alpha}, w0);
      const ShapeScan scan{alpha, a.theta0, a.theta1 - a.theta0};
      if (r.usable() && i % 8 == 0) {  // the scan is not blind: it finds the curves that exist
        ++solved_scanned;
        solved_found += scan_finds_a_curve(scan);
      }
      if (r.summary.status != Status::no_solution) return;
      ++refusals;
      if (scan_finds_a_curve(scan)) {
        std::lock_guard lock(m);
        counterexamples.push_back("theta0 " + std::to_string(a.theta0) + " theta1 " + std::to_string(a.theta1));
      }
    });
    EXPECT_TRUE(counterexamples.empty()) << "alpha " << alpha << ": the scan found a curve for " << counterexamples.size()
                                         << " refusals, first: " << counterexamples[0];
    EXPECT_GT(refusals.load(), 0) << "alpha " << alpha << ": the S-shaped inputs have no curve";
    EXPECT_GT(solved_scanned.load(), 0) << "alpha " << alpha;
    EXPECT_EQ(solved_found.load(), solved_scanned.load()) << "alpha " << alpha << ": the scan missed existing curves";
  }
}

}  // namespace
}  // namespace lac
