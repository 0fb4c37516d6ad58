// Curvature and logarithmic curvature graph (LCG) of the certified B-splines (export/to_bspline.hpp)
// against the LA curves they approximate: does the exported curve keep the LA property (a straight
// LCG of slope α, [Harada et al. 1999], 000 Eq. (1))? For three curves (the G2 Hermite acceptance
// curve, a single G1 segment with α = 2, a closed G2 chain), degree 5 and 3, tolerances 1e-3 and 1e-6 of
// the length. The B-spline's curvature comes from its Bézier pieces (bezier_pieces): κ = (B' × B'')
// / |B'|³ and its derivative in the B-spline's own arc length from B'''. LCG: x = log ρ, y =
// log(ρ ds/dρ) = log|κ / (dκ/ds)|, ρ = 1/|κ|; on an LA segment y = α x − log Λ.
// Writes results/export_lcg.{md,csv} (per curve, degree, tolerance, LA segment) and
// results/export_lcg_points.csv (samples) for experiments/figures/export_lcg.py.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "io/table.hpp"
#include "lac/constructions/chain.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/export/to_bspline.hpp"
#include "lac/export/write.hpp"

namespace {

using C = std::complex<double>;

/// Derivatives 0..3 of a Bézier piece in its own parameter t ∈ [0, 1] (hodographs, de Casteljau).
std::array<C, 4> bezier_derivatives(std::vector<C> p, double t) {
  std::array<C, 4> d{};
  double factor = 1;
  for (int order = 0; order < 4; ++order) {
    const int n = static_cast<int>(p.size()) - 1;
    if (n < 0) break;
    std::vector<C> q = p;
    for (int r = n; r > 0; --r)
      for (int i = 0; i < r; ++i) q[i] = (1 - t) * q[i] + t * q[i + 1];
    d[order] = factor * q[0];
    factor *= n;
    for (int i = 0; i < n; ++i) p[i] = p[i + 1] - p[i];  // hodograph (the factor n is in `factor`)
    p.pop_back();
  }
  return d;
}

double cross(C a, C b) { return a.real() * b.imag() - a.imag() * b.real(); }

/// Signed curvature and its derivative in arc length from the derivatives in any parameter.
std::pair<double, double> curvature(const std::array<C, 4>& d) {
  const double v = std::abs(d[1]);
  const double k = cross(d[1], d[2]) / (v * v * v);
  const double dk_dt = cross(d[1], d[3]) / (v * v * v) -
                       3 * cross(d[1], d[2]) * (d[1].real() * d[2].real() + d[1].imag() * d[2].imag()) / std::pow(v, 5);
  return {k, dk_dt / v};
}

/// The LCG point (log ρ, log(ρ ds/dρ)) of curvature κ and dκ/ds; NaN where it does not exist.
std::pair<double, double> lcg(double k, double dk) {
  if (!(std::abs(k) > 0) || !(std::abs(dk) > 0)) return {std::nan(""), std::nan("")};
  return {-std::log(std::abs(k)), std::log(std::abs(k / dk))};
}

struct Sample {
  double s, kappa_la, dkappa_la, kappa_b, dkappa_b;
  size_t segment;
};

/// Samples at `per_piece` parameters (j + 1/2)/per_piece inside every Bézier piece (never at a knot).
std::vector<Sample> sample(const lac::PlanarCurve& curve, const lac::BSpline& b, int per_piece) {
  const auto pieces = lac::bezier_pieces(b);
  std::vector<double> knots;
  std::vector<int> mult;
  b.distinct_knots(knots, mult);
  std::vector<Sample> out;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const double a = knots.at(i), c = knots.at(i + 1);
    for (int j = 0; j < per_piece; ++j) {
      const double t = (j + 0.5) / per_piece, s = a + t * (c - a);
      const auto [kb, dkb] = curvature(bezier_derivatives(pieces[i], t));
      out.push_back({s, curve.kappa_at(s), curve.dkappa_ds_at(s), kb, dkb, curve.segment_at(s)});
    }
  }
  return out;
}

