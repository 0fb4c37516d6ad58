// --comb: the curvature comb on `--format svg`, checked against the same command's JSON points
// (their x, y, theta, kappa), and its refusal without an SVG output.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <cmath>
#include <regex>
#include <sstream>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

const std::string kG2 = "g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 --alpha -0.5";

/// The value of attribute `attr` of the element with id `id`.
std::string attribute(const std::string& svg, const std::string& id, const std::string& attr) {
  const size_t at = svg.find("id=\"" + id + "\"");
  if (at == std::string::npos) return {};
  const size_t end = svg.find('>', at);
  const size_t a = svg.find(" " + attr + "=\"", at);
  if (a == std::string::npos || a > end) return {};
  const size_t from = a + attr.size() + 3;
  return svg.substr(from, svg.find('"', from) - from);
}

struct Tooth {
  double x, y, tx, ty;  // curve coordinates (y up)
};

/// "M x,y L x,y …" in SVG coordinates (y down) back to the curve's.
std::vector<Tooth> parse_teeth(const std::string& d) {
  std::string s = d;
  std::replace(s.begin(), s.end(), ',', ' ');
  std::istringstream in(s);
  std::vector<Tooth> out;
  std::string m, l;
  Tooth t;
  while (in >> m >> t.x >> t.y >> l >> t.tx >> t.ty) {
    EXPECT_EQ(m, "M");
    EXPECT_EQ(l, "L");
    t.y = -t.y, t.ty = -t.ty;
    out.push_back(t);
  }
  return out;
}

TEST(CliComb, TeethFollowTheReportedCurvature) {
  const int n = 60;
  const std::string args = kG2 + " --samples " + std::to_string(n);
  const auto j = test::run_lac_json(args + " --format json");
  ASSERT_EQ(j["points"].size(), static_cast<size_t>(n));
  const test::CliRun svg = test::run_lac_stdout(args + " --format svg --comb");
  ASSERT_EQ(svg.status, 0) << svg.out;
  const std::vector<Tooth> teeth = parse_teeth(attribute(svg.out, "comb-teeth", "d"));
  ASSERT_EQ(teeth.size(), static_cast<size_t>(n));  // one tooth per sample
  ASSERT_FALSE(attribute(svg.out, "comb-tips", "points").empty());
  EXPECT_NE(svg.out.find("<desc>Curvature comb"), std::string::npos);

  // The scale, independently: 0.15 x the diagonal of the samples' and end points' box / max |kappa|.
  double x0 = 0, x1 = 4, y0 = 0, y1 = 0, kmax = 0;  // the polygon: p0 = (0, 0), p1 = (4, 0)
  for (const auto& p : j["points"]) {
    x0 = std::min(x0, p["x"].get<double>()), x1 = std::max(x1, p["x"].get<double>());
    y0 = std::min(y0, p["y"].get<double>()), y1 = std::max(y1, p["y"].get<double>());
    kmax = std::max(kmax, std::abs(p["kappa"].get<double>()));
  }
  ASSERT_GT(kmax, 0);
  const double c = 0.15 * std::hypot(x1 - x0, y1 - y0) / kmax;
  double longest = 0;
  int positive = 0, negative = 0;
  for (int i = 0; i < n; ++i) {
    const auto& p = j["points"][i];
    const double x = p["x"], y = p["y"], theta = p["theta"], kappa = p["kappa"];
    const Tooth& t = teeth[i];
    EXPECT_NEAR(t.x, x, 1e-12) << i;
    EXPECT_NEAR(t.y, y, 1e-12) << i;
    // The tooth is −c·κ·N, N = (−sin θ, cos θ): normal to the tangent, away from the centre of curvature.
    const double dx = t.tx - t.x, dy = t.ty - t.y;
    EXPECT_NEAR(dx, c * kappa * std::sin(theta), 1e-9 * c * kmax) << i;
    EXPECT_NEAR(dy, -c * kappa * std::cos(theta), 1e-9 * c * kmax) << i;
    EXPECT_NEAR(dx * std::cos(theta) + dy * std::sin(theta), 0, 1e-9 * c * kmax) << i;  // along the normal
    EXPECT_NEAR(std::hypot(dx, dy), c * std::abs(kappa), 1e-9 * c * kmax) << i;         // ∝ |κ|
    longest = std::max(longest, std::hypot(dx, dy));
    (kappa > 0 ? positive : negative) += 1;
  }
  EXPECT_GT(positive, 0);  // this curve has an inflection: teeth on both sides
  EXPECT_GT(negative, 0);
  EXPECT_NEAR(longest, 0.15 * std::hypot(x1 - x0, y1 - y0), 1e-9 * longest);
}

TEST(CliComb, DrawsOnEveryPlanarSvgCommand) {
  for (const std::string cmd : {"g1 --points \"0,0 1,0 2,1\" --alpha -1", "eval --alpha 2 --lambda 0.5 --theta 1",
                                "chain --points \"0,0 2,-0.5 4,0.3 5,2\" --alpha -0.5"}) {
    const test::CliRun svg = test::run_lac_stdout(cmd + " --format svg --comb --samples 30");
    ASSERT_EQ(svg.status, 0) << cmd << "\n" << svg.out;
    EXPECT_EQ(parse_teeth(attribute(svg.out, "comb-teeth", "d")).size(), 30u) << cmd;
  }
}

// --export FILE.svg --comb: the exported B-spline's SVG carries its comb (one tooth per parameter
// t = i/16 of each cubic piece, export/write.hpp SvgOptions); without --comb it has none.
TEST(CliComb, ExportedSvgCarriesTheComb) {
  const std::string path = ::testing::TempDir() + "lac_comb_export_" + std::to_string(::getpid()) + ".svg";
  for (const bool comb : {true, false}) {
    const auto j = test::run_lac_json(kG2 + " --export " + path + (comb ? " --comb" : ""));
    ASSERT_EQ(j["export"]["status"], "ok") << j.dump();
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const size_t pieces = j["export"]["spans"].get<size_t>();  // the Bézier pieces: non-empty knot spans
    EXPECT_EQ(parse_teeth(attribute(text.str(), "comb-teeth", "d")).size(), comb ? pieces * 17 : 0u) << j.dump();
  }
  std::remove(path.c_str());
}

TEST(CliComb, WithoutAnSvgOutputIsInvalid) {
  for (const std::string extra : {"", " --format json", " --format csv --samples 5", " --export c.dxf"}) {
    const test::CliRun run = test::run_lac_stderr(kG2 + " --comb" + extra);
    EXPECT_EQ(run.status, 2) << extra << "\n" << run.out;
    EXPECT_NE(run.out.find("comb"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("--format svg"), std::string::npos) << run.out;  // names the valid use
    EXPECT_NE(run.out.find("--export FILE.svg"), std::string::npos) << run.out;
  }
  EXPECT_EQ(test::run_lac("space --comb").status, 2) << "space has no --comb";
}

}  // namespace
}  // namespace lac
