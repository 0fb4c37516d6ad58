#include "lac/curves/space/frenet.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <optional>

#include "lac/integrators/magnus.hpp"
#include "lac/integrators/ode.hpp"

namespace lac {
namespace {

using State = Eigen::Matrix<double, 12, 1>;

State pack(const Frame3& f) {
  State y;
  y << f.p, f.t, f.n, f.b;
  return y;
}

Frame3 unpack(const State& y) {
  return {y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), y.segment<3>(9)};
}

// Gram–Schmidt on (T, N) and B = T × N: projects the frame back onto SO(3) after each step.
void orthonormalize(State& y) {
  Vec3 t = y.segment<3>(3).normalized();
  Vec3 n = y.segment<3>(6);
  n = (n - n.dot(t) * t).normalized();
  y.segment<3>(3) = t;
  y.segment<3>(6) = n;
  y.segment<3>(9) = t.cross(n);
}

struct FrenetRhs {
  const LaSpaceCurve* curve;
  State operator()(double s, const State& y) const {
    const double k = curve->kappa(s), w = curve->tau(s);
    State d;
    d.segment<3>(0) = y.segment<3>(3);
    d.segment<3>(3) = k * y.segment<3>(6);
    d.segment<3>(6) = -k * y.segment<3>(3) + w * y.segment<3>(9);
    d.segment<3>(9) = -w * y.segment<3>(6);
    return d;
  }
};

double cone_gap(const State& y, double cone_angle) { return cone_angle_of(y.segment<3>(0)) - cone_angle; }

// One stepping loop for all methods. `advance(s, y, f0, h)` returns the state after one exact
// step of size h; event location calls it with varying h from the same step start.
struct Stepper {
  const LaSpaceCurve& curve;
  const OdeOptions& opt;
  FrenetRhs rhs{&curve};

  // Body-frame generator of g = (F, P) ∈ SE(3), g' = g ξ: ω = (τ, 0, κ) (Darboux vector), v = e_x.
  Twist generator(double s) const { return {Vec3(curve.tau(s), 0, curve.kappa(s)), Vec3::UnitX()}; }

  // Magnus step (integrators/magnus.hpp); `scaled_err` gets |Ω6 − Ω4| over the tolerance.
  State magnus(double s, const State& y, double h, long& evals, double* scaled_err) const {
    RigidMotion g;
    g.rotation << y.segment<3>(3), y.segment<3>(6), y.segment<3>(9);
    g.position = y.segment<3>(0);
    double err = 0;
    magnus6_step([this](double u) { return generator(u); }, s, h, g, scaled_err ? &err : nullptr);
    evals += 3;
    if (scaled_err) {
      const double scale = opt.atol + opt.rtol * std::max(1.0, y.segment<3>(0).cwiseAbs().maxCoeff());
      *scaled_err = err / scale;
    }
    State out;
    out << g.position, g.rotation.col(0), g.rotation.col(1), g.rotation.col(2);
    return out;
  }

  // One exact step of size h from (s, y); f0 = f(s, y) for rk45. `scaled_err` (adaptive methods)
  // receives the step's error over the tolerance; f_end the rk45 FSAL stage.
  State advance(double s, const State& y, const State& f0, double h, long& evals, double* scaled_err = nullptr,
                State* f_end = nullptr) const {
    switch (opt.method) {
      case OdeMethod::rk4:
        evals += 4;
        return rk4_step(rhs, s, y, h);
      case OdeMethod::magnus6:
        return magnus(s, y, h, evals, scaled_err);
      case OdeMethod::rk45: break;
    }
    auto f = rhs;
    auto st = DormandPrince45<State>::step(f, s, y, f0, h);
    evals += 6;
    if (scaled_err) *scaled_err = scaled_error(st.error, y, st.y, opt.atol, opt.rtol);
    if (f_end) *f_end = st.f_end;
    return st.y;
  }

