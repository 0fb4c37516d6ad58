// `lac eval` end to end: JSON keys, and exit status 2 with one line naming the parameter.
#include <gtest/gtest.h>

#include "tests/support/run_cli.hpp"

#include <array>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace {

using lac::test::run_lac;

TEST(CliEval, JsonPointHasTheDocumentedKeys) {
  auto r = run_lac("eval --alpha 2 --lambda 1 --theta 1 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"x", "y", "s", "theta", "kappa"}) EXPECT_TRUE(j["point"].contains(key)) << key;
  for (const char* key : {"status", "length", "kappa0", "kappa1", "evaluations", "seconds", "segments"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_DOUBLE_EQ(j["info"]["rho"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["point"]["s"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["kappa1"].get<double>(), 0.5);
  EXPECT_TRUE(j["iterations"].is_null());  // no solver
  EXPECT_EQ(j["segments"][0]["lambda"], 1.0);  // the standard form's own Λ
  // --degrees: the same point from θ in degrees.
  auto d = nlohmann::json::parse(run_lac("eval --alpha 2 --lambda 1 --theta 57.295779513082323 --degrees").out);
  EXPECT_NEAR(d["point"]["x"].get<double>(), j["point"]["x"].get<double>(), 1e-14);
}

TEST(CliEval, SamplesFromTheReferencePoint) {
  auto r = run_lac("eval --alpha -1 --lambda 1 --s 0.8 --samples 5 --integrator rk4 --h 0.01 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["points"].is_array());
  EXPECT_EQ(j["points"].size(), 5u);
  EXPECT_DOUBLE_EQ(j["points"].back()["s"].get<double>(), 0.8);
  EXPECT_NEAR(j["points"].back()["x"].get<double>(), j["point"]["x"].get<double>(), 1e-12);
}

TEST(CliEval, InvalidInputExitsWithStatusTwoAndOneLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"eval --alpha 2 --lambda -1 --theta 1", "lambda"},
      {"eval --alpha 0.5 --lambda 1 --theta 3", "theta"},
      {"eval --alpha 2 --lambda 1 --s -0.9", "s"},
      {"eval --alpha nan --lambda 1 --theta 1", "alpha"},
      {"eval --alpha 2 --lambda 1 --theta 1 --samples 1", "samples"},
      {"eval --alpha 0.5 --lambda 1 --theta -0.5 --samples 2147483647", "samples"},  // was bad_alloc, exit 1
      {"eval --alpha 2 --lambda 1 --theta 1 --s 1", "theta"},
      {"eval --alpha 2 --lambda 1 --theta 1 --integrator euler", "integrator"},
      {"eval --alpha 2 --lambda 1 --theta 1 --integrator rk45 --h 0.1", "h"},
      {"eval --alpha 2 --lambda 1 --theta 1 --integrator gk-tanh-sinh --panels 4", "panels"},
      {"eval --alpha 2 --lambda 1 --theta 1 --integrator gauss-legendre --panels 0", "panels"},
      {"eval --alpha 2 --lambda 1", "theta"},
  };
  for (auto [args, parameter] : cases) {
    auto r = run_lac(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(parameter), std::string::npos) << args << "\n" << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << "\n" << r.out;
  }
}

TEST(CliEval, HelpIsUseful) {
  auto r = run_lac("eval --help");
  EXPECT_EQ(r.status, 0);
  for (const char* opt : {"--alpha", "--lambda", "--theta", "--s", "--form", "--integrator", "--h", "--tol", "--panels",
                          "--samples", "--format", "--batch", "--degrees"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  // --integrator lists every registered method (the help comes from the registry).
  for (const char* name : {"rk4", "rk45", "gauss-kronrod", "gauss-legendre", "gk-tanh-sinh", "igf"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
}

TEST(CliEval, EveryRegisteredMethodByName) {
  for (const char* args : {"--integrator gauss-legendre --panels 4", "--integrator gk-tanh-sinh --tol 1e-12",
                           "--integrator gk", "--integrator igf --tol 1e-11"}) {
    auto r = run_lac(std::string("eval --alpha 2 --lambda 1 --theta 1.5 --format json ") + args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("\"status\": \"ok\""), std::string::npos) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("\"point\": {"), std::string::npos) << args << "\n" << r.out;
  }
}

}  // namespace
