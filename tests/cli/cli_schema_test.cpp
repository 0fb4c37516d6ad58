// One schema for every subcommand (docs/cli.md "Schema"): the common keys in their order, null for
// numbers that do not exist, the CSV form under the same names, --samples points and --degrees.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

using Json = nlohmann::ordered_json;

const std::vector<std::string> kCommonKeys = {"status",     "message",     "length",  "kappa0", "kappa1",
                                              "iterations", "evaluations", "seconds", "solver", "integrator",
                                              "residuals",  "error",       "accept",  "segments"};

const std::string kSpaceEnds =
    "--p0 0,0,0 --v0 1,0,0 --p1 0.36235775447667362,0.93203908596722629,0 "
    "--v1=-0.4838825660252134,0.8293701183329452,0.279289937364832 ";
const std::string kG2 = "g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 ";

struct Case {
  std::string good;      ///< exit 0
  std::string failing;   ///< exit 3: no usable result
  bool construction;     ///< a failed construction has no curve: length, kappa0, kappa1 null, no segments
  std::vector<std::string> point_keys;
};

const std::vector<std::string> kPlanar = {"s", "x", "y", "theta", "kappa"};
const std::vector<Case> kCases = {
    {"eval --alpha 2 --lambda 1 --theta 1", "eval --alpha 1 --lambda 1 --theta 1 --integrator rk4 --h 1e-9", false, kPlanar},
    {"quadratic --alpha 1 --gamma 1 --lambda 1", "quadratic --alpha 1 --gamma 1 --lambda 1 --integrator rk4 --h 1e-9", false,
     kPlanar},
    {"g1 --points '0,0 1,0 2,1' --alpha -1", "g1 --points '0,0 1,0 2,1' --alpha 5 --winding 0", true, kPlanar},
    {"compound --points '3,2 1.5,0.2 0.5,0.9' --alpha0 2 --alpha1 0.5 --r 0.3",
     "compound --points '0,0 1,0 2,1' --alpha0 5 --alpha1 5", true, kPlanar},
    {"scurve --points '0,0 1,0 2,1 3,1' --alpha -1", "scurve --points '0,0 1,0.5 2,0.5 3,1' --alpha 1.5", true, kPlanar},
    {"g1 --p0 0,0 --theta0 0.3 --p1 1,0 --theta1 0.4 --alpha -1", "g1 --p0 0,0 --theta0 0.3 --p1 1,0 --theta1 0.4 --alpha 1 --winding 0",
     true, kPlanar},
    {"chain --points '0,0 1,1 2,0 3,1' --alpha -1", "chain --points '0,0 1,0 2,0' --thetas '0.2 -0.2 -0.4' --alpha 1 --winding 0", true,
     kPlanar},
    {kG2 + "--alpha -0.5", "g2 --p0 0,0 --theta0 0.3 --kappa0 1 --p1 1,0 --theta1 0.3 --kappa1 -1 --alpha 1", true, kPlanar},
    {"space " + kSpaceEnds + "--alpha -1 --beta -1",
     "space --p0 0,0,0 --v0 1,0,0 --p1 1,0.1,0.1 --v1 -1,0,0 --alpha -1 --beta 0", true,
     {"s", "x", "y", "z", "kappa", "tau"}},
};

Json run_json(const std::string& args, int expected) {
  const test::CliRun r = test::run_lac_stdout(args);
  EXPECT_EQ(r.status, expected) << args << "\n" << r.out;
  try {
    return Json::parse(r.out);
  } catch (const nlohmann::json::exception& e) {
    ADD_FAILURE() << args << ": not JSON\n" << r.out;
    return Json::object();
  }
}

std::vector<std::string> keys(const Json& j) {
  std::vector<std::string> out;
  for (const auto& [k, v] : j.items()) out.push_back(k);
  return out;
}

void flatten(const Json& j, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [k, v] : j.items()) {
    if (v.is_array()) continue;
    if (v.is_object()) flatten(v, prefix + k + ".", out);
    else out.push_back(prefix + k);
  }
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
  return out;
}

TEST(CliSchema, CommonKeysFirstInTheirOrder) {
  for (const Case& c : kCases) {
    const Json j = run_json(c.good, 0);
    const std::vector<std::string> k = keys(j);
    ASSERT_GE(k.size(), kCommonKeys.size()) << c.good;
    EXPECT_EQ(std::vector<std::string>(k.begin(), k.begin() + kCommonKeys.size()), kCommonKeys) << c.good;
    EXPECT_EQ(j["status"], "ok") << c.good;
    EXPECT_TRUE(j["message"].is_null()) << c.good;
    for (const char* key : {"length", "kappa0", "kappa1", "evaluations", "seconds"}) EXPECT_TRUE(j[key].is_number()) << c.good << " " << key;
    EXPECT_EQ(keys(j["residuals"]), (std::vector<std::string>{"position", "angle", "curvature"})) << c.good;
    EXPECT_EQ(j["accept"], 1e-6) << c.good;  // the default accept bound (common/accuracy.hpp)
    // The constructions that grade their achieved error themselves (triangle, space) report it.
    if (c.good.rfind("compound", 0) == 0 || c.good.rfind("space", 0) == 0) {
      EXPECT_TRUE(j["error"].is_number()) << c.good;
      EXPECT_LE(j["error"].get<double>(), 1e-6) << c.good;
    }
    ASSERT_FALSE(j["segments"].empty()) << c.good;
    for (const Json& seg : j["segments"])
      for (const char* key : {"kind", "alpha", "lambda", "length", "start", "kappa"}) EXPECT_TRUE(seg.contains(key)) << c.good << " " << key;
    EXPECT_EQ(j["solver"].is_null(), !c.construction) << c.good;
    EXPECT_EQ(j["iterations"].is_null(), !c.construction) << c.good;
    EXPECT_FALSE(j.contains("points") && c.good.rfind("quadratic", 0) != 0) << c.good;  // only with --samples
  }
}