  // cone_angle < 0: no event.
  FrenetResult run(const Frame3& start, double s0, double s1, double cone_angle) const {
    FrenetResult r;
    State y = pack(start);
    orthonormalize(y);
    double s = s0;
    r.s = s0;
    const double span = s1 - s0;
    if (!(span > 0)) {
      r.frame = unpack(y);
      return r;
    }
    const bool adaptive = opt.method != OdeMethod::rk4;
    State f0 = State::Zero();  // first stage of the next rk45 step (FSAL); unused otherwise
    double h;
    if (!adaptive) {
      h = span / std::max(1.0, std::ceil(span / opt.h));
    } else if (opt.method == OdeMethod::magnus6) {  // exact for a helix: start with a bounded turn
      h = std::min(span, 0.05 * curve.rho(s));
    } else {  // Hairer's starting step for order 5 with the state's scale (|T| = 1)
      f0 = rhs(s, y);
      ++r.evaluations;
      const double tol = opt.atol + opt.rtol * std::max(1.0, y.cwiseAbs().maxCoeff());
      h = std::clamp(0.5 * std::pow(tol, 0.2) / std::max(f0.cwiseAbs().maxCoeff(), 1e-300), 1e-12 * span, span);
    }
    long attempts = 0;
    while (s < s1) {
      if (++attempts > opt.max_steps) {
        r.status = Status::max_iterations;
        r.message = "frenet: step cap " + std::to_string(opt.max_steps) + " reached at s = " + format_number(s);
        break;
      }
      const bool last = (s1 - s) <= h * (1 + 1e-12);
      const double hs = last ? s1 - s : h;
      double e = 0;
      State f_end = State::Zero();
      State y_new = advance(s, y, f0, hs, r.evaluations, adaptive ? &e : nullptr, &f_end);
      double factor = 1.0;
      if (!adaptive && !y_new.allFinite()) {  // a fixed step cannot retry smaller (R11)
        r.status = Status::numerical_failure;
        r.message = "frenet: non-finite state at s = " + format_number(s + hs) + " (kappa = " +
                    format_number(curve.kappa(s + hs)) + ", tau = " + format_number(curve.tau(s + hs)) + ")";
        break;
      }
      if (adaptive) {
        if (!std::isfinite(e) || !y_new.allFinite()) {
          h *= 0.1;
          if (h < 1e-15 * std::max(1.0, std::abs(s))) {
            r.status = Status::numerical_failure;
            r.message = "frenet: non-finite state at s = " + format_number(s);
            break;
          }
          continue;
        }
        factor = e == 0 ? 5.0 : std::clamp(0.9 * std::pow(e, -0.2), 0.2, 5.0);
        if (e > 1.0) {
          h = hs * factor;
          if (h < 1e-15 * std::max(1.0, std::abs(s))) {
            r.status = Status::numerical_failure;
            r.message = "frenet: step size underflow at s = " + format_number(s);
            break;
          }
          continue;
        }
        r.error_estimate += e * (opt.atol + opt.rtol);
      }
      orthonormalize(y_new);
      if (!y_new.allFinite()) {  // e.g. a degenerate frame after the step
        r.status = Status::numerical_failure;
        r.message = "frenet: non-finite state at s = " + format_number(s + hs);
        break;
      }
      if (cone_angle >= 0 && cone_gap(y_new, cone_angle) >= 0) {  // first meeting within this step
        const double g0 = cone_gap(y, cone_angle), g1 = cone_gap(y_new, cone_angle);
        auto gap = [&](double hh) {
          if (hh <= 0) return g0;
          if (hh >= hs) return g1;
          State z = advance(s, y, f0, hh, r.evaluations);
          orthonormalize(z);
          return cone_gap(z, cone_angle);
        };
        std::uintmax_t iters = 100;
        const auto root = boost::math::tools::toms748_solve(gap, 0.0, hs, g0, g1,
                                                            boost::math::tools::eps_tolerance<double>(52), iters);
        const double hh = 0.5 * (root.first + root.second);
        State z = hh >= hs ? y_new : advance(s, y, f0, hh, r.evaluations);
        orthonormalize(z);
        r.frame = unpack(z);
        r.s = s + hh;
        r.met_cone = true;
        ++r.steps;
        return r;
      }
      ++r.steps;
      s = last ? s1 : s + hs;
      y = y_new;
      if (opt.method == OdeMethod::rk45) f0 = f_end;
      if (adaptive) h = hs * factor;
    }
    r.frame = unpack(y);
    r.s = s;
    return r;
  }
};

void check_start(const Frame3& f, const char* who) {
  const Vec3* parts[4] = {&f.p, &f.t, &f.n, &f.b};
  const char* names[4] = {"start.p", "start.t", "start.n", "start.b"};
  for (int i = 0; i < 4; ++i)
    if (!parts[i]->allFinite()) throw_input_error(who, names[i], "must have finite coordinates");
}

void check_interval(const LaSpaceCurve& curve, double s0, double s1, const char* who) {
  require_finite(who, "s0", s0);
  require_finite(who, "s1", s1);
  const Interval range = curve.s_range();
  if (!range.contains(s0)) throw_input_error(who, "s0", s0, interval_text(range.lo, range.hi));
  if (!(s1 >= s0) || !(s1 < range.hi)) throw_input_error(who, "s1", s1, interval_text(s0, range.hi, true));
}

}  // namespace

void detail::check_frenet_input(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1, const char* who) {
  check_interval(curve, s0, s1, who);
  check_start(start, who);
}

double Frame3::orthonormality_error() const {
  Eigen::Matrix3d f;
  f << t, n, b;
  return (f.transpose() * f - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

double cone_angle_of(const Vec3& p) { return std::atan2(std::hypot(p.y(), p.z()), p.x()); }

FrenetResult integrate_frenet(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1,
                              const OdeOptions& options) {
  options.validate();
  detail::check_frenet_input(curve, start, s0, s1, "integrate_frenet");
  return Stepper{curve, options}.run(start, s0, s1, -1.0);
}

FrenetResult integrate_to_cone(const LaSpaceCurve& curve, const Frame3& start, double s0, double s_limit,
                               double cone_angle, const OdeOptions& options) {
  constexpr const char* who = "integrate_to_cone";
  options.validate();
  check_interval(curve, s0, s_limit, who);
  check_start(start, who);
  if (!(cone_angle > 0 && cone_angle < M_PI)) throw_input_error(who, "cone_angle", cone_angle, "(0, pi)");
  if (!(cone_angle_of(start.p) < cone_angle))
    throw_input_error(who, "start.p", cone_angle_of(start.p), "angle to e_x below cone_angle");
  return Stepper{curve, options}.run(start, s0, s_limit, cone_angle);
}

std::vector<Frame3> sample_frenet(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1, int n,
                                  const OdeOptions& options, Status* status) {
  if (n < 2) throw_input_error("sample_frenet", "n", n, "[2, inf)");
  check_interval(curve, s0, s1, "sample_frenet");
  check_start(start, "sample_frenet");
  options.validate();
  std::vector<Frame3> out;
  out.reserve(static_cast<size_t>(n));
  out.push_back(start);
  Status st = Status::ok;
  Frame3 f = start;
  double s = s0;
  for (int i = 1; i < n; ++i) {
    const double s_next = i + 1 == n ? s1 : s0 + (s1 - s0) * i / (n - 1);
    FrenetResult r = Stepper{curve, options}.run(f, s, s_next, -1.0);
    if (r.status != Status::ok) st = r.status;
    f = r.frame;
    s = s_next;
    out.push_back(f);
  }
  if (status) *status = st;
  return out;
}

}  // namespace lac
