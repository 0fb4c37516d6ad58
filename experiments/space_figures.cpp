// The compound-rhythm LA space curves of 000 Figs. 5 and 6 (the paper's six parameter sets) and
// the r_θ sweep of its Fig. 7, solved with the paper's modified downhill simplex. 000 gives no
// endpoint coordinates, so each set gets a configuration where it is drawable by construction:
// P0 = 0, v0 = e_x, P1 = (cos θ, sin θ, 0) and v1 = the end tangent of the construction at a
// trial (Λ0, ν0) taken from a fixed list (first one that meets the cones and that the simplex then
// solves from its default start). Writes results/space_figures.{md,csv} (parameters found),
// results/space_rtheta.{md,csv} (Fig. 7 sweep) and results/space_figures_points.csv (curve
// samples for experiments/figures/space_figures.py).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "io/table.hpp"
#include "lac/constructions/space_segment.hpp"

namespace {

struct FigureSet {
  const char* name;
  lac::CompoundSpaceSpec spec;
};

// 000 §5, Fig. 5 (type 1) and Fig. 6 (type 2) captions; r_θ is not given there (0.5 here).
const std::array<FigureSet, 6> kSets = {{
    {"5a", {-1, 1, -1, 1, 0.1, 0.5, lac::TorsionType::type1}},
    {"5b", {0, -1, 2, 1, 0.1, 0.5, lac::TorsionType::type1}},
    {"5c", {-1, 1, 2, -1, 0.6, 0.5, lac::TorsionType::type1}},
    {"6a", {1, 0, 0, 1, 0.3, 0.5, lac::TorsionType::type2}},
    {"6b", {1, -1, 1, -2, 0.3, 0.5, lac::TorsionType::type2}},
    {"6c", {-1, 1, -1, 2, 0.15, 0.5, lac::TorsionType::type2}},
}};

// Trial (Λ0, ν0, θ) that define candidate endpoint configurations, tried in this order.
const std::array<std::array<double, 3>, 11> kTrials = {{{0.2, 2.5, 1.2},
                                                       {0.3, 1.5, 1.0},
                                                       {0.4, 1.2, 0.9},
                                                       {0.5, 1.5, 0.7},
                                                       {0.3, 1.5, 0.6},
                                                       {1.0, 1.0, 0.5},
                                                       {0.3, 3.0, 0.8},
                                                       {0.2, 1.0, 0.5},
                                                       {0.8, 2.0, 0.4},
                                                       {0.15, 2.0, 1.0},
                                                       {2.0, 0.8, 0.35}}};

std::string vec_text(const lac::Vec3& v) {
  return lac::io::fmt(v.x(), 4) + ", " + lac::io::fmt(v.y(), 4) + ", " + lac::io::fmt(v.z(), 4);
}

// 240 samples split over the pieces by their share of the length, each piece sampled uniformly
// in s from its start to its end (the joint appears once per piece).
void write_points(std::ofstream& csv, const std::string& figure, double r_theta, const lac::SpaceCurve& c) {
  constexpr int kPoints = 240;
  csv.precision(10);
  lac::io::write_numbers_plainly(csv);
  const auto& pieces = c.pieces();
  double total = 0;
  for (const auto& p : pieces) total += p.s_end - p.s_begin;
  int left = kPoints;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const int later = 2 * static_cast<int>(pieces.size() - k - 1);  // at least 2 per later piece
    const int m = k + 1 == pieces.size()
                      ? left
                      : std::clamp(static_cast<int>(std::lround(kPoints * (pieces[k].s_end - pieces[k].s_begin) / total)),
                                   2, left - later);
    left -= m;
    for (const auto& p : c.sample(c.piece_start(k), c.piece_start(k + 1), m))
      csv << figure << ',' << r_theta << ',' << k << ',' << p.s << ',' << p.p.x() << ',' << p.p.y() << ',' << p.p.z()
          << ',' << p.kappa << ',' << p.tau << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"000 Figs. 5-7: compound-rhythm LA space curves for the paper's parameter sets"};
  std::string out = "results";
  app.add_option("--out", out, "Output folder")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const std::string cmd = lac::io::command_line(argc, argv);

