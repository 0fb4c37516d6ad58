// Drawable regions of planar LA segments from control points (001 §6 names them as future
// work): over the control triangle's shape — its base angles b0 at a0 and b2 at a2, a0 = (0, 0),
// a2 = (1, 0) (position, orientation and scale do not matter) — and over (α0, α1, r), does a
// curve exist? Each cell is one solve with the default settings; its status (ok / no_solution /
// tolerance_not_met / other) goes to results/planar_drawable_grid.csv, a per-panel summary to
// planar_drawable.{md,csv}, heatmaps are drawn by experiments/figures/planar_drawable.py.
//
// The sweep runs on all cores (TBB parallel_for; every cell is independent and written into its
// own slot, so the output does not depend on the thread count: check with --threads 1). Beyond one
// machine the same cells run on a Dask cluster (python/examples/sweeps_dask.py, docs/python.md),
// whose rows are identical to this program's.
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>

#include "io/table.hpp"
#include "io/timing.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

struct Panel {
  double alpha0, alpha1, r;  // r = 1: monotonic segment of slope alpha0
};

const Panel kPanels[] = {
    {-2, -2, 1}, {-1, -1, 1}, {0, 0, 1}, {0.5, 0.5, 1}, {1, 1, 1}, {1.5, 1.5, 1}, {2, 2, 1}, {3, 3, 1},
    {-1, 1.5, 0.5}, {1.5, -1, 0.5}, {0.5, 2, 0.5}, {2, 0.5, 0.5}, {-1, 2, 0.2}, {-1, 2, 0.8}, {-2, -0.5, 0.5}, {3, 0, 0.5},
};

struct Cell {
  int panel = 0, i = 0, j = 0;
};

struct Outcome {
  std::string status;
  double lambda0 = 0;
  int iterations = 0;
};

/// Valid cells (b0 + b2 < π) of all panels in a fixed order (the row index of the outputs).
std::vector<Cell> all_cells(int grid) {
  std::vector<Cell> cells;
  for (int p = 0; p < static_cast<int>(std::size(kPanels)); ++p)
    for (int i = 0; i < grid; ++i)
      for (int j = 0; j < grid; ++j)
        if (i + j + 1 < grid) cells.push_back({p, i, j});  // centres satisfy b0 + b2 < π
  return cells;
}

double angle(int i, int grid) { return (i + 0.5) * kPi / grid; }

Outcome solve_cell(const Cell& c, int grid) {
  const double b0 = angle(c.i, grid), b2 = angle(c.j, grid);
  const double h = std::sin(b0) * std::sin(b2) / std::sin(b0 + b2);  // apex height on the unit base
  const lac::ControlTriangle t{{0, 0}, {h / std::tan(b0), h}, {1, 0}};
  const Panel& p = kPanels[c.panel];
  const lac::TriangleResult g = p.r < 1 ? lac::solve_compound(t, p.alpha0, p.alpha1, p.r) : lac::solve_g1(t, p.alpha0);
  Outcome o;
  o.status = std::string(lac::to_string(g.summary.status));
  o.iterations = g.summary.iterations;
  o.lambda0 = g.info.pieces.empty() ? 0 : g.info.pieces[0].lambda_user;
  return o;
}

std::string row_text(size_t index, const Cell& c, int grid, const Outcome& o) {
  const Panel& p = kPanels[c.panel];
  std::ostringstream os;
  os.precision(10);
  lac::io::write_numbers_plainly(os);
  os << index << ',' << c.panel << ',' << p.alpha0 << ',' << p.alpha1 << ',' << p.r << ',' << angle(c.i, grid) << ','
     << angle(c.j, grid) << ',' << o.status << ',' << o.lambda0 << ',' << o.iterations;
  return os.str();
}

const char* kHeader = "index,panel,alpha0,alpha1,r,b0,b2,status,lambda0_user,iterations";

