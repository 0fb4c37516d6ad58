#pragma once
// Options and report shared by `lac g1` (control triangle or Hermite data) and `lac scurve`
// (four control points): both are the G1 Hermite problem of one LA segment
// (constructions/g1_hermite.hpp), entered in different ways.
#include <optional>
#include <string>

#include "cli/options.hpp"
#include "cli/quadrature_args.hpp"
#include "cli/report.hpp"
#include "lac/constructions/g1_hermite.hpp"

namespace lac::cli {

struct G1HermiteArgs {
  CommonArgs common;
  std::optional<std::string> points;
  std::optional<std::string> p0, p1;
  std::optional<double> theta0, theta1;
  std::optional<double> alpha;
  std::string solver = "auto";
  QuadratureArgs quadrature{.integrator = "auto"};
  std::optional<int> winding;
  std::optional<double> max_turning;
};

/// --alpha, --solver (names of g1_hermite_solvers()), --integrator and its options, --winding,
/// --max-turning and the common options; --points is the caller's (its count and meaning differ).
void add_g1_hermite_options(CLI::App& sub, G1HermiteArgs& a);

/// Hermite data --p0 --theta0 --p1 --theta1 (g1).
void add_hermite_data_options(CLI::App& sub, G1HermiteArgs& a);

/// The options of the solve: solver, winding, max_turning, accept, and with an explicit --integrator that integrator
/// for the result's check (G1HermiteOptions::verify) and the points.
G1HermiteOptions g1_hermite_options(const G1HermiteArgs& a);

/// Solves and reports: the common keys, segments, `inflection` (arc length of the inflection, or
/// null), info {shape, turning, phi0, phi1, winding, max_turning, constructions, error_estimate}, points with
/// --samples. `polygon`: the control points drawn under an SVG curve.
Report g1_hermite_report(const G1HermiteProblem& problem, const G1HermiteArgs& a,
                         std::vector<std::complex<double>> polygon);

}  // namespace lac::cli
