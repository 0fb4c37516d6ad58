#pragma once
// Options and report of `lac compound` (cli/triangle_report.cpp), the compound-rhythm control-
// triangle construction of [Yoshida–Saito 2009]. (`lac g1` takes a control triangle as G1
// Hermite data: cli/g1_hermite_args.hpp.)
#include <optional>
#include <string>

#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "cli/report.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lac::cli {

struct TriangleArgs {
  CommonArgs common;
  std::optional<std::string> points;
  std::string solver = "toms748";
  QuadratureArgs quadrature{.integrator = "auto"};
  std::optional<double> max_evaluations;
};

/// --points (3 control points), --solver (1-D registry), --integrator and its options,
/// --max-evaluations, and the common options.
void add_triangle_options(CLI::App& sub, TriangleArgs& a);

/// The control triangle and the construction's options from the arguments (InputError naming
/// the option).
struct PreparedTriangle {
  ControlTriangle triangle;
  TriangleOptions options;  ///< integrator: the construction's default unless --integrator names one
  bool explicit_integrator = false;
};
PreparedTriangle prepare_triangle(const TriangleArgs& a);

/// The report of a solve: common keys, segments in the curve's order (from a0), info
/// {segment0_at_a0, turning, bracket_probes, constructions, error_estimate} and, for a compound
/// curve, info.joint and info.rho_joint; points with --samples.
Report triangle_report(const TriangleResult& g, const TriangleArgs& a, const PreparedTriangle& p);

}  // namespace lac::cli
