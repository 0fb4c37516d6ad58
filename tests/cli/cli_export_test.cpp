// --export FILE on the planar constructions: the report's export object, the files of every
// format, the status rule (a bound above --export-tol is inaccurate: exit 3), invalid input, and
// batch mode's one file per row. The files' contents are read back in tests/export/.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

namespace fs = std::filesystem;

const std::string kG2 = "g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 --alpha -0.5";

fs::path temp_dir() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("lac_cli_export_" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
  }();
  return d;
}

TEST(CliExport, AcceptanceG2EveryFormat) {
  for (const std::string ext : {"step", "iges", "dxf", "svg"}) {
    const fs::path f = temp_dir() / ("curve." + ext);
    const auto j = test::run_lac_json(kG2 + " --export " + f.string() + " --export-tol 1e-6");
    ASSERT_EQ(j["status"], "ok") << j.dump();
    const auto& e = j["export"];
    std::vector<std::string> keys;
    for (const auto& [k, v] : e.items()) keys.push_back(k);
    EXPECT_EQ(std::vector<std::string>(keys.begin(), keys.begin() + 6),
              (std::vector<std::string>{"file", "format", "degree", "control_points", "max_deviation", "curvature_monotone"}));
    EXPECT_EQ(e["file"], f.string());
    EXPECT_EQ(e["format"], ext);
    EXPECT_EQ(e["status"], "ok");
    EXPECT_GT(e["max_deviation"].get<double>(), 0);
    EXPECT_LE(e["max_deviation"].get<double>(), 1e-6);
    EXPECT_GT(e["control_points"].get<int>(), 4);
    EXPECT_TRUE(e["curvature_monotone"].is_boolean());
    EXPECT_EQ(e["degree"], ext == "svg" ? 3 : 5);
    EXPECT_EQ(e["continuity"], ext == "svg" ? "G1" : "G2");
    if (ext != "svg") {
      EXPECT_EQ(e["curvature_monotone"], true);
    }
    EXPECT_GT(fs::file_size(f), 100u) << f;
  }
}

TEST(CliExport, EveryPlanarConstruction) {
  const std::vector<std::string> commands = {
      "g1 --p0 0,0 --theta0 0 --p1 2,1 --theta1 0.7853981633974483 --alpha -0.5",
      "scurve --points '0,0 1,1 2,-1 3,0' --alpha -1",
      "compound --points '0,0 1,0 2,1' --alpha0 -1 --alpha1 0.5",
      "chain --points '0,0 1,1 2,0 3,1' --alpha -1 --continuity g2",
      kG2};
  for (const std::string& c : commands) {
    const fs::path f = temp_dir() / "c.dxf";
    fs::remove(f);
    const auto j = test::run_lac_json(c + " --export " + f.string());
    ASSERT_EQ(j["status"], "ok") << c << j.dump();
    // Default tolerance: 1e-6 x length.
    EXPECT_DOUBLE_EQ(j["export"]["tolerance"].get<double>(), 1e-6 * j["length"].get<double>()) << c;
    EXPECT_LE(j["export"]["max_deviation"].get<double>(), j["export"]["tolerance"].get<double>()) << c;
    EXPECT_TRUE(fs::exists(f)) << c;
  }
}

TEST(CliExport, BoundAboveToleranceIsInaccurate) {
  const fs::path f = temp_dir() / "tight.svg";
  fs::remove(f);
  const auto j = test::run_lac_json(kG2 + " --export " + f.string() + " --export-tol 1e-17", 3);
  EXPECT_NE(j["export"]["status"], "ok");
  EXPECT_TRUE(j["export"]["file"].is_null());
  EXPECT_FALSE(fs::exists(f));
}

TEST(CliExport, InvalidInput) {
  EXPECT_EQ(test::run_lac(kG2 + " --export " + (temp_dir() / "c.stl").string()).status, 2);
  EXPECT_EQ(test::run_lac(kG2 + " --export " + (temp_dir() / "c.dxf").string() + " --export-tol -1").status, 2);
  EXPECT_EQ(test::run_lac(kG2 + " --export /nonexistent-dir/c.dxf").status, 2);
  EXPECT_EQ(test::run_lac(kG2 + " --export " + (temp_dir() / "c.svg").string() + " --export-degree 5").status, 2);
  EXPECT_EQ(test::run_lac(kG2 + " --export " + (temp_dir() / "c.dxf").string() + " --export-degree 4").status, 2);
  const auto j = test::run_lac_json(kG2 + " --export " + (temp_dir() / "c.dxf").string() + " --export-degree 3");
  EXPECT_EQ(j["export"]["degree"], 3);
}

