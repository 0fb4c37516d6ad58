// lac g1 (Hermite data or control triangle), lac scurve (four points) and lac chain: the same G1
// Hermite problem entered three ways gives the same curve; every solver of g1_hermite_solvers() and
// every integrator; the papers' searches on the inputs they take; --degrees; chain reports.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "lac/constructions/chain.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/integrators/registry.hpp"
#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Control triangle (0,0) (1,0) (2,1): θ0 = 0, θ1 = π/4, P1 = (2,1).
const std::string kTriangle = "g1 --points '0,0 1,0 2,1' --alpha -0.5";
const std::string kHermite = "g1 --p0 0,0 --theta0 0 --p1 2,1 --theta1 0.7853981633974483 --alpha -0.5";

TEST(CliG1, TriangleHermiteAndLibraryAgree) {
  const auto t = test::run_lac_json(kTriangle), h = test::run_lac_json(kHermite);
  const G1HermiteResult lib = solve_g1_hermite({{0, 0}, 0, {2, 1}, std::numbers::pi / 4, -0.5});
  ASSERT_TRUE(lib.usable());
  for (const auto* j : {&t, &h}) {
    ASSERT_EQ((*j)["status"], "ok") << j->dump();
    EXPECT_LE(rel((*j)["length"].get<double>(), lib.curve.length()), 1e-14);
    EXPECT_LE(rel((*j)["kappa0"].get<double>(), lib.curve.kappa_at(0)), 1e-13);
    EXPECT_LE(rel((*j)["kappa1"].get<double>(), lib.curve.kappa_at(lib.curve.length())), 1e-13);
    EXPECT_EQ((*j)["solver"], "auto");
    EXPECT_EQ((*j)["info"]["shape"], "convex");
    EXPECT_TRUE((*j)["inflection"].is_null());  // convex, no inflection
    EXPECT_EQ((*j)["segments"].size(), 1u);
  }
  // Degrees: the same problem.
  const auto d = test::run_lac_json("g1 --p0 0,0 --theta0 0 --p1 2,1 --theta1 45 --degrees --alpha -0.5");
  EXPECT_LE(rel(d["length"].get<double>(), lib.curve.length()), 1e-14);
  // Both input forms at once, or neither: invalid.
  EXPECT_EQ(test::run_lac(kTriangle + " --p0 0,0").status, 2);
  EXPECT_EQ(test::run_lac("g1 --alpha -1").status, 2);
  EXPECT_EQ(test::run_lac("g1 --p0 0,0 --theta0 0 --p1 2,1 --alpha -1").status, 2);  // no --theta1
}

// The solver names are the registries': an alias of the root registry names its method in g1 too.
TEST(CliG1, SolverAliasesAreTheRootRegistrys) {
  const auto j = test::run_lac_json(kTriangle + " --solver newton");
  EXPECT_EQ(j["status"], "ok") << j.dump();
  EXPECT_EQ(j["solver"], "secant") << j.dump();
  const auto bad = test::run_lac("g1 --p0 0,0 --theta0 0.3 --p1 1,0 --theta1 -0.2 --alpha -1 --solver brent");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("solver"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("secant (alias newton)"), std::string::npos) << bad.out;
}

// Every solver name × every integrator (which checks the result and draws the points): the same curve.
TEST(CliG1, EverySolverAndIntegrator) {
  const auto ref = test::run_lac_json(kTriangle);
  for (const auto& s : g1_hermite_solvers()) {
    if (s.name == "s-curve") continue;  // S-shaped input only: below
    for (const MethodInfo& q : quadrature_methods()) {
      const std::string args = kTriangle + " --solver " + std::string(s.name) + " --integrator " + std::string(q.name) + " --samples 3";
      const auto j = test::run_lac_json(args);
      ASSERT_EQ(j["status"], "ok") << args << ": " << j.dump();
      EXPECT_EQ(j["solver"].get<std::string>().rfind(std::string(s.name), 0), 0u) << args << ": " << j["solver"];
      EXPECT_LE(rel(j["length"].get<double>(), ref["length"].get<double>()), 1e-10) << args;
      EXPECT_LE(rel(j["kappa0"].get<double>(), ref["kappa0"].get<double>()), 1e-9) << args;
      if (s.name != "triangle") {  // 001's search measures the end angle only
        EXPECT_LE(j["residuals"]["position"].get<double>(), 1e-9) << args;
      }
      EXPECT_LE(j["residuals"]["angle"].get<double>(), 1e-9) << args;
      EXPECT_EQ(j["points"].size(), 3u) << args;
    }
  }
  // A paper method on input it does not take: invalid input naming the solver.
  const test::CliRun s = test::run_lac(kTriangle + " --solver s-curve");
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.out.find("solver"), std::string::npos) << s.out;
}

