#include "lac/export/space_to_bspline.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>

#include "lac/common/error.hpp"
#include "lac/curves/space/certified_frenet.hpp"
#include "lac/export/detail/hermite_bound.hpp"

namespace lac {

namespace {

constexpr const char* kWho = "to_bspline";
using detail::HermiteSpanBound;
using Poly = detail::MajorantPoly<10>;  // variables k_0 … k_4 (|κ^(j)|), t_0 … t_4 (|τ^(j)|)

/// Majorants of |c^(m)|, m = 1 … 6, as √(A² + B² + C²) of the Frenet components (header comment).
class FrameMajorants {
 public:
  FrameMajorants() {
    std::array<size_t, 10> next{};
    for (size_t j = 0; j < 5; ++j) next[j] = std::min<size_t>(j + 1, 4), next[5 + j] = 5 + std::min<size_t>(j + 1, 4);
    comp_[1] = {Poly::constant(1), Poly{}, Poly{}};
    for (int m = 1; m < 6; ++m) {
      const auto& [a, b, c] = comp_[m];
      Poly na = a.derivative(next), nb = b.derivative(next), nc = c.derivative(next);
      na += b.times(0);
      nb += a.times(0);
      nb += c.times(5);
      nc += b.times(5);
      comp_[m + 1] = {na, nb, nc};
    }
  }
  double operator()(int m, const std::array<double, 10>& v) const {
    const auto& [a, b, c] = comp_[m];
    const double x = a(v), y = b(v), z = c(v);
    return std::sqrt(x * x + y * y + z * z);
  }

