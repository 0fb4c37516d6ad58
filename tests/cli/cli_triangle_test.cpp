// lac compound (and lac g1's control-triangle input): every --integrator and --solver of the
// registries, the JSON keys, the statuses and bad names. lac g1's solvers: cli_g1_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lac/constructions/triangle_g1.hpp"
#include "lac/integrators/registry.hpp"
#include "lac/solvers/root_1d.hpp"
#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

const std::string kG1 = "g1 --points '0,0 1,0 2,1' --alpha -1";
const std::string kCompound = "compound --points '3,2 1.5,0.2 0.5,0.9' --alpha0 2 --alpha1 0.5 --r 0.3";  // swapped, mirrored

/// The keys in the printed order (parsed as ordered_json).
std::vector<std::string> ordered_keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> out;
  for (const auto& [k, v] : j.items()) out.push_back(k);
  return out;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(CliTriangle, JsonKeysAndSegmentsAgreeWithTheLibrary) {
  const std::vector<std::string> common = {"status",     "message",    "length",    "kappa0", "kappa1",
                                           "iterations", "evaluations", "seconds",  "solver", "integrator",
                                           "residuals",  "error",      "accept",
                                           "segments",   "info"};
  const nlohmann::ordered_json g = test::run_lac_json(kG1);
  std::vector<std::string> g1_keys = common;
  g1_keys.insert(g1_keys.end() - 1, "inflection");
  EXPECT_EQ(ordered_keys(g), g1_keys) << g.dump();
  EXPECT_TRUE(g["message"].is_null());
  std::vector<std::string> with_points = common;
  with_points.push_back("points");
  const nlohmann::ordered_json c = test::run_lac_json(kCompound + " --samples 9");
  EXPECT_EQ(ordered_keys(c), with_points) << c.dump();
  EXPECT_EQ(c["info"]["segment0_at_a0"], false);
  EXPECT_LT(c["info"]["turning"].get<double>(), 0);  // signed: a right turn
  EXPECT_EQ(c["integrator"], "gk-tanh-sinh");
  EXPECT_EQ(c["solver"], "toms748");
  // Segments in the curve's order from a0; swapped: the first one is 001's segment 1 (α1).
  const TriangleResult lib = solve_compound({{3, 2}, {1.5, 0.2}, {0.5, 0.9}}, 2, 0.5, 0.3);
  ASSERT_EQ(c["segments"].size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const auto& seg = c["segments"][k];
    const TrianglePiece& piece = lib.info.pieces[1 - k];
    EXPECT_EQ(seg["kind"], "la");
    EXPECT_EQ(seg["alpha"].get<double>(), piece.alpha);
    EXPECT_LE(rel(seg["lambda"].get<double>(), piece.lambda_user), 1e-12) << seg.dump();
    EXPECT_LE(rel(seg["length"].get<double>(), lib.curve.segments()[k].length()), 1e-15);
  }
  EXPECT_NEAR(c["segments"][1]["start"]["x"].get<double>(), c["info"]["joint"]["x"].get<double>(), 1e-12);
  EXPECT_NEAR(c["segments"][0]["kappa"].get<double>(), c["kappa0"].get<double>(), 1e-15);
  EXPECT_NEAR(c["segments"][1]["kappa_end"].get<double>(), c["kappa1"].get<double>(), 1e-12);
  // The points run from a0 to a2, uniform in s.
  const auto& pts = c["points"];
  ASSERT_EQ(pts.size(), 9u);
  EXPECT_NEAR(pts.front()["x"].get<double>(), 3, 1e-14);
  EXPECT_NEAR(pts.back()["x"].get<double>(), 0.5, 1e-14);
  EXPECT_NEAR(pts.back()["s"].get<double>(), c["length"].get<double>(), 1e-14);
  const double piece0 = c["segments"][0]["length"].get<double>(), piece1 = c["segments"][1]["length"].get<double>();
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
  for (const std::string& base : {kCompound}) {
    const nlohmann::ordered_json ref = test::run_lac_json(base);
    ASSERT_EQ(ref["status"], "ok") << ref.dump();
    for (const MethodInfo& q : quadrature_methods()) {
      for (const std::string& solver : solvers) {
        const std::string args = base + " --integrator " + std::string(q.name) + " --solver " + solver;
        const nlohmann::ordered_json j = test::run_lac_json(args);
        ASSERT_EQ(j["status"], "ok") << args << ": " << j.dump();
        EXPECT_EQ(j["solver"], std::string(to_string(parse_root_method(solver)))) << args;
        EXPECT_EQ(j["integrator"].get<std::string>().rfind(std::string(q.name), 0), 0u) << args << ": " << j["integrator"];
        EXPECT_LE(rel(j["length"].get<double>(), ref["length"].get<double>()), 1e-11) << args;
        EXPECT_LE(rel(j["kappa0"].get<double>(), ref["kappa0"].get<double>()), 1e-11) << args;
        EXPECT_LE(rel(j["segments"][0]["lambda"].get<double>(), ref["segments"][0]["lambda"].get<double>()), 1e-11) << args;
        EXPECT_LE(j["residuals"]["angle"].get<double>(), 1e-11) << args;
      }
    }
  }
}