void write_outputs(const fs::path& out, const std::string& cmd, int grid, const std::vector<std::string>& rows,
                   double seconds, int threads) {
  {
    std::ofstream f(out / "planar_drawable_grid.csv");
    f << "# written by: " << cmd << "\n";
    f << "# one row per control triangle a0=(0,0), a1 apex, a2=(1,0) with base angles b0 (at a0), b2 (at a2) in rad, "
         "grid " << grid << "x" << grid << " over (0, pi)^2 with b0+b2 < pi; r = 1 rows are monotonic segments; "
         "lambda0_user = Lambda of segment 0 in these units (0 if no curve)\n";
    f << kHeader << "\n";
    for (const auto& r : rows) f << r << "\n";
  }
  // Per-panel summary.
  std::map<int, std::map<std::string, int>> counts;
  std::map<int, std::vector<double>> iterations;
  for (const auto& r : rows) {
    std::stringstream ss(r);
    std::vector<std::string> v;
    std::string cell;
    while (std::getline(ss, cell, ',')) v.push_back(cell);
    const int panel = std::stoi(v[1]);
    counts[panel][v[7]]++;
    if (v[7] == "ok") iterations[panel].push_back(std::stod(v[9]));
  }
  lac::io::Table t;
  t.columns = {"α0", "α1", "r", "cells", "ok", "tolerance_not_met", "no_solution", "other status", "drawable share (ok)",
               "median iterations (ok)"};
  for (const auto& [panel, c] : counts) {
    const Panel& p = kPanels[panel];
    int total = 0, other = 0;
    for (const auto& [k, n] : c) {
      total += n;
      if (k != "ok" && k != "no_solution" && k != "tolerance_not_met") other += n;
    }
    const int ok = c.count("ok") ? c.at("ok") : 0;
    const int none = c.count("no_solution") ? c.at("no_solution") : 0;
    const int loose = c.count("tolerance_not_met") ? c.at("tolerance_not_met") : 0;
    auto& it = iterations[panel];
    std::sort(it.begin(), it.end());
    t.add_row({lac::io::fmt(p.alpha0), p.r < 1 ? lac::io::fmt(p.alpha1) : "(monotonic)", p.r < 1 ? lac::io::fmt(p.r) : "",
               std::to_string(total), std::to_string(ok), std::to_string(loose), std::to_string(none), std::to_string(other),
               lac::io::fmt(static_cast<double>(ok) / total, 3), it.empty() ? "" : lac::io::fmt(it[it.size() / 2])});
  }
  lac::io::ResultDoc doc;
  doc.title = "Drawable regions of planar G1 / compound-rhythm LA segments over the control triangle's shape";
  doc.command = cmd;
  doc.description =
      "Control triangle a0 = (0, 0), a2 = (1, 0), apex a1 above the base, base angles b0 (at a0) and b2 (at a2) on a " +
      std::to_string(grid) + " × " + std::to_string(grid) +
      " grid of cell centres over (0, π)² with b0 + b2 < π (the turning is b0 + b2). One solve per cell with the "
      "default settings (TOMS 748, Gauss–Kronrod / tanh-sinh positions); \"no_solution\" means the triangle is "
      "proven outside the drawable region (the start angle of the trial curves increases with Λ0, and the "
      "triangle's angle at the short-leg end is at or above its limit at the end of the Λ0 range), "
      "\"tolerance_not_met\" a curve whose end tangents miss the legs by more than 1e-11 rad (usable, "
      "found in extreme shapes where ρ varies by many orders of magnitude), \"other\" any other status "
      "(not_converged: a curve exists, but its Λ0 lies closer to the end of the range than the search resolves "
      "in double precision). By 001 §4 segment 0 (α0) is always put at the end with the shorter leg (the larger base "
      "angle), so every map is symmetric in b0 ↔ b2; the diagonal (isosceles triangles) is the circular arc, Λ0 = 0. Heatmaps: results/figures/planar_drawable.png. Wall time of the "
      "run: planar_drawable_timing.md.";
  doc.notes =
      "001 leaves the drawable regions as future work, so there is nothing to compare with. For monotonic "
      "0 < α ≤ 1 the length is unbounded as Λ → Λmax, the start angle tends to the turning, and every triangle is "
      "drawable. At α = 0 the length grows only like log(1/(Λmax − Λ)), so for the most skewed triangles the "
      "needed Λ0 lies closer to Λmax than double precision resolves (not_converged, counted as other status) "
      "or the tangents lose accuracy (tolerance_not_met). α < 0 (finite length up to the inflection) and α > 1 (ρ → 0 at the start) "
      "lose the triangles whose start angle is too close to the turning, i.e. one leg much shorter than the "
      "other. A finer grid: --grid 200 (or on a Dask cluster: python/examples/sweeps_dask.py --grid 200).";
  lac::io::write_result_table(out, "planar_drawable", doc, t);
  lac::io::Table tt;
  tt.columns = {"cells", "threads", "seconds"};
  tt.add_row({std::to_string(rows.size()), std::to_string(threads), lac::io::fmt(seconds, 3)});
  lac::io::ResultDoc tdoc;
  tdoc.title = doc.title + " — times";
  tdoc.command = cmd;
  tdoc.description =
      "Wall time of the whole grid of planar_drawable.md, a timing only for planning "
      "larger grids; it varies between runs.";
  lac::io::write_result_table(out, "planar_drawable_timing", tdoc, tt);
  std::cout << t.markdown();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Drawable-region maps of planar G1 / compound-rhythm LA segments (TBB)"};
  std::string out = "results";
  int grid = 36;
  int threads = 0;
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--grid", grid, "Cells per base-angle axis (default 36; 200 for a fine map)")->capture_default_str()->check(CLI::Range(4, 2000));
  app.add_option("--threads", threads, "Worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, 1024));
  CLI11_PARSE(app, argc, argv);
  const fs::path dir(out);
  fs::create_directories(dir);
  const std::string cmd = lac::io::command_line(argc, argv);
  const std::vector<Cell> cells = all_cells(grid);
  const int used_threads = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(used_threads));
  std::vector<std::string> rows(cells.size());
  lac::io::Stopwatch clock;
  tbb::parallel_for(size_t{0}, cells.size(), [&](size_t k) { rows[k] = row_text(k, cells[k], grid, solve_cell(cells[k], grid)); });
  const double seconds = clock.seconds();
  std::cerr << "planar_drawable: " << rows.size() << " cells in " << seconds << " s on " << used_threads << " threads\n";

  write_outputs(dir, cmd, grid, rows, seconds, used_threads);
  return 0;
}
