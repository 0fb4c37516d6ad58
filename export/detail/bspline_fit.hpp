#pragma once
// Internal: a B-spline with fewer control points than the certified Hermite B-spline H, fitted to H
// by least squares reweighted toward the minimax (Lawson), with a proven distance to H
// (docs/export.md, "Fewer control points").
//
// The fit B has a degree q ≥ 3 (H's degree p or another), simple knots inside each smooth part
// (C^(q−1)), uniform in the index of H's spans, and at the joints of the curve's parts the
// continuity H has there (multiplicity q − p + H's).
// Its first and last points, tangents and (p ≥ 5) second derivatives are H's, so B keeps the curve's
// end data. The distance |B(t) − H(t)| is bounded exactly: both are written as Bézier pieces
// (bezier_pieces_on, export/detail/bspline_core.hpp) on the union of their knots, the one of lower
// degree raised to the other's (exactly: convex combinations of its points), and the difference of
// two Bézier pieces of one degree on one interval is at most the largest distance of their control
// points (the Bernstein basis is a nonnegative partition of unity). With H's own certified bound on each of its
// spans the triangle inequality gives B's. Written by hand: the fitting and refinement are the
// textbook algorithms (The NURBS Book A2.2, §5.3, §9.4.1); Eigen solves the normal equations.
#include <Eigen/Sparse>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <complex>
#include <vector>

#include "lac/export/detail/bspline_core.hpp"

