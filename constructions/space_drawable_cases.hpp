#pragma once
// Random space-segment inputs for which a curve exists by construction (tests, the solver timing
// experiment, benchmarks): draw the standard-form construction at random (Λ0, ν0) for a random
// cone angle θ (drawable_endpoints), then move the endpoint data by a random rotation,
// translation and scale and give v0, v1 random lengths. The solver is not told (Λ0, ν0).
// Ranges (uniform unless noted): α, β ∈ [−1, 2]; Ω0 ∈ [0.05, 0.6]; r_θ ∈ [0.3, 0.7]; type 1 or 2;
// Λ0 ∈ [0.2, 3] and ν0 ∈ [0.5, 4] log-uniform; θ ∈ [0.3, 1.2] rad; scale ∈ [0.1, 10] log-uniform;
// translation ∈ [−5, 5]³; rotation uniform on SO(3).
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <random>

#include "lac/constructions/space_segment.hpp"

namespace lac {

struct DrawableCase {
  SpaceEndpoints ends;
  CompoundSpaceSpec spec;  ///< G1 cases use alpha0, beta0, omega0, type
  bool compound = false;
  double lambda0 = 0, nu0 = 0, theta = 0;  ///< the construction's unknowns (hidden from the solver)
  G1SpaceSpec g1() const { return {spec.alpha0, spec.beta0, spec.omega0, spec.type}; }
};

/// Draws until a construction meets its cones (at most 1000 tries; returns the last try otherwise,
/// which callers detect by `ok == false`). Deterministic for a given engine state.
inline DrawableCase random_drawable_case(std::mt19937_64& rng, bool compound, bool* ok = nullptr) {
  auto u = [&](double a, double b) { return a + (b - a) * (static_cast<double>(rng() >> 11) * 0x1.0p-53); };
  auto log_u = [&](double a, double b) { return std::exp(u(std::log(a), std::log(b))); };
  DrawableCase c;
  c.compound = compound;
  for (int attempt = 0; attempt < 1000; ++attempt) {
    c.spec.alpha0 = u(-1, 2);
    c.spec.alpha1 = u(-1, 2);
    c.spec.beta0 = u(-1, 2);
    c.spec.beta1 = u(-1, 2);
    c.spec.omega0 = u(0.05, 0.6);
    c.spec.r_theta = u(0.3, 0.7);
    c.spec.type = u(0, 1) < 0.5 ? TorsionType::type1 : TorsionType::type2;
    c.lambda0 = log_u(0.2, 3);
    c.nu0 = log_u(0.5, 4);
    c.theta = u(0.3, 1.2);
    const auto drawn = drawable_endpoints(c.spec, compound, c.lambda0, c.nu0, c.theta);
    if (drawn.summary.status != Status::ok) continue;
    const SpaceEndpoints& local = drawn.info.ends;
    Eigen::Vector4d qv;
    do qv = Eigen::Vector4d(u(-1, 1), u(-1, 1), u(-1, 1), u(-1, 1));
    while (qv.norm() > 1 || qv.norm() < 1e-3);  // uniform in the ball → uniform rotation
    const Eigen::Quaterniond q = Eigen::Quaterniond(qv[0], qv[1], qv[2], qv[3]).normalized();
    const Eigen::Matrix3d rot = q.toRotationMatrix();
    const double scale = log_u(0.1, 10);
    const Vec3 shift(u(-5, 5), u(-5, 5), u(-5, 5));
    c.ends.p0 = shift + scale * (rot * local.p0);
    c.ends.p1 = shift + scale * (rot * local.p1);
    c.ends.v0 = log_u(0.1, 10) * (rot * local.v0);
    c.ends.v1 = log_u(0.1, 10) * (rot * local.v1);
    if (ok) *ok = true;
    return c;
  }
  if (ok) *ok = false;
  return c;
}

}  // namespace lac
