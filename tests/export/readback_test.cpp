// Every export format read back by an independent reader and compared with the LA curve at
// ≥ 1000 points: STEP and IGES by OpenCASCADE's readers, DXF by ezdxf (Python), SVG by the path
// parser below. The B-spline's parameter is the arc length, so the comparison is at equal s.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lac/constructions/g2_hermite.hpp"
#include "lac/export/to_bspline.hpp"
#include "lac/export/write.hpp"
#include "tests/export/read_back.hpp"
#ifdef LAC_WITH_OCCT
#include "lac/export/occt/occt_writer.hpp"
#endif

namespace lac {
namespace {

constexpr int kPoints = 1001;

struct Exported {
  PlanarCurve curve;
  ExportResult result;
};

/// Quintic (G2) for STEP, IGES and DXF; cubic for SVG (its paths hold cubic Béziers).
const Exported& acceptance(int degree);
const Exported& acceptance() { return acceptance(5); }

// lac g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 --alpha -0.5
const Exported& acceptance(int degree) {
  static const auto make = [](int d) {
    Exported x;
    const G2Result g = solve_g2({{{0, 0}, 0.6, 0.5}, {{4, 0}, -0.6, -0.3}, -0.5});
    x.curve = g.curve;
    x.result = to_bspline(x.curve, {.tolerance = 1e-6, .degree = d});
    return x;
  };
  static const Exported cubic = make(3), quintic = make(5);
  return degree == 3 ? cubic : quintic;
}

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("lac_export_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

/// Largest |c(t) − read(t)| over the points.
template <class Read>
double compare(const PlanarCurve& c, double t0, double t1, const Read& read) {
  double worst = 0;
  for (int i = 0; i < kPoints; ++i) {
    const double t = t0 + (t1 - t0) * i / (kPoints - 1);
    worst = std::max(worst, std::abs(position_at(c, std::clamp(t, 0.0, c.length())).point.position - read(t)));
  }
  return worst;
}

#ifdef LAC_WITH_OCCT
/// The file read back by OpenCASCADE against the LA curve at kPoints parameters.
void check_occt_read_back(const std::string& path, ExportFormat format, const Exported& e) {
  const test::OcctReadBack r =
      test::read_occt(path, format, e.result.curve.degree, e.result.curve.control_points.size(), e.curve.length());
  ASSERT_FALSE(r.curve.IsNull());
  const double d = compare(e.curve, r.first, r.last, [&](double t) {
    const gp_Pnt p = r.curve->Value(t);
    EXPECT_EQ(p.Z(), 0.0);
    return std::complex<double>(p.X(), p.Y());
  });
  EXPECT_LE(d, e.result.info.max_deviation);
  std::printf("read back: deviation %.3g, bound %.3g\n", d, e.result.info.max_deviation);
}

TEST(ExportReadBack, StepByOpenCascade) {
  const Exported& e = acceptance();
  ASSERT_TRUE(e.result.usable());
  const std::string path = temp_file("curve.step");
  write_step(path, e.result.curve);
  check_occt_read_back(path, ExportFormat::step, e);
  std::filesystem::remove(path);
}

TEST(ExportReadBack, IgesByOpenCascade) {
  const Exported& e = acceptance();
  ASSERT_TRUE(e.result.usable());
  const std::string path = temp_file("curve.iges");
  write_iges(path, e.result.curve);
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("     126"), std::string::npos) << "no entity 126 in the directory section";
  check_occt_read_back(path, ExportFormat::iges, e);
  std::filesystem::remove(path);
}
#endif

TEST(ExportReadBack, DxfByEzdxf) {
  const Exported& e = acceptance();
  ASSERT_TRUE(e.result.usable());
  const std::string path = temp_file("curve.dxf");
  write_file(path, ExportFormat::dxf, e.result.curve);
  const test::DxfReadBack d = test::read_dxf(path, kPoints, 2);
  EXPECT_EQ(d.degree, 5);
  EXPECT_EQ(d.control_points, e.result.curve.control_points.size());
  EXPECT_EQ(d.t.size(), static_cast<size_t>(kPoints));
  double worst = 0;
  for (size_t i = 0; i < d.t.size(); ++i)
    worst = std::max(worst, std::abs(position_at(e.curve, std::clamp(d.t[i], 0.0, e.curve.length())).point.position -
                                     std::complex<double>(d.point[i][0], d.point[i][1])));
  EXPECT_LE(worst, e.result.info.max_deviation);
  std::printf("ezdxf: deviation %.3g, bound %.3g\n", worst, e.result.info.max_deviation);
  std::filesystem::remove(path);
}

/// The cubic pieces of the one path's d attribute ("M x y C x y x y x y ..." only).
std::vector<std::array<std::complex<double>, 4>> parse_svg_path(const std::string& svg) {
  const size_t at = svg.find(" d=\"");
  EXPECT_NE(at, std::string::npos);
  std::istringstream in(svg.substr(at + 4, svg.find('"', at + 4) - at - 4));
  std::string cmd;
  double x, y;
  in >> cmd >> x >> y;
  EXPECT_EQ(cmd, "M");
  std::complex<double> cur{x, y};
  std::vector<std::array<std::complex<double>, 4>> pieces;
  while (in >> cmd) {
    EXPECT_EQ(cmd, "C");
    std::array<std::complex<double>, 4> p{cur};
    for (int i = 1; i <= 3; ++i) {
      in >> x >> y;
      p[i] = {x, y};
    }
    cur = p[3];
    pieces.push_back(p);
  }
  return pieces;
}

TEST(ExportReadBack, SvgCubicPath) {
  const Exported& e = acceptance(3);
  ASSERT_TRUE(e.result.usable());
  std::ostringstream out;
  write_svg(out, e.result.curve);
  const auto pieces = parse_svg_path(out.str());
  std::vector<double> knots;
  std::vector<int> mult;
  e.result.curve.distinct_knots(knots, mult);
  ASSERT_EQ(pieces.size() + 1, knots.size());  // one C command per span
  double worst = 0;
  int points = 0;
  for (size_t j = 0; j < pieces.size(); ++j) {
    const int n = 1 + kPoints / static_cast<int>(pieces.size());
    for (int i = 0; i <= n; ++i) {
      const double u = static_cast<double>(i) / n, v = 1 - u;
      const auto& p = pieces[j];
      const std::complex<double> b = v * v * v * p[0] + 3 * v * v * u * p[1] + 3 * v * u * u * p[2] + u * u * u * p[3];
      const double s = knots[j] + (knots[j + 1] - knots[j]) * u;
      worst = std::max(worst, std::abs(position_at(e.curve, std::min(s, e.curve.length())).point.position - b));
      ++points;
    }
  }
  EXPECT_GE(points, kPoints);
  EXPECT_LE(worst, e.result.info.max_deviation);
}

TEST(ExportReadBack, FormatFromExtension) {
  EXPECT_EQ(export_format_from_path("a/b.STEP"), ExportFormat::step);
  EXPECT_EQ(export_format_from_path("b.stp"), ExportFormat::step);
  EXPECT_EQ(export_format_from_path("b.igs"), ExportFormat::iges);
  EXPECT_EQ(export_format_from_path("b.Iges"), ExportFormat::iges);
  EXPECT_EQ(export_format_from_path("b.dxf"), ExportFormat::dxf);
  EXPECT_EQ(export_format_from_path("b.svg"), ExportFormat::svg);
  EXPECT_THROW(export_format_from_path("b.stl"), InputError);
  EXPECT_THROW(export_format_from_path("dir.step/b"), InputError);
}

}  // namespace
}  // namespace lac
