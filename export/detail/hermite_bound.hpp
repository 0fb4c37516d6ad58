#pragma once
// Internal: the one implementation of the certified Hermite export, used by every to_bspline
// (export/to_bspline.hpp: PlanarCurve and the quadratic LA curve; export/space_to_bspline.hpp:
// SpaceCurve). Independent of the dimension (the point type P: std::complex<double> in the plane,
// Vec3 in space): the Peano constants of the cubic and quintic Hermite interpolants, the least
// bound over the derivative orders on a span, the splitting of a parameter interval until every
// span's bound is below a target, majorant polynomials in bounds of derivatives, degree elevation
// of a Bézier piece, the Hermite Bézier pieces and their assembly into one B-spline (blossoms), the
// ending of an export (ExportInfo, summary, status) and the check of ExportOptions. On top, for planar curves: the span sources (a curve as a sequence of
// smooth parts) and certified_bspline, which cuts them into spans and assembles the B-spline.
#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"
#include "lac/common/summary.hpp"
#include "lac/export/detail/bspline_fit.hpp"
#include "lac/export/to_bspline.hpp"

namespace lac::detail {

// Peano-kernel constants of the Hermite interpolants on [0, 1]: C[m] = max over t of ∫|K_m(t, τ)| dτ,
// where f(t) − (Hf)(t) = ∫ K_m(t, τ) f^(m)(τ) dτ, m the derivative used (tests/reference/
// export_kernels.py; rounded up). Cubic (f, f' at both ends), m = 2, 3, 4: 0.0624987 < 1/16, 1/96,
// 1/384 (the classical t²(1−t)²/24). Quintic (f, f', f'' at both ends), m = 3 … 6: 1/46080 at m = 6
// (t³(1−t)³/720), 1/10240 at m = 5, 0.0061849 and 0.00067702 at m = 3, 4; no m = 2 (the
// interpolant takes f''). For a vector-valued f the same bounds hold with |f^(m)| the Euclidean
// norm (the kernel is scalar: |∫ K f^(m)| ≤ ∫ |K| |f^(m)|).
inline constexpr std::array<double, 7> kHermiteCubic{
    0, 0, 1.0 / 16.0, 1.0 / 96.0 * (1 + 1e-9), 1.0 / 384.0 * (1 + 1e-9), 0, 0};
inline constexpr std::array<double, 7> kHermiteQuintic{
    0, 0, 0, 0.00619, 0.000678, 0.0000977, 1.0 / 46080.0 * (1 + 1e-9)};
/// Relative slack on derivative bounds evaluated in floating point at the span ends.
inline constexpr double kDerivativeSlack = 1e-9;

struct HermiteSpanBound {
  double value = HUGE_VAL;           ///< the interpolation bound
  int order = 2;                     ///< the derivative it uses (its rate in h)
  int degree = 3;                    ///< the Hermite interpolant: 3 (c, c') or 5 (c, c', c'')
  std::array<double, 7> by_order{};  ///< the bound of each order of that degree (0: unused)
};

/// The least over m of C_m h^m M[m] for the Hermite interpolant of `degree` (3 or 5) on a span of
/// length h, M[m] ≥ |c^(m)| on the span (+inf: unbounded). For degree 5 with every order unbounded,
/// the cubic's (a quintic span is then the cubic one raised to degree 5).
inline HermiteSpanBound hermite_span_bound(double h, int degree, const std::array<double, 7>& M) {
  HermiteSpanBound best;
  for (int d : {degree, 3}) {
    const auto& C = d == 3 ? kHermiteCubic : kHermiteQuintic;
    best = {HUGE_VAL, 2, d, {}};
    for (int order = 2; order <= d + 1; ++order) {
      if (C[order] == 0) continue;
      const double v = C[order] * std::pow(h, order) * M[order];
      best.by_order[order] = std::isnan(v) ? HUGE_VAL : v;
      if (v < best.value) best.value = v, best.order = order;
    }
    if (best.value < HUGE_VAL) break;
  }
  return best;
}

/// Splits [u0, u1] until every span's bound (bound(a, b), a HermiteSpanBound whose by_order scale
/// as (b − a)^m) is at most `target`, appending the spans' ends after u0 and their bounds. False
/// when the cap on spans is reached (ends counts the spans already made).
template <class Bound>
bool split_hermite_spans(double u0, double u1, double target, long cap, const Bound& bound, std::vector<double>& ends,
                         std::vector<HermiteSpanBound>& bounds) {
  const HermiteSpanBound b = bound(u0, u1);
  if (b.value <= target || !(u1 - u0 > 4 * DBL_EPSILON * std::max(std::abs(u0), std::abs(u1)))) {
    if (static_cast<long>(ends.size()) >= cap) return false;
    ends.push_back(u1);
    bounds.push_back(b);
    return true;
  }
  // Into n equal parts, n the least over the orders m of (bound_m / target)^(1/m) (bound_m ∝ h^m,
  // the derivative bounds do not grow on a part), at least 2 and at most 64 per level.
  double n_real = HUGE_VAL;
  for (int m = 2; m < 7; ++m)
    if (b.by_order[m] > 0 && std::isfinite(b.by_order[m]))
      n_real = std::min(n_real, std::ceil(std::pow(b.by_order[m] / target, 1.0 / m) * 1.01));
  const int n = static_cast<int>(std::clamp(std::isfinite(n_real) ? n_real : 2.0, 2.0, 64.0));
  double a = u0;
  for (int i = 1; i <= n; ++i) {
    const double c = i == n ? u1 : u0 + (u1 - u0) * i / n;
    if (!split_hermite_spans(a, c, target, cap, bound, ends, bounds)) return false;
    a = c;
  }
  return true;
}

/// A polynomial with nonnegative coefficients in V variables v_i ≥ |f_i|, bounds of functions and
/// their derivatives; derivative() is the formal derivative with v_i' = v_{next[i]} (a chain
/// k_0 → k_1 → … per function), a majorant of |p'| when p majorizes |p(f)| term by term.
template <size_t V>
class MajorantPoly {
 public:
  using Exponents = std::array<int, V>;
  static MajorantPoly constant(double c) {
    MajorantPoly p;
    p.terms_[Exponents{}] = c;
    return p;
  }
  MajorantPoly& operator+=(const MajorantPoly& o) {
    for (const auto& [e, c] : o.terms_) terms_[e] += c;
    return *this;
  }
  /// This polynomial times v_i.
  MajorantPoly times(size_t i) const {
    MajorantPoly p;
    for (const auto& [e, c] : terms_) {
      Exponents f = e;
      ++f[i];
      p.terms_[f] += c;
    }
    return p;
  }
  MajorantPoly derivative(const std::array<size_t, V>& next) const {
    MajorantPoly p;
    for (const auto& [e, c] : terms_)
      for (size_t j = 0; j < V; ++j) {
        if (e[j] == 0) continue;
        Exponents d = e;
        --d[j];
        ++d[next[j]];
        p.terms_[d] += c * e[j];
      }
    return p;
  }
  /// The value at v (each ≥ 0; an unbounded factor +inf makes the term +inf, 0·inf included).
  double operator()(const std::array<double, V>& v) const {
    double sum = 0;
    for (const auto& [e, c] : terms_) {
      double term = c;
      for (size_t j = 0; j < V; ++j)
        for (int i = 0; i < e[j]; ++i) term *= v[j];
      sum += std::isnan(term) ? HUGE_VAL : term;
    }
    return sum;
  }