TEST(CliTriangle, CsvAndSvg) {
  const test::CliRun csv = test::run_lac(kCompound + " --format csv");
  ASSERT_EQ(csv.status, 0) << csv.out;
  EXPECT_EQ(csv.out.rfind("# status,message,length,kappa0,kappa1,iterations,evaluations,seconds,solver,integrator,"
                          "residuals.position,residuals.angle,residuals.curvature,error,accept,info.segment0_at_a0,info.turning,",
                          0),
            0u)
      << csv.out;
  EXPECT_NE(csv.out.find("\n# ok,,"), std::string::npos) << csv.out;
  EXPECT_NE(csv.out.find("\nkind,alpha,q0,q1,lambda,length,start.x,start.y,theta,kappa,theta_end,kappa_end\nla,0.5,"),
            std::string::npos)
      << csv.out;
  const test::CliRun points = test::run_lac(kG1 + " --format csv --samples 5");
  ASSERT_EQ(points.status, 0) << points.out;
  EXPECT_NE(points.out.find("\ns,x,y,theta,kappa\n0,0,0,"), std::string::npos) << points.out;
  const test::CliRun svg = test::run_lac(kCompound + " --format svg");
  ASSERT_EQ(svg.status, 0) << svg.out;
  EXPECT_EQ(svg.out.rfind("<svg", 0), 0u) << svg.out;
  EXPECT_NE(svg.out.find("#d62728"), std::string::npos);  // segment 1 drawn
}

TEST(CliTriangle, StatusesAndBadInput) {
  // Proven outside the drawable region at winding 0 (turnings of at most pi): a status with its
  // reason, exit 3 (no usable curve).
  const nlohmann::ordered_json none = test::run_lac_json("g1 --points '0,0 1,0 2,1' --alpha 5 --winding 0", 3);
  EXPECT_EQ(none["status"], "no_solution");
  EXPECT_NE(none["message"].get<std::string>().find("alpha > 1"), std::string::npos) << none.dump();
  for (const char* key : {"length", "kappa0", "kappa1"}) EXPECT_TRUE(none[key].is_null()) << key;
  EXPECT_TRUE(none["segments"].empty());
  EXPECT_FALSE(none.contains("points"));
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
  const test::CliRun degenerate = test::run_lac("g1 --points '0,0 0,0 2,0' --alpha 1");
  EXPECT_EQ(degenerate.status, 2);
  EXPECT_NE(degenerate.out.find("points"), std::string::npos) << degenerate.out;
  const test::CliRun collinear = test::run_lac("compound --points '0,0 1,0 2,0' --alpha0 1 --alpha1 2");
  EXPECT_EQ(collinear.status, 2);
  EXPECT_NE(collinear.out.find("turning"), std::string::npos) << collinear.out;
  // The search's evaluation budget: out of range names the option (exit 2); spent, the status says
  // so (exit 3).
  const test::CliRun budget = test::run_lac(kCompound + " --max-evaluations 0");
  EXPECT_EQ(budget.status, 2);
  EXPECT_NE(budget.out.find("max-evaluations"), std::string::npos) << budget.out;
  const nlohmann::ordered_json spent = test::run_lac_json(kCompound + " --integrator rk4 --max-evaluations 10", 3);
  EXPECT_EQ(spent["status"], "max_iterations") << spent.dump();
  EXPECT_NE(spent["message"].get<std::string>().find("max_evaluations = 10"), std::string::npos) << spent.dump();
}

}  // namespace
}  // namespace lac
