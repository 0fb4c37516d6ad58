// Conversions between LA segments and the standard form (curves/planar/standard_form.hpp):
// round trips, positions through the conversion (quadrature and the igf closed form), the 001 use
// (a LaCurve over a θ interval plus a similarity, mirrored, reversed, compound).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "lac/curves/planar/la_position.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/planar/standard_form.hpp"
#include "lac/integrators/igf.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

constexpr double kPi = std::numbers::pi;

double angle_difference(double a, double b) { return std::remainder(a - b, 2 * kPi); }

std::map<int, LaSegment> reference_segments() {
  const auto t = test::read_reference_csv("la_segment.csv");
  std::map<int, LaSegment> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    auto n = [&](const char* name) { return t.number(r, name); };
    out.emplace(static_cast<int>(n("id")),
                LaSegment(LaLaw{n("alpha"), n("sigma")}, n("ua"), n("ub"), n("qa"), n("qb"), n("phi_a"),
                          Placement{{n("x0"), n("y0")}, n("scale"), {n("rx"), n("ry")}}));
  }
  return out;
}

TEST(Similarity, CompositionAndInverse) {
  const Similarity a{std::polar(2.0, 0.3), {1, -2}, true}, b{std::polar(0.5, -1.1), {0.25, 3}, false};
  for (const std::complex<double> z : {std::complex<double>{0.3, 0.7}, {-2, 5}}) {
    EXPECT_LT(std::abs(a.after(b)(z) - a(b(z))), 1e-14);
    EXPECT_LT(std::abs(b.after(a)(z) - b(a(z))), 1e-14);
    EXPECT_LT(std::abs(a.inverse()(a(z)) - z), 1e-14);
    EXPECT_LT(std::abs(b.inverse()(b(z)) - z), 1e-14);
  }
}

// Segment → standard pieces → segments describes the same curve: κ, θ (mod 2π) and positions at
// the same points; the closed form igf_position_delta through the conversion gives the positions
// too (pieces are anchored at s = 0, so C(θ) − C(0) places a point).
TEST(StandardForm, SegmentRoundTripAndIgfPositions) {
  int pieces_checked = 0, igf_points = 0;
  double worst_igf = 0;
  for (const auto& [id, seg] : reference_segments()) {
    SCOPED_TRACE("case " + std::to_string(id));
    const double L = seg.length();
    const auto end = position_at(seg, L, GaussKronrod{});
    ASSERT_EQ(end.status, Status::ok);
    const auto pieces = to_standard_pieces(seg, end.point.position);
    const auto inflection = seg.inflection_u();
    const bool split = inflection && *inflection > seg.ua() && *inflection < seg.ub();
    ASSERT_EQ(pieces.size(), split ? 2u : 1u);
    double s_lo = 0;  // user arc length where the piece starts
    for (const StandardPiece& piece : pieces) {
      EXPECT_EQ(piece.curve.alpha(), seg.law().alpha);
      EXPECT_TRUE(piece.from == 0 || piece.to == 0);  // anchored at an end
      // The standard position at `from`: 0 at the anchor, else back through the similarity.
      const auto p_from = position_at(seg, s_lo, GaussKronrod{});
      const std::complex<double> c_from = piece.from == 0 ? std::complex<double>{} : piece.to_user.inverse()(p_from.point.position);
      const LaSegment back = to_segment(piece, c_from);
      EXPECT_LT(std::abs(back.start() - p_from.point.position), 1e-13 * (L + std::abs(p_from.point.position)));
      for (double f : {0.0, 0.3, 0.75, 1.0}) {
        const double s = f * back.length();
        const double s_orig = std::min(L, s_lo + s);
        // Near an inflection κ = K(q) moves by K(a few ε·max|q|) with the rounding of q.
        const double q_rounding = 8 * std::numeric_limits<double>::epsilon() * std::max(std::abs(seg.qa()), std::abs(seg.qb()));
        const double kappa_rounding = std::abs(seg.law().kappa_of_q(q_rounding)) / seg.scale();
        EXPECT_NEAR(back.kappa_at(s), seg.kappa_at(s_orig), 1e-12 * std::abs(seg.kappa_at(s_orig)) + kappa_rounding);
        EXPECT_NEAR(angle_difference(back.theta_at(s), seg.theta_at(s_orig)), 0.0, 1e-12 * (1 + std::abs(seg.theta_at(s_orig))));
        const auto a = position_at(back, s, GaussKronrod{}), b = position_at(seg, s_orig, GaussKronrod{});
        EXPECT_LT(std::abs(a.point.position - b.point.position), 1e-12 * (L + std::abs(b.point.position)));
        // igf: C(θ) − C(0) of the standard form, strictly inside its domain.
        const double s_std = piece.from + (piece.to - piece.from) * f;
        if (f == 0.0 || f == 1.0) continue;
        const double theta = piece.curve.theta_at_s(s_std);
        // θ as the parameter is ill-conditioned where ρ is huge (the straight middle of the small-|α|
        // S of cases 40 and 41, θ next to θ_max): the rounding of θ alone moves s by ρ·ε|θ|.
        if (piece.curve.log_rho_at_s(s_std) + std::log(4 * std::numeric_limits<double>::epsilon() * (1 + std::abs(theta))) >
            std::log(1e-13 * L))
          continue;
        const auto closed = igf_position_delta(piece.curve.alpha(), piece.curve.lambda(), 0.0, theta);
        ASSERT_TRUE(usable(closed.status)) << closed.message;
        const double e = std::abs(piece.to_user(closed.value) - b.point.position) / L;
        worst_igf = std::max(worst_igf, e);
        EXPECT_LT(e, 1e-11);
        ++igf_points;
      }
      s_lo += back.length();
      ++pieces_checked;
    }
    EXPECT_NEAR(s_lo, L, 1e-13 * L);
  }
  std::printf("round trips of %d standard pieces; igf through the conversion at %d points, worst %.2e of the length\n",
              pieces_checked, igf_points, worst_igf);
}

