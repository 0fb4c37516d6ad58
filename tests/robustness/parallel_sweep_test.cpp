// Parallel sweeps give the same results with 1 and with N threads: the solvers keep no
// shared mutable state, so a TBB sweep over independent problems must reproduce the sequential
// answers bit for bit. Covered: the drawable-region sweep of planar segments (the cells of
// experiments/planar_drawable.cpp, in-process and through the experiment executable with
// --threads 1 / 2) and the random problems of the solver experiments (planar triangles as in
// planar_solvers, G2 Hermite data as in g2_random, space segments from drawable_cases.hpp).
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/triangle_g1.hpp"
#include "lac/constructions/space_drawable_cases.hpp"

namespace {

constexpr int kThreads = 4;  // more than the cores of the CI machine: forces interleaving

/// Bit pattern of a double, so that the comparison is exact (NaN == NaN, 0 != −0).
uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

/// Runs solve(k) for k < n into a vector, on `threads` TBB workers.
template <class Result>
std::vector<Result> sweep(size_t n, int threads, const std::function<Result(size_t)>& solve) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
  std::vector<Result> out(n);
  tbb::parallel_for(size_t{0}, n, [&](size_t k) { out[k] = solve(k); });
  return out;
}

/// What a sweep records of one solve: status and the numbers, as bit patterns.
struct Fingerprint {
  std::string status;
  std::vector<uint64_t> numbers;
  bool operator==(const Fingerprint&) const = default;
};

template <class Solve>
void expect_same_with_1_and_n_threads(size_t n, Solve solve) {
  const std::function<Fingerprint(size_t)> f = solve;
  const auto one = sweep<Fingerprint>(n, 1, f);
  const auto many = sweep<Fingerprint>(n, kThreads, f);
  ASSERT_EQ(one.size(), many.size());
  size_t differing = 0;
  for (size_t k = 0; k < n; ++k) {
    if (one[k] == many[k]) continue;
    ++differing;
    ADD_FAILURE() << "problem " << k << ": status " << one[k].status << " (1 thread) vs " << many[k].status << " ("
                  << kThreads << " threads), or different numbers";
  }
  EXPECT_EQ(differing, 0u) << "of " << n << " problems";
  // Guard against a vacuous sweep: at least one problem must have been solved.
  size_t ok = 0;
  for (const auto& r : one) ok += r.status == "ok";
  EXPECT_GT(ok, 0u) << "no problem of the sweep was solved; the comparison would be vacuous";
}

Fingerprint fingerprint(const lac::TriangleResult& g) {
  Fingerprint f{std::string(lac::to_string(g.summary.status)), {}};
  const lac::PlanarCurve& c = g.curve;
  const bool curve = !c.segments().empty();
  for (double v : {c.length(), curve ? c.kappa_at(0) : 0.0, curve ? c.kappa_at(c.length()) : 0.0, g.info.turning,
                   g.summary.residuals.angle.value_or(0.0), g.info.residual, g.info.rho_joint, g.info.joint.real(),
                   g.info.joint.imag()})
    f.numbers.push_back(bits(v));
  for (const auto& p : g.info.pieces) f.numbers.push_back(bits(p.lambda_user));
  f.numbers.push_back(static_cast<uint64_t>(g.summary.iterations));
  f.numbers.push_back(static_cast<uint64_t>(g.summary.evaluations));
  return f;
}

// The cells of experiments/planar_drawable.cpp on a coarse grid: base angles b0, b2 at cell
// centres, a0 = (0, 0), a2 = (1, 0), a monotonic and a compound panel.
TEST(ParallelSweep, PlanarDrawableCellsSameWithOneAndManyThreads) {
  constexpr int kGrid = 10;
  struct Cell {
    int panel, i, j;
  };
  std::vector<Cell> cells;
  for (int p = 0; p < 3; ++p)
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j + i + 1 < kGrid; ++j) cells.push_back({p, i, j});
  expect_same_with_1_and_n_threads(cells.size(), [&](size_t k) {
    const Cell& c = cells[k];
    const double b0 = (c.i + 0.5) * std::numbers::pi / kGrid, b2 = (c.j + 0.5) * std::numbers::pi / kGrid;
    const double h = std::sin(b0) * std::sin(b2) / std::sin(b0 + b2);
    const lac::ControlTriangle t{{0, 0}, {h / std::tan(b0), h}, {1, 0}};
    if (c.panel == 0) return fingerprint(lac::solve_g1(t, -1.0));
    if (c.panel == 1) return fingerprint(lac::solve_g1(t, 2.0));
    return fingerprint(lac::solve_compound(t, -1.0, 1.5, 0.5));
  });
}