/// Least-squares slope and intercept of y on x.
std::pair<double, double> fit(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {slope, (sy - slope * sx) / n};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lac;
  CLI::App app{"Curvature and LCG of the certified B-spline exports against the LA curves"};
  std::string out = "results";
  int per_piece = 64, plot_points = 400;
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--per-piece", per_piece, "Samples per Bezier piece for the measures")
      ->capture_default_str()
      ->check(CLI::Range(2, 10000));
  app.add_option("--plot-points", plot_points, "Samples per case in export_lcg_points.csv")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const std::string cmd = io::command_line(argc, argv);

  struct Case {
    std::string name;
    PlanarCurve curve;
  };
  std::vector<Case> cases;
  {
    const G2Result g = solve_g2({{{0, 0}, 0.6, 0.5}, {{4, 0}, -0.6, -0.3}, -0.5});
    if (g.usable()) cases.push_back({"g2 acceptance", g.curve});
    const G1HermiteResult s = solve_g1_hermite({{0, 0}, 0, {2, 1}, std::numbers::pi / 3, 2});
    if (s.usable()) cases.push_back({"g1 segment", s.curve});
    const ChainResult c =
        solve_chain({.points = {{0, 0}, {2, -0.5}, {4, 0.3}, {5, 2}, {4, 4}, {2, 4.6}, {0.2, 3.8}, {-0.8, 2}},
                     .alpha = -0.5,
                     .continuity = ChainContinuity::g2,
                     .closed = true});
    if (c.usable()) cases.push_back({"g2 chain", c.curve});
  }

  std::ofstream pts(std::filesystem::path(out) / "export_lcg_points.csv");
  pts << "# written by: " << cmd << "\n";
  pts << "# samples of the LA curves of export_lcg.md and their B-spline exports; s arc length of the LA curve (the "
         "B-spline's parameter); kappa signed curvature; kappa_la the LA curve's at the same s; x_lcg = log rho, y_lcg "
         "= log(rho ds/drho) (empty where "
         "kappa or its derivative is 0); degree 0 = the LA curve itself\n";
  pts << "curve,degree,tolerance,segment,alpha,s,kappa,kappa_la,x_lcg,y_lcg\n";
  pts.precision(9);
  io::write_numbers_plainly(pts);
  auto cell = [](double v) { return std::isfinite(v) ? io::fmt(v, 9) : std::string(); };

  io::Table t;
  t.columns = {"curve",
               "segments",
               "with LCG",
               "degree",
               "tolerance",
               "spans",
               "max_deviation / length",
               "LA slope error",
               "B-spline slope error",
               "max LCG gap",
               "median LCG gap",
               "κ error"};
  for (const Case& c : cases) {
    const double length = c.curve.length();
    // The LA curve itself (degree 0) at plot_points.
    for (int j = 0; j < plot_points; ++j) {
      const double s = (j + 0.5) / plot_points * length;
      const size_t k = c.curve.segment_at(s);
      const double kappa = c.curve.kappa_at(s);
      const auto [x, y] = lcg(kappa, c.curve.dkappa_ds_at(s));
      pts << c.name << ",0,0," << k << "," << c.curve.segments()[k].law().alpha << "," << cell(s) << "," << cell(kappa)
          << "," << cell(kappa) << "," << cell(x) << "," << cell(y) << "\n";
    }
    for (const int degree : {5, 3}) {
      for (const double rel : {1e-3, 1e-6}) {
        const ExportResult r = to_bspline(c.curve, {.tolerance = rel * length, .degree = degree});
        if (!r.usable()) {
          t.add_row({c.name, std::to_string(c.curve.segments().size()), "—", std::to_string(degree), io::sci(rel, 1),
                     std::string(to_string(r.summary.status)), "—", "—", "—", "—", "—", "—"});
          continue;
        }
        // Samples for the points file: plot_points uniform in the pieces' count.
        const int pp = std::max(2, plot_points / static_cast<int>(bezier_pieces(r.curve).size()));
        for (const Sample& q : sample(c.curve, r.curve, pp)) {
          const auto [x, y] = lcg(q.kappa_b, q.dkappa_b);
          pts << c.name << "," << degree << "," << rel << "," << q.segment << ","
              << c.curve.segments()[q.segment].law().alpha << "," << cell(q.s) << "," << cell(q.kappa_b) << ","
              << cell(q.kappa_la) << "," << cell(x) << "," << cell(y) << "\n";
        }
        const std::vector<Sample> v = sample(c.curve, r.curve, per_piece);
        int with_lcg = 0;
        double la_slope_err = 0, slope_err = 0, dev_max = 0, dkappa = 0, kmax_all = 0;
        std::vector<double> dev;
        for (const Sample& q : v) kmax_all = std::max(kmax_all, std::abs(q.kappa_la));
        for (const Sample& q : v) dkappa = std::max(dkappa, std::abs(q.kappa_b - q.kappa_la) / kmax_all);
        for (size_t k = 0; k < c.curve.segments().size(); ++k) {
          const LaSegment& seg = c.curve.segments()[k];
          const double alpha = seg.law().alpha, k0 = seg.kappa_start(), k1 = seg.kappa_end();
          if (std::abs(k1 - k0) <= 1e-9 * std::max(std::abs(k0), std::abs(k1))) continue;  // an arc: no LCG
          double kmax = 0;
          for (const Sample& q : v)
            if (q.segment == k) kmax = std::max(kmax, std::abs(q.kappa_la));
          // LCG points where |κ| is at least 1e-3 of the segment's largest (the LCG runs off to
          // infinity at an inflection).
          std::vector<double> xl, yl, xb, yb;
          for (const Sample& q : v) {
            if (q.segment != k || std::abs(q.kappa_la) < 1e-3 * kmax) continue;
            const auto [x0, y0] = lcg(q.kappa_la, q.dkappa_la);
            const auto [x1, y1] = lcg(q.kappa_b, q.dkappa_b);
            if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) continue;
            xl.push_back(x0), yl.push_back(y0), xb.push_back(x1), yb.push_back(y1);
          }
          if (xl.size() < 8) continue;
          ++with_lcg;
          const auto [slope_la, icpt_la] = fit(xl, yl);
          const auto [slope_b, icpt_b] = fit(xb, yb);
          la_slope_err = std::max(la_slope_err, std::abs(slope_la - alpha));
          slope_err = std::max(slope_err, std::abs(slope_b - alpha));
          // Departure of the B-spline's LCG points from the LA line (the LA curve's own fit).
          for (size_t i = 0; i < xb.size(); ++i) {
            dev.push_back(std::abs(yb[i] - (slope_la * xb[i] + icpt_la)));
            dev_max = std::max(dev_max, dev.back());
          }
        }
        std::sort(dev.begin(), dev.end());
        const bool any = with_lcg > 0;
        t.add_row({c.name, std::to_string(c.curve.segments().size()), std::to_string(with_lcg), std::to_string(degree),
                   io::sci(rel, 1), std::to_string(r.info.spans), io::sci(r.info.max_deviation / length, 2),
                   any ? io::sci(la_slope_err, 1) : "—", any ? io::sci(slope_err, 2) : "—",
                   any ? io::sci(dev_max, 2) : "—", any ? io::sci(dev[dev.size() / 2], 2) : "—", io::sci(dkappa, 2)});
      }
    }
  }
  io::ResultDoc doc;
  doc.title = "Curvature and LCG of the certified B-spline exports";
  doc.command = cmd;
  doc.description =
      "Curves: `g2 acceptance` = lac g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 "
      "--alpha -0.5 (three LA segments, an inflection); `g1 segment` = G1 Hermite (0,0) 0 → (2,1) π/3 with α = 2 "
      "(one LA segment); `g2 chain` = the closed G2 chain through the eight points of chain_figures.md with α = −0.5. "
      "Each is exported by to_bspline at tolerance 1e-3 and 1e-6 × length, degree 5 (G2) and 3 (G1). The "
      "B-spline's own curvature κ_b and dκ_b/ds_b come from its Bézier pieces (κ = B' × B'' / |B'|³, the derivative "
      "from B'''), at " +
      std::to_string(per_piece) +
      " parameters inside every piece (never at a knot), and are compared with the LA curve's closed-form κ and "
      "dκ/ds at the same arc length s (the B-spline's parameter). LCG: x = log ρ, y = log(ρ ds/dρ) = log|κ/(dκ/ds)|, "
      "per LA segment whose curvature changes (`with LCG`: arcs have none), on samples with |κ_LA| ≥ 1e-3 of the "
      "segment's largest (the LCG runs off to infinity at an inflection). `LA slope error`: largest |slope − α| over "
      "the segments, the least-squares slope "
      "of the LA curve's own LCG samples (a check that its graph is the LA line); "
      "`B-spline slope error`: the same for the B-spline's LCG; `max / median LCG gap`: vertical distance of the "
      "B-spline's LCG points from the LA line, over all segments with an LCG; `κ error`: max |κ_b − κ_LA| / max "
      "|κ_LA|, the curvature "
      "difference over the whole curve. Plots: results/figures/export_lcg.png "
      "(experiments/figures/export_lcg.py).";
  doc.notes =
      "The quintic is curvature continuous and its curvature converges with the tolerance, so its LCG approaches the "
      "LA line; the cubic is G1 only, its curvature jumps at every knot and its dκ/ds is only first-order accurate "
      "inside a span, so its LCG is a set of short pieces around the line. Near-arc segments of the chain (curvature "
      "changing by little) have a small dκ/ds, where a small absolute error of dκ/ds moves the LCG most.";
  io::write_result_table(out, "export_lcg", doc, t);
  return 0;
}
