#include "lac/curves/detail/taylor_frame.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "lac/common/error.hpp"

namespace lac::detail {
namespace {

constexpr int kTerms = kTaylorTerms;
constexpr long kMaxSteps = 10000;  // steps per call
constexpr int kMaxShrinks = 60;     // step reductions per step
constexpr double kEps = DBL_EPSILON;

using M3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// K's scaled coefficient matrix from κ_i, τ_i: F' = F K, K = [[0, −κ, 0], [κ, 0, −τ], [0, τ, 0]].
M3 generator(double k, double t) {
  M3 m;
  m << 0, -k, 0, k, 0, -t, 0, t, 0;
  return m;
}

/// G_0 … G_n from K's scaled coefficients (G_{j+1} = Σ_{i≤j} G_i K_{j−i} / (j + 1), G_0 = I).
template <class Coefficient>
std::array<M3, kTerms + 1> propagator_series(Coefficient&& K) {
  std::array<M3, kTerms + 1> G;
  G[0] = M3::Identity();
  for (int j = 0; j < kTerms; ++j) {
    M3 sum = M3::Zero();
    for (int i = 0; i <= j; ++i) sum += G[i] * K(j - i);
    G[j + 1] = sum / (j + 1.0);
  }
  return G;
}

}  // namespace

FrameMajorantFunction end_majorant(FrameSeriesFunction series) {
  return [series = std::move(series)](double s0, double s1, double h) {
    const FrameSeries a = series(s0, h), b = series(s1, h);
    FrameMajorant m;
    for (int i = 0; i < kTerms; ++i) {
      m.kappa[i] = std::max(std::abs(a.kappa[i]), std::abs(b.kappa[i]));
      m.tau[i] = std::max(std::abs(a.tau[i]), std::abs(b.tau[i]));
    }
    return m;
  };
}

TaylorFrame integrate_taylor_frame(const FrameSeriesFunction& series, const FrameMajorantFunction& majorant, const M3& frame,
                                   const Vec3& position, double s0, double s1, double position_error,
                                   double frame_error, const char* who) {
  TaylorFrame r;
  r.position_error = position_error;
  r.frame_error = frame_error;
  M3 F = frame;
  Vec3 P = position;
  double s = s0;
  double h = s1 - s0;
  const double min_step = std::ldexp(s1 - s0, -60);
  while (s < s1) {
    if (r.steps >= kMaxSteps) {
      r.status = Status::max_iterations;
      r.message = std::string(who) + ": more than " + std::to_string(kMaxSteps) + " steps needed";
      return r;
    }
    h = std::min(h, s1 - s);
    std::array<M3, kTerms + 1> G, Ghat;
    FrameSeries at;
    double frame_remainder = 0, position_remainder = 0;
    for (int shrink = 0;; ++shrink) {
      const double end = h == s1 - s ? s1 : s + h;
      h = end - s;  // the step actually taken: s + h is rounded (exact difference, Sterbenz)
      const FrameMajorant most = majorant(s, end, h);
      // The majorant's coefficients through the same recursion bound G's on the whole step.
      Ghat = propagator_series([&](int i) -> M3 { return generator(most.kappa[i], most.tau[i]).cwiseAbs(); });
      frame_remainder = Ghat[kTerms].norm();
      position_remainder = h * Ghat[kTerms].col(0).norm() / (kTerms + 1);
      // Remainders far below rounding (an eighth of an ulp of the unit frame and of the step).
      if (frame_remainder <= kEps / 8 && std::isfinite(frame_remainder) && std::isfinite(position_remainder)) break;
      if (shrink == kMaxShrinks || !(h > min_step)) {
        r.status = Status::max_iterations;
        r.message = std::string(who) + ": no step from s = " + format_number(s) +
                    " keeps the Taylor remainder below rounding (the step shrank to " + format_number(h) + ")";
        return r;
      }
      const double ratio = std::isfinite(frame_remainder) ? std::pow(kEps / 8 / frame_remainder, 1.0 / kTerms) : 0.1;
      h *= std::clamp(0.9 * ratio, 0.1, 0.9);
    }
    at = series(s, h);
    G = propagator_series([&](int i) -> M3 { return generator(at.kappa[i], at.tau[i]); });
    // The step's propagator and its displacement ∫₀¹ G(x) e₁ dx (scaled), with their rounding: a
    // majorant E_j of |computed G_j − G_j| by the recursion's own rule, from the coefficients'
    // errors and (j + 3)ε per entry of each sum of products.
    std::array<M3, kTerms> K_abs, dK, G_abs, E;
    for (int i = 0; i < kTerms; ++i) {
      K_abs[i] = generator(at.kappa[i], at.tau[i]).cwiseAbs();
      dK[i] = generator(at.kappa_error[i], at.tau_error[i]).cwiseAbs();
      G_abs[i] = G[i].cwiseAbs();
    }
    E[0] = M3::Zero();
    for (int j = 0; j + 1 < kTerms; ++j) {
      M3 carried = M3::Zero(), size = M3::Zero();
      for (int i = 0; i <= j; ++i) {
        carried += E[i] * K_abs[j - i] + G_abs[i] * dK[j - i];
        size += G_abs[i] * K_abs[j - i];
      }
      E[j + 1] = (carried + (j + 4) * kEps * size) / (j + 1.0);
    }
    M3 step = M3::Zero(), step_error = M3::Zero(), step_size = M3::Zero();
    Vec3 moved = Vec3::Zero(), moved_error = Vec3::Zero(), moved_size = Vec3::Zero();
    for (int j = 0; j < kTerms; ++j) {
      step += G[j];
      moved += G[j].col(0) / (j + 1.0);
      step_error += E[j];
      step_size += G_abs[j];
      moved_error += E[j].col(0) / (j + 1.0);
      moved_size += G_abs[j].col(0) / (j + 1.0);
    }
    // Summing kTerms terms, then F · step (3-term dot products): (kTerms + 8)ε of the sizes.
    const double rounding = step_error.norm() + (kTerms + 8) * kEps * step_size.norm();
    const double rounding_moved = moved_error.norm() + (kTerms + 8) * kEps * moved_size.norm();
    const double delta = r.frame_error;
    const M3 F_next = F * step;
    const Vec3 P_next = P + h * (F * moved);
    // Exact propagators are orthogonal: errors are carried without growth (header comment).
    r.frame_error = delta + (1 + delta) * (frame_remainder + rounding);
    r.position_error += delta * h + (1 + delta) * (position_remainder + h * rounding_moved) + 2 * kEps * P_next.norm();
    F = F_next;
    P = P_next;
    s = h == s1 - s ? s1 : s + h;  // = the step's end above
    ++r.steps;
    h *= 1.5;
    if (!F.allFinite() || !P.allFinite() || !std::isfinite(r.frame_error) || !std::isfinite(r.position_error)) {
      r.status = Status::numerical_failure;
      r.message = std::string(who) + ": non-finite frame or bound at s = " + format_number(s);
      return r;
    }
  }
  r.frame = F;
  r.position = P;
  return r;
}

CertifiedTangentIntegral integrate_plane_tangent(const FrameSeriesFunction& series, const FrameMajorantFunction& majorant,
                                                 const std::function<double(double t, double& error)>& angle,
                                                 double t0, double t1, std::optional<TangentZone> zone, const char* who) {
  struct Piece {
    double a, b;
    bool zone;
  };
  std::vector<Piece> pieces;
  if (zone) {
    const double za = std::max(t0, zone->a), zb = std::min(t1, zone->b);
    if (za < zb) {
      if (t0 < za) pieces.push_back({t0, za, false});
      pieces.push_back({za, zb, true});
      if (zb < t1) pieces.push_back({zb, t1, false});
    }
  }
  if (pieces.empty()) pieces.push_back({t0, t1, false});
  CertifiedTangentIntegral r;
  for (const Piece& piece : pieces) {
    double dtheta = 0;
    const double theta = angle(piece.a, dtheta);
    const double len = piece.b - piece.a;
    if (piece.zone) {
      // |e^{iθ(t)} − e^{iθ(a)}| ≤ |θ(t) − θ(a)| ≤ len·max|κ|.
      r.value += len * std::polar(1.0, theta);
      r.error += len * (len * zone->kappa + dtheta + 2 * kEps);
      continue;
    }
    M3 F;
    F << std::cos(theta), -std::sin(theta), 0, std::sin(theta), std::cos(theta), 0, 0, 0, 1;
    // A rotation by an angle error δ is δ√2 away in the Frobenius norm; cos and sin add 4ε.
    const TaylorFrame t = integrate_taylor_frame(series, majorant, F, Vec3::Zero(), piece.a, piece.b, 0.0,
                                                 std::sqrt(2.0) * dtheta + 4 * kEps, who);
    r.steps += t.steps;
    if (t.status != Status::ok) {
      r.status = t.status;
      r.message = t.message;
      r.error = HUGE_VAL;
      return r;
    }
    r.value += std::complex<double>(t.position.x(), t.position.y());
    r.error += t.position_error + 2 * kEps * std::abs(r.value);
  }
  return r;
}

}  // namespace lac::detail