// scurve's four points are G1 Hermite data: the default solver and [Miura et al. 2013]'s Λ search
// give the same curve, and so does g1 with the same data.
TEST(CliG1, SCurveIsTheSameProblem) {
  const std::string pts = "'0,0 1,0 1.6,1.2 3,1'";
  const auto a = test::run_lac_json("scurve --points " + pts + " --alpha -0.5");
  const auto b = test::run_lac_json("scurve --points " + pts + " --alpha -0.5 --solver s-curve");
  const auto g = test::run_lac_json("g1 --p0 0,0 --theta0 0 --p1 3,1 --theta1 " + std::to_string(std::atan2(1 - 1.2, 3 - 1.6)) +
                          " --alpha -0.5");
  ASSERT_EQ(a["status"], "ok") << a.dump();
  ASSERT_EQ(b["status"], "ok") << b.dump();
  EXPECT_EQ(a["info"]["shape"], "s-shaped");
  EXPECT_LE(rel(a["length"].get<double>(), b["length"].get<double>()), 1e-11);
  EXPECT_LE(rel(a["length"].get<double>(), g["length"].get<double>()), 1e-5);  // θ1 printed to 6 digits
  EXPECT_LE(rel(a["inflection"].get<double>(), b["inflection"].get<double>()), 1e-10);
}

TEST(CliG1, ChainReports) {
  const std::string pts = "'0,0 2,-0.5 4,0.3 5,2 4,4 2,4.6 0.2,3.8 -0.8,2'";
  const auto g1 = test::run_lac_json("chain --points " + pts + " --alpha -1 --closed --samples 5");
  ASSERT_EQ(g1["status"], "ok") << g1.dump();
  EXPECT_EQ(g1["segments"].size(), 8u);
  EXPECT_EQ(g1["info"]["pairs"], 8);
  EXPECT_TRUE(g1["info"]["failed_pair"].is_null());
  EXPECT_EQ(g1["info"]["thetas"].size(), 8u);
  EXPECT_EQ(g1["points"].size(), 5u);
  EXPECT_NEAR(g1["points"][4]["x"].get<double>(), 0, 1e-9);  // closed: back at the start
  const auto g2 = test::run_lac_json("chain --points " + pts + " --alpha -1 --closed --continuity g2");
  ASSERT_EQ(g2["status"], "ok") << g2.dump();
  EXPECT_EQ(g2["segments"].size(), 24u);
  EXPECT_EQ(g2["solver"], "newton");
  // Given tangents in degrees, the library's curve.
  const auto given = test::run_lac_json("chain --points '0,0 1,0.5 2,0' --thetas '10 -20 5' --degrees --alpha -1");
  const double d = std::numbers::pi / 180;
  const ChainResult lib = solve_chain({.points = {{0, 0}, {1, 0.5}, {2, 0}}, .thetas = {10 * d, -20 * d, 5 * d}, .alpha = -1});
  ASSERT_TRUE(lib.usable());
  EXPECT_LE(rel(given["length"].get<double>(), lib.curve.length()), 1e-14);
  EXPECT_EQ(given["info"]["tangents"], "given");
  // Bad input: exit 2 naming the parameter.
  for (const auto& [args, parameter] : {std::pair<std::string, std::string>{"chain --points '0,0' --alpha -1", "points"},
                                        {"chain --points '0,0 1,0' --thetas '0 1 2' --alpha -1", "thetas"},
                                        {"chain --points '0,0 1,0' --alpha -1 --continuity g3", "continuity"},
                                        {"chain --points '0,0 1,0 2,1' --alpha -1 --solver foo", "solver"}}) {
    const test::CliRun r = test::run_lac(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(parameter), std::string::npos) << args << "\n" << r.out;
  }
}

}  // namespace
}  // namespace lac
