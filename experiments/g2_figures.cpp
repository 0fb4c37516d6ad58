// Figure data like 004 Figs. 3, 6, 7 and 8 (004 gives no coordinates, so the boundary data
// here are ours):
//   fig3  S-shaped curves on one set of four control points for several α < 0 (004 Fig. 3);
//   fig7  triple LA curves, α = −0.5, one pair of end points and tangents, several end
//         curvatures (004 Fig. 7; the first set has small end curvatures like Figs. 4 and 6);
//   fig8  two triples of different α joined G2 at a shared point, tangent and curvature (Fig. 8).
// Writes results/g2_figures.{md,csv} (what was solved) and results/g2_figures_points.csv
// (samples) for experiments/figures/g2_figures.py.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>

#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/s_curve.hpp"
#include "io/table.hpp"

namespace {

using namespace lac;

struct G2Spec {
  const char* figure;
  const char* label;
  G2Problem problem;
};

// Curvature monotone along the curve (non-strictly, sampled)?
bool monotone(const std::vector<PositionResult>& pts) {
  bool up = true, down = true;
  for (size_t k = 1; k < pts.size(); ++k) {
    up = up && pts[k].point.kappa >= pts[k - 1].point.kappa - 1e-12;
    down = down && pts[k].point.kappa <= pts[k - 1].point.kappa + 1e-12;
  }
  return up || down;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"004 Figs. 3, 6-8: S-curves and triple LA curves"};
  std::string out = "results";
  int samples = 300;
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--samples", samples, "Points per curve")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const std::string cmd = io::command_line(argc, argv);

  std::ofstream pts(std::filesystem::path(out) / "g2_figures_points.csv");
  pts << "# written by: " << cmd << "\n";
  pts << "# samples of the solved curves; piece = index of the curve within a joined figure; s arc length from the "
         "piece's start; theta tangent angle; kappa signed curvature\n";
  pts << "figure,label,alpha,piece,S,s,x,y,theta,kappa\n";
  pts.precision(12);
  lac::io::write_numbers_plainly(pts);
  // S = s / length, uniform (PlanarCurve::sample is uniform in s).
  auto write = [&](const std::string& fig, const std::string& label, double alpha, int piece,
                   const std::vector<PositionResult>& v) {
    for (size_t k = 0; k < v.size(); ++k) {
      const CurvePoint& q = v[k].point;
      const double S = k + 1 == v.size() ? 1.0 : static_cast<double>(k) / static_cast<double>(v.size() - 1);
      pts << fig << "," << label << "," << alpha << "," << piece << "," << S << "," << q.s << "," << q.position.real()
          << "," << q.position.imag() << "," << q.theta << "," << q.kappa << "\n";
    }
  };

  io::Table t;
  t.columns = {"figure", "curve", "α", "status", "length", "|ΔP|", "|Δθ|", "|Δκ|", "κ monotone", "iterations", "ms"};

  // Fig. 3: S-curves, one control polygon, several α.
  const std::array<std::complex<double>, 4> P{{{0, 0}, {1, 0}, {1.6, 1.2}, {3, 1.0}}};
  for (double alpha : {-0.25, -0.5, -1.0, -2.0, -4.0}) {
    const SCurveResult r = solve_s_curve(P, alpha);
    const std::string label = "alpha " + io::fmt(alpha);
    std::vector<PositionResult> v;
    if (r.summary.status == Status::ok) v = r.curve.sample(samples), write("fig3", label, alpha, 0, v);
    const Summary& e = r.summary;
    t.add_row({"fig3 (S-curve)", label, io::fmt(alpha), std::string(to_string(e.status)), io::fmt(r.curve.length(), 6),
               io::sci(e.residuals.position.value_or(0), 2), io::sci(e.residuals.angle.value_or(0), 2), "—",
               v.empty() ? "—" : (monotone(v) ? "yes" : "no"), std::to_string(e.iterations), io::fmt(1e3 * e.seconds)});
  }