TEST(CliSchema, MissingNumbersAreNull) {
  for (const Case& c : kCases) {
    const Json j = run_json(c.failing, 3);
    EXPECT_NE(j["status"], "ok") << c.failing;
    EXPECT_TRUE(j["message"].is_string()) << c.failing;
    if (c.construction) {
      for (const char* key : {"length", "kappa0", "kappa1"}) EXPECT_TRUE(j[key].is_null()) << c.failing << " " << key;
      for (const auto& [k, v] : j["residuals"].items()) EXPECT_TRUE(v.is_null()) << c.failing << " " << k;
      EXPECT_TRUE(j["segments"].empty()) << c.failing;
    } else {  // an evaluation whose positions failed: the positions are null, the closed forms stay
      const Json& p = j.contains("point") ? j["point"] : j["points"][0];
      EXPECT_TRUE(p["x"].is_null() && p["y"].is_null()) << c.failing << ": " << p.dump();
      EXPECT_TRUE(p["kappa"].is_number()) << c.failing;
    }
  }
}

TEST(CliSchema, SamplesAreThePointsWithTheDocumentedKeys) {
  for (const Case& c : kCases) {
    const Json j = run_json(c.good + " --samples 4", 0);
    ASSERT_EQ(j["points"].size(), 4u) << c.good;
    for (const Json& p : j["points"]) EXPECT_EQ(keys(p), c.point_keys) << c.good;
    EXPECT_EQ(keys(j).back(), "points") << c.good;
    const test::CliRun one = test::run_lac_stderr(c.good + " --samples 1");
    EXPECT_EQ(one.status, 2) << c.good;
    EXPECT_NE(one.out.find("samples"), std::string::npos) << one.out;
  }
}

TEST(CliSchema, CsvUsesTheJsonNames) {
  for (const Case& c : kCases) {
    const Json j = run_json(c.good + " --samples 3", 0);
    const test::CliRun csv = test::run_lac_stdout(c.good + " --samples 3 --format csv");
    ASSERT_EQ(csv.status, 0) << csv.out;
    std::istringstream in(csv.out);
    std::string header, values, columns;
    std::getline(in, header);
    std::getline(in, values);
    std::getline(in, columns);
    std::vector<std::string> summary;
    flatten(j, "", summary);
    ASSERT_EQ(header.rfind("# ", 0), 0u) << csv.out;
    EXPECT_EQ(split(header.substr(2)), summary) << c.good;
    EXPECT_EQ(values.rfind("# ok,", 0), 0u) << csv.out;
    EXPECT_EQ(split(columns), c.point_keys) << c.good;
    int rows = 0;
    for (std::string line; std::getline(in, line);) ++rows;
    EXPECT_EQ(rows, 3) << csv.out;
  }
}

TEST(CliSchema, SvgForPlanarCurves) {
  for (const Case& c : kCases) {
    const test::CliRun svg = test::run_lac_stdout(c.good + " --format svg");
    if (c.point_keys.size() == 6) {  // space: no svg
      EXPECT_EQ(svg.status, 2) << c.good;
      continue;
    }
    EXPECT_EQ(svg.status, 0) << c.good;
    EXPECT_EQ(svg.out.rfind("<svg", 0), 0u) << c.good;
    EXPECT_NE(svg.out.find("<polyline"), std::string::npos) << c.good;
  }
}

TEST(CliSchema, DegreesConvertEveryInputAngle) {
  const Json rad = run_json(kG2 + "--alpha -0.5", 0);
  const Json deg = run_json("g2 --p0 0,0 --theta0 34.377467707849391 --kappa0 0.5 --p1 4,0 --theta1 -34.377467707849391 "
                            "--kappa1 -0.3 --alpha -0.5 --degrees",
                            0);
  EXPECT_NEAR(deg["length"].get<double>(), rad["length"].get<double>(), 1e-12);
  EXPECT_NEAR(deg["segments"][0]["theta"].get<double>(), 0.6, 1e-15);  // output angles in radians
}

TEST(CliSchema, AcceptIsTheCommandLinesBound) {
  for (const std::string& args : {std::string("compound --points '3,2 1.5,0.2 0.5,0.9' --alpha0 2 --alpha1 0.5 --r 0.3"),
                                  "space " + kSpaceEnds + "--alpha -1 --beta -1"}) {
    const Json j = run_json(args + " --accept 0.001", 0);
    EXPECT_EQ(j["accept"], 0.001) << args;
    EXPECT_EQ(test::run_lac_stderr(args + " --accept 0.5").status, 2) << args;  // beyond kMaxAccept
  }
}

}  // namespace
}  // namespace lac