  lac::SpaceSegmentOptions opt;
  opt.solver = lac::NonlinearMethod::simplex;  // 000's method

  std::ofstream pts(std::filesystem::path(out) / "space_figures_points.csv");
  pts << "# written by: " << cmd << "\n";
  pts << "# samples of the solved curves in user coordinates; kappa, tau in user units; piece 0/1 = segment\n";
  pts << "figure,r_theta,piece,s,x,y,z,kappa,tau\n";

  lac::io::Table t;
  t.columns = {"figure", "type", "α0, α1", "β0, β1", "Ω0", "r_θ", "θ (rad)", "v1", "status", "Λ0", "ν0",
               "Λ1", "Ω1", "ν1", "s_c", "length", "joint at (share of length)", "tangent error", "constructions",
               "ms"};
  lac::SpaceEndpoints sweep_ends;
  bool sweep_ok = false;
  for (const FigureSet& set : kSets) {
    bool drawn = false;
    for (const auto& trial : kTrials) {
      const auto drawable = lac::drawable_endpoints(set.spec, true, trial[0], trial[1], trial[2], opt);
      if (drawable.summary.status != lac::Status::ok) continue;
      const lac::SpaceEndpoints& e = drawable.info.ends;
      const auto r = lac::solve_compound_space_segment(e, set.spec, opt);
      if (r.summary.status != lac::Status::ok) continue;
      drawn = true;
      const lac::SpaceCurve& c = r.curve;
      const lac::SpacePiece& p0 = c.pieces()[0];
      const lac::SpacePiece& p1 = c.pieces()[1];
      const double share = c.placement().scale * (p0.s_end - p0.s_begin) / c.length();
      t.add_row({set.name, set.spec.type == lac::TorsionType::type1 ? "1" : "2",
                 lac::io::fmt(set.spec.alpha0) + ", " + lac::io::fmt(set.spec.alpha1),
                 lac::io::fmt(set.spec.beta0) + ", " + lac::io::fmt(set.spec.beta1), lac::io::fmt(set.spec.omega0),
                 lac::io::fmt(set.spec.r_theta), lac::io::fmt(trial[2]), vec_text(e.v1),
                 std::string(lac::to_string(r.summary.status)) + (r.info.torsion_sign < 0 ? " (mirrored)" : ""),
                 lac::io::fmt(p0.law.lambda(), 4), lac::io::fmt(p0.law.nu(), 4), lac::io::fmt(p1.law.lambda(), 4),
                 lac::io::fmt(p1.law.omega(), 4), lac::io::fmt(p1.law.nu(), 4), lac::io::fmt(p1.s_begin, 4),
                 lac::io::fmt(c.length(), 4), lac::io::fmt(share, 3), lac::io::sci(*r.summary.residuals.angle, 2),
                 std::to_string(r.summary.constructions), lac::io::fmt(1e3 * r.summary.seconds, 3)});
      write_points(pts, set.name, set.spec.r_theta, c);
      if (std::string(set.name) == "5a") {
        sweep_ends = e;
        sweep_ok = true;
      }
      break;
    }
    if (!drawn) t.add_row({set.name, "", "", "", "", "", "", "", "no configuration of the trial list was solved", "",
                           "", "", "", "", "", "", "", "", "", ""});
  }
  lac::io::ResultDoc doc;
  doc.title = "000 Figs. 5 and 6: compound-rhythm LA space curves";
  doc.command = cmd;
  doc.description =
      "The six parameter sets of 000 Figs. 5 (type 1) and 6 (type 2), r_θ = 0.5 (not stated in the paper). "
      "000 gives no endpoint coordinates; each set uses P0 = (0, 0, 0), v0 = (1, 0, 0), P1 = (cos θ, sin θ, 0) "
      "and the v1 shown, which is the end tangent of the construction at the first (Λ0, ν0, θ) of a fixed trial "
      "list (experiments/space_figures.cpp) that meets both cones; the solver (000's modified downhill simplex, "
      "from its default start) is not told that (Λ0, ν0), so it may find another solution. Λ1, Ω1, ν1, s_c come "
      "from the LCG/LTG continuity at the joint (000 Eqs. 11, 16–18; docs/math.md §3). Length in user units "
      "(|P1 − P0| = 1). Plots: results/figures/space_figures_type1.png, space_figures_type2.png. Wall times: "
      "space_figures_timing.md.";
  doc.notes =
      "The paper shows these curves only as pictures (with shadows) and their curvature/torsion plots, without "
      "numbers, so there is nothing numeric to compare; our plots show the same kind of κ, τ profiles along s: "
      "κ monotone (ρ increasing), τ decreasing for type 1 (μ increasing) and increasing for type 2, with the "
      "slope change at the joint.";
  lac::io::write_result_table_with_timing(out, "space_figures", doc, t, {"figure"}, {"ms"},
                                          "ms: wall time of the solve of one set (Summary::seconds), single call.");
  std::cout << t.markdown() << "\n";

