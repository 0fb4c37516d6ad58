// The `simplex` method of solvers/nonlinear.hpp: modified downhill simplex (Nelder–Mead) as 000 §2.2
// and its reference [13] use it. The merit may be undefined at some points (a space curve that never
// meets the cone); such points rank worse than every defined point (value +inf), so the simplex
// retreats from them by the ordinary contraction and shrink moves. Standard coefficients
// (reflection 1, expansion 2, contraction 1/2, shrink 1/2); restarts from the best vertex counter
// Nelder–Mead's known stalls. Hand-written: Boost.Math has no Nelder–Mead, and the Ceres and Eigen
// minimizers need defined values everywhere.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/solvers/detail/nonlinear_methods.hpp"

namespace lac::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <int N>
NonlinearResult simplex(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o) {
  using Vec = Eigen::Matrix<double, N, 1>;
  const SimplexOptions& so = o.simplex;
  const auto n = x0.size();
  const size_t vertices = static_cast<size_t>(n) + 1;
  const bool own_merit = static_cast<bool>(so.merit);
  NonlinearResult r;
  // Merit at x; with the default merit ‖r‖ the residual goes to `res`. Undefined ranks worst.
  auto eval = [&](const Vec& x, Eigen::VectorXd& res) -> double {
    ++r.evaluations;
    double v = kInf;
    if (own_merit) {
      const std::optional<double> m = so.merit(ConstVectorMap(x.data(), n));
      if (m) v = *m;
    } else if (residual.f(ConstVectorMap(x.data(), n), VectorMap(res.data(), res.size())) && res.allFinite()) {
      v = residual_norm(res, o.norm);
    }
    return std::isfinite(v) ? v : kInf;
  };
  const Eigen::Index m = own_merit ? 0 : residual.size;
  std::vector<Vec> p(vertices, Vec::Zero(n));
  std::vector<double> fv(vertices);
  std::vector<Eigen::VectorXd> rs(vertices, Eigen::VectorXd(m));
  auto build = [&](const Vec& center, double step) {
    const Vec c = center;
    for (size_t i = 0; i < vertices; ++i) {
      p[i] = c;
      if (i > 0) p[i][static_cast<Eigen::Index>(i - 1)] += step;
      fv[i] = eval(p[i], rs[i]);
    }
  };
  std::vector<size_t> idx(vertices);
  auto order = [&] {
    std::iota(idx.begin(), idx.end(), size_t{0});
    std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return fv[a] < fv[b]; });
    std::vector<Vec> p2(vertices);
    std::vector<double> f2(vertices);
    std::vector<Eigen::VectorXd> r2(vertices);
    for (size_t i = 0; i < vertices; ++i) {
      p2[i] = p[idx[i]];
      f2[i] = fv[idx[i]];
      r2[i] = std::move(rs[idx[i]]);
    }
    p.swap(p2);
    fv.swap(f2);
    rs.swap(r2);
  };
  build(x0, so.initial_step);
  order();
  const size_t w = vertices - 1;  // the worst vertex after order()
  int restarts_left = so.restarts;
  Eigen::VectorXd rr(m), re(m), rc(m);
  auto replace_worst = [&](const Vec& x, double f, Eigen::VectorXd& res) {
    p[w] = x;
    fv[w] = f;
    rs[w].swap(res);  // res keeps a buffer of size m
  };
  if (!std::isfinite(fv[0])) {
    r.status = Status::not_converged;
    r.message = "simplex: merit undefined at every vertex of the initial simplex";
  } else {
    for (;;) {
      if (fv[0] <= o.residual_tolerance) {
        r.status = Status::ok;
        break;
      }
      double size = 0;
      for (size_t i = 1; i < vertices; ++i) size = std::max(size, (p[i] - p[0]).cwiseAbs().maxCoeff());
      const bool flat = std::isfinite(fv[w]) && fv[w] - fv[0] <= so.f_tolerance;
      const bool positive_minimum = so.minimum_spread > 0 && std::isfinite(fv[w]) &&
                                    size <= 1e-4 * so.initial_step && fv[w] - fv[0] <= so.minimum_spread * fv[0];
      if ((size <= so.x_tolerance && (flat || so.f_tolerance == 0)) || positive_minimum) {
        if (restarts_left-- > 0) {
          build(p[0], std::max(1e3 * so.x_tolerance, 1e-3 * so.initial_step));
          order();
          continue;
        }
        r.status = Status::not_converged;
        r.message = positive_minimum ? "simplex: stopped at a positive local minimum of the merit, " + format_number(fv[0]) +
                                           " (spread within minimum_spread)"
                                     : "simplex: collapsed (vertices within x_tolerance) at merit " + format_number(fv[0]) +
                                           ", above the tolerance";
        break;
      }
      if (r.iterations >= so.max_iterations || r.evaluations >= so.max_evaluations) {
        r.status = Status::max_iterations;
        r.message = "simplex: cap reached (" + std::to_string(r.iterations) + " iterations, " +
                    std::to_string(r.evaluations) + " evaluations)";
        break;
      }
      ++r.iterations;
      Vec centroid = Vec::Zero(n);
      for (size_t i = 0; i < w; ++i) centroid += p[i];
      centroid /= static_cast<double>(n);
      const Vec xr = centroid + (centroid - p[w]);
      const double fr = eval(xr, rr);
      if (fr < fv[0]) {  // expansion
        const Vec xe = centroid + 2.0 * (centroid - p[w]);
        const double fe = eval(xe, re);
        if (fe < fr) {
          replace_worst(xe, fe, re);
        } else {
          replace_worst(xr, fr, rr);
        }
      } else if (fr < fv[w - 1]) {
        replace_worst(xr, fr, rr);
      } else {  // contraction, outside if the reflection improved on the worst, else inside
        const bool outside = fr < fv[w];
        const Vec xc = outside ? Vec(centroid + 0.5 * (xr - centroid)) : Vec(centroid + 0.5 * (p[w] - centroid));
        const double fc = eval(xc, rc);
        if (fc < (outside ? fr : fv[w]) || (!std::isfinite(fv[w]) && std::isfinite(fc))) {
          replace_worst(xc, fc, rc);
        } else {  // shrink toward the best vertex
          for (size_t i = 1; i < vertices; ++i) {
            p[i] = p[0] + 0.5 * (p[i] - p[0]);
            fv[i] = eval(p[i], rs[i]);
          }
        }
      }
      order();
    }
  }
  r.x = p[0];
  r.merit = fv[0];
  if (!own_merit && std::isfinite(fv[0])) {
    r.residual = rs[0];
    r.residual_norm = fv[0];
  }
  return r;
}

}  // namespace

NonlinearResult simplex_solve(const NonlinearResidual& residual, const Eigen::VectorXd& x0, const NonlinearOptions& o) {
  return with_static_size(x0.size(), [&]<int N>() { return simplex<N>(residual, x0, o); });
}

}  // namespace lac::detail
