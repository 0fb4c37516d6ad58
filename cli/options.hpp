#pragma once
// The option vocabulary every subcommand shares (docs/cli.md):
//   --points "x0,y0 x1,y1 …"   control points (only this meaning)
//   --samples N                 number of output points, uniform in arc length (0: none)
//   --format json|csv[|svg]     svg for planar curves
//   --batch FILE|-              one problem per CSV row (cli/batch.hpp)
//   --degrees                   every angle given on the command line is in degrees
// plus --integrator / --solver with names from the registries (cli/quadrature_args.hpp,
// solver_names below). Values a construction needs are std::optional and checked by need(), not
// by CLI11's required(): in batch mode they may come from the file.
#include <optional>
#include <span>
#include <string>

#include "cli/command.hpp"
#include "lac/common/accuracy.hpp"

namespace lac::cli {

/// The options of every subcommand that prints a report (cli/report.hpp).
struct CommonArgs {
  int samples = 0;
  std::string format = "json";
  std::string batch;
  bool degrees = false;
  /// --accept: the accept bound relative to the size scale (common/accuracy.hpp); a result whose
  /// achieved error exceeds it is inaccurate (exit 3).
  double accept = kDefaultAccept;
  /// --export FILE (planar constructions, cli/export.hpp): the curve as a certified B-spline;
  /// --export DIR/ (a trailing slash): DIR/curve.<export_format>, with --batch DIR/curve_row<N>.….
  std::string export_path{};
  /// --export-format: the format of an --export DIR/ (step | stp | iges | igs | dxf | svg; default
  /// step); with --export FILE it must name FILE's own extension.
  std::optional<std::string> export_format{};
  /// --export-tol: bound on the export's deviation, absolute (default 1e-6 x the curve's length).
  std::optional<double> export_tol{};
  /// --export-degree: 5 (G2; the default) or 3 (G1; the only one for .svg, which holds cubic Béziers).
  std::optional<int> export_degree{};
  /// --export-fit-degree: the B-spline fitted with a proven bound, degrees 3 up to this (3 … 9; 3
  /// for .svg), the fewest control points kept (ExportOptions::fit_max_degree); unset: no fit.
  std::optional<int> export_fit_degree{};
  /// --comb (planar commands): the curvature comb on the --format svg drawing (from the samples'
  /// kappa) and on an --export FILE.svg (the B-spline's own curvature, SvgOptions in
  /// export/write.hpp). InputError "comb" without either SVG output.
  bool comb = false;
};

/// Adds --samples, --format (json | csv, and svg when `planar`), --batch, --degrees, --accept and,
/// when `planar`, --comb.
void add_common_options(CLI::App& sub, CommonArgs& a, bool planar);

/// Adds --export FILE|DIR/, --export-format F, --export-tol T, --export-degree D and
/// --export-fit-degree Q (cli/export.hpp).
void add_export_options(CLI::App& sub, CommonArgs& a);

/// Points to compute: --samples, or 200 for an SVG drawing without --samples. InputError
/// "samples" unless 0 or in [2, 10^6]; InputError "comb" for --comb without --format svg or
/// --export FILE.svg.
int sample_count(const CommonArgs& a);

/// --max-evaluations N: N as a count, 0 when not given; InputError naming max-evaluations unless
/// N ∈ [1, max].
long max_evaluations_option(const std::optional<double>& value, double max);

/// The file --export names for one curve (before batch mode's _row<N>): FILE itself, or
/// DIR/curve.<format> for --export DIR/. InputError naming export-format for a format that is not
/// one of the six or that contradicts FILE's extension. Empty without --export.
std::string export_file(const CommonArgs& a);

/// An angle from the command line in radians (it was given in degrees with --degrees).
double radians(double value, const CommonArgs& a);

/// The range of a slope α for help texts, from a construction's constants (e.g. kG1MinAbsAlpha,
/// kG1MaxAbsAlpha), so that the help says what the library accepts: "[-5, 5]" when min_abs is 0,
/// else "0 or 0.1 <= |alpha| <= 5".
std::string alpha_range_text(double min_abs, double max_abs);

/// InputError "--<name> is required", naming it.
[[noreturn]] void throw_missing(const char* name);
/// The value of an option a command needs; InputError naming it when it was given neither on
/// the command line nor in the batch row.
template <class T>
const T& need(const std::optional<T>& value, const char* name) {
  if (!value) throw_missing(name);
  return *value;
}

/// "bisection | secant (newton) | toms748 | ceres": the names and aliases of a solver registry.
template <class Info>
std::string solver_names(std::span<const Info> methods) {
  std::string text;
  for (const Info& m : methods) {
    text.append(text.empty() ? "" : " | ").append(m.name);
    for (size_t i = 0; i < m.aliases.size(); ++i) text.append(i == 0 ? " (" : ", ").append(m.aliases[i]);
    if (!m.aliases.empty()) text.append(")");
  }
  return text;
}

}  // namespace lac::cli
