// Figure set like 001 Figs. 7–8: compound-rhythm LA curves with the same end points and end
// tangents (one control triangle), for several (α0, α1, r). 001 gives no coordinates or
// parameter values for its figures, so the triangle and the parameter sets here are ours: set
// "fig7" mixes signs (V and upside-down-V LCGs, 001 Fig. 7), set "fig8" has both slopes of the
// same sign (001 Fig. 8 (a), (b), (e), (f)). Monotonic segments of the same triangle are drawn
// beside them. Writes results/planar_figures.{md,csv} (parameters found) and
// results/planar_figures_points.csv (samples) for experiments/figures/planar_figures.py.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "io/table.hpp"
#include "io/timing.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace {

struct Spec {
  const char* figure;
  double alpha0, alpha1, r;  // r = 1: monotonic segment of slope alpha0
};

const Spec kSpecs[] = {
    {"fig7", -1, 1.5, 0.5}, {"fig7", 1.5, -1, 0.5}, {"fig7", -1, 2, 0.3},  {"fig7", 2, -1, 0.7},
    {"fig7", 0, 3, 0.5},    {"fig7", -1, 1, 1},     {"fig7", 1.5, 0, 1},   {"fig8", 0.5, 2, 0.5},
    {"fig8", 2, 0.5, 0.5},  {"fig8", -0.5, -2, 0.5}, {"fig8", -2, -0.5, 0.5}, {"fig8", 1.2, 3, 0.4},
    {"fig8", -1, -0.2, 0.6},
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"001 Figs. 7-8: compound-rhythm LA curves on one control triangle"};
  std::string out = "results";
  int samples = 400;
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--samples", samples, "Points per curve")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const std::string cmd = lac::io::command_line(argc, argv);

  const lac::ControlTriangle tri{{0, 0}, {1, 0}, {1.8, 1.2}};
  std::ofstream pts(std::filesystem::path(out) / "planar_figures_points.csv");
  pts << "# written by: " << cmd << "\n";
  pts << "# samples of the solved curves, control triangle (0,0) (1,0) (1.8,1.2); s from a0, theta tangent angle,"
         " kappa signed curvature; piece 0 = segment of alpha0 (at a0), 1 = segment of alpha1\n";
  pts << "figure,alpha0,alpha1,r,piece,s,x,y,theta,kappa\n";
  pts.precision(12);
  lac::io::write_numbers_plainly(pts);

  lac::io::Table t;
  t.columns = {"figure", "α0", "α1", "r", "status", "Λ0", "Λ1 (001 Eq. 3.5)", "ρ at joint", "joint share of length",
               "length", "κ(a0)", "κ(a2)", "tangent error (rad)", "iterations", "µs"};
  for (const Spec& s : kSpecs) {
    const bool compound = s.r < 1;
    lac::io::Stopwatch clock;
    const lac::TriangleResult g = compound ? lac::solve_compound(tri, s.alpha0, s.alpha1, s.r) : lac::solve_g1(tri, s.alpha0);
    const double us = 1e6 * clock.seconds();
    const std::string a1 = compound ? lac::io::fmt(s.alpha1) : "(monotonic)";
    if (g.summary.status != lac::Status::ok) {
      t.add_row({s.figure, lac::io::fmt(s.alpha0), a1, compound ? lac::io::fmt(s.r) : "",
                 std::string(lac::to_string(g.summary.status)), "", "", "", "", "", "", "", "",
                 std::to_string(g.summary.iterations), lac::io::fmt(us, 3)});
      continue;
    }
    const lac::PlanarCurve& curve = g.curve;
    const lac::TriangleInfo& info = g.info;
    const size_t pieces = curve.segments().size();
    auto piece_of = [&](size_t k) { return info.segment0_at_a0 ? k : pieces - 1 - k; };  // curve segment k
    const double piece0_length = curve.segments()[piece_of(0)].length();
    t.add_row({s.figure, lac::io::fmt(s.alpha0), a1, compound ? lac::io::fmt(s.r) : "", "ok",
               lac::io::fmt(info.pieces[0].lambda, 6), compound ? lac::io::fmt(info.pieces[1].lambda, 6) : "",
               compound ? lac::io::fmt(info.rho_joint, 6) : "", compound ? lac::io::fmt(piece0_length / curve.length(), 3) : "",
               lac::io::fmt(curve.length(), 8), lac::io::fmt(curve.kappa_at(0), 6), lac::io::fmt(curve.kappa_at(curve.length()), 6),
               lac::io::sci(*g.summary.residuals.angle, 2), std::to_string(g.summary.iterations), lac::io::fmt(us, 3)});
    // Each segment uniform in s, about `samples` points in all shared by length, the joint once
    // (the last point of the first segment), positions by the construction's default method.
    const int n0 = pieces == 2 ? std::clamp(static_cast<int>(std::lround(samples * piece0_length / curve.length())), 2,
                                            std::max(2, samples - 1))
                               : samples;
    for (size_t k = 0; k < pieces; ++k) {
      const int count = piece_of(k) == 0 ? n0 : std::max(2, samples - n0 + 1);
      const auto segment_points =
          lac::polyline(curve, curve.segment_start(k), curve.segment_start(k + 1), count, lac::GkTanhSinh{});
      for (size_t j = k == 0 ? 0 : 1; j < segment_points.size(); ++j) {
        const lac::CurvePoint& q = segment_points[j].point;
        pts << s.figure << ',' << s.alpha0 << ',' << (compound ? s.alpha1 : s.alpha0) << ',' << (compound ? s.r : 1.0) << ','
            << piece_of(k) << ',' << q.s << ',' << q.position.real() << ',' << q.position.imag() << ',' << q.theta << ','
            << q.kappa << '\n';
      }
    }
  }
  lac::io::ResultDoc doc;
  doc.title = "001 Figs. 7–8: compound-rhythm LA curves on one control triangle";
  doc.command = cmd;
  doc.description =
      "Control points a0 = (0, 0), a1 = (1, 0), a2 = (1.8, 1.2) (legs 1 and 1.44, turning 56.3°), solved with the "
      "default settings (TOMS 748 on the start-angle mismatch, Gauss–Kronrod/tanh-sinh positions). Rows with "
      "α1 = \"(monotonic)\" are single-slope segments (001 §2) drawn for comparison. Λ0 and Λ1 are in segment 0's "
      "standard-form units (Λ1 = Λ0 ρc^(α1−α0)); lengths and curvatures in user units, κ signed (left turn "
      "positive). Plots: results/figures/planar_figures_fig7.png, planar_figures_fig8.png (curves with evolutes "
      "and joints, LCGs recomputed from the samples, curvature along s).";
  doc.notes =
      "001 shows its Figs. 7–8 as pictures without coordinates or parameter values, so there are no numbers to "
      "set beside these; what the figures share with 001's is the construction (same end points and tangents, "
      "G3 joints: the evolutes are tangent-continuous at the joint) and the V / upside-down-V LCGs.";
  lac::io::write_result_table_with_timing(out, "planar_figures", doc, t, {"figure", "α0", "α1", "r"}, {"µs"},
                                          "µs: wall time of one solve (io::Stopwatch), single call.");
  std::cout << t.markdown();
  return 0;
}