// Random drawable triangles as in experiments/planar_solvers.cpp (any rotation, scale, mirror).
TEST(ParallelSweep, RandomPlanarTrianglesSameWithOneAndManyThreads) {
  std::mt19937_64 rng(20260521);
  std::uniform_real_distribution<double> u(0, 1);
  struct Case {
    lac::ControlTriangle t;
    double alpha0, alpha1, r;
    lac::RootMethod solver;
  };
  std::vector<Case> cases;
  while (cases.size() < 48) {
    const double b0 = 0.05 + 1.5 * u(rng), b2 = 0.05 + 1.5 * u(rng);
    if (b0 + b2 > std::numbers::pi - 0.05) continue;
    const double h = std::sin(b0) * std::sin(b2) / std::sin(b0 + b2);
    const lac::Point2 rot = std::polar(std::pow(10.0, 4 * u(rng) - 2), 2 * std::numbers::pi * u(rng));
    const lac::Point2 apex{h / std::tan(b0), u(rng) < 0.5 ? -h : h};
    const lac::Point2 origin{3, -1};
    cases.push_back({{origin, origin + apex * rot, origin + rot}, -2 + 5 * u(rng), -2 + 5 * u(rng), 0.1 + 0.8 * u(rng),
                     static_cast<lac::RootMethod>(cases.size() % 4)});
  }
  expect_same_with_1_and_n_threads(cases.size(), [&](size_t k) {
    const Case& c = cases[k];
    lac::TriangleOptions o;
    o.solver = c.solver;
    return fingerprint(k % 2 ? lac::solve_compound(c.t, c.alpha0, c.alpha1, c.r, o) : lac::solve_g1(c.t, c.alpha0, o));
  });
}

// Random G2 Hermite data as in experiments/g2_random.cpp, every solver.
TEST(ParallelSweep, RandomG2ProblemsSameWithOneAndManyThreads) {
  using namespace lac;
  std::mt19937_64 rng(20130501);
  std::uniform_real_distribution<double> angle(-std::numbers::pi / 2, std::numbers::pi / 2), curvature(-3, 3);
  std::vector<G2Problem> problems;
  for (int i = 0; i < 24; ++i) {
    const double t0 = angle(rng), k0 = curvature(rng), t1 = angle(rng), k1 = curvature(rng);
    problems.push_back({{{0, 0}, t0, k0}, {{1, 0}, t1, k1}, i % 2 ? -1.0 : -0.5});
  }
  expect_same_with_1_and_n_threads(problems.size(), [&](size_t k) {
    G2Options o;
    o.solver = g2_solvers()[k % g2_solvers().size()].method;
    o.grid_fallback = false;
    const G2Result r = solve_g2(problems[k], o);
    const Summary& e = r.summary;
    Fingerprint f{std::string(lac::to_string(e.status)), {}};
    for (double v : {r.curve.length(), e.residuals.position.value_or(-1), e.residuals.angle.value_or(-1),
                     e.residuals.curvature.value_or(-1)})
      f.numbers.push_back(bits(v));
    f.numbers.push_back(static_cast<uint64_t>(e.iterations));
    f.numbers.push_back(static_cast<uint64_t>(e.evaluations));
    f.numbers.push_back(static_cast<uint64_t>(e.constructions));
    return f;
  });
}

// Random drawable space configurations (constructions/space_drawable_cases.hpp), G1 and compound.
TEST(ParallelSweep, RandomSpaceSegmentsSameWithOneAndManyThreads) {
  std::mt19937_64 rng(20110315);
  std::vector<lac::DrawableCase> cases;
  for (int i = 0; i < 8; ++i) {
    bool ok = false;
    cases.push_back(lac::random_drawable_case(rng, i % 2 == 1, &ok));
    ASSERT_TRUE(ok) << "case " << i << " could not be drawn";
  }
  expect_same_with_1_and_n_threads(cases.size(), [&](size_t k) {
    const lac::DrawableCase& c = cases[k];
    const auto r = c.compound ? lac::solve_compound_space_segment(c.ends, c.spec)
                              : lac::solve_g1_space_segment(c.ends, c.g1());
    Fingerprint f{std::string(lac::to_string(r.summary.status)), {}};
    for (double v : {r.curve.length(), r.curve.placement().scale, r.summary.residuals.angle.value_or(-1.0),
                     r.summary.residuals.position.value_or(-1.0)})
      f.numbers.push_back(bits(v));
    for (const auto& p : r.curve.pieces()) f.numbers.push_back(bits(p.law.lambda()));
    f.numbers.push_back(static_cast<uint64_t>(r.summary.iterations));
    f.numbers.push_back(static_cast<uint64_t>(r.summary.constructions));
    return f;
  });
}

/// Output of a command (stdout and stderr) and its exit status.
int run_command(const std::string& cmd, std::string* output) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((cmd + " 2>&1").c_str(), "r"), pclose);
  if (!pipe) return -1;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe.get())) output->append(buf, n);
  const int status = pclose(pipe.release());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> data_lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

// The experiment itself: its per-cell grid must not depend on --threads.
TEST(ParallelSweep, PlanarDrawableExperimentSameGridWithOneAndTwoThreads) {
  const std::filesystem::path exe = std::filesystem::path(LAC_BINARY_DIR) / "exp_planar_drawable";
  ASSERT_TRUE(std::filesystem::exists(exe)) << exe << " is not built (build the exp_planar_drawable target)";
  const auto dir = std::filesystem::temp_directory_path() / ("lac_parallel_" + std::to_string(::getpid()));
  std::vector<std::vector<std::string>> grids;
  for (int threads : {1, 2}) {
    const auto out = dir / ("threads_" + std::to_string(threads));
    std::string log;
    ASSERT_EQ(run_command(exe.string() + " --grid 6 --threads " + std::to_string(threads) + " --out " + out.string(), &log), 0)
        << log;
    grids.push_back(data_lines(out / "planar_drawable_grid.csv"));
  }
  std::filesystem::remove_all(dir);
  ASSERT_GT(grids[0].size(), 1u) << "empty grid";
  EXPECT_EQ(grids[0], grids[1]);
}

}  // namespace
