// constructions/triangle_g1.hpp: monotonic and compound-rhythm segments from control points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "lac/constructions/triangle_g1.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

// Tolerances (relative unless stated), in one place.
constexpr double kReferenceTol = 1e-11;     // Λ, length, κ, ρc against the mpmath table
constexpr double kEndpointTol = 1e-12;      // end points, relative to the chord |a2 − a0|
constexpr double kTangentTol = 1e-12;       // end tangent directions (rad)
constexpr double kJointTol = 1e-10;         // ρ and dρ/ds at the joint (closed forms, G3)
constexpr double kJointNumericTol = 1e-6;   // the same from finite differences of the samples
constexpr double kLcgSlopeTol = 1e-4;       // LCG slope fitted to curvature recomputed from positions
constexpr double kSameCurveTol = 1e-11;     // α0 = α1 versus the monotonic segment
constexpr double kLimitTol = 1e-6;          // r = 1e-9 and r = 1 − 1e-9 versus the monotonic segment

constexpr RootMethod kSolvers[] = {RootMethod::bisection, RootMethod::secant, RootMethod::toms748, RootMethod::ceres};

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

SegmentOptions with_solver(RootMethod m) {
  SegmentOptions o;
  o.solver = m;
  return o;
}

std::string cell(const test::CsvTable& t, size_t row, const std::string& name) {
  const size_t c = t.column(name);
  return c < t.rows[row].size() ? t.rows[row][c] : std::string();
}

TEST(PlanarSegments, MatchesMpmathReferenceWithEverySolver) {
  const auto t = test::read_reference_csv("planar_segments.csv");
  ASSERT_GE(t.rows.size(), 10u);
  double worst = 0;
  std::string worst_where;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const ControlTriangle tri{{t.number(i, "x0"), t.number(i, "y0")}, {t.number(i, "x1"), t.number(i, "y1")},
                              {t.number(i, "x2"), t.number(i, "y2")}};
    const bool compound = cell(t, i, "kind") == "compound";
    for (RootMethod m : kSolvers) {
      const G1Segment g = compound ? solve_compound(tri, t.number(i, "alpha0"), t.number(i, "alpha1"), t.number(i, "r"), with_solver(m))
                                   : solve_g1(tri, t.number(i, "alpha0"), with_solver(m));
      const std::string where = cell(t, i, "name") + " / " + std::string(to_string(m));
      ASSERT_EQ(g.status, Status::ok) << where << ": " << g.message;
      std::vector<std::pair<std::string, double>> errors = {
          {"lambda0", rel(g.pieces[0].lambda, t.number(i, "lambda0"))},
          {"length", rel(g.length, t.number(i, "length"))},
          {"kappa0", rel(g.kappa0, t.number(i, "kappa0"))},
          {"kappa1", rel(g.kappa1, t.number(i, "kappa1"))}};
      if (compound) {
        errors.push_back({"lambda1", rel(g.pieces[1].lambda, t.number(i, "lambda1"))});
        errors.push_back({"rho_joint", rel(g.rho_joint, t.number(i, "rho_joint"))});
      }
      for (const auto& [what, e] : errors) {
        EXPECT_LE(e, kReferenceTol) << where << " " << what;
        if (e > worst) {
          worst = e;
          worst_where = where + " " + what;
        }
      }
    }
  }
  std::printf("  worst relative error against planar_segments.csv: %.2e (%s)\n", worst, worst_where.c_str());
}

/// Random triangles of every orientation and scale, both turning directions, both leg orders.
std::vector<ControlTriangle> random_triangles(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ControlTriangle> out;
  while (static_cast<int>(out.size()) < n) {
    const double b0 = 0.15 + 1.1 * u(rng), b2 = 0.15 + 1.1 * u(rng);  // base angles at a0 and a2
    if (b0 + b2 > 2.8) continue;
    // Triangle on the unit base: a0 = 0, a2 = 1, a1 above.
    const double h = std::sin(b0) * std::sin(b2) / std::sin(b0 + b2);
    const Point2 a1 = {h / std::tan(b0), h};
    const double scale = std::pow(10.0, -3 + 6 * u(rng));
    const Point2 rot = std::polar(scale, 2 * std::numbers::pi * u(rng));
    const Point2 shift = {100 * (u(rng) - 0.5), 100 * (u(rng) - 0.5)};
    const bool mirror = u(rng) < 0.5, swap = u(rng) < 0.5;
    auto m = [&](Point2 z) { return (mirror ? std::conj(z) : z) * rot + shift; };
    if (swap)
      out.push_back({m(1), m(a1), m(0)});
    else
      out.push_back({m(0), m(a1), m(1)});
  }
  return out;
}

