#include "lac/export/to_bspline.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/curves/planar/certified_position.hpp"
#include "lac/export/detail/hermite_bound.hpp"
#include "lac/export/write.hpp"

namespace lac {

namespace {

constexpr const char* kWho = "to_bspline";

/// |K^(j)(q)|, j = 0 … 4 (la_law.hpp): a power of |t| (t the plain q, or σ(1 − αq) in the offset
/// form, where dt/dq = −σα), e^q for α = 0: monotone in |t| on each side of t = 0; +inf where a
/// negative power meets t = 0.
double abs_dK(const LaLaw& law, double q, int order) {
  if (law.alpha == 0) return std::exp(q);
  const double b = -1.0 / law.alpha;
  double coeff = 1;
  for (int i = 0; i < order; ++i) coeff *= std::abs(b - i) * (law.offset ? std::abs(law.alpha) : 1.0);
  if (coeff == 0) return 0.0;
  const double t = law.offset ? std::abs(1.0 - law.alpha * q) : std::abs(q);
  return coeff * std::pow(t, b - order);
}

/// Majorants of |c^(m)|, m = 1 … 6, polynomials in k_j ≥ |κ^(j)| (j = 0 … 4): c^(m) = A_m e^{iθ} with
/// A_1 = 1, A_{m+1} = A_m' + iκ A_m, so |A_{m+1}| ≤ D(M_m) + k_0 M_m, D the formal derivative with
/// k_j' = k_{j+1} (all coefficients positive). E.g. M_4 = k_2 + 3 k_0 k_1 + k_0³, from
/// c⁗ = (iκ'' − 3κκ' − iκ³) e^{iθ}. (k_4 enters M_6 only and is never differentiated.)
class Majorants {
 public:
  using Poly = detail::MajorantPoly<5>;
  Majorants() {
    const std::array<size_t, 5> next{1, 2, 3, 4, 4};
    polys_[1] = Poly::constant(1);
    for (int m = 1; m < 6; ++m) {
      polys_[m + 1] = polys_[m].derivative(next);
      polys_[m + 1] += polys_[m].times(0);
    }
  }
  double operator()(int m, const std::array<double, 5>& k) const { return polys_[m](k); }

