#pragma once
// The one output module of `lac` (docs/cli.md "Schema"): every subcommand builds its result as a
// Report with the functions below and prints it with print_report(), so that every command has
// the same keys, the same null rule and the same CSV and SVG forms. Batch mode (cli/batch.hpp)
// prints the same objects, one line per row.
//
// Keys, in this order: status, message (null when ok), length, kappa0, kappa1 (signed curvature
// at the start and end, left turn positive), iterations, evaluations, seconds, solver, integrator,
// residuals {position, angle, curvature}, segments [ … ], the command's extras (e.g. info,
// inflection), points [ … ] (with --samples). A number that does not exist or is not finite
// (a failed solve, a point that failed, no solver) is null, never 0.
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lac/common/summary.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/integrators/registry.hpp"

namespace lac::cli {

using Json = nlohmann::ordered_json;

/// What a subcommand prints: the report object and, for an SVG drawing, the control points drawn
/// under the curve.
struct Report {
  Json json;
  std::vector<std::complex<double>> polygon;
};

/// A number, or null when it does not exist (nullopt) or is not finite.
Json number(double v);
Json number(const std::optional<double>& v);
Json xy(std::complex<double> p);  ///< {"x", "y"}
Json xyz(const Vec3& p);          ///< {"x", "y", "z"}

/// The common keys in their order from a construction's Summary (length, kappa0, kappa1 null
/// until a curve is added). Records the status for the exit status (cli/command.hpp).
Json construction_report(const Summary& summary);
/// The same for an evaluation without a solver (eval, quadratic): iterations and solver null.
Json evaluation_report(Status status, const std::string& message, long evaluations, double seconds,
                       const std::string& integrator, std::optional<double> error = {},
                       double accept = kDefaultAccept);

/// Sets length, kappa0 and kappa1 (null where not finite).
void set_extent(Json& report, double length, double kappa0, double kappa1);

/// A planar LA segment: kind "la", alpha, q0, q1 (q = sgn κ |κ|^−α, log|κ| for α = 0, in user
/// units: linear in s, [Miura et al. 2013] Eqs. (2)–(3)), lambda (|dq/ds|/|α|, |dq/ds| for α = 0), length,
/// start {x, y}, theta, kappa, theta_end, kappa_end.
Json planar_segment(const LaSegment& segment);
/// length, kappa0, kappa1 and segments of a usable planar curve.
void add_planar_curve(Json& report, const PlanarCurve& curve);
/// A point {s, x, y, theta, kappa}; x, y null when its position failed (its status is recorded).
Json planar_point(const PositionResult& p);
/// `n` points uniform in s with `integrator` (igf, for standard forms only: gk-tanh-sinh), as
/// "points"; nothing for n = 0.
void add_planar_points(Json& report, const PlanarCurve& curve, int n, const AnyQuadrature& integrator);

/// length, kappa0, kappa1 (κ ≥ 0) and segments (kind "la-space": alpha, beta, lambda, omega, nu,
/// type, length, start {x, y, z}, kappa, tau) of a usable space curve.
void add_space_curve(Json& report, const SpaceCurve& curve);
/// `n` points {s, x, y, z, kappa, tau} uniform in s; x, y, z null where the frame failed.
void add_space_points(Json& report, const SpaceCurve& curve, int n);

/// Prints in `format`: json (indented), csv (write_csv_report) or svg (write_svg, with the
/// curvature comb when `comb`).
void print_report(const Report& report, const std::string& format, bool comb = false);
/// Prints a flat record (`special …`): json (indented) or csv (a header line and a value line).
void print_record(const Json& record, const std::string& format);

/// CSV: the summary keys (nested objects flattened as residuals.angle, arrays left out) as a
/// header comment and a value comment, then the points, or the segments without points, as a
/// table whose column names are their JSON keys. Null is an empty cell.
void write_csv_report(std::ostream& out, const Json& report);
/// The flattened summary keys and values of a report (as in its CSV header comment).
void flatten_summary(const Json& report, std::vector<std::string>& keys, std::vector<const Json*>& values);
/// One CSV cell: strings quoted when needed, numbers in their shortest exact form, null empty.
std::string csv_cell(const Json& value);
/// SVG of a planar report: its control polygon (grey) and points, one colour per segment. With
/// `comb` also the curvature comb of the points (their theta and kappa): a <desc> stating the
/// convention and scale, a <path id="comb-teeth"> of "M x,y L x,y" pairs, one per point with a
/// curvature, from the point to point − c·κ·N (N the unit left normal, so away from the centre of
/// curvature; c makes the longest tooth 0.15 of the drawing's bounding-box diagonal), and a
/// <polyline id="comb-tips"> through the tips (y flipped, as the curve).
void write_svg(std::ostream& out, const Report& report, bool comb = false);

}  // namespace lac::cli