 private:
  std::map<Exponents, double> terms_;
};

/// The same Bézier curve one degree higher (exact up to rounding).
template <class P>
std::vector<P> elevate_bezier(const std::vector<P>& p) {
  const size_t n = p.size() - 1;
  std::vector<P> q(n + 2);
  q[0] = p[0];
  q[n + 1] = p[n];
  for (size_t i = 1; i <= n; ++i) {
    const double a = static_cast<double>(i) / static_cast<double>(n + 1);
    q[i] = a * p[i - 1] + (1 - a) * p[i];
  }
  return q;
}

/// The Bézier piece of degree p (3 or 5) of the Hermite interpolant of `degree` on a span of arc
/// length h from (q0, t0, n0) to (q1, t1, n1): position, unit tangent c' and c'' (docs/export.md).
/// Degree 5 uses all three; degree 3 positions and tangents only, raised to 5 when p = 5.
template <class P>
std::vector<P> hermite_bezier(int degree, int p, double h, const P& q0, const P& t0, const P& n0, const P& q1,
                              const P& t1, const P& n1) {
  if (degree == 5)
    return {q0,
            q0 + (h / 5) * t0,
            q0 + (2 * h / 5) * t0 + (h * h / 20) * n0,
            q1 - (2 * h / 5) * t1 + (h * h / 20) * n1,
            q1 - (h / 5) * t1,
            q1};
  std::vector<P> piece{q0, q0 + (h / 3) * t0, q1 - (h / 3) * t1, q1};
  if (p == 5) piece = elevate_bezier(elevate_bezier(piece));
  return piece;
}

/// The B-spline of consecutive Hermite Bézier pieces of degree p (3 or 5) over the parameter
/// values knots[0] < … < knots[n] (blossoms; docs/export.md). junction[j]: the continuity after
/// piece j (2: C2, 1: C1). Degree 3, every junction C1 (knot ×2): B0, then B1 B2 of each span,
/// then the end. Degree 5: B0 B1, then B2 B3 of each span and at a junction C2 (knot ×3) the
/// point f(a, b, b, b, c) = B3 + (c − a)/(b − a) (B4 − B3), at a junction C1 (knot ×4) B4 and the
/// next span's B1; then B4 B5 of the last span.
template <class P>
void assemble_hermite_bspline(const std::vector<std::vector<P>>& pieces, const std::vector<int>& junction,
                              const std::vector<double>& knots, int p, std::vector<double>& out_knots,
                              std::vector<P>& out_points) {
  const size_t n = pieces.size();
  out_knots.clear();
  out_points.clear();
  for (int i = 0; i <= p; ++i) out_knots.push_back(knots.front());
  out_points.push_back(pieces[0][0]);
  if (p == 5) out_points.push_back(pieces[0][1]);
  for (size_t j = 0; j < n; ++j) {
    const std::vector<P>& pc = pieces[j];
    out_points.push_back(p == 3 ? pc[1] : pc[2]);
    out_points.push_back(p == 3 ? pc[2] : pc[3]);
    if (j + 1 == n) break;
    const int multiplicity = p - (p == 5 ? junction[j] : 1);
    for (int i = 0; i < multiplicity; ++i) out_knots.push_back(knots[j + 1]);
    if (p == 5) {
      if (junction[j] == 2) {
        const double a = knots[j], bb = knots[j + 1], c = knots[j + 2];
        out_points.push_back(pc[3] + ((c - a) / (bb - a)) * (pc[4] - pc[3]));
      } else {
        out_points.push_back(pc[4]);
        out_points.push_back(pieces[j + 1][1]);
      }
    }
  }
  if (p == 5) out_points.push_back(pieces.back()[4]);
  out_points.push_back(pieces.back().back());
  for (int i = 0; i <= p; ++i) out_knots.push_back(knots.back());
}

/// The largest bounds over the spans so far (absolute): interpolation, positions (end data and
/// rounding) and their sum, the certified deviation.
struct HermiteBounds {
  double interpolation = 0, positions = 0, deviation = 0;
  std::vector<double> span_deviation;  ///< interp + pos of each span, in order
  void add_span(double interp, double pos) {
    interpolation = std::max(interpolation, interp);
    positions = std::max(positions, pos);
    deviation = std::max(deviation, interp + pos);
    span_deviation.push_back(interp + pos);
  }
};

/// Knot removal within a certified bound (Tiller's algorithm, The NURBS Book A5.8, one occurrence
/// at a time). Removing one occurrence of u (multiplicity s) solves for the new control points
/// from both sides; the bound of that step is exact, not Tiller's estimate: u is inserted again
/// into the new curve (Boehm), which gives it the old knot vector, and two B-splines on one knot
/// vector differ by at most the largest distance of their control points (the basis is a
/// nonnegative partition of unity), wherever the changed basis functions are nonzero,
/// [U[first], U[last + p + 1]]. Each Hermite span j (parameter [span_knots[j], span_knots[j+1]])
/// carries its bound `deviation[j]`; a removal is kept when every span it touches stays within
/// `tol` with the step's bound (and rounding) added, which the span then carries (triangle
/// inequality). Knots at the values `fixed` (joints of the curve's segments) are kept. Passes
/// over the interior knots, one occurrence of each per pass, until a pass removes nothing.
/// Returns the largest deviation after the removals.
template <class P>
double remove_knots_within(int p, std::vector<double>& U, std::vector<P>& pts, const std::vector<double>& span_knots,
                           std::vector<double> deviation, const std::vector<double>& fixed, double tol) {
  auto is_fixed = [&](double u) { return std::binary_search(fixed.begin(), fixed.end(), u); };
  auto spans_of = [&](double a, double b) {
    const auto lo = std::lower_bound(span_knots.begin(), span_knots.end(), a);
    const auto hi = std::upper_bound(span_knots.begin(), span_knots.end(), b);
    const size_t j0 = static_cast<size_t>(lo - span_knots.begin());
    size_t j1 = static_cast<size_t>(hi - span_knots.begin());  // pieces j0 … j1 − 2 lie in [a, b]
    j1 = j1 >= 1 ? j1 - 1 : 0;
    return std::pair{j0, std::min(j1, deviation.size())};
  };
  std::vector<P> temp, q;
  for (int pass = 0; pass <= 2 * p + 2; ++pass) {
    bool removed = false;
    for (size_t r = static_cast<size_t>(p) + 1; r + static_cast<size_t>(p) + 1 < U.size();) {
      const double u = U[r];
      size_t rl = r;  // the last occurrence of u
      while (rl + 1 + static_cast<size_t>(p) + 1 < U.size() && U[rl + 1] == u) ++rl;
      const int s = static_cast<int>(rl - r) + 1;
      if (is_fixed(u) || s > p - 1) {
        r = rl + 1;
        continue;
      }
      const size_t first = rl - p, last = rl - s, off = first - 1;
      temp.assign(last + 2 - off, pts[off]);  // every entry used is written below
      temp[0] = pts[off];
      temp[last + 1 - off] = pts[last + 1];
      size_t i = first, j = last, ii = 1, jj = last - off;
      while (j > i) {
        const double ai = (u - U[i]) / (U[i + p + 1] - U[i]);
        const double aj = (u - U[j]) / (U[j + p + 1] - U[j]);
        temp[ii] = (pts[i] - (1 - ai) * temp[ii - 1]) / ai;
        temp[jj] = (pts[j] - aj * temp[jj + 1]) / (1 - aj);
        ++i, ++ii, --j, --jj;
      }
      // The candidate: the left half from the left, the right half from the right, one point fewer.
      q.assign(pts.begin(), pts.end());
      for (i = first, j = last; j > i; ++i, --j) {
        q[i] = temp[i - off];
        q[j] = temp[j - off];
      }
      const size_t fout = (2 * rl - static_cast<size_t>(s) - static_cast<size_t>(p)) / 2;
      q.erase(q.begin() + static_cast<std::ptrdiff_t>(fout));
      // Its distance from the old curve: u inserted again (knot vector U without U[rl]).
      auto u_new = [&](size_t k) { return k < rl ? U[k] : U[k + 1]; };
      double e = 0, size = 0;
      bool finite = true;
      for (size_t k = first; k <= last; ++k) {
        const double a = (u - u_new(k)) / (u_new(k + p) - u_new(k));
        const P back = a * q[k] + (1 - a) * q[k - 1];
        e = std::max(e, point_distance(back, pts[k]));
        size = std::max(size, point_norm(pts[k]) + point_norm(q[k]));
        finite = finite && std::isfinite(e);
      }
      const double step = e + 64 * DBL_EPSILON * size;  // rounding of the solve and the insertion
      const auto [j0, j1] = spans_of(U[first], U[last + p + 1]);
      double worst = 0;
      for (size_t k = j0; k < j1; ++k) worst = std::max(worst, deviation[k]);
      if (!finite || j0 >= j1 || !(worst + step <= tol)) {
        r = rl + 1;
        continue;
      }
      for (size_t k = j0; k < j1; ++k) deviation[k] += step;
      pts.swap(q);
      U.erase(U.begin() + static_cast<std::ptrdiff_t>(rl));
      removed = true;
      r = rl;  // the next distinct knot
    }
    if (!removed) break;
  }
  return deviation.empty() ? 0.0 : *std::max_element(deviation.begin(), deviation.end());
}

/// The end of every to_bspline: r.curve (degree p) assembled from the pieces; with `reduce`, its
/// knots removed within `tol` (remove_knots_within; the knots at `fixed`, the joints, kept), and with
/// `fit` also the least-squares fits of degree p (fit_max_degree 0) or 3 … fit_max_degree tried
/// (export/detail/bspline_fit.hpp); ExportInfo's span count (non-empty knot spans), continuity and bounds, check(r.curve, r.info), the summary, and
/// the status: ok when the deviation is within `tol`, else inaccurate ("<what> <deviation> exceeds
/// the tolerance <tol>").
template <class R, class P, class Check>
void finish_hermite_export(R& r, int p, const std::vector<std::vector<P>>& pieces, const std::vector<int>& junction,
                           const std::vector<double>& knots, bool g2, const HermiteBounds& bounds, double tol,
                           double length, const char* what, std::chrono::steady_clock::time_point t_start,
                           const Check& check, bool reduce = false, const std::vector<double>& fixed = {},
                           bool fit = false, int fit_max_degree = 0) {
  r.curve.degree = p;
  assemble_hermite_bspline(pieces, junction, knots, p, r.curve.knots, r.curve.control_points);
  r.info.continuity = g2 ? "G2" : "G1";
  r.info.interpolation = bounds.interpolation;
  r.info.positions = bounds.positions;
  double deviation = bounds.deviation;
  check(r.curve, r.info);
  if (reduce && deviation <= tol) {
    deviation = remove_knots_within(p, r.curve.knots, r.curve.control_points, knots, bounds.span_deviation, fixed, tol);
    check(r.curve, r.info);
  }
  if (reduce && fit && deviation <= tol) {
    // Least-squares fits with fewer points within the tolerance (export/detail/bspline_fit.hpp), of
    // degree p, or of each degree 3 … fit_max_degree when that is set (fewest_spans_fit). Of those
    // with fewer points than the knot removal's result, the one with the fewest (the lower degree on
    // a tie) that keeps the curvature monotone wherever that result does is taken.
    std::vector<double> UH;
    std::vector<P> PH;
    assemble_hermite_bspline(pieces, junction, knots, p, UH, PH);
    const size_t removed_points = r.curve.control_points.size();
    std::vector<std::pair<int, FittedBSpline<P>>> fits;  // (degree, fit)
    for (int q = fit_max_degree > 0 ? 3 : p; q <= (fit_max_degree > 0 ? fit_max_degree : p); ++q) {
      FittedBSpline<P> f = fewest_spans_fit(p, q, UH, PH, knots, bounds.span_deviation, fixed, tol, removed_points);
      if (f.points.size() < removed_points && f.deviation <= tol) fits.emplace_back(q, std::move(f));
    }
    std::stable_sort(fits.begin(), fits.end(),
                     [](const auto& x, const auto& y) { return x.second.points.size() < y.second.points.size(); });
    for (auto& [q, f] : fits) {
      auto candidate = r.curve;
      candidate.degree = q;
      candidate.knots = f.knots;
      candidate.control_points = f.points;
      auto info = r.info;
      check(candidate, info);
      bool keeps = true;
      if constexpr (requires { info.curvature_monotone; }) keeps = info.curvature_monotone || !r.info.curvature_monotone;
      if (keeps) {
        r.curve = std::move(candidate);
        r.info = info;
        deviation = f.deviation;
        break;
      }
    }
  }
  r.info.max_deviation = deviation;
  r.info.spans = 0;
  const auto degree = static_cast<size_t>(r.curve.degree);
  for (size_t i = degree; i + degree + 1 < r.curve.knots.size(); ++i)
    if (r.curve.knots[i + 1] > r.curve.knots[i]) ++r.info.spans;
  r.summary.error = deviation / length;
  r.summary.error_estimate = deviation;
  r.summary.iterations = static_cast<int>(std::min<long>(r.info.spans, std::numeric_limits<int>::max()));
  r.summary.seconds = seconds_since(t_start);
  if (deviation <= tol) {
    r.conclude(Status::ok, "");
  } else {
    r.conclude(Status::inaccurate, std::string(what) + " " + format_number(deviation) +
                                       " exceeds the tolerance " + format_number(tol));
  }
}

/// InputError "tolerance" unless ≥ 0 and finite, "max_spans" unless ≥ 1, "degree" unless 3 or 5.
void validate_export_options(const ExportOptions& options);

// ---- Planar curves: span sources (export/to_bspline.cpp, export/to_bspline_quadratic.cpp) ----

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
/// With options.remove_knots, a result whose curvature is not monotone is replaced by the Hermite
/// spans' B-spline (remove_knots false) when that one's is.
ExportResult certified_bspline(const std::vector<const SpanSource*>& parts, const std::vector<double>& starts,
                               double extent, const ExportOptions& options, const CurvatureCheck& check);

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
