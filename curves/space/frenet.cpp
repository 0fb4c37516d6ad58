#include "lac/curves/space/frenet.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <optional>

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

// ---- Magnus integrator on SE(3) -------------------------------------------------------------
// The Frenet frame and position form g = (F, P) ∈ SE(3) with g' = g ξ(s), body-frame generator
// ξ = (ω, v), ω = (τ, 0, κ) (Darboux vector), v = e_x. Magnus methods step g ← g exp(Ω) with Ω
// from the generator at Gauss nodes; a helix (constant κ, τ) is integrated exactly and the frame
// stays on SO(3) by construction. Hand-written: no library offers Lie-group Magnus steppers.
// Ω of order 6 and the embedded order-4 Ω (error estimate) use 3 Gauss nodes (Blanes, Casas, Oteo,
// Ros, Phys. Rep. 470 (2009), §5.2: Ω = α1 + α3/12 + [−20α1 − α3 + C1, α2 + C2]/240 with
// C1 = [α1, α2], C2 = −[α1, 2α3 + C1]/60; order 4: α1 + α3/12 − [α1, α2]/12). Those formulas are
// for Y' = A Y; for g' = g ξ every bracket [X, Y] becomes [Y, X] (transposition).
struct Twist {
  Vec3 w, v;
  Twist operator+(const Twist& o) const { return {w + o.w, v + o.v}; }
  Twist operator-(const Twist& o) const { return {w - o.w, v - o.v}; }
  Twist operator*(double c) const { return {c * w, c * v}; }
};
// Bracket of the right-multiplied equation: [X, Y]_right = [Y, X]_se(3).
Twist bracket(const Twist& x, const Twist& y) { return {y.w.cross(x.w), y.w.cross(x.v) - x.w.cross(y.v)}; }

// exp of a twist: rotation R(w) and translation V(w) v (Rodrigues; series for small |w|).
void apply_exp(const Twist& om, Vec3& t, Vec3& n, Vec3& b, Vec3& p) {
  const double th2 = om.w.squaredNorm();
  double A, B, C;
  if (th2 < 1e-4) {
    A = 1 - th2 / 6 * (1 - th2 / 20);
    B = 0.5 - th2 / 24 * (1 - th2 / 30);
    C = 1.0 / 6 - th2 / 120 * (1 - th2 / 42);
  } else {
    const double th = std::sqrt(th2), s = std::sin(th), c = std::cos(th);
    A = s / th;
    B = (1 - c) / th2;
    C = (th - s) / (th2 * th);
  }
  const Vec3& w = om.w;
  auto rot = [&](const Vec3& x) { return Vec3(x + A * w.cross(x) + B * w.cross(w.cross(x))); };
  const Vec3 d = om.v + B * w.cross(om.v) + C * w.cross(w.cross(om.v));  // body-frame displacement
  // new frame columns F R e_i, new position P + F d, with F = [t n b]
  Eigen::Matrix3d f;
  f << t, n, b;
  p += f * d;
  t = f * rot(Vec3::UnitX());
  n = f * rot(Vec3::UnitY());
  b = f * rot(Vec3::UnitZ());
}

// One stepping loop for all methods. `advance(s, y, f0, h)` returns the state after one exact
// step of size h; event location calls it with varying h from the same step start.
struct Stepper {
  const LaSpaceCurve& curve;
  const FrenetOptions& opt;
  FrenetRhs rhs{&curve};

  Twist generator(double s) const { return {Vec3(curve.tau(s), 0, curve.kappa(s)), Vec3::UnitX()}; }