  // 000 Fig. 7: r_θ moves the joint. Same endpoints as set 5a.
  lac::io::Table s;
  s.columns = {"r_θ", "status", "Λ0", "ν0", "joint (x, y, z)", "joint at (share of length)", "length",
               "tangent error", "constructions"};
  if (sweep_ok) {
    const FigureSet& base = kSets[0];
    for (double r_theta : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9}) {
      lac::CompoundSpaceSpec sp = base.spec;
      sp.r_theta = r_theta;
      const auto r = lac::solve_compound_space_segment(sweep_ends, sp, opt);
      if (r.summary.status != lac::Status::ok) {
        s.add_row({lac::io::fmt(r_theta), std::string(lac::to_string(r.summary.status)), "", "", "", "", "", "",
                   std::to_string(r.summary.constructions)});
        continue;
      }
      const lac::SpaceCurve& c = r.curve;
      const lac::SpacePiece& p0 = c.pieces()[0];
      s.add_row({lac::io::fmt(r_theta), std::string(lac::to_string(r.summary.status)), lac::io::fmt(p0.law.lambda(), 4),
                 lac::io::fmt(p0.law.nu(), 4), vec_text(*r.info.joint),
                 lac::io::fmt(c.placement().scale * (p0.s_end - p0.s_begin) / c.length(), 3),
                 lac::io::fmt(c.length(), 4), lac::io::sci(*r.summary.residuals.angle, 2),
                 std::to_string(r.summary.constructions)});
      write_points(pts, "7", r_theta, c);
    }
  }
  lac::io::ResultDoc sdoc;
  sdoc.title = "000 Fig. 7: the cone ratio r_θ moves the joint";
  sdoc.command = cmd;
  sdoc.description =
      "Parameter set of 000 Fig. 5(a) (α0 = −1, α1 = 1, β0 = −1, β1 = 1, Ω0 = 0.1, type 1) with the endpoints "
      "chosen for it in space_figures.md; r_θ from 0.1 to 0.9, each solved by the modified downhill simplex from "
      "its default start. The joint is where segment 0 meets the inner cone of half-angle r_θ·θ (000 §4.1). "
      "Plot: results/figures/space_rtheta.png.";
  sdoc.notes =
      "000 Fig. 7 shows the joint moving along the curve as r_θ grows, without numbers; here the joint's share of "
      "the length grows monotonically with r_θ as well (r_θ is not proportional to arc length, as 000 notes).";
  lac::io::write_result_table(out, "space_rtheta", sdoc, s);
  std::cout << s.markdown();
  return 0;
}
