// 004 §3.3: outer iteration on h, bisection on c30 for Eq. (33), Newton on c10 for Eq. (41).
// Both bisections are the 1-D registry's (solvers/root_1d.hpp), their brackets and the inner
// Newton with the analytic derivative of Eq. (41) (Eqs. 42–44) solvers/bracket.hpp's.
#include <cmath>
#include <optional>

#include "lac/constructions/detail/g2_system.hpp"
#include "lac/solvers/bracket.hpp"
#include "lac/solvers/root_1d.hpp"

namespace lac::detail {
namespace {

// Bisection width of both searches: 4e-16 relative (the paper solver's historical tolerance).
RootOptions bisection_options(const G2Options& o) {
  RootOptions r;
  r.x_rtol = 4e-16;
  r.x_atol = 0;
  r.f_atol = 0;
  r.max_iterations = o.max_inner_iterations;
  return r;
}

struct PaperSolver {
  const G2System& p;
  const G2Options& o;
  long evaluations = 0;
  long constructions = 0;
  int inner_steps = 0;
  double q0 = 0, q3 = 0;

  // ∂T/∂qa, ∂T/∂qb of a segment's turning T = L·F[qa, qb] (004 Appendix A in linear-q form).
  double dT_dqa(double L, double a, double b) const {
    return L * (p.law.divided_difference(a, b) - p.law.kappa_of_q(a)) / (b - a);
  }
  double dT_dqb(double L, double a, double b) const {
    return L * (p.law.kappa_of_q(b) - p.law.divided_difference(a, b)) / (b - a);
  }

  // Eq. (41) up to the constant factor (α−1)/α: φs + T1 + T2 + T3 − φe as a function of c10.
  double f(double c10, double q2) const {
    const double q1 = q0 + c10 * kG2S1;
    return p.phi_s + kG2S1 * p.law.divided_difference(q0, q1) + (kG2S2 - kG2S1) * p.law.divided_difference(q1, q2) +
           (1 - kG2S2) * p.law.divided_difference(q2, q3) - p.phi_e;
  }
  bool q_allowed(double q) const { return std::isfinite(q) && (p.law.alpha <= 0 || p.law.t_of_q(q) * p.law.sigma > 0); }

  // c10 solving f = 0 for the given q2: Newton with the analytic derivative (Eqs. 42–44), and
  // bisection where Newton is unusable (c20 ≈ 0, Appendix A) or does not converge.
  std::optional<double> solve_c10(double q2, double guess) {
    const int budget = std::min(50, 100 * o.max_inner_iterations - inner_steps);
    if (budget > 0) {
      // No value (q1 outside the law's domain, f not finite) or no derivative (the middle
      // segment an arc, c20 ≈ 0): Newton stops and bisection takes over.
      const auto fd = [&](double c10) {
        const double q1 = q0 + c10 * kG2S1;
        if (!q_allowed(q1)) return Newton1dSample{};
        const double fv = f(c10, q2);
        const double c20 = (q2 - q1) / (kG2S2 - kG2S1);
        if (!std::isfinite(fv) || std::abs(c20) < 1e-9 * std::max(1.0, std::abs(q1))) return Newton1dSample{fv, NAN};
        return Newton1dSample{fv, kG2S1 * (dT_dqb(kG2S1, q0, q1) + dT_dqa(kG2S2 - kG2S1, q1, q2))};
      };
      // The Newton step, halved until q1 stays in the law's domain.
      const auto step_rule = [&](double c10, const Newton1dSample& s, bool) {
        double step = -s.f / s.df;
        for (int k = 0; k < 60 && !q_allowed(q0 + (c10 + step) * kG2S1); ++k) step *= 0.5;
        return c10 + step;
      };
      Newton1dOptions no;
      no.f_atol = 1e-15;
      no.x_rtol = 1e-15;
      no.x_atol = 1e-15;
      no.max_iterations = budget;
      no.form_bracket = false;  // 004's Newton: the analytic step, no bracket
      no.stop_at_failure = true;
      const Newton1dResult r = safeguarded_newton(fd, guess, no, step_rule);
      inner_steps += r.iterations;
      if (r.status == Status::ok) return r.x;
    }
    return bisect_c10(q2, guess);
  }

  std::optional<double> bisect_c10(double q2, double guess) {
    // f is monotonic in c10 (κ is monotonic in q); expand a bracket around the guess.
    auto fv = [&](double c) { return q_allowed(q0 + c * kG2S1) ? f(c, q2) : NAN; };
    double lo = guess, flo = fv(lo);
    if (!std::isfinite(flo)) {
      // For α > 0 halfway to q1 = 0 (t = 0: q1 = 1/α in the offset form).
      lo = p.law.alpha > 0 ? ((p.law.offset ? 1 / p.law.alpha : 0.0) - q0) / kG2S1 * 0.5 : 0.0;
      flo = fv(lo);
    }
    if (!std::isfinite(flo)) return std::nullopt;
    BracketSearchOptions bo;
    bo.step = 0.1 * std::max(1.0, std::abs(lo));
    bo.growth = 2;
    bo.max_probes = 160;  // 80 doublings each way
    bo.from_start = true;
    const BracketSearchResult s = search_bracket(fv, lo, bo, flo);
    if (!s.found) return std::nullopt;
    const Bracket& b = s.bracket;
    if (b.f_lo == 0) return b.lo;
    if (b.f_hi == 0) return b.hi;
    const RootResult r = bisection(fv, b, bisection_options(o));
    inner_steps += r.iterations;
    if (r.status == Status::numerical_failure) return std::nullopt;
    return 0.5 * (r.lo + r.hi);
  }

