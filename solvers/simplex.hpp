#pragma once
// Modified downhill simplex (Nelder–Mead) as 000 §2.2 and its reference [13] use it: the objective
// may be undefined at some points (a space curve that never meets the cone, or leaves its s
// range); such points count as worse than every defined point (value +inf), so the simplex
// retreats from them by the ordinary contraction and shrink moves.
// Hand-written: Boost.Math has no Nelder–Mead, and Ceres/Eigen minimizers need defined values.
// Standard coefficients (reflection 1, expansion 2, contraction 1/2, shrink 1/2); optional
// restarts from the best vertex counter Nelder–Mead's known stalls.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "lac/common/error.hpp"
#include "lac/common/status.hpp"

namespace lac {

struct SimplexOptions {
  double initial_step = 0.25;   ///< edge length of the initial simplex (per coordinate)
  double value_target = -std::numeric_limits<double>::infinity();  ///< stop as soon as f ≤ this (ok)
  double x_tolerance = 1e-12;   ///< converged when every vertex is within this of the best (max-norm)
  double f_tolerance = 0;       ///< ... and the spread of defined values is ≤ this
  long max_iterations = 2000;   ///< cap on simplex moves (status max_iterations)
  long max_evaluations = 5000;  ///< cap on objective calls (status max_iterations)
  int restarts = 2;             ///< fresh simplices around the best point after convergence
  void validate() const {
    constexpr const char* who = "SimplexOptions";
    if (!(initial_step > 0) || !std::isfinite(initial_step)) throw_input_error(who, "initial_step", initial_step, "(0, inf)");
    if (!(x_tolerance >= 0)) throw_input_error(who, "x_tolerance", x_tolerance, "[0, inf)");
    if (!(f_tolerance >= 0)) throw_input_error(who, "f_tolerance", f_tolerance, "[0, inf)");
    if (std::isnan(value_target)) throw_input_error(who, "value_target", value_target, "[-inf, inf]");
    if (max_iterations < 1) throw_input_error(who, "max_iterations", static_cast<double>(max_iterations), "[1, inf)");
    if (max_evaluations < 1) throw_input_error(who, "max_evaluations", static_cast<double>(max_evaluations), "[1, inf)");
    if (restarts < 0) throw_input_error(who, "restarts", restarts, "[0, inf)");
  }
};

template <int N>
struct SimplexResult {
  Eigen::Matrix<double, N, 1> x;  ///< best vertex
  double value = std::numeric_limits<double>::infinity();  ///< f(x); +inf when nothing was defined
  long iterations = 0;
  long evaluations = 0;
  Status status = Status::ok;
  std::string message;
};

/// Minimizes f: Eigen::Matrix<double, N, 1> → double or std::optional<double>; a non-finite value or
/// nullopt means "undefined" and ranks worst. Status: ok (value_target reached or simplex converged),
/// max_iterations (a cap), no_solution (f undefined at every vertex of the initial simplex).
template <int N, class F>
SimplexResult<N> minimize_simplex(F&& f, const Eigen::Matrix<double, N, 1>& x0, const SimplexOptions& opt = {}) {
  static_assert(N >= 1, "fixed dimension");
  using Vec = Eigen::Matrix<double, N, 1>;
  opt.validate();
  SimplexResult<N> r;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  auto eval = [&](const Vec& x) -> double {
    ++r.evaluations;
    double v;
    if constexpr (std::is_same_v<std::decay_t<decltype(f(x))>, std::optional<double>>) {
      const auto o = f(x);
      v = o ? *o : kInf;
    } else {
      v = static_cast<double>(f(x));
    }
    return std::isfinite(v) ? v : kInf;  // undefined ranks worst
  };
  std::array<Vec, N + 1> p;
  std::array<double, N + 1> fv;
  auto build = [&](const Vec& center, double step) {
    p[0] = center;
    fv[0] = eval(center);
    for (int i = 0; i < N; ++i) {
      p[i + 1] = center;
      p[i + 1][i] += step;
      fv[i + 1] = eval(p[i + 1]);
    }
  };
  auto order = [&] {
    std::array<int, N + 1> idx;
    for (int i = 0; i <= N; ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](int a, int b) { return fv[a] < fv[b]; });
    std::array<Vec, N + 1> p2;
    std::array<double, N + 1> f2;
    for (int i = 0; i <= N; ++i) {
      p2[i] = p[idx[i]];
      f2[i] = fv[idx[i]];
    }
    p = p2;
    fv = f2;
  };
  build(x0, opt.initial_step);
  order();
  if (!std::isfinite(fv[0])) {
    r.x = p[0];
    r.status = Status::no_solution;
    r.message = "simplex: objective undefined at every vertex of the initial simplex";
    return r;
  }
  int restarts_left = opt.restarts;
  for (;;) {
    if (fv[0] <= opt.value_target) {
      r.status = Status::ok;
      break;
    }
    double size = 0;
    for (int i = 1; i <= N; ++i) size = std::max(size, (p[i] - p[0]).cwiseAbs().maxCoeff());
    const bool flat = std::isfinite(fv[N]) && fv[N] - fv[0] <= opt.f_tolerance;
    if (size <= opt.x_tolerance && (flat || opt.f_tolerance == 0)) {
      if (restarts_left-- > 0 && std::isfinite(opt.value_target)) {
        build(p[0], std::max(1e3 * opt.x_tolerance, 1e-3 * opt.initial_step));
        order();
        continue;
      }
      r.status = Status::ok;
      r.message = "simplex: converged (vertices within x_tolerance)";
      break;
    }
    if (r.iterations >= opt.max_iterations || r.evaluations >= opt.max_evaluations) {
      r.status = Status::max_iterations;
      r.message = "simplex: cap reached (" + std::to_string(r.iterations) + " iterations, " +
                  std::to_string(r.evaluations) + " evaluations)";
      break;
    }
    ++r.iterations;
    Vec centroid = Vec::Zero();
    for (int i = 0; i < N; ++i) centroid += p[i];
    centroid /= static_cast<double>(N);
    const Vec xr = centroid + (centroid - p[N]);
    const double fr = eval(xr);
    if (fr < fv[0]) {  // expansion
      const Vec xe = centroid + 2.0 * (centroid - p[N]);
      const double fe = eval(xe);
      if (fe < fr) {
        p[N] = xe;
        fv[N] = fe;
      } else {
        p[N] = xr;
        fv[N] = fr;
      }
    } else if (fr < fv[N - 1]) {
      p[N] = xr;
      fv[N] = fr;
    } else {  // contraction, outside if the reflection improved on the worst, else inside
      const bool outside = fr < fv[N];
      const Vec xc = outside ? Vec(centroid + 0.5 * (xr - centroid)) : Vec(centroid + 0.5 * (p[N] - centroid));
      const double fc = eval(xc);
      if (fc < (outside ? fr : fv[N]) || (!std::isfinite(fv[N]) && std::isfinite(fc))) {
        p[N] = xc;
        fv[N] = fc;
      } else {  // shrink toward the best vertex
        for (int i = 1; i <= N; ++i) {
          p[i] = p[0] + 0.5 * (p[i] - p[0]);
          fv[i] = eval(p[i]);
        }
      }
    }
    order();
  }
  r.x = p[0];
  r.value = fv[0];
  return r;
}

}  // namespace lac
