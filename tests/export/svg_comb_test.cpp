// write_svg with SvgOptions::comb: the comb of the cubic B-spline itself. The test reads the
// Bézier pieces and the teeth back from the SVG text and checks every tooth against the
// curvature of its piece computed here by central differences of de Casteljau's evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

#include "lac/common/error.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/export/to_bspline.hpp"
#include "lac/export/write.hpp"

namespace lac {
namespace {

using C = std::complex<double>;

/// The numbers of attribute `attr` of the element with id `id` ("" = the first path's d).
std::vector<double> numbers(const std::string& svg, const std::string& id, const std::string& attr) {
  size_t at = id.empty() ? svg.find("<path") : svg.find("id=\"" + id + "\"");
  if (at == std::string::npos) return {};
  at = svg.find(" " + attr + "=\"", at) + attr.size() + 3;
  std::string s = svg.substr(at, svg.find('"', at) - at);
  for (char& ch : s)
    if (ch == ',' || ch == 'M' || ch == 'L' || ch == 'C') ch = ' ';
  std::istringstream in(s);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

C de_casteljau(std::array<C, 4> p, double t) {
  for (int r = 3; r > 0; --r)
    for (int i = 0; i < r; ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
  return p[0];
}

TEST(ExportSvgComb, TeethAreNormalAndProportionalToTheBezierCurvature) {
  // lac g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 --alpha -0.5 (an inflection)
  const G2Result g = solve_g2({{{0, 0}, 0.6, 0.5}, {{4, 0}, -0.6, -0.3}, -0.5});
  ASSERT_TRUE(g.usable());
  const ExportResult r = to_bspline(g.curve, {.tolerance = 1e-4, .degree = 3});
  ASSERT_TRUE(r.usable());
  for (const int n : {16, 5}) {
    std::ostringstream out;
    write_svg(out, r.curve, {.comb = true, .comb_teeth_per_piece = n});
    const std::string svg = out.str();
    EXPECT_NE(svg.find("<desc>Curvature comb"), std::string::npos);
    // The curve path: M x y, then 3 points per piece.
    const std::vector<double> d = numbers(svg, "", "d");
    ASSERT_EQ((d.size() - 2) % 6, 0u);
    std::vector<std::array<C, 4>> pieces;
    for (size_t k = 2; k + 6 <= d.size(); k += 6)
      pieces.push_back({C(d[k - 2], d[k - 1]), C(d[k], d[k + 1]), C(d[k + 2], d[k + 3]), C(d[k + 4], d[k + 5])});
    const std::vector<double> teeth = numbers(svg, "comb-teeth", "d");
    ASSERT_EQ(teeth.size(), 4 * pieces.size() * (n + 1));
    EXPECT_EQ(numbers(svg, "comb-tips", "points").size(), 2 * pieces.size() * (n + 1));

    // Per tooth: length / |κ| is the one scale c; the tooth is normal to the tangent, on the side
    // away from the centre of curvature (−sign κ · left normal).
    std::vector<double> ratio;
    double longest = 0, kmax = 0;
    int sides[2] = {0, 0};
    for (size_t k = 0; k < teeth.size() / 4; ++k) {
      const auto& P = pieces[k / (n + 1)];
      // Five-point central differences, exact for a polynomial of degree ≤ 4 up to rounding.
      const double t = static_cast<double>(k % (n + 1)) / n, h = 1e-2;
      const C b = de_casteljau(P, t), bp = de_casteljau(P, t + h), bm = de_casteljau(P, t - h);
      const C bpp = de_casteljau(P, t + 2 * h), bmm = de_casteljau(P, t - 2 * h);
      const C d1 = (8.0 * (bp - bm) - (bpp - bmm)) / (12 * h);
      const C d2 = (16.0 * (bp + bm) - (bpp + bmm) - 30.0 * b) / (12 * h * h);
      const double kappa = (d1.real() * d2.imag() - d1.imag() * d2.real()) / std::pow(std::abs(d1), 3);
      const C base(teeth[4 * k], teeth[4 * k + 1]), tip(teeth[4 * k + 2], teeth[4 * k + 3]);
      EXPECT_LT(std::abs(base - b), 1e-12) << k;
      const C tooth = tip - base, tangent = d1 / std::abs(d1);
      const double len = std::abs(tooth);
      longest = std::max(longest, len);
      kmax = std::max(kmax, std::abs(kappa));
      if (len == 0) continue;
      EXPECT_LT(std::abs((std::conj(tangent) * tooth).real()) / len, 1e-7) << k;  // normal to the tangent
      const double side = (std::conj(C(0, 1) * tangent) * tooth).real() / len;    // along the left normal
      EXPECT_NEAR(side, kappa > 0 ? -1.0 : 1.0, 1e-7) << k;
      ++sides[kappa > 0];
      if (std::abs(kappa) > 1e-3 * kmax) ratio.push_back(len / std::abs(kappa));
    }
    EXPECT_GT(sides[0], 0);
    EXPECT_GT(sides[1], 0);
    const auto [lo, hi] = std::minmax_element(ratio.begin(), ratio.end());
    EXPECT_LT((*hi - *lo) / *hi, 1e-6) << "tooth length not proportional to the Bézier curvature";
    // The longest tooth: 0.15 of the control points' diagonal.
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (const C& c : r.curve.control_points)
      x0 = std::min(x0, c.real()), x1 = std::max(x1, c.real()), y0 = std::min(y0, c.imag()),
      y1 = std::max(y1, c.imag());
    EXPECT_NEAR(longest, kCombFraction * std::hypot(x1 - x0, y1 - y0), 1e-9 * longest);
    EXPECT_NEAR(*hi * kmax, longest, 1e-6 * longest);
  }
}

TEST(ExportSvgComb, OffByDefaultAndTeethCountChecked) {
  const G2Result g = solve_g2({{{0, 0}, 0.6, 0.5}, {{4, 0}, -0.6, -0.3}, -0.5});
  const ExportResult r = to_bspline(g.curve, {.tolerance = 1e-3, .degree = 3});
  ASSERT_TRUE(r.usable());
  std::ostringstream plain;
  write_svg(plain, r.curve);
  EXPECT_EQ(plain.str().find("comb"), std::string::npos);
  std::ostringstream out;
  EXPECT_THROW(write_svg(out, r.curve, {.comb = true, .comb_teeth_per_piece = 0}), InputError);
}

}  // namespace
}  // namespace lac