// The piece of 001: LaCurve(α, Λ) over a θ interval, placed by a similarity (mirrored or not), in
// either direction, one end possibly at the inflection; and back to a standard piece.
TEST(StandardForm, PieceToSegmentAndBack) {
  struct Case {
    double alpha, lambda, from, to;
  };
  const Similarity placements[] = {{std::polar(2.5, 0.7), {1, -2}, false}, {std::polar(0.3, -2.0), {-4, 0.5}, true}};
  int checked = 0;
  for (const Case& k : {Case{-1.5, 0.8, 0.0, 0.4}, Case{-1.5, 0.8, 0.0, 0.5}, Case{-1.5, 0.8, 0.5, -0.3}, Case{0.0, 1.2, -0.6, 0.8},
                        Case{0.5, 2.0, 0.0, 0.45}, Case{1.0, 0.7, 1.2, 0.0}, Case{2.0, 1.0, -0.4, 1.5}, Case{3.0, 0.25, 0.0, 2.0},
                        Case{-0.5, 0.0, 0.0, 2.0}}) {
    for (const Similarity& sim : placements) {
      SCOPED_TRACE("alpha " + std::to_string(k.alpha) + " lambda " + std::to_string(k.lambda) + " theta " +
                   std::to_string(k.from) + " -> " + std::to_string(k.to) + (sim.mirror ? " mirrored" : ""));
      const LaCurve c(k.alpha, k.lambda);
      const bool to_inflection = k.alpha < 0 && k.lambda > 0 && k.to == c.theta_domain().hi;
      const bool from_inflection = k.alpha < 0 && k.lambda > 0 && k.from == c.theta_domain().hi;
      const std::complex<double> c_from =
          from_inflection ? position_at(c, Parameter::s, std::nextafter(c.s_domain().hi, 0.0), GaussKronrod{}).point.position
          : k.from == 0   ? std::complex<double>{}
                          : position_at(c, Parameter::theta, k.from, GaussKronrod{}).point.position;
      const StandardPiece piece{c, Parameter::theta, k.from, k.to, sim};
      const LaSegment seg = to_segment(piece, c_from);
      const auto [s_from, s_to] = s_range(piece);
      const double ell = std::abs(sim.factor);
      EXPECT_NEAR(seg.length(), ell * std::abs(s_to - s_from), 1e-15 * seg.length());
      const double dir = k.to > k.from ? 1.0 : -1.0, mirror = sim.mirror ? -1.0 : 1.0;
      if (to_inflection) EXPECT_EQ(seg.kappa_end(), 0.0);
      if (from_inflection) EXPECT_EQ(seg.kappa_start(), 0.0);
      for (double f : {0.1, 0.5, 0.9}) {
        const double theta = k.from + (k.to - k.from) * f;
        const CurvePoint q = c.frame_at(Parameter::theta, theta);
        const double s_user = ell * std::abs(q.s - s_from);
        const auto got = position_at(seg, s_user, GaussKronrod{});
        const auto want = position_at(c, Parameter::theta, theta, GaussKronrod{});
        EXPECT_LT(std::abs(got.point.position - sim(want.point.position)), 1e-12 * (seg.length() + std::abs(got.point.position)));
        EXPECT_NEAR(seg.kappa_at(s_user), dir * mirror * q.kappa / ell, 1e-12 * q.kappa / ell);
        const double theta_user = std::arg(sim.factor) + mirror * theta + (dir < 0 ? kPi : 0.0);
        EXPECT_NEAR(angle_difference(seg.theta_at(s_user), theta_user), 0.0, 1e-12 * (1 + std::abs(theta)));
      }
      // Back: one standard piece (the segment has no inflection inside), the same curve.
      const auto end = position_at(seg, seg.length(), GaussKronrod{});
      const auto back = to_standard_pieces(seg, end.point.position);
      ASSERT_EQ(back.size(), 1u);
      EXPECT_EQ(back[0].curve.alpha(), k.alpha);
      const LaSegment again =
          to_segment(back[0], back[0].from == 0 ? std::complex<double>{} : back[0].to_user.inverse()(seg.start()));
      EXPECT_NEAR(again.length(), seg.length(), 1e-13 * seg.length());
      for (double f : {0.2, 0.7}) {
        const double s = f * seg.length();
        EXPECT_NEAR(again.kappa_at(s), seg.kappa_at(s), 1e-12 * std::abs(seg.kappa_at(s)));
        EXPECT_LT(std::abs(position_at(again, s, GaussKronrod{}).point.position - position_at(seg, s, GaussKronrod{}).point.position),
                  1e-12 * (seg.length() + std::abs(seg.start())));
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 18);
}

// 001's compound curve from two standard pieces: segment 1 in its own standard form at the joint,
// scaled by ρc (Λ1' = Λ0 ρc^(1−α0)), composed with the similarity onto the user's plane: joined G2.
TEST(StandardForm, CompoundCurveFromStandardPiecesIsG2) {
  const double alpha0 = -0.5, alpha1 = 1.5, lambda0 = 0.6, theta0 = 0.5, theta1 = 0.4;
  const LaCurve c0(alpha0, lambda0);
  const double log_rho_c = c0.log_rho_at_theta(theta0), rho_c = std::exp(log_rho_c);
  const LaCurve c1(alpha1, lambda0 * std::exp((1.0 - alpha0) * log_rho_c));
  const std::complex<double> joint = position_at(c0, Parameter::theta, theta0, GaussKronrod{}).point.position;
  for (bool mirror : {false, true}) {
    const Similarity user{std::polar(3.0, 1.1), {2, 1}, mirror};
    const Similarity at_joint{rho_c * std::polar(1.0, theta0), joint, false};
    const LaSegment s0 = to_segment({c0, Parameter::theta, 0.0, theta0, user});
    const LaSegment s1 = to_segment({c1, Parameter::theta, 0.0, theta1, user.after(at_joint)});
    const PlanarCurve curve({s0, s1});
    const auto joints = curve.joints(GaussKronrod{});
    ASSERT_EQ(joints.size(), 1u);
    EXPECT_LT(joints[0].position_gap, 1e-14 * curve.length());
    EXPECT_LT(std::abs(joints[0].angle_gap), 1e-15);
    EXPECT_LT(std::abs(joints[0].curvature_gap), 1e-15 * std::abs(s0.kappa_end()));
    EXPECT_NEAR(joints[0].s, s0.length(), 0.0);
  }
}

TEST(StandardForm, InvalidInput) {
  const LaCurve c(-1.5, 0.8);
  EXPECT_THROW(to_segment({c, Parameter::theta, 0.0, 0.0, {}}), InputError);    // empty
  EXPECT_THROW(to_segment({c, Parameter::theta, 0.0, 0.6, {}}), InputError);    // beyond the domain
  EXPECT_THROW(to_segment({c, Parameter::theta, 0.0, 0.3, {{0, 0}, {}, false}}), InputError);  // factor 0
  const LaSegment through(LaLaw{-1.0}, 0.0, 1.0, 1.0, -1.0, 0.0);
  try {
    to_standard_pieces(through);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "end_point");
  }
  EXPECT_THROW(to_standard_pieces(LaSegment(LaLaw{-1.0}, 0.0, 1.0, 0.0, 0.0, 0.0)), InputError);  // straight
}

}  // namespace
}  // namespace lac
