// lac g1 and lac compound: every --integrator and --solver of the registries, the JSON keys, the
// statuses and bad names.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "lac/integrators/registry.hpp"
#include "lac/solvers/root_1d.hpp"
#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

const std::string kG1 = "g1 --points '0,0 1,0 2,1' --alpha -1";
const std::string kCompound = "compound --points '3,2 1.5,0.2 0.5,0.9' --alpha0 2 --alpha1 0.5 --r 0.3";  // swapped, mirrored

nlohmann::json run_json(const std::string& args, int exit_status = 0) {
  const test::CliRun run = test::run_lac(args);
  EXPECT_EQ(run.status, exit_status) << args << "\n" << run.out;
  try {
    return nlohmann::json::parse(run.out);
  } catch (const nlohmann::json::exception& e) {
    ADD_FAILURE() << args << ": not JSON (" << e.what() << ")\n" << run.out;
    return {};
  }
}

std::set<std::string> keys(const nlohmann::json& j) {
  std::set<std::string> out;
  for (const auto& [k, v] : j.items()) out.insert(k);
  return out;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(CliTriangle, JsonKeys) {
  const std::set<std::string> common = {"status",     "length",         "kappa0",         "kappa1",     "alpha",
                                        "lambda",     "lambda_user",    "segment_lengths", "segment0_at_a0", "turning",
                                        "tangent_error", "iterations",  "bracket_probes", "trials",     "evaluations",
                                        "seconds",    "solver",         "integrator"};
  const nlohmann::json g = run_json(kG1);
  EXPECT_EQ(keys(g), common) << g.dump();
  std::set<std::string> compound = common;
  compound.insert({"joint", "rho_joint", "points"});
  const nlohmann::json c = run_json(kCompound + " --points-out 9");
  EXPECT_EQ(keys(c), compound) << c.dump();
  EXPECT_EQ(c["segment0_at_a0"], false);
  EXPECT_EQ(c["integrator"], "gk-tanh-sinh");
  EXPECT_EQ(c["solver"], "toms748");
  // The points run from a0 to a2; the pieces share them by length, the joint once (in piece 0).
  const auto& pts = c["points"];
  ASSERT_EQ(pts.size(), 9u);
  EXPECT_NEAR(pts.front()["x"].get<double>(), 3, 1e-14);
  EXPECT_NEAR(pts.back()["x"].get<double>(), 0.5, 1e-14);
  EXPECT_NEAR(pts.back()["s"].get<double>(), c["length"].get<double>(), 1e-14);
  EXPECT_EQ(pts.front()["segment"], 1);  // swapped: segment 0 (α0) is at a2
  EXPECT_EQ(pts.back()["segment"], 0);
  int joints = 0;
  for (const auto& p : pts)
    joints += std::abs(p["x"].get<double>() - c["joint"][0].get<double>()) < 1e-12 &&
              std::abs(p["y"].get<double>() - c["joint"][1].get<double>()) < 1e-12;
  EXPECT_EQ(joints, 1);
  const double piece0 = c["segment_lengths"][0].get<double>(), piece1 = c["segment_lengths"][1].get<double>();
  EXPECT_NEAR(piece0 + piece1, c["length"].get<double>(), 1e-14);
}

// Every integrator × every solver name (aliases too): ok, and the same curve as the defaults to
// the integrator's accuracy (rk4's fixed step 1e-3 is the loosest).
TEST(CliTriangle, EveryIntegratorAndSolverAgree) {
  std::vector<std::string> solvers;
  for (const RootMethodInfo& m : root_methods()) {
    solvers.emplace_back(m.name);
    for (const auto& alias : m.aliases) solvers.emplace_back(alias);
  }
  for (const std::string& base : {kG1, kCompound}) {
    const nlohmann::json ref = run_json(base);
    ASSERT_EQ(ref["status"], "ok") << ref.dump();
    for (const MethodInfo& q : quadrature_methods()) {
      for (const std::string& solver : solvers) {
        const std::string args = base + " --integrator " + std::string(q.name) + " --solver " + solver;
        const nlohmann::json j = run_json(args);
        ASSERT_EQ(j["status"], "ok") << args << ": " << j.dump();
        EXPECT_EQ(j["solver"], std::string(to_string(parse_root_method(solver)))) << args;
        EXPECT_EQ(j["integrator"].get<std::string>().rfind(std::string(q.name), 0), 0u) << args << ": " << j["integrator"];
        EXPECT_LE(rel(j["length"].get<double>(), ref["length"].get<double>()), 1e-11) << args;
        EXPECT_LE(rel(j["kappa0"].get<double>(), ref["kappa0"].get<double>()), 1e-11) << args;
        EXPECT_LE(rel(j["lambda_user"][0].get<double>(), ref["lambda_user"][0].get<double>()), 1e-11) << args;
        EXPECT_LE(j["tangent_error"].get<double>(), 1e-11) << args;
      }
    }
  }
}

TEST(CliTriangle, CsvAndSvg) {
  const test::CliRun csv = test::run_lac(kCompound + " --format csv");
  ASSERT_EQ(csv.status, 0) << csv.out;
  EXPECT_NE(csv.out.find("# status ok"), std::string::npos) << csv.out;
  EXPECT_NE(csv.out.find("segment,alpha,lambda,lambda_user,turning,length,rho_small,rho_large\n0,2,"), std::string::npos)
      << csv.out;
  const test::CliRun points = test::run_lac(kG1 + " --format csv --points-out 5");
  ASSERT_EQ(points.status, 0) << points.out;
  EXPECT_NE(points.out.find("x,y,s,theta,kappa,segment\n0,0,0,"), std::string::npos) << points.out;
  const test::CliRun svg = test::run_lac(kCompound + " --format svg");
  ASSERT_EQ(svg.status, 0) << svg.out;
  EXPECT_EQ(svg.out.rfind("<svg", 0), 0u) << svg.out;
  EXPECT_NE(svg.out.find("#d62728"), std::string::npos);  // segment 1 drawn
}

TEST(CliTriangle, StatusesAndBadInput) {
  // Proven outside the drawable region: a status with its reason, exit 3 (no usable curve).
  const nlohmann::json none = run_json("g1 --points '0,0 1,0 2,1' --alpha 5", 3);
  EXPECT_EQ(none["status"], "no_solution");
  EXPECT_NE(none["message"].get<std::string>().find("drawable region"), std::string::npos) << none.dump();
  EXPECT_EQ(none["length"], 0.0);
  // Unknown names: exit 2 listing the valid ones.
  const test::CliRun solver = test::run_lac(kG1 + " --solver foo");
  EXPECT_EQ(solver.status, 2);
  EXPECT_NE(solver.out.find("toms748"), std::string::npos) << solver.out;
  const test::CliRun integrator = test::run_lac(kCompound + " --integrator foo");
  EXPECT_EQ(integrator.status, 2);
  EXPECT_NE(integrator.out.find("gk-tanh-sinh"), std::string::npos) << integrator.out;
  const test::CliRun option = test::run_lac(kG1 + " --tol 1e-10");  // an option without --integrator
  EXPECT_EQ(option.status, 2);
  EXPECT_NE(option.out.find("--integrator"), std::string::npos) << option.out;
  const test::CliRun collinear = test::run_lac("g1 --points '0,0 1,0 2,0' --alpha 1");
  EXPECT_EQ(collinear.status, 2);
  EXPECT_NE(collinear.out.find("turning"), std::string::npos) << collinear.out;
}

}  // namespace
}  // namespace lac