 private:
  std::array<std::array<Poly, 3>, 7> comp_;
};

/// |κ^(j)| and |τ^(j)|, j = 0 … 4, at standard-form s (header comment; 000 Eqs. (3)–(5)).
std::array<double, 10> law_derivatives(const LaSpaceCurve& law, double s) {
  std::array<double, 10> v{};
  const double lr = law.log_rho(s), lm = law.log_mu(s);
  double ck = 1, ct = 1;
  for (int j = 0; j < 5; ++j) {
    v[j] = ck * std::exp(-(1 + j * law.alpha()) * lr);
    v[5 + j] = ct * std::exp(-(1 + j * law.beta()) * lm);
    ck *= law.lambda() * std::abs(1 + j * law.alpha());
    ct *= law.omega() * std::abs(1 + j * law.beta());
  }
  return v;
}

HermiteSpanBound span_bound(const LaSpaceCurve& law, double s0, double s1, int degree) {
  static const FrameMajorants majorants;
  const auto v0 = law_derivatives(law, s0), v1 = law_derivatives(law, s1);
  std::array<double, 10> v{};
  for (size_t i = 0; i < v.size(); ++i) v[i] = (1 + detail::kDerivativeSlack) * std::max(v0[i], v1[i]);
  std::array<double, 7> M{};
  for (int m = 1; m <= 6; ++m) M[m] = (1 + detail::kDerivativeSlack) * majorants(m, v);
  return detail::hermite_span_bound(s1 - s0, degree, M);
}

using Piece = std::vector<Vec3>;

}  // namespace

SpaceExportResult to_bspline(const SpaceCurve& curve, const ExportOptions& options) {
  const auto t_start = std::chrono::steady_clock::now();
  if (curve.pieces().empty()) throw_input_error(kWho, "curve", "an empty curve has nothing to export");
  detail::validate_export_options(options);
  const int p = options.degree;
  SpaceExportResult r;
  const double length = curve.length();
  if (!(length > 0)) throw_input_error(kWho, "curve", "a curve of length 0 has nothing to export");
  const double tol = options.tolerance > 0 ? options.tolerance : kDefaultExportTolerance * length;
  r.info.tolerance = tol;
  r.summary.accept = tol / length;
  const SpacePlacement& pl = curve.placement();
  const double sigma = pl.scale;
  const double extent = pl.origin.norm() + length;
  // 9/10 of the tolerance for the interpolation (1/10 when knots are removed afterwards: the rest is
  // theirs), the rest for the end data and rounding; no finer than the rounding of the coordinates.
  // In standard-form units.
  const double target = std::max((options.remove_knots ? 0.1 : 0.9) * tol, 64 * DBL_EPSILON * extent) / sigma;
  auto fail = [&](Status status, std::string message) {
    r.conclude(status, std::move(message));
    r.summary.seconds = seconds_since(t_start);
    return r;
  };
  auto to_user = [&](const Vec3& x) -> Vec3 { return pl.origin + pl.matrix * x; };

  std::vector<Piece> pieces;  // in the standard-form space, mapped at the end
  std::vector<int> junction;
  std::vector<double> knots{0.0};
  detail::HermiteBounds totals;  // user units
  bool all_g2 = p == 5;
  const auto& cps = curve.pieces();
  for (size_t k = 0; k < cps.size(); ++k) {
    const SpacePiece& sp = cps[k];
    const LaSpaceCurve& law = sp.law;
    if (!(sp.s_end > sp.s_begin)) continue;  // an empty piece adds no span
    std::vector<double> ends;
    std::vector<HermiteSpanBound> bounds;
    const long cap = options.max_spans - static_cast<long>(pieces.size());
    const auto bound = [&](double a, double b) { return span_bound(law, a, b, p); };
    if (!detail::split_hermite_spans(sp.s_begin, sp.s_end, target, cap, bound, ends, bounds))
      return fail(Status::max_iterations, "more than max_spans = " + std::to_string(options.max_spans) +
                                              " spans needed for tolerance " + format_number(tol));
    CertifiedFrame f;
    f.frame = sp.start;
    double s_prev = sp.s_begin;
    // End data: position, tangent, κN (standard form) and their proven error bounds.
    Vec3 p0 = sp.start.p, t0 = sp.start.t, n0 = law.kappa(sp.s_begin) * sp.start.n;
    double dp0 = 0, dt0 = 0, dn0 = 0;
    for (size_t i = 0; i < ends.size(); ++i) {
      const double s1 = ends[i];
      const bool last = i + 1 == ends.size();
      const double h = s1 - s_prev;
      f = integrate_frenet_certified(law, f.frame, s_prev, s1, f.position_error, f.frame_error);
      r.summary.evaluations += f.steps;
      if (f.status != Status::ok)
        return fail(Status::numerical_failure, "the Frenet integration of piece " + std::to_string(k) + " to s = " +
                                                   format_number(s1) + " failed: " + f.message);
      // κ(s1) = e^(−log ρ) to a few ulps of 1 + |log ρ| (relative).
      const double kappa1 = law.kappa(s1);
      Vec3 p1 = f.frame.p, t1 = f.frame.t, n1 = kappa1 * f.frame.n;
      double dp1 = f.position_error, dt1 = f.frame_error,
             dn1 = kappa1 * (f.frame_error + 8 * DBL_EPSILON * (1 + std::abs(law.log_rho(s1))) * (1 + f.frame_error));
      const int degree = bounds[i].degree;
      const int next_degree = i + 1 < bounds.size() ? bounds[i + 1].degree : p;
      int cont = degree == 5 && next_degree == 5 ? 2 : 1;
      if (last && k + 1 < cps.size()) {
        // The next piece starts at its own start frame (000 Eq. (17)): the B-spline uses it, and its
        // κ when the joint is G2 (curvature gap ≤ 1e-6 of the curvatures' scale).
        const SpacePiece& nx = cps[k + 1];
        const double kn = nx.law.kappa(nx.s_begin);
        dp1 += (nx.start.p - p1).norm();
        dt1 += (nx.start.t - t1).norm();
        const double gap = std::abs(kn - kappa1);
        const bool g2 = gap <= 1e-6 * (kn + kappa1 + sigma / length);
        const Vec3 n_next = (g2 ? kn : kappa1) * nx.start.n;
        dn1 += (n_next - n1).norm();
        p1 = nx.start.p;
        t1 = nx.start.t;
        n1 = n_next;
        cont = degree == 5 && g2 ? 2 : 1;
        if (!g2) all_g2 = false;
      }
      Piece piece = detail::hermite_bezier(degree, p, h, p0, t0, n0, p1, t1, n1);
      // Displacement of the B-spline by the end data's errors (header comment).
      const double moved =
          degree == 5 ? std::max(dp0 + 2 * h / 5 * dt0 + h * h / 20 * dn0, dp1 + 2 * h / 5 * dt1 + h * h / 20 * dn1)
                      : std::max(dp0 + h / 3 * dt0, dp1 + h / 3 * dt1);
      if (degree != 5 && p == 5) all_g2 = false;
      if (!pieces.empty() && junction.back() == 2 && degree != 5) junction.back() = 1;
      pieces.push_back(std::move(piece));
      junction.push_back(cont);
      knots.push_back(last ? curve.piece_start(k + 1) : curve.piece_start(k) + sigma * (s1 - sp.s_begin));
      // Rounding: the control points in standard form and their image in user coordinates.
      const double size = std::max(p0.norm(), p1.norm()) + h;
      const double rounding = 64 * DBL_EPSILON * (sigma * size + extent);
      const double interp = sigma * bounds[i].value;
      const double pos = sigma * moved + rounding;
      totals.add_span(interp, pos);
      p0 = p1, t0 = t1, n0 = n1;
      dp0 = dp1, dt0 = dt1, dn0 = dn1;
      s_prev = s1;
    }
  }
  if (pieces.empty()) throw_input_error(kWho, "curve", "a curve of length 0 has nothing to export");
  for (Piece& pc : pieces)
    for (Vec3& x : pc) x = to_user(x);
  knots.back() = length;
  std::vector<double> joints;  // the knots where one piece ends and the next begins
  for (size_t k = 1; k < cps.size(); ++k) joints.push_back(curve.piece_start(k));
  detail::finish_hermite_export(r, p, pieces, junction, knots, all_g2, totals, tol, length, "deviation bound", t_start,
                                [](const BSpline3&, SpaceExportInfo&) {}, options.remove_knots, joints, options.fit,
                                options.fit_max_degree);
  return r;
}

}  // namespace lac