namespace lac::detail {

/// Coordinates of a point type: std::complex<double> (2) or an Eigen vector (its size).
inline constexpr int point_dimension(const std::complex<double>*) { return 2; }
template <class V>
constexpr int point_dimension(const V*) {
  return V::RowsAtCompileTime;
}
inline double coordinate(const std::complex<double>& p, int d) { return d == 0 ? p.real() : p.imag(); }
inline void set_coordinate(std::complex<double>& p, int d, double v) { d == 0 ? p.real(v) : p.imag(v); }
template <class V>
double coordinate(const V& p, int d) {
  return p(d);
}
template <class V>
void set_coordinate(V& p, int d, double v) {
  p(d) = v;
}
/// The nonzero basis functions N_{k−p} … N_k at t in span k (The NURBS Book A2.2).
inline void basis_functions(int p, const std::vector<double>& U, size_t k, double t, std::vector<double>& N) {
  N.assign(p + 1, 0.0);
  std::vector<double> left(p + 1), right(p + 1);
  N[0] = 1;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - U[k + 1 - j];
    right[j] = U[k + j] - t;
    double saved = 0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

/// The first control points of a clamped B-spline (knots U, degree p) that give it the value,
/// first and (`count` = 3) second derivative d0, d1, d2 at its start.
template <class P>
void start_points(int p, const std::vector<double>& U, const P& d0, const P& d1, const P& d2, int count,
                  std::vector<P>& pts) {
  const double a = U[p], h1 = U[p + 1] - a, h2 = U[p + 2] - a;
  pts[0] = d0;
  pts[1] = d0 + (h1 / p) * d1;
  if (count == 3) pts[2] = pts[1] + h2 * ((h1 / (p * (p - 1.0))) * d2 + (1.0 / h1) * P(pts[1] - pts[0]));
}

/// Value, first and second derivative at the start of a clamped B-spline.
template <class P>
void start_derivatives(int p, const std::vector<double>& U, const std::vector<P>& pts, P& d0, P& d1, P& d2) {
  const double a = U[p], h1 = U[p + 1] - a, h2 = U[p + 2] - a;
  d0 = pts[0];
  d1 = (p / h1) * P(pts[1] - pts[0]);
  d2 = (p * (p - 1.0) / h1) * P((1.0 / h2) * P(pts[2] - pts[1]) - (1.0 / h1) * P(pts[1] - pts[0]));
}

/// The same B-spline traversed backwards on the reflected parameter a + b − t.
template <class P>
void reverse_bspline(std::vector<double>& U, std::vector<P>& pts) {
  const double sum = U.front() + U.back();
  std::reverse(U.begin(), U.end());
  for (double& u : U) u = sum - u;
  std::reverse(pts.begin(), pts.end());
}

/// Rounds of Lawson's reweighting in fit_bspline (1: plain least squares).
inline constexpr int kLawsonRounds = 8;

/// The same Bézier piece written in degree q ≥ its own (degree elevation, The NURBS Book Eq. 5.36,
/// once per degree: each new point a convex combination of two old ones).
template <class P>
std::vector<P> elevate_bezier(std::vector<P> piece, int q) {
  while (static_cast<int>(piece.size()) - 1 < q) {
    const int r = static_cast<int>(piece.size()) - 1;
    std::vector<P> up(r + 2, piece[0]);
    up[r + 1] = piece[r];
    for (int i = 1; i <= r; ++i) {
      const double a = static_cast<double>(i) / (r + 1);
      up[i] = a * piece[i - 1] + (1 - a) * piece[i];
    }
    piece.swap(up);
  }
  return piece;
}

template <class P>
struct FittedBSpline {
  std::vector<double> knots;
  std::vector<P> points;
  double deviation = HUGE_VAL;  ///< proven bound on |B − curve|: |B − H| plus H's span bounds
};

/// The fit of degree q (≥ 3) with about `spans` knot spans in all (each part at least one),
/// certified against H (degree p, knots UH, points PH; `span_knots` its Hermite span ends with
/// `span_deviation` each, `fixed` the joints). deviation stays +inf when there are too few points to
/// fit or the solve fails.
template <class P>
FittedBSpline<P> fit_bspline(int p, int q, const std::vector<double>& UH, const std::vector<P>& PH,
                             const std::vector<double>& span_knots, const std::vector<double>& span_deviation,
                             const std::vector<double>& fixed, long spans) {
  FittedBSpline<P> out;
  const double a = UH[p], b = UH[UH.size() - 1 - p], length = b - a;
  // Knots: inside each part uniform in the index of H's spans, the joints with H's continuity.
  std::vector<double>& U = out.knots;
  U.assign(q + 1, a);
  double from = a;
  std::vector<double> ends;
  for (double f : fixed)
    if (f > a && f < b) ends.push_back(f);
  ends.push_back(b);
  for (double to : ends) {
    // Uniform in the index of H's span ends inside the part: H's spans are short where the curve
    // needs many points (their lengths equalize the interpolation bound), so B's knots follow them.
    const auto e0 = std::lower_bound(span_knots.begin(), span_knots.end(), from);
    const auto e1 = std::lower_bound(span_knots.begin(), span_knots.end(), to);
    const double span_count = static_cast<double>(e1 - e0);
    const long n = std::max(1L, std::lround(static_cast<double>(spans) * (to - from) / length));
    for (long i = 1; i < n; ++i) {
      const double x = span_count * static_cast<double>(i) / static_cast<double>(n);
      const auto j = static_cast<std::ptrdiff_t>(std::floor(x));
      const double lo = e0[j], hi = e0 + j + 1 <= e1 ? e0[j + 1] : to;
      U.push_back(lo + (hi - lo) * (x - static_cast<double>(j)));
    }
    const auto range = std::equal_range(UH.begin(), UH.end(), to);
    const long m = to == b ? q + 1 : std::max(1L, q - p + std::min<long>(p - 1, range.second - range.first));
    for (long i = 0; i < m; ++i) U.push_back(to);
    from = to;
  }
  const int fixed_count = p >= 5 ? 3 : 2;
  const size_t n = U.size() - q - 1;
  if (n < static_cast<size_t>(2 * fixed_count) || U[q + 1] == a || U[q + 2] == a) return out;
  std::vector<P>& pts = out.points;
  pts.assign(n, PH[0]);
  {  // end data: H's value and derivatives at both ends
    P d0, d1, d2;
    start_derivatives(p, UH, PH, d0, d1, d2);
    start_points(q, U, d0, d1, d2, fixed_count, pts);
    std::vector<double> UHr = UH, Ur = U;
    std::vector<P> PHr = PH, Pr = pts;
    reverse_bspline(UHr, PHr);
    reverse_bspline(Ur, Pr);
    if (Ur[q + 1] == Ur[q] || Ur[q + 2] == Ur[q]) return out;
    start_derivatives(p, UHr, PHr, d0, d1, d2);
    start_points(q, Ur, d0, d1, d2, fixed_count, Pr);
    for (int i = 0; i < fixed_count; ++i) pts[n - 1 - i] = Pr[i];
  }
  // Least squares at 2q + 2 Chebyshev points of each knot span, against H. Unknowns: the free
  // points (indices fixed_count … n − 1 − fixed_count, every coordinate) and, for the cubic, the
  // lengths λ of the end tangents (points 1 and n − 2 at P0 + λT0 and P_{n−1} − λT1: the
  // tangents' directions kept, G1 end data; the quintic keeps its second points, hence G2).
  constexpr int D = point_dimension(static_cast<const P*>(nullptr));
  const bool free_lengths = p == 3;
  const size_t free_begin = fixed_count, free_end = n - fixed_count, nf = free_end - free_begin;
  const Eigen::Index columns = static_cast<Eigen::Index>(D * nf) + (free_lengths ? 2 : 0);
  P t_start = pts[1] - pts[0], t_end = pts[n - 2] - pts[n - 1];
  t_start = (1.0 / point_norm(t_start)) * t_start;
  t_end = (1.0 / point_norm(t_end)) * t_end;
  if (free_lengths) pts[1] = pts[0], pts[n - 2] = pts[n - 1];  // the λ parts come from the solve
  if (columns > 0) {
    auto dot = [](const P& x, const P& y) {
      double sum = 0;
      for (int d = 0; d < D; ++d) sum += coordinate(x, d) * coordinate(y, d);
      return sum;
    };
    struct Sample {
      std::vector<std::pair<Eigen::Index, P>> entries;  // column, its vector at this sample
      P target;                                          // H minus the fixed points' part
    };
    std::vector<Sample> samples;
    std::vector<double> N;
    const int m = 2 * q + 2;
    for (size_t k = q; k + q + 1 < U.size(); ++k) {
      if (!(U[k + 1] > U[k])) continue;
      for (int j = 0; j < m; ++j) {
        const double t = U[k] + (U[k + 1] - U[k]) * 0.5 * (1 - std::cos(M_PI * (j + 0.5) / m));
        basis_functions(q, U, k, t, N);
        Sample sample{{}, de_boor(p, UH, PH, {}, t)};
        for (int i = 0; i <= q; ++i) {
          const size_t gi = k - q + i;
          if (gi >= free_begin && gi < free_end) {
            for (int d = 0; d < D; ++d) {
              P unit = pts[0] - pts[0];
              set_coordinate(unit, d, N[i]);
              sample.entries.emplace_back(static_cast<Eigen::Index>(D * (gi - free_begin) + d), unit);
            }
            continue;
          }
          sample.target = sample.target - N[i] * pts[gi];
          if (free_lengths && gi == 1) sample.entries.emplace_back(columns - 2, N[i] * t_start);
          if (free_lengths && gi == n - 2) sample.entries.emplace_back(columns - 1, N[i] * t_end);
        }
        samples.push_back(std::move(sample));
      }
    }
    // Weighted least squares, reweighted toward the discrete minimax (Lawson: w ← w·|error|,
    // normalized); the solution with the smallest largest sample error is kept.
    std::vector<double> w(samples.size(), 1.0);
    Eigen::VectorXd x, best_x;
    double best_max = HUGE_VAL;
    for (int round = 0; round < kLawsonRounds; ++round) {
      std::vector<Eigen::Triplet<double>> triplets;
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(columns);
      for (size_t q = 0; q < samples.size(); ++q)
        for (const auto& [c1, v1] : samples[q].entries) {
          for (const auto& [c2, v2] : samples[q].entries) triplets.emplace_back(c1, c2, w[q] * dot(v1, v2));
          rhs(c1) += w[q] * dot(v1, samples[q].target);
        }
      Eigen::SparseMatrix<double> A(columns, columns);
      A.setFromTriplets(triplets.begin(), triplets.end());
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
      if (solver.info() != Eigen::Success) break;
      x = solver.solve(rhs);
      if (solver.info() != Eigen::Success || !x.allFinite()) break;
      double largest = 0, total = 0;
      std::vector<double> e(samples.size());
      for (size_t q = 0; q < samples.size(); ++q) {
        P fitted = samples[q].target - samples[q].target;
        for (const auto& [c, v] : samples[q].entries) fitted = fitted + x(c) * v;
        e[q] = point_norm(P(samples[q].target - fitted));
        largest = std::max(largest, e[q]);
        total += w[q] * e[q];
      }
      if (largest < best_max) best_max = largest, best_x = x;
      if (!(total > 0)) break;
      for (size_t q = 0; q < samples.size(); ++q) w[q] *= e[q] * static_cast<double>(samples.size()) / total;
    }
    if (!std::isfinite(best_max)) return out;
    x = best_x;
    for (size_t i = 0; i < nf; ++i)
      for (int d = 0; d < D; ++d) set_coordinate(pts[free_begin + i], d, x(static_cast<Eigen::Index>(D * i + d)));
    if (free_lengths) {
      if (!(x(columns - 2) > 0 && x(columns - 1) > 0)) return out;  // a tangent turned round
      pts[1] = pts[0] + x(columns - 2) * t_start;
      pts[n - 2] = pts[n - 1] + x(columns - 1) * t_end;
    }
  }
  // Certification on the union of the two knot sets.
  std::vector<double> breaks;
  for (size_t i = p; i + p < UH.size(); ++i) breaks.push_back(UH[i]);
  for (size_t i = q; i + q < U.size(); ++i) breaks.push_back(U[i]);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  {  // each interval in quarters: the control polygons' distance nears the curves' (O(h²) closer)
    std::vector<double> finer{breaks.front()};
    for (size_t j = 0; j + 1 < breaks.size(); ++j) {
      for (int q = 1; q < 4; ++q) {
        const double x = breaks[j] + (breaks[j + 1] - breaks[j]) * q / 4.0;
        if (x > finer.back() && x < breaks[j + 1]) finer.push_back(x);
      }
      finer.push_back(breaks[j + 1]);
    }
    breaks.swap(finer);
  }
  const auto pb = bezier_pieces_on(q, U, pts, breaks);
  const auto ph = bezier_pieces_on(p, UH, PH, breaks);
  const int r = std::max(p, q);
  double worst = 0;
  for (size_t j = 0; j < pb.size(); ++j) {
    const std::vector<P> bj = elevate_bezier(pb[j], r), hj = elevate_bezier(ph[j], r);
    double e = 0, size = 0;
    for (int i = 0; i <= r; ++i) {
      e = std::max(e, point_norm(P(bj[i] - hj[i])));
      size = std::max(size, point_norm(bj[i]) + point_norm(hj[i]));
    }
    // Rounding of the blossoms and the elevation (at most r levels of convex combinations each).
    e += (64 + 16 * r * r) * DBL_EPSILON * size;
    const double mid = 0.5 * (breaks[j] + breaks[j + 1]);
    size_t k = static_cast<size_t>(std::upper_bound(span_knots.begin(), span_knots.end(), mid) - span_knots.begin());
    k = std::min(k == 0 ? 0 : k - 1, span_deviation.size() - 1);
    worst = std::max(worst, e + span_deviation[k]);
    if (!std::isfinite(worst)) return out;
  }
  out.deviation = worst;
  return out;
}

/// The fit of degree q with the fewest knot spans whose proven bound is within `tol`, found by
/// doubling and then bisection on the span count; none (deviation +inf, no points) when every fit
/// with fewer than `max_points` control points misses the tolerance.
template <class P>
FittedBSpline<P> fewest_spans_fit(int p, int q, const std::vector<double>& UH, const std::vector<P>& PH,
                                  const std::vector<double>& span_knots, const std::vector<double>& span_deviation,
                                  const std::vector<double>& fixed, double tol, size_t max_points) {
  auto points_of = [&](long n) { return fit_bspline(p, q, UH, PH, span_knots, span_deviation, fixed, n); };
  FittedBSpline<P> best;
  long lo = 0, hi = 0, upper = 0;  // lo fails (or 0), hi the best success (or 0), upper ≥ hi
  for (long n = 1; n <= 2 * static_cast<long>(max_points); n *= 2) {
    FittedBSpline<P> f = points_of(n);
    if (f.points.size() >= max_points) {
      upper = n;
      break;
    }
    if (f.deviation <= tol) {
      best = std::move(f);
      hi = upper = n;
      break;
    }
    lo = n;
  }
  while (upper > lo + 1) {
    const long mid = lo + (upper - lo) / 2;
    FittedBSpline<P> f = points_of(mid);
    if (f.deviation <= tol && (hi == 0 || f.points.size() < best.points.size())) {
      best = std::move(f);
      hi = upper = mid;
    } else if (f.deviation <= tol) {
      upper = mid;
    } else {
      lo = mid;
    }
  }
  return hi > 0 ? best : FittedBSpline<P>{};
}

}  // namespace lac::detail