  // Magnus step; `scaled_err` gets |Ω6 − Ω4| over the tolerance.
  State magnus(double s, const State& y, double h, long& evals, double* scaled_err) const {
    constexpr double kC = 0.3872983346207417;  // √15/10
    const Twist a1 = generator(s + (0.5 - kC) * h), a2 = generator(s + 0.5 * h), a3 = generator(s + (0.5 + kC) * h);
    evals += 3;
    const Twist al1 = a2 * h, al2 = (a3 - a1) * (h * 1.2909944487358056), al3 = (a3 - a2 * 2.0 + a1) * (h * 10.0 / 3.0);
    const Twist c1 = bracket(al1, al2);
    const Twist c2 = bracket(al1, al3 * 2.0 + c1) * (-1.0 / 60.0);
    const Twist om6 = al1 + al3 * (1.0 / 12.0) + bracket(al1 * -20.0 - al3 + c1, al2 + c2) * (1.0 / 240.0);
    if (scaled_err) {
      const Twist om4 = al1 + al3 * (1.0 / 12.0) - c1 * (1.0 / 12.0);
      const Twist d = om6 - om4;
      const double scale = opt.atol + opt.rtol * std::max(1.0, y.segment<3>(0).cwiseAbs().maxCoeff());
      *scaled_err = std::max(d.w.cwiseAbs().maxCoeff(), d.v.cwiseAbs().maxCoeff()) / scale;
    }
    Vec3 p = y.segment<3>(0), t = y.segment<3>(3), n = y.segment<3>(6), b = y.segment<3>(9);
    apply_exp(om6, t, n, b, p);
    State out;
    out << p, t, n, b;
    return out;
  }

  // One exact step of size h from (s, y); f0 = f(s, y) for rk45. `scaled_err` (adaptive methods)
  // receives the step's error over the tolerance; f_end the rk45 FSAL stage.
  State advance(double s, const State& y, const State& f0, double h, long& evals, double* scaled_err = nullptr,
                State* f_end = nullptr) const {
    switch (opt.method) {
      case FrenetMethod::rk4:
        evals += 4;
        return rk4_step(rhs, s, y, h);
      case FrenetMethod::magnus6:
        return magnus(s, y, h, evals, scaled_err);
      case FrenetMethod::rk45: break;
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
    const bool adaptive = opt.method != FrenetMethod::rk4;
    State f0 = State::Zero();  // first stage of the next rk45 step (FSAL); unused otherwise
    double h;
    if (!adaptive) {
      h = span / std::max(1.0, std::ceil(span / opt.h));
    } else if (opt.method == FrenetMethod::magnus6) {  // exact for a helix: start with a bounded turn
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
      if (opt.method == FrenetMethod::rk45) f0 = f_end;
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

double Frame3::orthonormality_error() const {
  Eigen::Matrix3d f;
  f << t, n, b;
  return (f.transpose() * f - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

void FrenetOptions::validate() const {
  constexpr const char* who = "FrenetOptions";
  if (!(rtol >= 1e-15) || !std::isfinite(rtol)) throw_input_error(who, "rtol", rtol, "[1e-15, inf)");
  if (!(atol > 0) || !std::isfinite(atol)) throw_input_error(who, "atol", atol, "(0, inf)");
  if (!(h > 0) || !std::isfinite(h)) throw_input_error(who, "h", h, "(0, inf)");
  if (max_steps < 1) throw_input_error(who, "max_steps", static_cast<double>(max_steps), "[1, inf)");
}

FrenetMethod parse_frenet_method(const std::string& name) {
  if (name == "rk45") return FrenetMethod::rk45;
  if (name == "rk4") return FrenetMethod::rk4;
  if (name == "magnus6") return FrenetMethod::magnus6;
  throw_input_error("parse_frenet_method", "integrator", "unknown name '" + name + "' (rk45 | rk4 | magnus6)");
}

const char* to_string(FrenetMethod m) {
  switch (m) {
    case FrenetMethod::rk45: return "rk45";
    case FrenetMethod::rk4: return "rk4";
    case FrenetMethod::magnus6: return "magnus6";
  }
  return "unknown";
}

double cone_angle_of(const Vec3& p) { return std::atan2(std::hypot(p.y(), p.z()), p.x()); }

FrenetResult integrate_frenet(const LaSpaceCurve& curve, const Frame3& start, double s0, double s1,
                              const FrenetOptions& options) {
  options.validate();
  check_interval(curve, s0, s1, "integrate_frenet");
  check_start(start, "integrate_frenet");
  return Stepper{curve, options}.run(start, s0, s1, -1.0);
}

FrenetResult integrate_to_cone(const LaSpaceCurve& curve, const Frame3& start, double s0, double s_limit,
                               double cone_angle, const FrenetOptions& options) {
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
                                  const FrenetOptions& options, Status* status) {
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