  // Figs. 6–7: α = −0.5, ends (0,0) at +0.6 rad and (4,0) at −0.6 rad, several end curvatures.
  const G2Spec fig7[] = {
      {"fig7", "k0 0.05 k1 0.05", {{{0, 0}, 0.6, 0.05}, {{4, 0}, -0.6, 0.05}, -0.5}},
      {"fig7", "k0 0.3 k1 -0.5", {{{0, 0}, 0.6, 0.3}, {{4, 0}, -0.6, -0.5}, -0.5}},
      {"fig7", "k0 -0.4 k1 0.6", {{{0, 0}, 0.6, -0.4}, {{4, 0}, -0.6, 0.6}, -0.5}},
      {"fig7", "k0 1 k1 1", {{{0, 0}, 0.6, 1.0}, {{4, 0}, -0.6, 1.0}, -0.5}},
  };
  // Fig. 8: two triples joined at Pm with one tangent and curvature there, α = −0.5 then −2.
  const G2Endpoint pm{{3, 1}, -0.1, -0.35};
  const G2Spec fig8[] = {
      {"fig8", "alpha -0.5 then -2", {{{0, 0}, 0.5, 0.2}, pm, -0.5}},
      {"fig8", "alpha -0.5 then -2", {pm, {{6, 0.5}, 0.4, 0.5}, -2.0}},
  };
  int piece = 0;
  std::vector<G2Spec> all(std::begin(fig7), std::end(fig7));
  all.insert(all.end(), std::begin(fig8), std::end(fig8));
  {
    for (const G2Spec& s : all) {
      const G2Result r = solve_g2(s.problem);
      std::vector<PositionResult> v;
      const bool joined = std::string(s.figure) == "fig8";
      if (r.usable()) {
        v = r.curve.sample(samples);
        write(s.figure, s.label, s.problem.alpha, joined ? piece : 0, v);
      }
      if (joined) ++piece;
      const Summary& e = r.summary;
      t.add_row({std::string(s.figure) + (joined ? " (joined G2)" : " (α = −0.5)"), s.label, io::fmt(s.problem.alpha),
                 std::string(to_string(e.status)), io::fmt(r.curve.length(), 6), io::sci(e.residuals.position.value_or(0), 2),
                 io::sci(e.residuals.angle.value_or(0), 2), io::sci(e.residuals.curvature.value_or(0), 2),
                 v.empty() ? "—" : (monotone(v) ? "yes" : "no"), std::to_string(e.iterations),
                 io::fmt(1e3 * e.seconds)});
    }
  }
  io::ResultDoc doc;
  doc.title = "S-curves and triple LA curves like 004 Figs. 3, 6–8";
  doc.command = cmd;
  doc.description =
      "004 gives no coordinates for its figures; the boundary data here are ours. fig3: S-shaped curves on the "
      "control polygon (0,0) (1,0) (1.6,1.2) (3,1) for five α (004 Fig. 3). fig7: triple LA curves (α = −0.5, "
      "solver newton, fast start) from (0,0) at +0.6 rad to (4,0) at −0.6 rad with four pairs of end curvatures "
      "(004 Figs. 6–7). fig8: a triple with α = −0.5 from (0,0) to (3,1) and a triple with α = −2 from (3,1) to "
      "(6,0.5), sharing tangent −0.1 rad and curvature −0.35 at (3,1), so the joined curve is G2 (004 Fig. 8). "
      "Residuals: end point (tanh-sinh), end angles, end curvatures. Plots: results/figures/g2_figures_*.png.";
  doc.notes =
      "As 004 observes for its Fig. 7, the curvature of a triple LA curve need not be monotone; small end curvatures "
      "(first fig7 row, like 004 Figs. 4 and 6) give a curvature profile that rises and falls. Wall times of the "
      "solves: g2_figures_timing.md.";
  io::write_result_table_with_timing(out, "g2_figures", doc, t, {"figure", "curve", "α"}, {"ms"},
                                     "ms: wall time of one solve (Summary::seconds).");
  return 0;
}
