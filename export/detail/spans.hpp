#pragma once
// The span machinery of to_bspline (export/to_bspline.hpp), shared by every curve it exports: a
// curve is a sequence of smooth parts (the LA segments of a PlanarCurve, the arc of a quadratic
// LA curve), each a SpanSource; certified_bspline cuts each part into spans until the Peano bound
// of each span's Hermite interpolant is small enough, and assembles the B-spline.
#include <array>
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "lac/common/status.hpp"
#include "lac/export/to_bspline.hpp"

namespace lac::detail {

/// A position at a span end with its error: the larger of two independent quadratures' estimates
/// and their difference (0 for a point known exactly, e.g. a segment's start).
struct SpanEndPosition {
  std::complex<double> point;
  double error = 0;
  long evaluations = 0;
  Status status = Status::ok;
  std::string message;
};

/// One smooth part of a curve, in a parameter w of its own on [w_begin(), w_end()], increasing
/// with the arc length (u for a LaSegment, s for a quadratic LA curve).
class SpanSource {
 public:
  virtual ~SpanSource() = default;
  virtual double w_begin() const = 0;
  virtual double w_end() const = 0;
  /// w strictly inside where a span must end (an inflection), increasing.
  virtual std::vector<double> breaks() const = 0;
  /// Arc length from w_begin() to w (the part's length at w_end(), exactly).
  virtual double arc(double w) const = 0;
  /// Arc length of [w0, w1].
  virtual double span_length(double w0, double w1) const = 0;
  /// k_j ≥ |κ^(j)(s)| (j = 0 … 4, derivatives in arc length) on [w0, w1], which holds no break;
  /// +inf where a derivative is unbounded.
  virtual std::array<double, 5> derivative_bounds(double w0, double w1) const = 0;
  virtual double theta(double w) const = 0;
  virtual double kappa(double w) const = 0;  ///< signed
  virtual SpanEndPosition position(double w) const = 0;
  /// max |θ| on the part (for the rounding of the closed-form θ).
  virtual double theta_scale() const = 0;
};

/// ExportInfo's curvature check on the assembled B-spline (run before the status is concluded).
using CurvatureCheck = std::function<void(const BSpline&, ExportInfo&)>;

/// The certified B-spline of the parts in order; starts[k] is the arc length of part k's start
/// along the whole curve (starts.size() = parts.size() + 1, the last the whole length). Consecutive
/// parts meet at the next part's start point and tangent (and its curvature when they agree, G2),
/// the gap entering the bound. `extent`: the size of the coordinates (for rounding). Everything
/// of ExportInfo but the curvature check (`check`) is filled in; options are validated by the caller.
ExportResult certified_bspline(const std::vector<const SpanSource*>& parts, const std::vector<double>& starts,
                               double extent, const ExportOptions& options, const CurvatureCheck& check);

/// InputError "tolerance" unless ≥ 0 and finite, "max_spans" unless ≥ 1, "degree" unless 3 or 5.
void validate_export_options(const ExportOptions& options);

/// k_j ≥ |κ^(j)(s)| (j = 0 … 4) on [s0, s1] of a quadratic LA curve, which holds no inflection
/// inside (to_bspline_quadratic.cpp derives them from 003's Eq. (4.3)).
std::array<double, 5> quadratic_derivative_bounds(const QuadraticLaCurve& c, double s0, double s1);

/// A stretch of the curve along which the LA curvature is monotone, for the curvature check:
/// its end (arc length along the whole curve), its curvature at both ends and the curve's own
/// curvature jump at its start (0 for the first and at a G2 joint).
struct MonotoneStretch {
  double end = 0;
  double kappa_start = 0, kappa_end = 0;
  double jump_before = 0;
};

/// ExportInfo's curvature check (to_bspline.hpp curvature_monotone) on given stretches.
bool curvature_monotone(const BSpline& b, const std::vector<MonotoneStretch>& stretches, double length,
                        long* monotone_segments, double* max_jump, long* constant_segments);

}  // namespace lac::detail