TEST(PlanarSegments, EndPointsAndTangentsMetOnRandomTriangles) {
  const auto tris = random_triangles(60, 20261121);
  const double alphas[] = {-2, -1, -0.3, 0, 0.5, 1, 1.5, 2, 4};
  double worst_point = 0, worst_tangent = 0;
  int solved = 0, no_curve = 0;
  for (size_t i = 0; i < tris.size(); ++i) {
    const auto& t = tris[i];
    for (double a : alphas) {
      const bool compound = i % 2 == 1;
      const G1Segment g = compound ? solve_compound(t, a, 1.0 - 0.7 * a, 0.35) : solve_g1(t, a);
      if (g.status == Status::no_solution) {
        ++no_curve;
        EXPECT_FALSE(g.message.empty());
        continue;
      }
      ASSERT_EQ(g.status, Status::ok) << g.message;
      ++solved;
      const auto pts = sample_segment(g, 40);
      const double chord = std::abs(t.a2 - t.a0);
      worst_point = std::max({worst_point, std::abs(pts.front().position - t.a0) / chord,
                              std::abs(pts.back().position - t.a2) / chord});
      const double e0 = std::abs(std::arg(std::polar(1.0, pts.front().theta) / (t.a1 - t.a0)));
      const double e1 = std::abs(std::arg(std::polar(1.0, pts.back().theta) / (t.a2 - t.a1)));
      worst_tangent = std::max({worst_tangent, e0, e1, g.tangent_error});
      // Signed curvature: the sign of the triangle's turning, and the sample ends agree with kappa0/kappa1.
      // The samples take ρ(s), kappa0/kappa1 take ρ(θ): near the end of a θ domain (α < 1, ρ large)
      // they differ by the conditioning d log ρ/dθ = Λ ρ^(1−α) (scale-invariant: user units) times
      // a few ulps of θ, e.g. 1.7e-11 at Λρ^(1−α) = 3.7e4.
      auto end_tol = [&](bool at_b2) {
        const SegmentPiece& p = at_b2 ? g.pieces.back() : g.pieces.front();
        return 1e-12 + 1e-14 * p.lambda_user * std::pow(at_b2 ? p.rho_large : p.rho_small, 1 - p.alpha);
      };
      EXPECT_NEAR(pts.front().kappa, g.kappa0, end_tol(!g.segment0_at_a0) * std::abs(g.kappa0));
      EXPECT_NEAR(pts.back().kappa, g.kappa1, end_tol(g.segment0_at_a0) * std::abs(g.kappa1));
      EXPECT_GT(g.kappa0 * g.turning, 0);
      EXPECT_NEAR(pts.back().s, g.length, 1e-12 * g.length);
    }
  }
  std::printf("  %d solved, %d outside the drawable region; worst end point %.2e (of chord), worst tangent %.2e rad\n", solved,
              no_curve, worst_point, worst_tangent);
  EXPECT_GT(solved, 400);
  EXPECT_LE(worst_point, kEndpointTol);
  EXPECT_LE(worst_tangent, kTangentTol);
}

