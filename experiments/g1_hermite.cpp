// G1 Hermite interpolation by one LA segment on the standard clothoid test set: P0 = (0,0),
// P1 = (1,0), θ0, θ1 uniform in (−π/2, π/2) (2000 problems, tests/support/g1_problem_set.hpp), at
// nine α. Per α, solver and input shape: solved, proven no curve, failed, iterations, largest
// residual; wall time per solve (median, p90) in the timing table. The paper methods (001's
// similar-triangle search, 004's Λ search) run beside the default on the inputs they accept.
// Writes results/g1_hermite.{md,csv}, g1_hermite_timing.{md,csv} and g1_hermite_grid.csv (status
// of every problem under the default solver, for experiments/figures/g1_hermite.py).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>

#include "io/table.hpp"
#include "lac/common/error.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "tests/support/g1_problem_set.hpp"

namespace {

using namespace lac;

struct Tally {
  int problems = 0, solved = 0, no_curve = 0, failed = 0;
  std::vector<double> micros;
  std::vector<int> iterations;
  double worst_residual = 0;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(std::min<double>(v.size() - 1, std::floor(q * (v.size() - 1) + 0.5)))];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"G1 Hermite by one LA segment on the 2000-problem clothoid test set"};
  std::string out = "results";
  int count = test::kG1ProblemCount;
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--problems", count, "Problems of the set to run")->capture_default_str()->check(CLI::Range(1, 1000000));
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const std::string cmd = io::command_line(argc, argv);
  const auto set = test::g1_problem_set(count);
  const double alphas[] = {-3, -2, -1, -0.5, 0, 0.5, 1, 2, 3};
  const char* solvers[] = {"auto", "toms748", "triangle", "s-curve"};
  const G1Shape shapes[] = {G1Shape::convex, G1Shape::convex_inflection, G1Shape::s_shaped, G1Shape::other};

  std::ofstream grid(std::filesystem::path(out) / "g1_hermite_grid.csv");
  grid << "# written by: " << cmd << "\n";
  grid << "# every problem of the set under the default solver: theta0, theta1 (rad), shape of the input or solution, "
          "status\n";
  grid << "alpha,theta0,theta1,shape,status\n";
  grid.precision(17);
  io::write_numbers_plainly(grid);

  io::Table t;
  t.columns = {"α", "solver", "shape", "problems", "solved", "no curve (proven)", "failed", "median iterations", "max residual", "median µs", "p90 µs"};
  for (double alpha : alphas) {
    for (const char* solver : solvers) {
      std::map<G1Shape, Tally> by_shape;
      int not_applicable = 0;
      G1HermiteOptions o;
      o.solver = parse_g1_solver(solver);
      for (const test::G1Angles& a : set) {
        const G1HermiteProblem p{{0, 0}, a.theta0, {1, 0}, a.theta1, alpha};
        G1HermiteResult r;
        const auto t0 = std::chrono::steady_clock::now();
        try {
          r = solve_g1_hermite(p, o);
        } catch (const InputError&) {  // a paper method on an input it does not take
          ++not_applicable;
          continue;
        }
        const double us = 1e6 * seconds_since(t0);
        Tally& s = by_shape[r.info.shape];
        ++s.problems;
        if (r.usable()) {
          ++s.solved;
          s.worst_residual = std::max({s.worst_residual, r.summary.residuals.position.value_or(0.0),
                                       r.summary.residuals.angle.value_or(0.0)});
        } else if (r.summary.status == Status::no_solution) {
          ++s.no_curve;
        } else {
          ++s.failed;
        }
        s.micros.push_back(us);
        s.iterations.push_back(r.summary.iterations);
        if (std::string(solver) == "auto")
          grid << alpha << "," << a.theta0 << "," << a.theta1 << "," << to_string(r.info.shape) << ","
               << to_string(r.summary.status) << "\n";
      }
      for (G1Shape shape : shapes) {
        Tally& s = by_shape[shape];
        if (s.problems == 0) continue;
        std::vector<double> it(s.iterations.begin(), s.iterations.end());
        t.add_row({io::fmt(alpha), solver, std::string(to_string(shape)), std::to_string(s.problems),
                   std::to_string(s.solved), std::to_string(s.no_curve), std::to_string(s.failed),
                   io::fmt(quantile(it, 0.5)), s.solved ? io::sci(s.worst_residual, 2) : "—",
                   io::fmt(quantile(s.micros, 0.5)), io::fmt(quantile(s.micros, 0.9))});
      }
      if (not_applicable > 0)
        t.add_row({io::fmt(alpha), solver, "not applicable", std::to_string(not_applicable), "—", "—", "—", "—", "—", "—", "—"});
    }
  }
  io::ResultDoc doc;
  doc.title = "G1 Hermite by one LA segment: the 2000-problem clothoid test set at nine α";
  doc.command = cmd;
  doc.description =
      "P0 = (0,0), P1 = (1,0), θ0 and θ1 uniform in (−π/2, π/2) (splitmix64, tests/support/g1_problem_set.hpp), "
      "the standard test set of G1 clothoid solvers, solved at each α with constructions/g1_hermite.hpp. Shapes "
      "(G1Shape): convex = tangents on opposite sides of the chord, no inflection; convex-inflection = the same "
      "input with an inflection in the curve; s-shaped = tangents on the same side of the chord (an inflection "
      "is needed); other = a tangent along the chord, |turning| ≥ π. solver auto is the default (safeguarded "
      "Newton with analytic derivative); toms748 is the 1-D registry's method on the same equation; triangle is "
      "001's similar-triangle search and s-curve 004's Λ search, each run only on the inputs it takes (the rest "
      "are counted in the row \"not applicable\"). no curve (proven): status no_solution, whose message "
      "states the proof (α ≥ 0: κ cannot change sign). max residual: the largest end-point (chord units) or "
      "end-angle (rad) error of the solved curves. Status map: results/figures/g1_hermite.png.";
  doc.notes =
      "Times are wall times of single calls inside this experiment (steady_clock), for comparing solvers within "
      "one run; the benchmark of record is bench/g1_hermite.cpp (docs/g1_hermite.md).";
  io::write_result_table_with_timing(out, "g1_hermite", doc, t, {"α", "solver", "shape"}, {"median µs", "p90 µs"},
                                     "Wall time per solve, median and 90th percentile over the problems of the row.");
  return 0;
}