  struct Eval {
    double c30 = NAN;
    double g = NAN;  // ∫ sin φ dS
    double c10 = NAN;
    std::complex<double> integral;
  };
  Eval eval_c30(double h, double c30, double c10_guess) {
    Eval e;
    e.c30 = c30;
    const double q2 = q3 - c30 * (1 - kG2S2);
    if (!q_allowed(q2)) return e;
    const auto c10 = solve_c10(q2, c10_guess);
    if (!c10) return e;
    e.c10 = *c10;
    const auto seg = g2_segments(p, h, q0 + *c10 * kG2S1, q2);
    for (const auto& s : seg) e.integral += p.integrate(p.law, s, evaluations);
    ++constructions;
    e.g = e.integral.imag();
    return e;
  }

  // c30 with ∫sin φ dS = 0 (Eq. 33) by bisection between `start` and `other` (g of opposite
  // signs). Each midpoint's Newton on c10 starts from the c10 of the bracket end on the start's
  // side; the result is the end with the smaller |g|.
  Eval bisect_c30(double h, const Eval& start, const Eval& other) {
    Eval same = start, opposite = other;
    const bool start_positive = start.g > 0;
    auto g = [&](double c30) {
      const Eval e = eval_c30(h, c30, same.c10);
      if (std::isfinite(e.g)) ((e.g > 0) == start_positive ? same : opposite) = e;
      return e.g;
    };
    const Bracket b = start.c30 < other.c30 ? Bracket{start.c30, other.c30, start.g, other.g}
                                            : Bracket{other.c30, start.c30, other.g, start.g};
    bisection(g, b, bisection_options(o));
    return std::abs(same.g) <= std::abs(opposite.g) ? same : opposite;
  }
};

}  // namespace

G2SolverOutcome solve_g2_paper(const G2System& p, const G2StartEstimate& s, const G2Options& o) {
  PaperSolver ps{p, o};
  G2SolverOutcome out;
  double h = s.h;
  ps.q0 = p.law.q_of_kappa(p.kappa_s * h);
  ps.q3 = p.law.q_of_kappa(p.kappa_e * h);
  double c10 = (g2_joint_q(p, s.k1, h) - ps.q0) / kG2S1;
  double c30 = (ps.q3 - g2_joint_q(p, s.k2, h)) / (1 - kG2S2);
  out.status = Status::max_iterations;
  out.message = "paper: outer iteration on h reached its cap";
  for (out.iterations = 1; out.iterations <= o.max_iterations; ++out.iterations) {
    ps.q0 = p.law.q_of_kappa(p.kappa_s * h);
    ps.q3 = p.law.q_of_kappa(p.kappa_e * h);
    // Bisection on c30 for ∫ sin φ dS = 0 (Eq. 33); bracket by doubling steps around c30.
    const PaperSolver::Eval e0 = ps.eval_c30(h, c30, c10);
    if (!std::isfinite(e0.g)) {
      out.status = Status::not_converged;
      out.message = "paper: no c10 solves Eq. (41) at the current c30";
      break;
    }
    PaperSolver::Eval best = e0;
    if (e0.g != 0) {
      // Doubling steps both ways from c30, each probe compared with c30's g; the bisection
      // starts from e0 (its c10 seeds the inner Newton) and the probe that changed sign.
      PaperSolver::Eval last;
      const auto g = [&](double c) {
        last = ps.eval_c30(h, c, e0.c10);
        return last.g;
      };
      BracketSearchOptions bo;
      bo.step = 0.05 * std::max(1.0, std::abs(c30));
      bo.growth = 2;
      bo.max_probes = 120;  // 60 doublings each way
      bo.from_start = true;
      if (!search_bracket(g, c30, bo, e0.g).found) {
        out.status = Status::not_converged;
        out.message = "paper: no sign change of Eq. (33) found in c30 (60 doubling steps each way)";
        break;
      }
      best = ps.bisect_c30(h, e0, last);
    }
    c30 = best.c30;
    c10 = best.c10;
    const double x = best.integral.real();
    if (!(x > 0)) {
      out.status = Status::not_converged;
      out.message = "paper: the end point moved behind the start (h would be negative, 004 §3.4)";
      break;
    }
    // Eq. (32): h = r / ∫cos φ dS with r = 1.
    const double h_new = 1.0 / x;
    const bool converged = std::abs(h_new - h) <= o.tolerance * h;
    // Keep κ at the joints when h changes (c10, c30 are per unit S of q(κh)).
    if (!converged) {
      const double q1 = ps.q0 + c10 * kG2S1, q2 = ps.q3 - c30 * (1 - kG2S2);
      const double k1 = p.law.kappa_of_q(q1) / h * h_new, k2 = p.law.kappa_of_q(q2) / h * h_new;
      const double q0n = p.law.q_of_kappa(p.kappa_s * h_new), q3n = p.law.q_of_kappa(p.kappa_e * h_new);
      const double c10n = (p.law.q_of_kappa(k1) - q0n) / kG2S1, c30n = (q3n - p.law.q_of_kappa(k2)) / (1 - kG2S2);
      if (std::isfinite(c10n) && std::isfinite(c30n)) c10 = c10n, c30 = c30n;
      h = h_new;
      continue;
    }
    out.status = Status::ok;
    out.message.clear();
    out.end = h * best.integral;
    out.h = h;
    out.q1 = ps.q0 + c10 * kG2S1;
    out.q2 = ps.q3 - c30 * (1 - kG2S2);
    break;
  }
  if (out.iterations > o.max_iterations) out.iterations = o.max_iterations;
  out.evaluations = ps.evaluations;
  out.constructions = ps.constructions;
  return out;
}

}  // namespace lac::detail
