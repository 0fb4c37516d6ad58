// `lac space` end to end: JSON keys, points on request, CSV, every integrator and solver by name, and
// exit status 2 naming the parameter.
// Needs the `lac` executable built in the same build folder.
#include <gtest/gtest.h>

#include "tests/support/run_cli.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace {

using lac::test::run_lac;

// 000 Fig. 5a parameters with drawable endpoints (experiments/space_figures.cpp, θ = 1.2).
const std::string kEnds =
    "--p0 0,0,0 --v0 1,0,0 --p1 0.36235775447667362,0.93203908596722629,0 "
    "--v1=-0.4838825660252134,0.8293701183329452,0.279289937364832 ";

TEST(CliSpace, CompoundJsonHasTheDocumentedKeysAndPoints) {
  const auto r = run_lac("space " + kEnds + "--alpha -1 --beta -1 --omega 0.1 --type 1 --alpha1 1 --beta1 1 --r-theta 0.5 --samples 7");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"status", "length", "kappa0", "kappa1", "residuals", "iterations", "seconds", "segments", "points", "info"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["status"], "ok");
  EXPECT_LE(j["residuals"]["angle"].get<double>(), 1e-10);
  EXPECT_TRUE(j["info"]["joint"]["x"].is_number());
  ASSERT_EQ(j["segments"].size(), 2u);
  for (const auto& seg : j["segments"]) {
    EXPECT_EQ(seg["kind"], "la-space");
    for (const char* key : {"alpha", "beta", "lambda", "omega", "nu", "type", "length", "start", "kappa", "tau"})
      EXPECT_TRUE(seg.contains(key)) << key;
  }
  // The second segment starts at the joint; the lengths add up.
  EXPECT_NEAR(j["segments"][1]["start"]["x"].get<double>(), j["info"]["joint"]["x"].get<double>(), 1e-12);
  EXPECT_NEAR(j["segments"][0]["length"].get<double>() + j["segments"][1]["length"].get<double>(),
              j["length"].get<double>(), 1e-14);
  for (const char* key : {"s", "x", "y", "z", "kappa", "tau"}) EXPECT_TRUE(j["points"][0].contains(key)) << key;
  ASSERT_EQ(j["points"].size(), 7u);
  const auto& last = j["points"].back();
  EXPECT_NEAR(last["x"].get<double>(), 0.36235775447667362, 1e-12);
  EXPECT_NEAR(last["y"].get<double>(), 0.93203908596722629, 1e-12);
  EXPECT_NEAR(last["z"].get<double>(), 0.0, 1e-12);
}

TEST(CliSpace, G1WithEachSolverAndCsv) {
  for (const char* solver : {"simplex", "ceres", "newton"}) {
    const auto r = run_lac("space " + kEnds + "--alpha -1 --beta -1 --omega 0.1 --type 1 --solver " + solver);
    ASSERT_EQ(r.status, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j.contains("status") && j.contains("segments")) << solver;
    EXPECT_EQ(j["solver"], solver);
  }
  const auto c = run_lac("space " + kEnds + "--alpha -1 --beta -1 --omega 0.1 --type 1 --format csv");
  ASSERT_EQ(c.status, 0) << c.out;
  EXPECT_EQ(c.out.rfind("# status,message,length,kappa0,kappa1,iterations,evaluations,seconds,solver,integrator,", 0), 0u)
      << c.out;
  EXPECT_NE(c.out.find("\nkind,alpha,beta,lambda,omega,nu,type,length,start.x,start.y,start.z,kappa,tau\nla-space,"),
            std::string::npos)
      << c.out;
}

TEST(CliSpace, EveryIntegratorByNameAndUniformPoints) {
  for (const char* integrator : {"magnus6", "rk45", "rk4"}) {
    const auto r = run_lac("space " + kEnds + "--alpha -1 --beta -1 --omega 0.1 --type 1 --alpha1 1 --beta1 1 --samples 5 "
                           "--integrator " + integrator);
    ASSERT_EQ(r.status, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["integrator"], integrator);
    EXPECT_EQ(j["status"], "ok") << j["message"];
    const double length = j["length"].get<double>();
    ASSERT_EQ(j["points"].size(), 5u);
    for (size_t k = 0; k < 5; ++k) EXPECT_NEAR(j["points"][k]["s"].get<double>(), length * k / 4, 1e-14 * length);
  }
  auto r = run_lac("space " + kEnds + "--alpha 0 --beta 0 --omega 0.1 --type 1 --integrator euler");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("integrator"), std::string::npos) << r.out;
}

TEST(CliSpace, EveryIntegratorWithEverySolver) {
  for (const char* integrator : {"magnus6", "rk45", "rk4"})
    for (const char* solver : {"newton", "ceres", "simplex"}) {
      const auto r = run_lac("space " + kEnds + "--alpha -1 --beta -1 --omega 0.1 --type 1 --alpha1 1 --beta1 1 --samples 3 " +
                             "--integrator " + integrator + " --solver " + solver);
      ASSERT_EQ(r.status, 0) << integrator << " " << solver << ": " << r.out;
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["integrator"], integrator);
      EXPECT_EQ(j["solver"], solver);
      EXPECT_EQ(j["status"], "ok") << integrator << " " << solver << ": " << j["message"];
      EXPECT_LE(j["residuals"]["angle"].get<double>(), 1e-10);
      ASSERT_EQ(j["points"].size(), 3u);
      const auto& last = j["points"].back();
      EXPECT_NEAR(last["x"].get<double>(), 0.36235775447667362, 1e-12) << integrator << " " << solver;
      EXPECT_NEAR(last["y"].get<double>(), 0.93203908596722629, 1e-12) << integrator << " " << solver;
      EXPECT_NEAR(last["z"].get<double>(), 0.0, 1e-12) << integrator << " " << solver;
    }
}

TEST(CliSpace, BadInputExitsWithStatus2NamingTheParameter) {
  auto r = run_lac("space --p0 0,0,0 --v0 1,0,0 --p1 2,0,0 --v1 0,1,0 --alpha 0 --beta 0 --omega 0.1 --type 1");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("v0"), std::string::npos) << r.out;
  r = run_lac("space " + kEnds + "--alpha 0 --beta 0 --omega 0.1 --type 3");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("type"), std::string::npos) << r.out;
  r = run_lac("space " + kEnds + "--alpha 0 --beta 0 --omega 0.1 --type 1 --r-theta 1.5");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("r_theta"), std::string::npos) << r.out;
  r = run_lac("space " + kEnds + "--alpha 0 --beta 0 --omega 0.1 --type 1 --solver bfgs");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("solver"), std::string::npos) << r.out;
  r = run_lac("space --p0 0,0 --v0 1,0,0 --p1 1,1,0 --v1 0,1,0 --alpha 0 --beta 0 --omega 0.1 --type 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("p0"), std::string::npos) << r.out;
}

}  // namespace
