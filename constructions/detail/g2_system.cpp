#include "lac/constructions/detail/g2_system.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

#include "lac/curves/planar/la_segment_kernel.hpp"
#include "lac/solvers/bracket.hpp"

namespace lac::detail {
namespace {

// Unknowns of newton and simplex: z = (log h, z1, z2) with q = z for α ≤ 0 and q = Q(σe^z)
// (z = log|κ̃|) for α > 0, so that h > 0 and q keeps the only sign an α > 0 segment allows
// (offset form: q = z·expm1(−αz)/(−αz), no exponential of z).
double q_of_z(const G2System& p, double z) {
  if (!(p.law.alpha > 0)) return z;
  return p.law.offset ? z * LaLaw::expm1_ratio(-p.law.alpha * z) : p.law.sigma * std::exp(-p.law.alpha * z);
}
/// dq/dz at q = q_of_z(z).
double dq_of_z(const G2System& p, double q) {
  if (!(p.law.alpha > 0)) return 1.0;
  return p.law.offset ? 1.0 - p.law.alpha * q : -p.law.alpha * q;
}
double z_of_q(const G2System& p, double q) {
  if (!(p.law.alpha > 0)) return q;
  return p.law.offset ? q * LaLaw::log1p_ratio(-p.law.alpha * q) : -std::log(std::abs(q)) / p.law.alpha;
}

}  // namespace

LaLaw g2_law(double alpha, double sigma) { return {alpha, sigma, alpha != 0 && std::abs(alpha) < kOffsetFormMaxAbsAlpha}; }

std::array<LinearQ, 3> plain_form(const LaLaw& law, const std::array<LinearQ, 3>& segments) {
  std::array<LinearQ, 3> out = segments;
  if (!law.offset) return out;
  for (LinearQ& s : out) s.qa = law.t_of_q(s.qa), s.qb = law.t_of_q(s.qb);
  return out;
}

std::array<LinearQ, 3> g2_segments(const G2System& p, double h, double q1, double q2) {
  const double q0 = p.law.q_of_kappa(p.kappa_s * h);
  const double q3 = p.law.q_of_kappa(p.kappa_e * h);
  std::array<LinearQ, 3> seg;
  seg[0] = {0.0, p.s1, q0, q1, p.phi_s};
  seg[1] = {p.s1, p.s2, q1, q2, seg[0].phi_b(p.law)};
  seg[2] = {p.s2, 1.0, q2, q3, seg[1].phi_b(p.law)};
  return seg;
}

std::array<double, 3> g2_residuals(const G2System& p, double h, double q1, double q2, long& evaluations) {
  return g2_linearize(p, h, q1, q2, evaluations, false).r;
}

G2Linearization g2_linearize(const G2System& p, double h, double q1, double q2, long& evaluations, bool jacobian) {
  const auto seg = g2_segments(p, h, q1, q2);
  G2Linearization out;
  auto& I = out.parts;
  std::complex<double> sum{};
  for (int k = 0; k < 3; ++k) sum += I[k] = p.integrate(p.law, seg[k], evaluations, &out.kernel_bounds[k]);
  const double phi_end = seg[2].phi_b(p.law);
  out.r = {phi_end - p.phi_e, h * sum.imag(), h * sum.real() - 1.0};
  if (!jacobian) return out;
  std::array<LaSegmentDerivatives, 3> d;
  for (int k = 0; k < 3; ++k) {
    const auto dk = segment_derivatives(p.law, seg[k], I[k]);
    if (!dk) return out;
    d[k] = *dk;
  }
  // The end values q0 = Q(κs·h), q3 = Q(κe·h) move with log h: t ∝ h^(−α) (t the plain q), so
  // dq/dlog h = −αq in the plain form, 1 − αq in the log forms (dq/dt = −σ/α there).
  const auto dq_dlogh = [&](double q) { return p.law.log_form() ? 1.0 - p.law.alpha * q : -p.law.alpha * q; };
  const std::array<std::array<double, 4>, 3> dq{{{dq_dlogh(seg[0].qa), 0, 0, dq_dlogh(seg[2].qb)}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
  const std::complex<double> i(0, 1);
  for (int j = 0; j < 3; ++j) {
    double dphi = 0;  // d φa of the segment
    std::complex<double> dsum{};
    for (int k = 0; k < 3; ++k) {
      dsum += i * I[k] * dphi + d[k].dI_dqa * dq[j][k] + d[k].dI_dqb * dq[j][k + 1];
      dphi += d[k].dphib_dqa * dq[j][k] + d[k].dphib_dqb * dq[j][k + 1];
    }
    if (j == 0) dsum += sum;  // ∂(h·Σ)/∂log h = h(Σ + ∂Σ/∂log h)
    out.jacobian[0][j] = dphi;
    out.jacobian[1][j] = h * dsum.imag();
    out.jacobian[2][j] = h * dsum.real();
  }
  out.jacobian_known = true;
  return out;
}

double g2_joint_q(const G2System& p, double kappa_tilde, double h) {
  // α ≥ 0, and the offset form (small |α|, where κ of the other sign is reached only within
  // ~e^(−1/|α|) of a zero of t): the sign σ.
  if ((p.law.alpha >= 0 || p.law.offset) && !(kappa_tilde * p.law.sigma > 0 && std::isfinite(kappa_tilde))) {
    kappa_tilde = p.law.sigma * std::sqrt(std::abs(p.kappa_s * p.kappa_e)) * h;  // geometric mean of the ends
  }
  return p.law.q_of_kappa(kappa_tilde);
}

namespace {
// α < 0, α ≠ −1: the clothoid's joint curvatures mapped through q = Q(κ̃) bend every segment's
// turning away from the clothoid's (q is linear in S, κ = K(q) is not; at α = −3 the start's
// residual grows from ~1e-3 to ~0.5). Instead q1 keeps the first segment's turning,
// F[q0, q1]·S1 = φ1 − φs, and q2 the total turning, F[q1, q2](S2 − S1) + F[q2, q3](1 − S2) =
// φe − φ1 (each increasing in its unknown, as K is): the start meets the end-angle equation.
// Newton steps on the peer set: α = −3 mean 8.7 → 6.0, α = −2 6.8 → 5.4. Left as it was where
// either root is not found.
void keep_clothoid_turnings(const G2System& p, G2StartEstimate& e) {
  const LaLaw& law = p.law;
  const double k0 = p.kappa_s * e.h, k3 = p.kappa_e * e.h;
  const double q0 = law.q_of_kappa(k0), q3 = law.q_of_kappa(k3);
  const double phi1 = p.phi_s + 0.5 * p.s1 * (k0 + e.k1);
  const auto increasing_root = [](auto&& f, double x0) -> std::optional<double> {
    if (!std::isfinite(x0)) return std::nullopt;
    BracketSearchOptions bo;
    bo.step = std::max(1.0, 0.5 * std::abs(x0));
    bo.growth = 2;
    bo.max_probes = 60;
    const BracketSearchResult b = search_bracket(f, x0, bo);
    if (!b.found) return std::nullopt;
    if (b.bracket.lo == b.bracket.hi) return b.bracket.lo;  // a probe hit the root exactly
    RootOptions ro;
    ro.x_rtol = 1e-10;  // a start: Newton does the rest
    ro.max_iterations = 60;
    const RootResult r = find_root(RootMethod::toms748, f, b.bracket, ro);
    return std::isfinite(r.root) ? std::optional<double>(r.root) : std::nullopt;
  };
  const auto q1 = increasing_root(
      [&](double q) { return law.divided_difference(q0, q) * p.s1 - (phi1 - p.phi_s); }, law.q_of_kappa(e.k1));
  if (!q1) return;
  const auto q2 = increasing_root(
      [&](double q) {
        return law.divided_difference(*q1, q) * (p.s2 - p.s1) + law.divided_difference(q, q3) * (1 - p.s2) -
               (p.phi_e - phi1);
      },
      law.q_of_kappa(e.k2));
  if (!q2) return;
  const double k1 = law.kappa_of_q(*q1), k2 = law.kappa_of_q(*q2);
  if (std::isfinite(k1) && std::isfinite(k2)) e.k1 = k1, e.k2 = k2;
}
}  // namespace

G2StartEstimate g2_fast_start(const G2System& p) {
  // Small-angle triple clothoid: κ̃ piecewise linear on the nodes 0, S1, S2, 1. With
  // sin φ ≈ φ the end conditions become linear in κ̃1, κ̃2:
  //   ∫κ̃ dS = φe − φs,   ∫φ dS = φs + ∫(1 − S)κ̃ dS = 0.
  // Then h = 1 / ∫cos φ dS of that clothoid (exact quadrature); two passes.
  const std::array<double, 4> nodes{0.0, p.s1, p.s2, 1.0};
  std::array<double, 4> A{}, B{};
  for (int i = 0; i < 3; ++i) {
    const double a = nodes[i], L = nodes[i + 1] - nodes[i];
    A[i] += 0.5 * L;
    A[i + 1] += 0.5 * L;
    B[i] += L * ((1.0 - a) / 2.0 - L / 6.0);
    B[i + 1] += L * ((1.0 - a) / 2.0 - L / 3.0);
  }
  G2StartEstimate e;
  const LaLaw clothoid{-1.0, 1.0};
  G2System c{clothoid, p.phi_s, p.phi_e, p.kappa_s, p.kappa_e, p.integrate, p.s1, p.s2};
  for (int pass = 0; pass < 2; ++pass) {
    const double k0 = p.kappa_s * e.h, k3 = p.kappa_e * e.h;
    Eigen::Matrix2d M;
    M << A[1], A[2], B[1], B[2];
    const Eigen::Vector2d rhs(p.phi_e - p.phi_s - A[0] * k0 - A[3] * k3, -p.phi_s - B[0] * k0 - B[3] * k3);
    const Eigen::Vector2d k = M.partialPivLu().solve(rhs);
    e.k1 = k(0);
    e.k2 = k(1);
    const auto seg = g2_segments(c, e.h, e.k1, e.k2);
    std::complex<double> sum{};
    for (const auto& s : seg) {
      const auto k = segment_integral(clothoid, s, e.evaluations);
      sum += k ? k->value : integrate_tangent(clothoid, s, e.evaluations);
    }
    if (!(sum.real() > 0.05) || !std::isfinite(sum.real())) break;  // keep the last usable h
    const double h_new = 1.0 / sum.real();
    e.k1 *= h_new / e.h;
    e.k2 *= h_new / e.h;
    e.h = h_new;
  }
  if (p.law.alpha < 0 && p.law.alpha != -1 && !p.law.offset) keep_clothoid_turnings(p, e);
  return e;
}

G2SolverOutcome solve_g2_nonlinear(NonlinearMethod method, const G2System& p, const G2StartEstimate& s,
                                   const G2Options& o) {
  G2SolverOutcome out;
  // An estimate beyond the double range (e.g. κ·chord ~ 1e300 overflows the joint curvatures) is
  // no starting point: numerical_failure, as solve_nonlinear reports a non-finite r at the start.
  const auto unusable_start = [&out, method] {
    out.status = Status::numerical_failure;
    out.message = std::string(to_string(method)) + ": the initial estimate gives a non-finite curve";
    return out;
  };
  NonlinearOptions no;
  no.norm = ResidualNorm::max;
  no.residual_tolerance = o.tolerance;
  NonlinearResult r;
  if (method == NonlinearMethod::ceres) {
    no.ceres.max_iterations = o.max_iterations;
    no.ceres.function_tolerance = 1e-30;
    no.ceres.gradient_tolerance = 1e-30;
    no.ceres.parameter_tolerance = 1e-16;
    no.ceres.stop_at_tolerance = false;
    const Eigen::VectorXd x0 = g2_ten_unknown_start(p, s);
    if (!x0.allFinite()) return unusable_start();
    r = solve_nonlinear(method, g2_ten_unknown_residual(p, out.evaluations), x0, no);
    const auto [h, q1, q2] = g2_ten_unknown_solution(p, r.x);
    out.h = h, out.q1 = q1, out.q2 = q2;
  } else {
    // Newton: the closed-form Jacobian (forward differences where a segment has none), no step
    // cap, the length changing by at most e^2 per trial, 30 trial steps 1 … 2^-29; a stall within
    // 1e3·tolerance counts as converged; a run creeping (o.stagnation_window) stops.
    no.newton.max_iterations = o.max_iterations;
    no.newton.max_evaluations = LONG_MAX;
    no.newton.fd_step = 1e-7;
    no.newton.backward_differences = false;
    no.newton.reject_singular = false;
    no.newton.max_step = std::numeric_limits<double>::infinity();
    // For α ≥ 0 the joint unknowns are log|κ̃| (z for α > 0, q itself for α = 0): a trial changes a
    // joint curvature by at most e^4 (unbounded, Newton wandered to κ̃ ~ 1e±300, where every trial
    // curve is a hard integral).
    const double z_change = p.law.alpha >= 0 ? 4.0 : std::numeric_limits<double>::infinity();
    no.newton.max_trial_change = Eigen::Vector3d(2.0, z_change, z_change);
    no.newton.max_halvings = 29;
    no.newton.step_tolerance = 0;
    no.newton.stall_factor = 1e3;
    no.newton.stagnation_window = o.stagnation_window;
    no.simplex.max_iterations = 100 * o.max_iterations;
    no.simplex.max_evaluations = 200L * o.max_iterations;
    NonlinearResidual residual{3, [&](ConstVectorMap z, VectorMap out_r) {
                                 const auto v = g2_residuals(p, std::exp(z[0]), q_of_z(p, z[1]), q_of_z(p, z[2]),
                                                             out.evaluations);
                                 out_r << v[0], v[1], v[2];
                                 return true;
                               }};
    // Newton's Jacobian in closed form (g2_linearize), chained from q to z.
    // The last point evaluated with its segment integrals: the solution's, when Newton stops there.
    Eigen::Vector3d last_z = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    G2Linearization last;
    residual.f_with_jacobian = [&](ConstVectorMap z, VectorMap out_r, double* jac, bool& known) {
      const double q1 = q_of_z(p, z[1]), q2 = q_of_z(p, z[2]);
      const G2Linearization v = g2_linearize(p, std::exp(z[0]), q1, q2, out.evaluations);
      last_z = z, last = v;
      out_r << v.r[0], v.r[1], v.r[2];
      known = v.jacobian_known;
      const std::array<double, 3> dq_dz{1.0, dq_of_z(p, q1), dq_of_z(p, q2)};
      for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) jac[3 * c + row] = v.jacobian[row][c] * dq_dz[c];
      return true;
    };
    // The end-angle residual needs no integral: a trial it alone rejects is not integrated.
    if (no.norm == ResidualNorm::max)
      residual.norm_lower_bound = [&](ConstVectorMap z) {
        const auto seg = g2_segments(p, std::exp(z[0]), q_of_z(p, z[1]), q_of_z(p, z[2]));
        const double r0 = std::abs(seg[2].phi_b(p.law) - p.phi_e);
        return std::isfinite(r0) ? r0 : 0.0;
      };
    const Eigen::Vector3d z0(std::log(s.h), z_of_q(p, g2_joint_q(p, s.k1, s.h)), z_of_q(p, g2_joint_q(p, s.k2, s.h)));
    if (!z0.allFinite()) return unusable_start();
    r = solve_nonlinear(method, residual, z0, no);
    out.h = std::exp(r.x[0]);
    out.q1 = q_of_z(p, r.x[1]);
    out.q2 = q_of_z(p, r.x[2]);
    if (r.x.size() == 3 && last_z == Eigen::Vector3d(r.x) &&
        std::all_of(last.kernel_bounds.begin(), last.kernel_bounds.end(), [](double b) { return std::isfinite(b); })) {
      std::array<LaSegmentIntegral, 3> parts;
      for (int k = 0; k < 3; ++k) parts[k] = {last.parts[k], last.kernel_bounds[k]};
      out.kernel_parts = parts;
    }
  }
  out.status = r.status;
  out.message = r.message;
  out.iterations = r.iterations;
  out.constructions = r.evaluations;
  // r(x) holds h∫cos φ dS − 1 and h∫sin φ dS: newton, simplex r[2], r[1]; ceres r[8], r[9] (Eqs. 32, 33).
  const bool ten = method == NonlinearMethod::ceres;
  if (r.residual.size() == (ten ? 10 : 3)) {
    const std::complex<double> end(r.residual[ten ? 8 : 2] + 1.0, r.residual[ten ? 9 : 1]);
    if (std::isfinite(end.real()) && std::isfinite(end.imag())) out.end = end;
  }
  return out;
}

}  // namespace lac::detail