TEST(PlanarSegments, MirroredSwappedRotatedScaledGiveTheSameShape) {
  const ControlTriangle base{{0, 0}, {1, 0}, {2, 1}};
  const G1Segment ref = solve_compound(base, -1, 1.5, 0.4);
  ASSERT_EQ(ref.status, Status::ok);
  const double k = 37.5;
  const Point2 rot = std::polar(k, 2.1);
  const Point2 shift{-3, 8};
  auto rs = [&](Point2 z) { return z * rot + shift; };
  struct Variant {
    const char* name;
    ControlTriangle t;
    double kappa_sign;
    bool reversed;
  };
  const Variant variants[] = {
      {"rotated+scaled", {rs(base.a0), rs(base.a1), rs(base.a2)}, 1, false},
      {"mirrored", {std::conj(base.a0), std::conj(base.a1), std::conj(base.a2)}, -1, false},
      {"swapped", {base.a2, base.a1, base.a0}, -1, true},
      {"swapped+mirrored+rotated", {rs(std::conj(base.a2)), rs(std::conj(base.a1)), rs(std::conj(base.a0))}, 1, true},
  };
  for (const auto& v : variants) {
    const G1Segment g = solve_compound(v.t, -1, 1.5, 0.4);
    ASSERT_EQ(g.status, Status::ok) << v.name;
    const double scale = std::abs(v.t.a2 - v.t.a0) / std::abs(base.a2 - base.a0);
    EXPECT_LE(rel(g.length, scale * ref.length), 1e-13) << v.name;
    const double k0 = v.reversed ? ref.kappa1 : ref.kappa0, k1 = v.reversed ? ref.kappa0 : ref.kappa1;
    EXPECT_LE(rel(g.kappa0, v.kappa_sign * k0 / scale), 1e-12) << v.name;
    EXPECT_LE(rel(g.kappa1, v.kappa_sign * k1 / scale), 1e-12) << v.name;
    EXPECT_LE(rel(g.pieces[0].lambda, ref.pieces[0].lambda), 1e-12) << v.name;
    EXPECT_EQ(g.segment0_at_a0, !v.reversed) << v.name;
  }
}

TEST(PlanarSegments, JointIsG3) {
  const ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  const double cases[][3] = {{-1, 1.5, 0.4}, {1.5, -1, 0.6}, {0.5, 2, 0.3}, {2, 0.5, 0.5}, {1, -0.5, 0.5}, {0, 3, 0.5}, {3, 0, 0.2}};
  double worst = 0, worst_numeric = 0;
  for (const auto& c : cases) {
    const G1Segment g = solve_compound(t, c[0], c[1], c[2]);
    ASSERT_EQ(g.status, Status::ok) << g.message;
    const StandardForm& f = g.form;
    // Paper's construction of segment 1 (001 §4): LaCurve(α1, Λ1) with Λ1 = Λ0 ρc^(α1−α0) from
    // θs, where its ρ equals ρc. Both sides in segment 0's standard-form units.
    const LaCurve c0(c[0], f.lambda0);
    const double theta_joint = f.configuration_b ? 0.0 : f.theta0;
    const double rho_c = c0.rho_at_theta(theta_joint);
    const LaCurve c1(c[1], g.pieces[1].lambda);
    const double theta_s = c1.theta_at_log_rho(std::log(rho_c));
    const double rho_1 = c1.rho_at_theta(theta_s);
    // dρ/ds = Λ ρ^(1−α) (MATH.md §1: ds/dρ = ρ^(α−1)/Λ).
    const double d0 = f.lambda0 * std::pow(rho_c, 1 - c[0]);
    const double d1 = g.pieces[1].lambda * std::pow(rho_1, 1 - c[1]);
    worst = std::max({worst, rel(rho_1, rho_c), rel(d1, d0)});
    EXPECT_LE(rel(rho_1, rho_c), kJointTol);
    EXPECT_LE(rel(d1, d0), kJointTol);
    EXPECT_LE(rel(g.rho_joint, std::abs(f.scale_rotation) * rho_c), 1e-13);

    // From the produced samples: one-sided second-order differences of ρ(s) on both sides.
    const auto pts = sample_segment(g, 4001);
    size_t j = 0;
    while (pts[j + 1].piece == pts[0].piece) ++j;  // last sample of the first piece (the joint)
    ASSERT_LE(std::abs(pts[j].position - g.joint), 1e-12 * g.length);
    auto rho = [&](size_t k) { return 1 / std::abs(pts[k].kappa); };
    const double hl = pts[j].s - pts[j - 1].s, hr = pts[j + 2].s - pts[j + 1].s;
    const double left = (3 * rho(j) - 4 * rho(j - 1) + rho(j - 2)) / (2 * hl);
    const double right = (-3 * rho(j) + 4 * rho(j + 1) - rho(j + 2)) / (2 * hr);
    worst_numeric = std::max(worst_numeric, std::abs(left - right) / std::abs(left));
    EXPECT_LE(std::abs(left - right) / std::abs(left), kJointNumericTol);
    EXPECT_NEAR(pts[j].theta, pts[j + 1].theta - (pts[j + 1].s - pts[j].s) * pts[j].kappa, 1e-6);
  }
  std::printf("  joint: worst relative mismatch of rho and drho/ds %.2e (closed forms), %.2e (finite differences)\n", worst,
              worst_numeric);
}

