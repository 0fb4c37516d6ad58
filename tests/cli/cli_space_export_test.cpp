// lac space --export FILE: the report's export object (the planar commands' keys; the planar
// curvature check null), STEP/IGES/DXF files for the G1 and the compound segment, .svg refused
// (planar curves only), the status rule (a bound above --export-tol: exit 3) and batch mode's one
// file per row. The files' contents are read back in tests/export/space_export_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

namespace fs = std::filesystem;

// 000 Fig. 5a parameters with drawable endpoints (as tests/cli/cli_space_test.cpp).
const std::string kSpace =
    "space --p0 0,0,0 --v0 1,0,0 --p1 0.36235775447667362,0.93203908596722629,0 "
    "--v1=-0.4838825660252134,0.8293701183329452,0.279289937364832 --alpha -1 --beta -1 --omega 0.1 --type 1";
const std::string kCompound = kSpace + " --alpha1 1 --beta1 1 --r-theta 0.5";

fs::path temp_dir() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("lac_cli_space_export_" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
  }();
  return d;
}

TEST(CliSpaceExport, G1AndCompoundEveryFormat) {
  for (const std::string& command : {kSpace, kCompound})
    for (const std::string ext : {"step", "iges", "dxf"}) {
      const fs::path f = temp_dir() / ("space." + ext);
      fs::remove(f);
      const auto j = test::run_lac_json(command + " --export " + f.string());
      ASSERT_EQ(j["status"], "ok") << j.dump();
      const auto& e = j["export"];
      std::vector<std::string> keys;
      for (const auto& [k, v] : e.items()) keys.push_back(k);
      EXPECT_EQ(keys,
                (std::vector<std::string>{"file", "format", "degree", "control_points", "max_deviation",
                                          "curvature_monotone", "tolerance", "spans", "continuity", "monotone_segments",
                                          "constant_curvature_segments", "max_curvature_jump", "status", "message"}));
      EXPECT_EQ(e["file"], f.string());
      EXPECT_EQ(e["format"], ext);
      EXPECT_EQ(e["status"], "ok");
      EXPECT_EQ(e["degree"], 5);
      EXPECT_EQ(e["continuity"], "G2");
      EXPECT_DOUBLE_EQ(e["tolerance"].get<double>(), 1e-6 * j["length"].get<double>());
      EXPECT_GT(e["max_deviation"].get<double>(), 0);
      EXPECT_LE(e["max_deviation"].get<double>(), e["tolerance"].get<double>());
      // N spans of degree 5: N + 5 points with simple knots, 3N + 3 with the Hermite spans' triple ones.
      EXPECT_GE(e["control_points"].get<long>(), e["spans"].get<long>() + 5);
      EXPECT_LE(e["control_points"].get<long>(), 3 * e["spans"].get<long>() + 3);
      EXPECT_TRUE(e["curvature_monotone"].is_null());
      EXPECT_TRUE(e["max_curvature_jump"].is_null());
      EXPECT_GT(fs::file_size(f), 100u) << f;
    }
}

TEST(CliSpaceExport, CubicAndTolerance) {
  const fs::path f = temp_dir() / "cubic.dxf";
  const auto j = test::run_lac_json(kSpace + " --export " + f.string() + " --export-degree 3 --export-tol 1e-8");
  EXPECT_EQ(j["export"]["degree"], 3);
  EXPECT_EQ(j["export"]["continuity"], "G1");
  EXPECT_EQ(j["export"]["tolerance"], 1e-8);
  EXPECT_LE(j["export"]["max_deviation"].get<double>(), 1e-8);
  EXPECT_GE(j["export"]["control_points"].get<long>(), j["export"]["spans"].get<long>() + 3);
  EXPECT_LE(j["export"]["control_points"].get<long>(), 2 * j["export"]["spans"].get<long>() + 2);
}

TEST(CliSpaceExport, BoundAboveToleranceIsInaccurate) {
  const fs::path f = temp_dir() / "tight.step";
  fs::remove(f);
  const auto j = test::run_lac_json(kSpace + " --export " + f.string() + " --export-tol 1e-15", 3);
  EXPECT_EQ(j["export"]["status"], "inaccurate");
  EXPECT_TRUE(j["export"]["file"].is_null());
  EXPECT_GT(j["export"]["max_deviation"].get<double>(), 1e-15);
  EXPECT_FALSE(fs::exists(f));
}

TEST(CliSpaceExport, InvalidInput) {
  const auto svg = test::run_lac(kSpace + " --export " + (temp_dir() / "c.svg").string());
  EXPECT_EQ(svg.status, 2);
  EXPECT_NE(svg.out.find("export"), std::string::npos) << svg.out;
  EXPECT_NE(svg.out.find(".svg holds planar curves"), std::string::npos) << svg.out;
  EXPECT_EQ(test::run_lac(kSpace + " --export " + (temp_dir() / "c.stl").string()).status, 2);
  EXPECT_EQ(test::run_lac(kSpace + " --export " + (temp_dir() / "c.dxf").string() + " --export-tol 0").status, 2);
  EXPECT_EQ(test::run_lac(kSpace + " --export " + (temp_dir() / "c.dxf").string() + " --export-degree 4").status, 2);
  EXPECT_EQ(test::run_lac(kSpace + " --export /nonexistent-dir/c.dxf").status, 2);
}

TEST(CliSpaceExport, BatchWritesOneFilePerRow) {
  const fs::path csv = temp_dir() / "rows.csv";
  std::ofstream(csv) << "p0,v0,p1,v1\n"
                        "\"0,0,0\",\"1,0,0\",\"0.36235775447667362,0.93203908596722629,0\","
                        "\"-0.4838825660252134,0.8293701183329452,0.279289937364832\"\n"
                        "\"1,1,1\",\"1,0,0\",\"1.36235775447667362,1.93203908596722629,1\","
                        "\"-0.4838825660252134,0.8293701183329452,0.279289937364832\"\n";
  const fs::path f = temp_dir() / "batch.dxf";
  const auto run =
      test::run_lac("space --alpha -1 --beta -1 --omega 0.1 --batch " + csv.string() + " --export " + f.string());
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(fs::exists(temp_dir() / "batch_row1.dxf"));
  EXPECT_TRUE(fs::exists(temp_dir() / "batch_row2.dxf"));
}

}  // namespace
}  // namespace lac
