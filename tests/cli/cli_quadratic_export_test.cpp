// --export FILE on `lac quadratic` (the drawn arc of a quadratic LA curve) and `lac eval` (the
// standard-form arc from s = 0 to the evaluated point): the .dxf read back by ezdxf
// (tests/export/read_dxf.py) lies within the reported max_deviation of the command's own points
// at the same arc length; exit 3 when the bound exceeds a too small --export-tol; exit 2 for an
// unknown extension.
#include <gtest/gtest.h>
#include <unistd.h>

#include <complex>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("lac_cli_quadratic_export_" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
  }();
  return d / name;
}

/// The DXF's spline at n points uniform in its parameter (arc length from 0), by ezdxf.
std::vector<std::complex<double>> read_dxf(const fs::path& f, int n, int* degree) {
  const std::string cmd = std::string("/usr/bin/python3 ") + LAC_SOURCE_DIR + "/tests/export/read_dxf.py " + f.string() +
                          " " + std::to_string(n);
  FILE* pipe = popen(cmd.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  if (!pipe) return {};
  std::string out;
  char buf[4096];
  while (size_t k = fread(buf, 1, sizeof buf, pipe)) out.append(buf, k);
  EXPECT_EQ(pclose(pipe), 0) << out;
  std::istringstream in(out);
  size_t control_points = 0;
  in >> *degree >> control_points;
  std::vector<std::complex<double>> pts;
  double t, x, y;
  while (in >> t >> x >> y) pts.emplace_back(x, y);
  return pts;
}

/// Runs `command --samples n --export F.dxf`, reads F back and compares it with the command's
/// points (uniform in s over the exported arc, as the spline's parameter).
void check_readback(const std::string& command, const std::string& name, int degree) {
  constexpr int n = 1001;
  const fs::path f = temp_file(name);
  fs::remove(f);
  const auto j = test::run_lac_json(command + " --samples " + std::to_string(n) + " --export " + f.string() +
                                    " --export-degree " + std::to_string(degree));
  ASSERT_EQ(j["status"], "ok") << j.dump();
  const auto& e = j["export"];
  ASSERT_EQ(e["status"], "ok") << e.dump();
  EXPECT_EQ(e["file"], f.string());
  EXPECT_EQ(e["format"], "dxf");
  EXPECT_EQ(e["degree"], degree);
  EXPECT_EQ(e["continuity"], degree == 5 ? "G2" : "G1");
  EXPECT_DOUBLE_EQ(e["tolerance"].get<double>(), 1e-6 * j["length"].get<double>());
  const double bound = e["max_deviation"].get<double>();
  EXPECT_GT(bound, 0);
  EXPECT_LE(bound, e["tolerance"].get<double>());
  int read_degree = 0;
  const auto pts = read_dxf(f, n, &read_degree);
  EXPECT_EQ(read_degree, degree);
  ASSERT_EQ(pts.size(), static_cast<size_t>(n));
  ASSERT_EQ(j["points"].size(), static_cast<size_t>(n));
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const auto& p = j["points"][static_cast<size_t>(i)];
    worst = std::max(worst, std::abs(std::complex<double>(p["x"].get<double>(), p["y"].get<double>()) - pts[static_cast<size_t>(i)]));
  }
  // The command's points: "error" is their largest error estimate relative to the arc length
  // integrated from s = 0 (at most |s of the arc's start| + length). The spline's parameter is
  // rounded to 17 digits.
  const double length = j["length"].get<double>();
  const double reference_error = j["error"].get<double>() * (length + std::abs(j["segments"][0].value("s", 0.0)));
  EXPECT_LE(worst, bound + reference_error + 1e-12) << command;
  std::printf("%s (degree %d): %zu control points, bound %.3g, measured %.3g at %d points\n", command.c_str(), degree,
              e["control_points"].get<size_t>(), bound, worst, n);
}

const std::string kQuadratic = "quadratic --alpha -1 --gamma -0.3 --lambda 1";
const std::string kEval = "eval --alpha -0.5 --lambda 1 --s 1.5";

TEST(CliQuadraticExport, QuadraticDxfReadsBack) {
  check_readback(kQuadratic, "q5.dxf", 5);
  check_readback(kQuadratic, "q3.dxf", 3);
  check_readback("quadratic --alpha 2.5 --gamma 0.3 --lambda 0.7 --s-from -0.2 --s-to 3", "q_range.dxf", 5);
}

TEST(CliQuadraticExport, EvalDxfReadsBack) {
  check_readback(kEval, "e5.dxf", 5);
  check_readback(kEval, "e3.dxf", 3);
}

TEST(CliQuadraticExport, BoundAboveToleranceIsInaccurate) {
  for (const std::string& c : {kQuadratic, kEval}) {
    const fs::path f = temp_file("tight.dxf");
    fs::remove(f);
    const auto j = test::run_lac_json(c + " --export " + f.string() + " --export-tol 1e-17", 3);
    EXPECT_EQ(j["export"]["status"], "inaccurate") << c;
    EXPECT_TRUE(j["export"]["file"].is_null()) << c;
    EXPECT_FALSE(fs::exists(f)) << c;
  }
}

TEST(CliQuadraticExport, InvalidInput) {
  for (const std::string& c : {kQuadratic, kEval}) {
    const auto bad = test::run_lac_stderr(c + " --export " + temp_file("c.xyz").string());
    EXPECT_EQ(bad.status, 2) << c;
    EXPECT_NE(bad.out.find("export"), std::string::npos) << bad.out;
    EXPECT_EQ(test::run_lac_stderr(c + " --export " + temp_file("c.dxf").string() + " --export-degree 4").status, 2) << c;
    EXPECT_EQ(test::run_lac_stderr(c + " --export " + temp_file("c.dxf").string() + " --export-tol -1").status, 2) << c;
  }
  // No arc at s = 0: "export" is null, nothing written.
  const fs::path f = temp_file("none.dxf");
  fs::remove(f);
  const auto j = test::run_lac_json("eval --alpha -0.5 --lambda 1 --s 0 --export " + f.string());
  EXPECT_TRUE(j["export"].is_null());
  EXPECT_FALSE(fs::exists(f));
}

}  // namespace
}  // namespace lac