/// Menger curvature of three points (signed, left positive).
double menger(Point2 p, Point2 q, Point2 r) {
  const Point2 a = q - p, b = r - q, c = r - p;
  const double cr = a.real() * b.imag() - a.imag() * b.real();
  return 2 * cr / (std::abs(a) * std::abs(b) * std::abs(c));
}

/// LCG slope of the samples of one piece from positions only: κ by Menger curvature, s by chord
/// sums, dρ/ds by central differences, least-squares slope of log(ρ ds/dρ) against log ρ.
double lcg_slope_from_positions(const std::vector<SegmentSample>& pts, int piece) {
  std::vector<Point2> p;
  for (const auto& q : pts)
    if (q.piece == piece) p.push_back(q.position);
  std::vector<double> s(p.size(), 0.0), rho(p.size(), 0.0);
  for (size_t k = 1; k < p.size(); ++k) s[k] = s[k - 1] + std::abs(p[k] - p[k - 1]);
  for (size_t k = 1; k + 1 < p.size(); ++k) rho[k] = 1 / std::abs(menger(p[k - 1], p[k], p[k + 1]));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (size_t k = 3; k + 3 < p.size(); ++k) {
    const double drho_ds = (rho[k + 1] - rho[k - 1]) / (s[k + 1] - s[k - 1]);
    const double x = std::log(rho[k]), y = std::log(rho[k] * std::abs(1 / drho_ds));
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(PlanarSegments, LcgOfEachPieceIsALineOfSlopeAlpha) {
  const ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  const double cases[][3] = {{-1, 1.5, 0.4}, {1.5, -1, 0.6}, {0.5, 2, 0.5}, {2, 0, 0.5}};
  double worst = 0;
  for (const auto& c : cases) {
    const G1Segment g = solve_compound(t, c[0], c[1], c[2]);
    ASSERT_EQ(g.status, Status::ok);
    const auto pts = sample_segment(g, 3001);
    for (int piece = 0; piece < 2; ++piece) {
      const double slope = lcg_slope_from_positions(pts, piece);
      worst = std::max(worst, std::abs(slope - c[piece]));
      EXPECT_NEAR(slope, c[piece], kLcgSlopeTol) << "alpha0 " << c[0] << " alpha1 " << c[1] << " piece " << piece;
    }
    // The monotonic segment too.
    const G1Segment m = solve_g1(t, c[0]);
    ASSERT_EQ(m.status, Status::ok);
    const double slope = lcg_slope_from_positions(sample_segment(m, 3001), 0);
    worst = std::max(worst, std::abs(slope - c[0]));
    EXPECT_NEAR(slope, c[0], kLcgSlopeTol);
  }
  std::printf("  worst |fitted LCG slope - alpha| %.2e\n", worst);
}

TEST(PlanarSegments, CompoundReducesToMonotonic) {
  const ControlTriangle tris[] = {{{0, 0}, {1, 0}, {2, 1}}, {{3, 2}, {1.5, 0.2}, {0.5, 0.9}}, {{0, 0}, {1.2, 0.3}, {2.0, 1.6}}};
  const double pairs[][2] = {{-1, 1.5}, {1.5, -1}, {0.5, 2}, {2, 0}};
  // Λ depends on where the standard form puts ρ = 1, so the pieces are compared by Λ in user
  // units (intrinsic to the curve).
  int compared = 0;
  for (const auto& t : tris) {
    for (const auto& a : pairs) {
      const G1Segment m0 = solve_g1(t, a[0]), m1 = solve_g1(t, a[1]);
      if (m0.status != Status::ok || m1.status != Status::ok) continue;  // not drawable as a monotonic segment
      ++compared;
      const G1Segment near1 = solve_compound(t, a[0], a[1], 1 - 1e-9);  // all turning in segment 0
      const G1Segment near0 = solve_compound(t, a[0], a[1], 1e-9);      // all turning in segment 1
      ASSERT_EQ(near1.status, Status::ok);
      ASSERT_EQ(near0.status, Status::ok);
      EXPECT_LE(rel(near1.length, m0.length), kLimitTol);
      EXPECT_LE(rel(near1.kappa0, m0.kappa0), kLimitTol);
      EXPECT_LE(rel(near1.kappa1, m0.kappa1), kLimitTol);
      EXPECT_LE(rel(near1.pieces[0].lambda_user, m0.pieces[0].lambda_user), kLimitTol);
      EXPECT_LE(rel(near0.length, m1.length), kLimitTol);
      EXPECT_LE(rel(near0.kappa0, m1.kappa0), kLimitTol);
      EXPECT_LE(rel(near0.kappa1, m1.kappa1), kLimitTol);
      EXPECT_LE(rel(near0.pieces[1].lambda_user, m1.pieces[0].lambda_user), kLimitTol);
      for (double r : {0.2, 0.5, 0.8}) {  // α0 = α1: the same curve for every r
        const G1Segment same = solve_compound(t, a[0], a[0], r);
        ASSERT_EQ(same.status, Status::ok);
        EXPECT_LE(rel(same.length, m0.length), kSameCurveTol);
        EXPECT_LE(rel(same.kappa0, m0.kappa0), kSameCurveTol);
        EXPECT_LE(rel(same.kappa1, m0.kappa1), kSameCurveTol);
        EXPECT_LE(rel(same.pieces[0].lambda_user, m0.pieces[0].lambda_user), kSameCurveTol);
        EXPECT_LE(rel(same.pieces[1].lambda_user, m0.pieces[0].lambda_user), kSameCurveTol);
      }
    }
  }
  EXPECT_GE(compared, 6);
}

TEST(PlanarSegments, IsoscelesTriangleGivesTheCircularArc) {
  const ControlTriangle t{{0, 0}, {1, 1}, {2, 0}};  // legs equal, turning π/2
  for (double a : {-1.0, 0.0, 2.0}) {
    const G1Segment g = solve_g1(t, a);
    ASSERT_EQ(g.status, Status::ok);
    const double radius = std::sqrt(2.0);
    EXPECT_LE(rel(g.length, radius * std::numbers::pi / 2), 1e-14);
    EXPECT_LE(rel(g.kappa0, -1 / radius), 1e-14);
    EXPECT_EQ(g.pieces[0].lambda, 0.0);
  }
}

TEST(PlanarSegments, OutsideTheDrawableRegionIsAStatus) {
  const ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  const G1Segment g = solve_g1(t, 5.0);  // α > 1: ρ reaches 0 before the start angle is large enough
  EXPECT_EQ(g.status, Status::no_solution);
  EXPECT_NE(g.message.find("drawable"), std::string::npos);
  EXPECT_TRUE(g.pieces.empty());
  EXPECT_THROW(sample_segment(g, 10), InputError);
  const G1Segment h = solve_g1({{10, 0}, {2, 0}, {0, 3}}, 3.0);
  EXPECT_EQ(h.status, Status::no_solution);
}

void expect_input_error(const std::function<void()>& f, const std::string& parameter) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << parameter;
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
  }
}

