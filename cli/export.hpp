#pragma once
// --export FILE on the planar constructions (docs/export.md): the curve as a B-spline with a
// certified deviation bound (export/to_bspline.hpp), written in the format of FILE's extension.
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "lac/curves/quadratic/quadratic_curve.hpp"

namespace lac::cli {

/// Without --export: nothing. Else writes the file (curve usable) and sets report["export"] =
/// {file, format, degree, control_points, max_deviation (the certified bound), curvature_monotone,
/// tolerance, spans, continuity (G2 or G1), max_curvature_jump, status, message}; degree 5 unless
/// --export-degree 3 or .svg; the export's status is
/// recorded (inaccurate when the bound exceeds --export-tol: exit 3). A curve that is not usable
/// gives "export": null and writes nothing. InputError "export" for an unknown extension, a file
/// that cannot be written, or STEP/IGES in a build without OpenCASCADE.
void add_export(Json& report, const PlanarCurve* curve, const CommonArgs& common);
/// The same for `lac space` (export/space_to_bspline.hpp): .svg is an InputError (planar curves
/// only); curvature_monotone, monotone_segments, constant_curvature_segments and
/// max_curvature_jump are null (the check is planar).
void add_export(Json& report, const SpaceCurve* curve, const CommonArgs& common);

/// The arc [s0, s1] (s0 < s1) of a quadratic LA curve (lac quadratic).
struct QuadraticArc {
  const QuadraticLaCurve& curve;
  double s0, s1;
};
/// The same for a quadratic arc (null: not usable).
void add_export(Json& report, const QuadraticArc* arc, const CommonArgs& common);

}  // namespace lac::cli
