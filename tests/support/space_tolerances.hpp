#pragma once
// Tolerances of the space-curve tests, in one place (what each bounds, and why it is this size).
namespace lac::test::space_tol {

// Frenet integration vs the mpmath reference (tests/reference/space_frenet.csv), max-norm over
// P, T, N, B at s_end; the integrator's own tolerance is beside each.
constexpr double kMagnusTight = 1e-12;  // magnus6, rtol 1e-12
constexpr double kMagnusDefault = 1e-10;  // magnus6, rtol 1e-10 (the segment solver's default)
constexpr double kRk45 = 1e-10;          // rk45, rtol 1e-12
constexpr double kRk4 = 1e-9;            // rk4, h = 1e-3
constexpr double kOrthonormal = 1e-12;   // |FᵀF − I| of every frame

// Closed forms vs independent formulas / quadrature (relative).
constexpr double kLaw = 1e-13;
constexpr double kTurning = 1e-12;

// Cone event: |angle(P, e_x) − θ| at the located point.
constexpr double kConeAngle = 1e-13;

// Segments.
constexpr double kTangent = 1e-10;       // end-tangent error in rad on success
constexpr double kPosition = 1e-12;      // |end − P1| / |P1 − P0|, and start at P0
constexpr double kJointRelative = 1e-12; // ρ, μ, dρ/ds, dμ/ds and the frame at the joint
constexpr double kSlope = 2e-3;          // LCG/LTG slopes recomputed by finite differences of frames

}  // namespace lac::test::space_tol