TEST(PlanarSegments, DegenerateInputThrows) {
  const double nan = std::nan("");
  expect_input_error([] { solve_g1({{0, 0}, {1, 0}, {2, 0}}, 1); }, "turning");                // collinear
  expect_input_error([] { solve_g1({{0, 0}, {1, 1e-12}, {2, 0}}, 1); }, "turning");            // nearly collinear
  expect_input_error([] { solve_g1({{0, 0}, {1, 0}, {0.5, 0}}, 1); }, "turning");              // turning = π
  expect_input_error([] { solve_g1({{0, 0}, {0, 0}, {2, 1}}, 1); }, "a1");                      // coincident
  expect_input_error([] { solve_g1({{0, 0}, {1, 0}, {1, 0}}, 1); }, "a2");
  expect_input_error([&] { solve_g1({{nan, 0}, {1, 0}, {2, 1}}, 1); }, "a0.x");
  expect_input_error([&] { solve_g1({{0, 0}, {1, 0}, {2, 1}}, nan); }, "alpha");
  expect_input_error([&] { solve_compound({{0, 0}, {1, 0}, {2, 1}}, 1, INFINITY, 0.5); }, "alpha1");
  for (double r : {0.0, 1.0, -0.1, 1.5, nan})
    expect_input_error([&] { solve_compound({{0, 0}, {1, 0}, {2, 1}}, 1, 2, r); }, "r");
  SegmentOptions o;
  o.root.max_iterations = 0;
  expect_input_error([&] { solve_g1({{0, 0}, {1, 0}, {2, 1}}, 1, o); }, "max_iterations");
}

