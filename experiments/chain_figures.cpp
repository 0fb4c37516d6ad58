// Closed LA chains through eight points: G1 chains at two α (tangents estimated by the circle
// through each point and its neighbours) and the G2 chain (curvatures estimated the same way).
// Writes results/chain_figures.{md,csv} (what was solved) and results/chain_figures_points.csv
// (samples with curvature) for experiments/figures/chain_figures.py (curve, curvature comb and
// curvature plot).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>

#include "io/table.hpp"
#include "lac/constructions/chain.hpp"

int main(int argc, char** argv) {
  using namespace lac;
  CLI::App app{"Closed LA chains through eight points, G1 and G2, at two alpha"};
  std::string out = "results";
  int samples = 400;
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--samples", samples, "Points per chain")->capture_default_str()->check(CLI::Range(2, 100000));
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const std::string cmd = io::command_line(argc, argv);

  const std::vector<std::complex<double>> points{{0, 0}, {2, -0.5}, {4, 0.3}, {5, 2}, {4, 4}, {2, 4.6}, {0.2, 3.8}, {-0.8, 2}};
  std::ofstream pts(std::filesystem::path(out) / "chain_figures_points.csv");
  pts << "# written by: " << cmd << "\n";
  pts << "# samples of closed chains through the eight points of chain_figures.md; s arc length from point 0; theta "
         "tangent angle; kappa signed curvature; pair = the pair of points (k, k+1) the sample lies between\n";
  pts << "continuity,alpha,s,x,y,theta,kappa,pair\n";
  pts.precision(12);
  io::write_numbers_plainly(pts);

  io::Table t;
  t.columns = {"continuity", "α", "status", "segments", "length", "max Δθ at joints", "max Δκ at joints",
               "κ min", "κ max", "iterations", "ms"};
  for (ChainContinuity c : {ChainContinuity::g1, ChainContinuity::g2}) {
    for (double alpha : {-1.0, -0.3}) {
      const ChainResult r = solve_chain({.points = points, .alpha = alpha, .continuity = c, .closed = true});
      const Summary& e = r.summary;
      std::vector<std::string> row{std::string(to_string(c)), io::fmt(alpha), std::string(to_string(e.status))};
      if (!r.usable()) {
        row.insert(row.end(), {"—", "—", "—", "—", "—", "—", std::to_string(e.iterations), io::fmt(1e3 * e.seconds)});
        t.add_row(row);
        continue;
      }
      double dtheta = 0, dkappa = 0;
      for (const Joint& j : r.curve.joints()) {
        dtheta = std::max(dtheta, std::abs(j.angle_gap));
        dkappa = std::max(dkappa, std::abs(j.curvature_gap));
      }
      const auto v = r.curve.sample(samples);
      const size_t per_pair = c == ChainContinuity::g1 ? 1 : 3;
      double kmin = HUGE_VAL, kmax = -HUGE_VAL;
      for (const PositionResult& p : v) {
        const CurvePoint& q = p.point;
        kmin = std::min(kmin, q.kappa);
        kmax = std::max(kmax, q.kappa);
        pts << to_string(c) << "," << alpha << "," << q.s << "," << q.position.real() << "," << q.position.imag() << ","
            << q.theta << "," << q.kappa << "," << r.curve.segment_at(q.s) / per_pair << "\n";
      }
      row.insert(row.end(), {std::to_string(r.curve.segments().size()), io::fmt(r.curve.length(), 8), io::sci(dtheta, 2),
                             io::sci(dkappa, 2), io::fmt(kmin, 4), io::fmt(kmax, 4), std::to_string(e.iterations),
                             io::fmt(1e3 * e.seconds)});
      t.add_row(row);
    }
  }
  io::ResultDoc doc;
  doc.title = "Closed LA chains through eight points";
  doc.command = cmd;
  doc.description =
      "Closed chains through (0,0) (2,−0.5) (4,0.3) (5,2) (4,4) (2,4.6) (0.2,3.8) (−0.8,2), back to (0,0). Tangent "
      "angles and curvatures at the points are estimated by the circle through each point and its two neighbours "
      "(constructions/chain.hpp). g1: one LA segment of slope α per pair of points (G1 Hermite); g2: the triple LA "
      "curve per pair (G2 Hermite), three segments each. Joint gaps from PlanarCurve::joints (angle, curvature). "
      "Plots: results/figures/chain_figures.png (curves with curvature combs, curvature against arc length).";
  doc.notes =
      "A G1 chain is continuous in tangent only: its curvature jumps at the points (the column max Δκ at joints). The G2 "
      "chain is curvature-continuous to the solver's accuracy. Wall times: chain_figures_timing.md.";
  io::write_result_table_with_timing(out, "chain_figures", doc, t, {"continuity", "α"}, {"ms"},
                                     "ms: wall time of one chain (Summary::seconds, all pairs).");
  return 0;
}