// --export-fit-degree Q: the fits of degree 3 … Q, the fewest control points kept (on a single
// smooth segment at a tight tolerance a high degree: fewer points than the default), within the
// tolerance; an out-of-range Q, or one above 3 for .svg, is invalid input naming the option.
TEST(CliExport, FitDegreeGivesFewerPoints) {
  const std::string g1 = "g1 --p0 0,0 --theta0 0 --p1 2,1 --theta1 0.7853981633974483 --alpha -0.5";
  const std::string f = (temp_dir() / "fit.dxf").string();
  const auto plain = test::run_lac_json(g1 + " --export " + f + " --export-tol 1e-9");
  const auto fitted = test::run_lac_json(g1 + " --export " + f + " --export-tol 1e-9 --export-fit-degree 8");
  ASSERT_EQ(plain["export"]["status"], "ok") << plain.dump();
  ASSERT_EQ(fitted["export"]["status"], "ok") << fitted.dump();
  EXPECT_LT(fitted["export"]["control_points"].get<int>(), plain["export"]["control_points"].get<int>());
  EXPECT_GE(fitted["export"]["degree"].get<int>(), 3);
  EXPECT_LE(fitted["export"]["degree"].get<int>(), 8);
  EXPECT_LE(fitted["export"]["max_deviation"].get<double>(), 1e-9);
  for (const std::string bad : {" --export-fit-degree 2", " --export-fit-degree 10"}) {
    const auto r = test::run_lac_stderr(g1 + " --export " + f + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.out.find("export-fit-degree"), std::string::npos) << r.out;
  }
  const auto svg = test::run_lac_stderr(g1 + " --export " + (temp_dir() / "fit.svg").string() + " --export-fit-degree 5");
  EXPECT_EQ(svg.status, 2);
  EXPECT_NE(svg.out.find("export-fit-degree"), std::string::npos) << svg.out;
  EXPECT_EQ(test::run_lac_json(g1 + " --export " + (temp_dir() / "fit.svg").string() + " --export-fit-degree 3")["export"]["degree"], 3);
}

TEST(CliExport, BatchWritesOneFilePerRow) {
  const fs::path csv = temp_dir() / "rows.csv";
  std::ofstream(csv) << "p0,theta0,kappa0,p1,theta1,kappa1\n"
                        "\"0,0\",0.6,0.5,\"4,0\",-0.6,-0.3\n"
                        "\"0,0\",0.3,0.2,\"3,1\",0.1,-0.2\n";
  const fs::path f = temp_dir() / "batch.svg";
  const auto run = test::run_lac("g2 --alpha -0.5 --batch " + csv.string() + " --export " + f.string());
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(fs::exists(temp_dir() / "batch_row1.svg"));
  EXPECT_TRUE(fs::exists(temp_dir() / "batch_row2.svg"));
  EXPECT_NE(run.out.find("batch_row2.svg"), std::string::npos);
}

// --export DIR/ (created if missing): DIR/curve.<--export-format>, one per row in batch mode; a bad
// row writes nothing and the rows after it are still exported.
TEST(CliExport, FolderTakesTheFormatOption) {
  const fs::path dir = temp_dir() / "folder" / "out";
  fs::remove_all(temp_dir() / "folder");
  const auto one = test::run_lac_json(kG2 + " --export " + dir.string() + "/");
  EXPECT_EQ(one["export"]["file"], (dir / "curve.step").string());
  EXPECT_EQ(one["export"]["format"], "step");
  EXPECT_TRUE(fs::exists(dir / "curve.step"));
  const fs::path csv = temp_dir() / "rows3.csv";
  std::ofstream(csv) << "p0,theta0,kappa0,p1,theta1,kappa1\n"
                        "\"0,0\",0.6,0.5,\"4,0\",-0.6,-0.3\n"
                        "\"0,0\",0.3,bad,\"3,1\",0.1,-0.2\n"
                        "\"0,0\",0.3,0.2,\"3,1\",0.1,-0.2\n";
  const auto run = test::run_lac("g2 --alpha -0.5 --batch " + csv.string() + " --export " + dir.string() + "/ --export-format DXF");
  EXPECT_EQ(run.status, 2) << run.out;  // the bad row's status (the batch goes on)
  EXPECT_TRUE(fs::exists(dir / "curve_row1.dxf"));
  EXPECT_FALSE(fs::exists(dir / "curve_row2.dxf"));
  EXPECT_TRUE(fs::exists(dir / "curve_row3.dxf"));
  const auto bad = test::run_lac(kG2 + " --export " + dir.string() + "/ --export-format stl");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("export-format"), std::string::npos) << bad.out;
  EXPECT_EQ(test::run_lac(kG2 + " --export " + (dir / "c.dxf").string() + " --export-format svg").status, 2);
  EXPECT_EQ(test::run_lac(kG2 + " --export-format svg").status, 2);
}

}  // namespace
}  // namespace lac