TEST(PlanarSegments, IntegratorChoiceAgrees) {
  const ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  const G1Segment ref = solve_compound(t, -1, 1.5, 0.4);
  for (const char* name : {"gauss-kronrod", "rk45"}) {
    const G1Segment g = solve_compound(t, -1, 1.5, 0.4, SegmentOptions{}, make_quadrature(name));
    ASSERT_TRUE(usable(g.status)) << name << " " << g.message;
    EXPECT_LE(rel(g.length, ref.length), 1e-10) << name;
    EXPECT_LE(rel(g.pieces[0].lambda, ref.pieces[0].lambda), 1e-9) << name;
  }
}

}  // namespace
}  // namespace lac

namespace lac {
namespace {

// Extreme shapes (base angles down to 1e-6 rad), scales 1e±100 and α up to ±50, α near 0 and 1:
// every call ends with a status (never NaN, never an exception for valid input), and usable
// results sample to finite points.
TEST(PlanarSegments, ExtremeInputGivesAStatusNeverNaN) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const double alphas[] = {-50, -5, -1e-9, 0, 1e-9, 1 - 1e-9, 1, 1 + 1e-9, 5, 50};
  int usable_count = 0, cases = 0;
  while (cases < 600) {
    const double b0 = std::pow(10.0, -6 * u(rng)) * 3.1, b2 = std::pow(10.0, -6 * u(rng)) * 3.1;
    if (b0 + b2 >= 3.14159) continue;
    ++cases;
    const double h = std::sin(b0) * std::sin(b2) / std::sin(b0 + b2);
    const double scale = std::pow(10.0, 200 * u(rng) - 100);
    const ControlTriangle t{0, Point2{h / std::tan(b0), h} * scale, Point2{1, 0} * scale};
    const double a0 = u(rng) < 0.5 ? alphas[rng() % 10] : -3 + 7 * u(rng);
    const double a1 = u(rng) < 0.5 ? alphas[rng() % 10] : -3 + 7 * u(rng);
    const double r = std::max(1e-12, u(rng));
    const G1Segment g = cases % 2 ? solve_compound(t, a0, a1, r) : solve_g1(t, a0);
    if (!usable(g.status)) {
      EXPECT_FALSE(g.message.empty());
      continue;
    }
    ++usable_count;
    ASSERT_TRUE(std::isfinite(g.length) && std::isfinite(g.kappa0) && std::isfinite(g.kappa1));
    EXPECT_LE(g.tangent_error, 1e-6);
    for (const auto& q : sample_segment(g, 12))
      ASSERT_TRUE(std::isfinite(std::abs(q.position)) && std::isfinite(q.kappa) && std::isfinite(q.s));
  }
  std::printf("  %d extreme cases, %d usable\n", cases, usable_count);
  EXPECT_GT(usable_count, 60);
}

}  // namespace
}  // namespace lac