 private:
  std::array<Poly, 7> polys_;
};

/// The interpolation bound of the span [w0, w1] of a source, of the Hermite interpolant of
/// `degree`; for degree 5 where a derivative it needs is unbounded (e.g. κ' at an inflection of an
/// LA segment with α < −1), the cubic's.
detail::HermiteSpanBound span_bound(const detail::SpanSource& src, double w0, double w1, int degree) {
  static const Majorants majorants;
  std::array<double, 5> k = src.derivative_bounds(w0, w1);
  for (double& x : k) x *= 1 + detail::kDerivativeSlack;
  std::array<double, 7> M{};
  for (int m = 1; m <= 6; ++m) M[m] = majorants(m, k);
  return detail::hermite_span_bound(src.span_length(w0, w1), degree, M);
}

using Piece = std::vector<std::complex<double>>;

std::complex<double> casteljau(Piece p, double t) {
  for (size_t r = 1; r < p.size(); ++r)
    for (size_t i = 0; i + r < p.size(); ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
  return p[0];
}

/// The derivative of a Bézier piece as a Bézier piece one degree lower (its hodograph).
Piece hodograph(const Piece& q) {
  const size_t n = q.size() - 1;
  Piece d(n);
  for (size_t i = 0; i < n; ++i) d[i] = static_cast<double>(n) * (q[i + 1] - q[i]);
  return d;
}

/// Signed curvature of a Bézier piece at t ∈ [0, 1] (from its first and second hodographs).
double bezier_curvature(const Piece& p, double t) {
  const Piece d1 = hodograph(p), d2 = hodograph(d1);
  const std::complex<double> v = casteljau(d1, t), a = casteljau(d2, t);
  const double speed = std::abs(v);
  return (v.real() * a.imag() - v.imag() * a.real()) / (speed * speed * speed);
}

/// Bernstein coefficients on [0, 1] of a polynomial.
using Bernstein = std::vector<double>;

double binomial(size_t n, size_t k) {
  double b = 1;
  for (size_t i = 1; i <= k; ++i) b = b * static_cast<double>(n - k + i) / static_cast<double>(i);
  return b;
}

/// The product in Bernstein form (degree m + n): c_k = Σ_{i+j=k} C(m,i) C(n,j) a_i b_j / C(m+n,k).
Bernstein times(const Bernstein& a, const Bernstein& b) {
  const size_t m = a.size() - 1, n = b.size() - 1;
  Bernstein c(m + n + 1, 0.0);
  for (size_t i = 0; i <= m; ++i)
    for (size_t j = 0; j <= n; ++j) c[i + j] += binomial(m, i) * binomial(n, j) * a[i] * b[j];
  for (size_t k = 0; k <= m + n; ++k) c[k] /= binomial(m + n, k);
  return c;
}

Bernstein minus(Bernstein a, const Bernstein& b, double factor = 1) {
  for (size_t i = 0; i < a.size(); ++i) a[i] -= factor * b[i];
  return a;
}

/// One coordinate of a Bézier piece as a polynomial in Bernstein form.
Bernstein part(const Piece& q, bool imag) {
  Bernstein b(q.size());
  for (size_t i = 0; i < q.size(); ++i) b[i] = imag ? q[i].imag() : q[i].real();
  return b;
}

/// The numerator of dκ/dt of a Bézier piece c(t), whose sign is that of dκ/ds:
///   κ = (c' × c'') / |c'|³,  dκ/dt = [(c' × c''') |c'|² − 3 (c' × c'') (c' · c'')] / |c'|⁵,
/// in Bernstein form (degree 4n − 6 for a piece of degree n ≥ 3).
Bernstein curvature_derivative_numerator(const Piece& p) {
  const Piece d1 = hodograph(p), d2 = hodograph(d1), d3 = hodograph(d2);
  const Bernstein x1 = part(d1, false), y1 = part(d1, true), x2 = part(d2, false), y2 = part(d2, true),
                  x3 = part(d3, false), y3 = part(d3, true);
  const Bernstein cross13 = minus(times(x1, y3), times(y1, x3)), speed2 = minus(times(x1, x1), times(y1, y1), -1.0);
  const Bernstein cross12 = minus(times(x1, y2), times(y1, x2)), dot12 = minus(times(x1, x2), times(y1, y2), -1.0);
  return minus(times(cross13, speed2), times(cross12, dot12), 3.0);
}

/// A bound on ∫ max(−dir · N(t), 0) dt over an interval of `width` (Bernstein coefficients b on
/// it): 0 where every coefficient has the sign of dir (their convex hull holds the graph), else
/// the width times the largest coefficient against it, or the sum over the halves (de Casteljau)
/// where that is smaller. Halving stops where the interval's share of `limit` is met, after 24
/// levels, or when `nodes` (a budget shared by the whole call) runs out.
double against(const Bernstein& b, double dir, double limit, long& nodes, double width = 1, int depth = 24) {
  double worst = 0;
  for (double c : b) worst = std::max(worst, -dir * c);
  const double here = width * worst;
  if (worst == 0 || here <= limit * width || depth == 0 || --nodes < 0) return here;
  Bernstein left(b.size()), right(b.size()), w = b;
  const size_t n = b.size() - 1;
  for (size_t r = 0; r <= n; ++r) {
    left[r] = w[0];
    right[n - r] = w[n - r];
    for (size_t i = 0; i + r < n; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
  }
  return std::min(here, against(left, dir, limit, nodes, width / 2, depth - 1) +
                            against(right, dir, limit, nodes, width / 2, depth - 1));
}

/// A bound on how far a Bézier piece's curvature moves against `dir` (its total variation in the
/// other direction): ∫ max(−dir κ'(t), 0) dt ≤ against(N) / min|c'|⁵, with min|c'|² bounded below
/// by the smallest Bernstein coefficient of |c'|² (infinite when that is not positive); refined
/// until it is below `limit` where it can be (at most 4096 halvings).
double curvature_against(const Piece& p, double dir, double limit) {
  const Piece d1 = hodograph(p);
  const Bernstein x1 = part(d1, false), y1 = part(d1, true);
  const Bernstein speed2 = minus(times(x1, x1), times(y1, y1), -1.0);
  const double min_speed2 = *std::min_element(speed2.begin(), speed2.end());
  if (!(min_speed2 > 0)) return HUGE_VAL;
  const double scale = std::pow(min_speed2, 2.5);
  long nodes = 4096;
  return against(curvature_derivative_numerator(p), dir, 0.5 * limit * scale, nodes) / scale;
}

}  // namespace

namespace detail {

bool curvature_monotone(const BSpline& b, const std::vector<MonotoneStretch>& stretches, double length,
                        long* monotone_segments, double* max_jump, long* constant_segments) {
  const auto pieces = bezier_pieces(b);
  std::vector<double> knots;
  std::vector<int> mult;
  b.distinct_knots(knots, mult);  // piece j spans [knots[j], knots[j + 1]]
  double jump = 0;
  long good = 0, constant = 0;
  size_t j = 0;
  double previous_end_kappa = NAN;
  for (const MonotoneStretch& st : stretches) {
    // A curvature constant to 1e-9 (an arc, up to the construction's rounding): no direction to
    // keep; a polynomial's curvature cannot be constant, so such a stretch is not checked.
    const double kscale = std::max(std::abs(st.kappa_start), std::abs(st.kappa_end)) + 1.0 / length;
    const double dk = st.kappa_end - st.kappa_start;
    const double dir = dk > 1e-9 * kscale ? 1.0 : dk < -1e-9 * kscale ? -1.0 : 0.0;
    if (dir == 0) ++constant;
    // Proven, up to a slack of 1e-9 of the curvature's scale: inside each piece the curvature moves
    // against the direction by at most that (curvature_against: the Bernstein coefficients of the
    // numerator of dκ/dt), and across each knot inside the stretch it steps the same way within it.
    double scale = std::max(std::abs(st.kappa_start), std::abs(st.kappa_end));
    std::vector<std::pair<double, double>> ends;  // κ at each piece's start and end
    std::vector<size_t> against_pieces;  // the stretch's pieces, checked once the scale is known
    bool pieces_ok = true;
    for (bool first_span = true; j < pieces.size() && j + 1 < knots.size() && knots[j + 1] <= st.end; ++j) {
      const double k0 = bezier_curvature(pieces[j], 0.0), k1 = bezier_curvature(pieces[j], 1.0);
      if (std::isfinite(previous_end_kappa))
        jump = std::max(jump, std::abs(k0 - previous_end_kappa - (first_span ? st.jump_before : 0.0)));
      first_span = false;
      ends.emplace_back(k0, k1);
      scale = std::max({scale, std::abs(k0), std::abs(k1)});
      previous_end_kappa = k1;
      if (dir != 0) against_pieces.push_back(j);
    }
    const double slack = 1e-9 * scale;
    for (size_t jj : against_pieces) pieces_ok = pieces_ok && curvature_against(pieces[jj], dir, slack) <= slack;
    for (size_t i = 1; i < ends.size() && pieces_ok; ++i)
      pieces_ok = dir * (ends[i].first - ends[i - 1].second) >= -slack;
    if (!ends.empty() && dir != 0 && pieces_ok) ++good;
  }
  if (monotone_segments) *monotone_segments = good;
  if (constant_segments) *constant_segments = constant;
  if (max_jump) *max_jump = jump;
  return good + constant == static_cast<long>(stretches.size());
}

namespace {

ExportResult certified_bspline_once(const std::vector<const SpanSource*>& parts, const std::vector<double>& starts,
                                    double extent, const ExportOptions& options, const CurvatureCheck& check) {
  const auto t_start = std::chrono::steady_clock::now();
  const int p = options.degree;
  ExportResult r;
  const double length = starts.back();
  const double tol = options.tolerance > 0 ? options.tolerance : kDefaultExportTolerance * length;
  r.info.tolerance = tol;
  r.summary.accept = tol / length;
  // 9/10 of the tolerance for the interpolation (1/10 when knots are removed afterwards: the rest is
  // theirs), the rest for positions and rounding; no finer than the rounding of the coordinates (a
  // tolerance below it ends inaccurate without a flood of spans).
  const double target = std::max((options.remove_knots ? 0.1 : 0.9) * tol, 64 * DBL_EPSILON * extent);
  auto fail = [&](Status status, std::string message) {
    r.conclude(status, std::move(message));
    r.summary.seconds = seconds_since(t_start);
    return r;
  };

  // Every span as a Bézier piece of degree p, with the continuity of the junction after it (2: C2,
  // 1: C1; the last one unused) and its knot.
  std::vector<Piece> pieces;
  std::vector<int> junction;
  std::vector<double> knots{0.0};
  HermiteBounds totals;
  bool all_g2 = p == 5;
  // The first part's first point (the later parts start where the previous one ended, below).
  SpanEndPosition first = parts.front()->position(parts.front()->w_begin());
  r.summary.evaluations += first.evaluations;
  if (!usable(first.status) || !std::isfinite(first.error))
    return fail(Status::numerical_failure, "the position at s = 0 failed: " + first.message);
  std::complex<double> p_first = first.point;
  double err_first = first.error;
  for (size_t k = 0; k < parts.size(); ++k) {
    const SpanSource& seg = *parts[k];
    std::vector<double> ends;
    std::vector<HermiteSpanBound> bounds;
    const long cap = options.max_spans - static_cast<long>(pieces.size());
    const auto bound = [&](double a, double b) { return span_bound(seg, a, b, p); };
    bool within_cap = true;
    double w_from = seg.w_begin();
    for (double w_break : seg.breaks()) {
      within_cap = within_cap && split_hermite_spans(w_from, w_break, target, cap, bound, ends, bounds);
      w_from = w_break;
    }
    within_cap = within_cap && split_hermite_spans(w_from, seg.w_end(), target, cap, bound, ends, bounds);
    if (!within_cap)
      return fail(Status::max_iterations, "more than max_spans = " + std::to_string(options.max_spans) +
                                              " spans needed for tolerance " + format_number(tol));
    const double s_base = starts[k];
    const double part_length = starts[k + 1] - starts[k];
    // The part's first point, tangent and c'' = iκ e^{iθ}: the first part's start (a segment's own
    // start, exact, or an integration), else the previous part's last span's end (which the previous
    // part took from this one's start).
    std::complex<double> p0 = p_first;
    double err0 = err_first;
    std::complex<double> t0 = std::polar(1.0, seg.theta(seg.w_begin()));
    std::complex<double> n0 = std::complex<double>(0, seg.kappa(seg.w_begin())) * t0;
    double u_prev = seg.w_begin();
    for (size_t i = 0; i < ends.size(); ++i) {
      const double u1 = ends[i];
      const bool last = i + 1 == ends.size();
      const double s1 = last ? part_length : std::min(part_length, seg.arc(u1));
      const double h = seg.span_length(u_prev, u1);
      const SpanEndPosition pk = seg.position(u1);
      r.summary.evaluations += pk.evaluations;
      if (!usable(pk.status) || !std::isfinite(pk.error))
        return fail(pk.status == Status::max_iterations ? Status::max_iterations : Status::numerical_failure,
                    "the position at s = " + format_number(s_base + s1) + " failed: " + pk.message);
      std::complex<double> p1 = pk.point;
      double err1 = pk.error;
      std::complex<double> t1 = std::polar(1.0, seg.theta(u1));
      std::complex<double> n1 = std::complex<double>(0, seg.kappa(u1)) * t1;
      const int degree = bounds[i].degree;
      const HermiteSpanBound next_bound = i + 1 < bounds.size() ? bounds[i + 1] : HermiteSpanBound{};
      int cont = degree == 5 && next_bound.degree == 5 ? 2 : 1;
      double moved_t = 0, moved_n = 0;  // how far the end's tangent and c'' are moved (joint data)
      if (last && k + 1 < parts.size()) {
        // The next part starts at its own start point and θ: the B-spline uses those, and its κ
        // when the joint is G2 (curvature gap ≤ 1e-6 of the curvatures' scale).
        const SpanSource& next = *parts[k + 1];
        const SpanEndPosition next_start = next.position(next.w_begin());
        r.summary.evaluations += next_start.evaluations;
        if (!usable(next_start.status) || !std::isfinite(next_start.error))
          return fail(Status::numerical_failure,
                      "the position at s = " + format_number(starts[k + 1]) + " failed: " + next_start.message);
        const std::complex<double> p_next = next_start.point, t_next = std::polar(1.0, next.theta(next.w_begin()));
        err1 += std::abs(p_next - p1) + next_start.error;
        moved_t = std::abs(t_next - t1);
        p1 = p_next;
        t1 = t_next;
        p_first = p1;
        err_first = err1;
        const double kappa_next = next.kappa(next.w_begin()), kappa_end = seg.kappa(seg.w_end());
        const double gap = std::abs(kappa_next - kappa_end);
        const bool g2 = gap <= 1e-6 * (std::abs(kappa_next) + std::abs(kappa_end) + 1.0 / length);
        const std::complex<double> n_own = n1;
        n1 = std::complex<double>(0, g2 ? kappa_next : kappa_end) * t1;
        moved_n = std::abs(n1 - n_own);
        cont = degree == 5 && g2 ? 2 : 1;  // the next part's first span is checked below
        if (!g2) all_g2 = false;
      }
      Piece piece = hermite_bezier(degree, p, h, p0, t0, n0, p1, t1, n1);
      // Bound on the curve's displacement by moved_t, moved_n (Bernstein weights ≤ 0.41).
      const double moved =
          degree == 5 ? 0.41 * (3 * h / 5 * moved_t + h * h / 20 * moved_n) : 4.0 / 9.0 * h / 3 * moved_t;
      if (degree != 5 && p == 5) all_g2 = false;
      // A junction is C2 only between two quintic Hermite spans sharing c'' (the previous one set it).
      if (!pieces.empty() && junction.back() == 2 && degree != 5) junction.back() = 1;
      pieces.push_back(std::move(piece));
      junction.push_back(cont);
      knots.push_back(last ? starts[k + 1] : s_base + s1);
      // Rounding: the control points (ulps of their size) and the closed-form θ (ulps of |θ|).
      const double size = std::max(std::abs(p0), std::abs(p1)) + h;
      const double rounding = 64 * DBL_EPSILON * size + h * 4 * DBL_EPSILON * (1 + seg.theta_scale());
      const double interp = bounds[i].value;
      const double pos = std::max(err0, err1) + moved + rounding;
      totals.add_span(interp, pos);
      p0 = p1;
      t0 = t1;
      n0 = n1;
      err0 = err1;
      u_prev = u1;
    }
  }

  finish_hermite_export(r, p, pieces, junction, knots, all_g2, totals, tol, length, "certified deviation", t_start,
                        [&](const BSpline& b, ExportInfo& info) {
                          if (check) check(b, info);
                        },
                        options.remove_knots, std::vector<double>(starts.begin() + 1, starts.end() - 1), options.fit,
                        options.fit_max_degree);
  return r;
}

}  // namespace

ExportResult certified_bspline(const std::vector<const SpanSource*>& parts, const std::vector<double>& starts,
                               double extent, const ExportOptions& options, const CurvatureCheck& check) {
  ExportResult r = certified_bspline_once(parts, starts, extent, options, check);
  // Knot removal can lose the monotone curvature of the Hermite spans (a C4 quintic cannot follow
  // a curvature that changes fast): then the Hermite B-spline at the full tolerance, if it keeps it.
  if (!options.remove_knots || !r.usable() || r.info.curvature_monotone) return r;
  ExportOptions hermite = options;
  hermite.remove_knots = false;
  ExportResult h = certified_bspline_once(parts, starts, extent, hermite, check);
  if (h.usable() && h.info.curvature_monotone) {
    h.summary.evaluations += r.summary.evaluations;
    h.summary.seconds += r.summary.seconds;
    return h;
  }
  return r;
}

}  // namespace detail

namespace {

/// An LA segment in its parameter u (u = ua + s/ℓ). On [u0, u1] without an inflection each
/// |κ^(j)| is a monotone function of s (a power of the LA law's t), so its largest value is at an end.
class SegmentSource final : public detail::SpanSource {
 public:
  explicit SegmentSource(const LaSegment& seg) : seg_(seg) {}
  double w_begin() const override { return seg_.ua(); }
  double w_end() const override { return seg_.ub(); }
  std::vector<double> breaks() const override {
    const auto infl = seg_.inflection_u();
    if (infl && *infl > seg_.ua() && *infl < seg_.ub()) return {*infl};
    return {};
  }
  double arc(double u) const override { return u == seg_.ub() ? seg_.length() : seg_.scale() * (u - seg_.ua()); }
  double span_length(double u0, double u1) const override { return seg_.scale() * (u1 - u0); }
  std::array<double, 5> derivative_bounds(double u0, double u1) const override {
    const LaLaw& law = seg_.law();
    const double l = seg_.scale(), m = std::abs(seg_.normalized().slope());
    const double q0 = seg_.q_at(u0), q1 = seg_.q_at(u1);
    std::array<double, 5> k{};
    k[0] = std::max(std::abs(law.kappa_of_q(q0)), std::abs(law.kappa_of_q(q1))) / l;
    for (int j = 1; j < 5; ++j)  // κ^(j) = K^(j)(q) (dq/du)^j / ℓ^(j+1)
      k[j] = std::max(abs_dK(law, q0, j), abs_dK(law, q1, j)) * std::pow(m, j) / std::pow(l, j + 1);
    return k;
  }
  double theta(double u) const override { return seg_.theta_at(local_s(u)); }
  double kappa(double u) const override { return seg_.kappa_at(local_s(u)); }
  detail::SpanEndPosition position(double u) const override {
    if (u == seg_.ua()) return {seg_.start(), 0.0, 0, Status::ok, ""};  // exact
    // Proven (curves/planar/certified_position.hpp), continued from the last position asked for:
    // span ends come in increasing u.
    if (!(u >= last_.u)) last_ = {seg_.ua(), seg_.start(), 0.0};
    const CertifiedPoint p = position_certified(seg_, last_.u, last_.position, last_.error, u);
    if (p.status == Status::ok) last_ = {u, p.position, p.error};
    return {p.position, p.error, p.steps, p.status, p.message};
  }
  double theta_scale() const override { return std::max(std::abs(seg_.theta_start()), std::abs(seg_.theta_end())); }

 private:
  double local_s(double u) const { return u == seg_.ub() ? seg_.length() : std::min(seg_.length(), arc(u)); }
  const LaSegment& seg_;
  struct Known {
    double u;
    std::complex<double> position;
    double error;
  };
  mutable Known last_{seg_.ua(), seg_.start(), 0.0};
};

std::vector<detail::MonotoneStretch> stretches_of(const PlanarCurve& curve) {
  std::vector<detail::MonotoneStretch> out;
  const auto& segs = curve.segments();
  for (size_t k = 0; k < segs.size(); ++k)
    out.push_back({curve.segment_start(k + 1), segs[k].kappa_start(), segs[k].kappa_end(),
                   k == 0 ? 0.0 : segs[k].kappa_start() - segs[k - 1].kappa_end()});
  return out;
}

}  // namespace

void detail::validate_export_options(const ExportOptions& options) {
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    throw_input_error(kWho, "tolerance", options.tolerance, "[0, inf) (0: 1e-6 x length)");
  if (options.max_spans < 1) throw_input_error(kWho, "max_spans", static_cast<double>(options.max_spans), "[1, inf)");
  if (options.degree != 3 && options.degree != 5) throw_input_error(kWho, "degree", options.degree, "3 or 5");
  if (options.fit_max_degree != 0 && (options.fit_max_degree < 3 || options.fit_max_degree > kMaxFitDegree))
    throw_input_error(kWho, "fit_max_degree", options.fit_max_degree,
                      "0 (the fit has the degree `degree`) or [3, " + std::to_string(kMaxFitDegree) + "]");
}

bool curvature_monotone(const BSpline& b, const PlanarCurve& curve, long* monotone_segments, double* max_jump,
                        long* constant_segments) {
  return detail::curvature_monotone(b, stretches_of(curve), curve.length(), monotone_segments, max_jump,
                                    constant_segments);
}

ExportResult to_bspline(const PlanarCurve& curve, const ExportOptions& options) {
  if (curve.segments().empty()) throw_input_error(kWho, "curve", "an empty curve has nothing to export");
  detail::validate_export_options(options);
  const double length = curve.length();
  double extent = length;
  for (const LaSegment& seg : curve.segments()) extent = std::max(extent, std::abs(seg.start()) + length);
  std::vector<SegmentSource> sources;
  sources.reserve(curve.segments().size());
  std::vector<const detail::SpanSource*> parts;
  std::vector<double> starts;
  for (size_t k = 0; k < curve.segments().size(); ++k) {
    sources.emplace_back(curve.segments()[k]);
    starts.push_back(curve.segment_start(k));
  }
  for (const SegmentSource& s : sources) parts.push_back(&s);
  starts.push_back(curve.segment_start(curve.segments().size()));
  return detail::certified_bspline(parts, starts, extent, options, [&](const BSpline& b, ExportInfo& info) {
    info.curvature_monotone = curvature_monotone(b, curve, &info.monotone_segments, &info.max_curvature_jump,
                                                 &info.constant_curvature_segments);
  });
}

}  // namespace lac
