#include "lac/curves/planar/la_segment_kernel.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "lac/common/detail/unit_phasors.hpp"
#include "lac/common/numeric.hpp"
#include "lac/curves/planar/la_law.hpp"
#include "lac/integrators/gauss_legendre.hpp"

namespace lac {
namespace {

using Complex = std::complex<double>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- forward-mode derivative (value, d/dx) of everything that depends on the shape variable x ----
struct Dual {
  double v = 0, d = 0;
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.d - b.d}; }
Dual operator-(Dual a) { return {-a.v, -a.d}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.v * b.d + a.d * b.v}; }
Dual operator/(Dual a, Dual b) { return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)}; }
Dual operator*(double k, Dual a) { return {k * a.v, k * a.d}; }
Dual operator+(double k, Dual a) { return {k + a.v, a.d}; }
Dual dual_pow(Dual a, double e) {  // a > 0
  const double p = power(a.v, e);
  return {p, e * p / a.v * a.d};
}
Dual dual_log(Dual a) { return {std::log(a.v), a.d / a.v}; }  // a > 0
Dual dual_exp(Dual a) {
  const double e = std::exp(a.v);
  return {e, e * a.d};
}
Dual dual_expm1(Dual a) {
  const double e = std::expm1(a.v);
  return {e, (e + 1) * a.d};
}
Dual dual_log1p(Dual a) { return {std::log1p(a.v), a.d / (1 + a.v)}; }  // a > −1
// expm1(y)/y and log1p(z)/z with their derivatives (series near 0, where the quotients cancel).
Dual expm1_ratio(Dual y) {
  if (std::abs(y.v) < 1e-3) {
    const double v = y.v;
    return {1 + v * (0.5 + v * (1.0 / 6 + v / 24)), (0.5 + v * (1.0 / 3 + v / 8)) * y.d};
  }
  const double e = std::expm1(y.v);
  return {e / y.v, (y.v * (e + 1) - e) / (y.v * y.v) * y.d};
}
Dual log1p_ratio(Dual z) {
  if (std::abs(z.v) < 1e-3) {
    const double v = z.v;
    return {1 + v * (-0.5 + v * (1.0 / 3 - v / 4)), (-0.5 + v * (2.0 / 3 - 0.75 * v)) * z.d};
  }
  const double l = std::log1p(z.v);
  return {l / z.v, (z.v / (1 + z.v) - l) / (z.v * z.v) * z.d};
}

constexpr int kN = 20;             // nodes per panel of the general kernel
constexpr double kPanelTurn = 6;   // radians of φ per 20-node panel (error ≲ 1e-15)
constexpr int kMaxPanels = 256;

// ---- the power law K(q) = sgn(q)|q|^b, b = −1/α (α ≠ 0), F = |q|^p / p, p = b + 1 (log|q| at α = 1) ----
struct Power {
  double alpha, b, p;
  bool log_F;
  explicit Power(double a) : alpha(a), b(-1.0 / a), p(1.0 - 1.0 / a), log_F(a == 1) {}

  double K(double q) const { return std::copysign(power(std::abs(q), b), q); }
  double F(double q) const {
    const double aq = std::abs(q);
    return log_F ? std::log(aq) : aq * power(aq, b) / p;
  }
  Dual F(Dual q) const {
    const double aq = std::abs(q.v);
    if (log_F) return {std::log(aq), q.d / q.v};
    const double w = power(aq, b);
    return {aq * w / p, std::copysign(w, q.v) * q.d};
  }
  // K^(n)(m) for n = 0 … 5: b(b−1)…(b−n+1) sgn(m)^(n+1) |m|^(b−n).
  void derivatives(double m, double out[6]) const {
    const double am = std::abs(m), sg = m < 0 ? -1.0 : 1.0, inv = 1.0 / am;
    double c = 1, pw = power(am, b);
    for (int n = 0; n < 6; ++n) {
      out[n] = c * pw * (n % 2 == 0 ? sg : 1.0);
      c *= b - n;
      pw *= inv;
    }
  }
  // F[m − d/2, m + d/2] by its midpoint series K + K''d²/24 + K''''d⁴/1920 (|d| ≤ 1e-3|m|).
  Dual midpoint(Dual m, Dual d) const {
    double k[6];
    derivatives(m.v, k);
    const double d2 = d.v * d.v;
    return {k[0] + k[2] * d2 / 24 + k[4] * d2 * d2 / 1920,
            (k[1] + k[3] * d2 / 24 + k[5] * d2 * d2 / 1920) * m.d + (k[2] * d.v / 12 + k[4] * d2 * d.v / 480) * d.d};
  }
  // F[x, z] with F(x) given: the difference quotient, or the series where it cancels. Near α = 1
  // (|p| < 1/2; F ~ 1/p) K(x)·E₁(p log1p(r))·log1p(r)/r, r = (z − x)/x (la_law.hpp), continuous
  // into the logarithmic spiral.
  Dual divided(Dual x, Dual Fx, Dual z) const {
    if (std::abs(p) < 0.5 && x.v != 0 && (z.v - x.v) / x.v > -1) {
      const Dual r = (z - x) / x, R = std::abs(r.v) > 0.5 ? dual_log(z / x) / r : log1p_ratio(r);  // log(z/x) direct: r ≈ −1 loses digits
      const Dual pL = p * (r * R);
      if (std::abs(pL.v) < 1) {  // beyond, F(z)/F(x) differs from 1 by a factor e: no cancellation
        const double ax = std::abs(x.v), w = power(ax, b);
        const Dual Kx{std::copysign(w, x.v), b * w / ax * x.d};
        return Kx * expm1_ratio(pL) * R;
      }
    }
    const Dual d = z - x, m = 0.5 * (x + z);
    if (std::abs(d.v) <= 1e-3 * std::abs(m.v)) return midpoint(m, d);
    return (F(z) - Fx) / d;
  }
  // g = F[s − c, s + c] / s, even in s and finite at s = 0 (the antisymmetric S, Δ = 0).
  Dual g(Dual s, Dual c) const {
    if (std::abs(c.v) <= 1e-3 * std::abs(s.v)) return midpoint(s, 2.0 * c) / s;
    if (std::abs(s.v) <= 1e-3 * std::abs(c.v)) {
      const Dual a = c.v < 0 ? -c : c;  // (F(a + s) − F(a − s)) / (2as), odd series in s
      double k[6];
      derivatives(a.v, k);
      const double s2 = s.v * s.v;
      const Dual num{k[0] + k[2] * s2 / 6 + k[4] * s2 * s2 / 120,
                     (k[1] + k[3] * s2 / 6 + k[5] * s2 * s2 / 120) * a.d + (k[2] * s.v / 3 + k[4] * s2 * s.v / 30) * s.d};
      return num / a;
    }
    return (F(s + c) - F(s - c)) / (2.0 * c * s);
  }
};

// ∫₀¹ e^{iφ} du and its derivative in x.
struct Integral {
  Complex I, dI;
};
// Quadrature nodes gathered so that their e^{iφ} come from one batch call (common/detail/
// unit_phasors.hpp: four or two at a time): each node adds w0·e^{iφ} to s0 and w1·e^{iφ} to s1, in node
// order. Flushed when full and when it goes out of scope: read the sums after that.
class PhasorBatch {
 public:
  PhasorBatch(Complex& s0, Complex& s1) : s0_(s0), s1_(s1) {}
  explicit PhasorBatch(Integral& r) : PhasorBatch(r.I, r.dI) {}
  PhasorBatch(const PhasorBatch&) = delete;
  PhasorBatch& operator=(const PhasorBatch&) = delete;
  ~PhasorBatch() { flush(); }
  void push(double phi, Complex w0, Complex w1) {
    phi_[n_] = phi;
    w_[0][n_] = w0.real(), w_[1][n_] = w0.imag(), w_[2][n_] = w1.real(), w_[3][n_] = w1.imag();
    if (++n_ == kSize) flush();
  }
  // The integrand e^{iφ} with weight w (value and x-derivative): I += w e^{iφ}, dI += (w' + iwφ')e^{iφ}.
  void add(Dual weight, Dual phi) { push(phi.v, weight.v, Complex(weight.d, weight.v * phi.d)); }
  void flush() {
    if (n_ == 0) return;
    std::array<double, kSize> c, sn;
    detail::unit_phasors(phi_.data(), static_cast<std::size_t>(n_), c.data(), sn.data());
    double r0 = 0, i0 = 0, r1 = 0, i1 = 0;  // (w0, w1)·e^{iφ} in real arithmetic
    for (int k = 0; k < n_; ++k) {
      r0 += w_[0][k] * c[k] - w_[1][k] * sn[k];
      i0 += w_[0][k] * sn[k] + w_[1][k] * c[k];
      r1 += w_[2][k] * c[k] - w_[3][k] * sn[k];
      i1 += w_[2][k] * sn[k] + w_[3][k] * c[k];
    }
    s0_ += Complex(r0, i0);
    s1_ += Complex(r1, i1);
    n_ = 0;
  }

 private:
  static constexpr int kSize = 20;  // one panel of the largest rule
  Complex &s0_, &s1_;
  std::array<double, kSize> phi_{};
  std::array<std::array<double, kSize>, 4> w_{};  // Re w0, Im w0, Re w1, Im w1
  int n_ = 0;
};
// 20-node panels for a piece turning `turning` rad; −1 past kMaxPanels (or not finite): the piece is
// not resolved (checked in double: the count can exceed int).
int panels_for(double turning) {
  const double panels = std::ceil(std::abs(turning) / kPanelTurn);
  return panels <= kMaxPanels ? std::max(1, static_cast<int>(panels)) : -1;
}
// node(t, w) over `panels` equal N-node Gauss–Legendre panels of [t0, t1]; returns the node count.
template <int N, class Node>
long gauss_panels(double t0, double t1, int panels, Node&& node) {
  const GaussLegendreRule<N>& g = gauss_legendre_rule<N>();
  const double h = (t1 - t0) / panels;
  for (int p = 0; p < panels; ++p)
    for (int k = 0; k < N; ++k) node(t0 + (p + g.nodes[k]) * h, g.weights[k] * h);
  return static_cast<long>(N) * panels;
}
// The same for an integrand e^{g(t)} with |g'|·(t1 − t0)/2 ≤ omega on [t0, t1]: 12, 16 or 20 nodes
// up to omega = 4, 8, 12, more 20-node panels beyond (error ≲ 1e-14 of the piece for the two kernels
// that use it, checked against a long-double reference; docs/g1_hermite.md). −1, and no node
// evaluated, where that needs more than kMaxPanels panels (or omega is not finite): the piece is
// not resolved and the caller's shape is "not evaluated".
template <class Node>
long gauss_by_omega(double omega, double t0, double t1, Node&& node) {
  if (omega <= 4) return gauss_panels<12>(t0, t1, 1, node);
  if (omega <= 8) return gauss_panels<16>(t0, t1, 1, node);
  const double panels = std::ceil(omega / 12);
  if (!(panels <= kMaxPanels)) return -1;
  return gauss_panels<kN>(t0, t1, static_cast<int>(panels), node);
}

// Summary::evaluations counts kernel evaluations: Gauss–Legendre nodes plus the terms of these
// closed-form series (a term costs about what a node does), so that it compares across α and methods.
// The power series of the log-variable kernels, Σ (iz)^n/n! with |z| ≤ kSeriesReach: a piece turning
// up to 3.2 rad needs no quadrature node; ≤ 34 terms to 1e-17, the largest term 3.2³/3! ≈ 5.5 (about
// half a digit of cancellation). 1/n, and 1/(1 + np) per thread for the last p.
constexpr double kSeriesReach = 3.2;
constexpr int kSeriesTerms = 48;
constexpr auto kReciprocals = [] {
  std::array<double, kSeriesTerms + 2> r{};
  for (int n = 1; n < kSeriesTerms + 2; ++n) r[n] = 1.0 / n;
  return r;
}();
const std::array<double, kSeriesTerms + 1>& series_reciprocals(double p) {
  thread_local std::array<double, kSeriesTerms + 1> inv{};
  thread_local double last = kNaN;
  if (p != last) {
    last = p;
    for (int n = 0; n <= kSeriesTerms; ++n) inv[n] = 1 / (1 + n * p);
  }
  return inv;
}

using Trial = LaKernelValue;

constexpr double kSmallAlpha = kLaKernelSmallAlpha;

// The kernel proper (LaSegmentKernel::evaluate copies its state in and out).
struct Kernel {
  double alpha = -1, phi0 = 0, delta = 0;
  long evaluations = 0;
  long constructions = 0;
  long budget = std::numeric_limits<long>::max();
  bool exhausted() const { return alpha < 0 && evaluations >= budget; }

  Trial evaluate(double x) {
    if (exhausted()) return Trial{};
    ++constructions;
    Integral r;
    Trial t;
    if (alpha == -1) {
      if (!(0.5 * std::abs(delta) + std::abs(x) <= 12.0 * kMaxPanels)) return t;  // turning beyond what is resolved
      r = clothoid(x);
      t.qa = delta - x;
      t.qb = delta + x;
    } else if (alpha == 0) {
      if (!exponential(x, r, t)) return t;
    } else if (std::abs(alpha) < kSmallAlpha && (alpha > 0 || std::abs(x) < std::abs(delta))) {
      // X = log(qb/qa): x itself for α > 0; for α < 0, qb/qa = (Δ + a)/(Δ − a) (no zero of q inside).
      const Dual X = alpha > 0 ? Dual{x, 1} : Dual{std::log1p(2 * x / (delta - x)), 2 * delta / ((delta - x) * (delta + x))};
      if (!near_zero(X, r, t)) return t;
    } else if (!power(x, r, t)) {
      return t;
    }
    t.I = r.I;
    t.dI = r.dI;
    t.f = r.I.imag();
    t.df = r.dI.imag();
    t.ok = std::isfinite(t.f) && std::isfinite(t.df) && std::isfinite(t.I.real());
    return t;
  }

  // α < 0, α ≠ −1: the segment with q = (qa, qb) per unit u at u = 0, 1 (plain form; Δ = F[qa, qb]
  // already in delta), no shape derivative.
  Trial evaluate_q(double qa, double qb) {
    if (exhausted()) return Trial{};
    ++constructions;
    Integral r;
    Trial t;
    if (!power_from_q(Dual{qa, 0}, Dual{qb, 0}, r, t)) return t;
    t.I = r.I;
    t.dI = r.dI;
    t.f = r.I.imag();
    t.df = r.dI.imag();
    t.ok = std::isfinite(t.f) && std::isfinite(t.I.real());
    return t;
  }

  // α = −1 [Bertolazzi–Frego 2015]: φ = φ0 + (Δ − A)u + Au², ∂φ/∂A = u² − u. The node count
  // follows ω = |Δ|/2 + |A| (the largest |dφ/dv| on v ∈ [−1, 1], u = (1 + v)/2, with the quadratic
  // part weighted twice): 12, 16 or 20 nodes up to 4, 8, 12 rad, as gauss_by_omega.
  template <int N>
  Integral clothoid_rule(double A, int panels) {
    const GaussLegendreRule<N>& g = gauss_legendre_rule<N>();
    const double h = 1.0 / panels;
    double re = 0, im = 0, dre = 0, dim = 0;  // I and dI/dA = ∫i(u² − u)e^{iφ}du
    for (int p = 0; p < panels; ++p) {
      std::array<double, N> u, phi, c, sn;
      for (int k = 0; k < N; ++k) {
        u[k] = (p + g.nodes[k]) * h;
        phi[k] = phi0 + delta * u[k] + A * (u[k] * (u[k] - 1));
      }
      detail::unit_phasors(phi.data(), N, c.data(), sn.data());
      double pr = 0, pi = 0, pdr = 0, pdi = 0;
      for (int k = 0; k < N; ++k) {
        const double w = g.weights[k] * h, wd = w * (u[k] * (u[k] - 1));
        pr += w * c[k], pi += w * sn[k];
        pdr -= wd * sn[k], pdi += wd * c[k];
      }
      re += pr, im += pi, dre += pdr, dim += pdi;
    }
    evaluations += static_cast<long>(N) * panels;
    return {Complex(re, im), Complex(dre, dim)};
  }
  Integral clothoid(double A) {
    // The quadratic part counts twice: e^{iAv²/4} needs more nodes than a linear phase of the same
    // slope (12 nodes leave 7.7e-13 at A = 8, Δ = 0; 2e-16 within these thresholds, checked against
    // a long-double composite rule on a grid of Δ/A shares).
    const double omega = 0.5 * std::abs(delta) + std::abs(A);
    if (omega <= 4) return clothoid_rule<12>(A, 1);
    if (omega <= 8) return clothoid_rule<16>(A, 1);
    return clothoid_rule<20>(A, std::max(1, static_cast<int>(std::ceil(omega / 12))));
  }

  // α = 0: κ = σ e^{q}, q = qa + bu, φ = φ0 + Δ expm1(bu)/expm1(b).
  bool exponential(double b, Integral& r, Trial& t) {
    if (std::abs(b) >= 1e-3) {
      if (!exponential_far(b, r)) return false;
    } else if (!exponential_near(b, r)) {
      return false;
    }
    // |κ| per u at u = 0: |Δ| b / expm1(b), logarithm without overflow.
    const double lr = b == 0 ? 0.0
                      : b > 0 ? std::log(b) - b - std::log(-std::expm1(-b))
                              : std::log(-b) - std::log(-std::expm1(b));
    t.qa = std::log(std::abs(delta)) + lr;
    t.qb = t.qa + b;
    return std::isfinite(t.qa) && std::isfinite(t.qb);
  }

  // |b| ≥ 1e-3. From the steep end (u = 0 for b < 0; for b > 0 the mirror u ↦ 1 − u, φ0 ↦ φ0 + Δ,
  // Δ ↦ −Δ) with m = |b| and v = mu: φ = φe + D(1 − e^(−v)), D = Δ/(1 − e^(−m)), I = (1/m)∫₀^m e^{iφ}dv.
  // Where |D|e^(−v) ≤ kSeriesReach (v ≥ V) the phase is a power series in e^(−v):
  // e^{iφ} = e^{i(φe + D)} Σ (−iD)^n e^(−nv)/n!, integrated term by term; [0, min(V, m)] (only for
  // turnings beyond kSeriesReach) by Gauss–Legendre. The derivative, with V held fixed:
  // dI/dm = (e^{i(φe ± Δ)} − I)/m + (i D′/m)∫₀^m (1 − e^(−v))e^{iφ}dv, D′ = −D/expm1(m).
  bool exponential_far(double b, Integral& r) {
    const bool mirror = b > 0;
    const double m = std::abs(b), phe = mirror ? phi0 + delta : phi0, dl = mirror ? -delta : delta;
    const double D = dl / -std::expm1(-m), W = std::min(m, std::max(0.0, std::log(std::abs(D) / kSeriesReach)));
    Complex J0, J1;  // ∫₀^m e^{iφ} dv and ∫₀^m (1 − e^(−v)) e^{iφ} dv
    if (W > 0) {
      PhasorBatch batch(J0, J1);
      const long n = gauss_by_omega(0.5 * W * (std::abs(D) + 1), 0.0, W, [&](double v, double wt) {
        const double g = -std::expm1(-v);
        batch.push(phe + D * g, wt, g * wt);
      });
      batch.flush();
      if (n < 0) return false;
      evaluations += n;
    }
    if (m > W) {
      // Σ c_n T_n and Σ c_n T_(n+1), c_n = (−iD)^n/n!, T_k = ∫_W^m e^(−kv)dv = e^(−kW) S_k / k with
      // S_k = 1 − e^(−kh), h = m − W, by S_(k+1) = S_1 + e^(−h) S_k (no cancellation for small h).
      const double eW = std::exp(-W), S1 = -std::expm1(-(m - W)), eh = 1 - S1;
      double pW = eW, Sk = S1;
      double T_next = pW * Sk;
      Complex c = 1, A = m - W, B = T_next;
      const double z = std::abs(D) * eW;  // ≤ kSeriesReach
      double bound = 1;
      for (int n = 1; n < kSeriesTerms; ++n) {
        ++evaluations;  // one series term: counted as one kernel evaluation (comparable with a node)
        c *= Complex(0, -D * kReciprocals[n]);
        A += c * T_next;
        pW *= eW;
        Sk = S1 + eh * Sk;
        T_next = pW * Sk * kReciprocals[n + 1];
        B += c * T_next;
        bound *= z * kReciprocals[n];
        if (bound < 1e-17) break;
      }
      const Complex e = std::polar(1.0, phe + D);
      J0 += e * A;
      J1 += e * (A - B);
    }
    r.I = J0 / m;
    const Complex dI_dm = (std::polar(1.0, phe + dl) - r.I) / m + Complex(0, -D / std::expm1(m)) * J1 / m;
    r.dI = mirror ? dI_dm : -dI_dm;
    return true;
  }

  // |b| < 1e-3 (near the arc): E = expm1(bu)/expm1(b) (b ≤ 0), mirrored for b > 0 (E = 1 − E(1 − u; −b)),
  // a series in b below 1e-6; 20 nodes per 6 rad of turning.
  bool exponential_near(double b, Integral& r) {
    const int panels = panels_for(delta);
    if (panels < 0) return false;
    const bool series = std::abs(b) < 1e-6, mirror = b > 0;
    const double beta = mirror ? -b : b, dbeta = mirror ? -1.0 : 1.0, em = std::expm1(beta);
    const Dual den{em, (em + 1) * dbeta};
    auto E = [&](double u) -> Dual {
      if (series) {
        const double e1 = 0.5 * u * (u - 1), e2 = u * (u - 1) * (2 * u - 1) / 12;
        return {u + b * e1 + b * b * e2, e1 + 2 * b * e2};
      }
      const double v = mirror ? 1 - u : u, n = std::expm1(beta * v);
      const Dual e = Dual{n, (n + 1) * v * dbeta} / den;
      return mirror ? 1.0 + (-e) : e;
    };
    PhasorBatch batch(r);
    evaluations += gauss_panels<kN>(0.0, 1.0, panels,
                                    [&](double u, double wt) { batch.add(Dual{wt, 0}, phi0 + delta * E(u)); });
    return true;
  }

  // 0 < |α| < kSmallAlpha, q of one sign on [0, 1], X = log(qb/qa): κ/κa = (1 + u·expm1(X))^(−1/α),
  // so with p = 1 − 1/α, L(u) = log1p(u·expm1(X)) and Y = pX (→ log(κb/κa) as α → 0)
  //   φ = φ0 + Δ·E(u),  E = expm1(pL)/expm1(Y)  (= e^(p(L−X))·expm1(−pL)/expm1(−Y) for Y > 0,
  //   L − X = log1p((1 − u)expm1(−X))),  |κa| = |Δ|·|p·expm1(X)/expm1(Y)|,
  // the α = 0 kernel's E = expm1(bu)/expm1(b) in the limit. Nodes: 20 per 6 rad of turning on
  // parts at distances 2^k/|B| from the end of largest |κ| (B = −X/α = log(κb/κa); log|κ| changes by
  // at most 2^k on each), one part for |B| ≤ 4; the parts are held fixed in X.
  bool near_zero(Dual X, Integral& r, Trial& t) {
    if (!(std::abs(X.v) <= 600) || delta == 0) return false;
    const double p = 1 - 1 / alpha;
    const Dual Y = p * X, m = dual_expm1(X), mneg = dual_expm1(-X);
    const bool mirror = Y.v > 0;
    const Dual den = mirror ? dual_expm1(-Y) : dual_expm1(Y);
    const auto E = [&](double u) -> Dual {
      if (!mirror) return dual_expm1(p * dual_log1p(u * m)) / den;
      const Dual pL = p * dual_log1p(u * m);
      return dual_exp(p * dual_log1p((1 - u) * mneg)) * dual_expm1(-pL) / den;
    };
    const double B = -X.v / alpha;
    std::array<double, 64> cuts{};
    int n = 0;
    cuts[n++] = 0;
    if (std::abs(B) > 4) {  // distances 2^k/|B| from the steep end (u = 1 for B > 0)
      std::array<double, 64> from_end{};
      int k = 0;
      for (double dist = 1 / std::abs(B); dist < 1 && k < 60; dist *= 2) from_end[k++] = dist;
      for (int i = k - 1; i >= 0; --i) {
        const double u = B > 0 ? 1 - from_end[i] : from_end[k - 1 - i];
        if (u > cuts[n - 1] && u < 1) cuts[n++] = u;
      }
    }
    cuts[n++] = 1;
    double e_prev = 0;
    PhasorBatch batch(r);
    for (int i = 0; i + 1 < n; ++i) {
      const double e_next = i + 2 == n ? 1.0 : E(cuts[i + 1]).v;
      const int panels = panels_for(delta * (e_next - e_prev));
      if (panels < 0) return false;
      e_prev = e_next;
      evaluations += gauss_panels<kN>(cuts[i], cuts[i + 1], panels,
                                      [&](double u, double wt) { batch.add(Dual{wt, 0}, phi0 + delta * E(u)); });
    }
    // log|κ_u| at u = 0 and 1, then q in the offset form (ℓ·expm1(−αℓ)/(−αℓ)).
    const double log_den = mirror ? Y.v + std::log(-den.v) : std::log(-den.v);
    const double la = std::log(std::abs(delta)) + std::log(std::abs(p)) + std::log(std::abs(m.v)) - log_den;
    const double lb = la + B;
    t.offset = true;
    t.qa = la * LaLaw::expm1_ratio(-alpha * la);
    t.qb = lb * LaLaw::expm1_ratio(-alpha * lb);
    return std::isfinite(t.qa) && std::isfinite(t.qb);
  }

  // α ≠ 0, −1: (m, c) = λ(s, c̄) with (s, c̄) = (Δ, a)/hypot(Δ, a) and λ from the turning:
  // F[λ(s − c̄), λ(s + c̄)] = λ^(−1/α) s g = Δ  ⇒  λ = (hypot(Δ, a)/g)^(−α).
  bool power(double a, Integral& r, Trial& t) {
    const Power law(alpha);
    Dual qa, qb;
    if (alpha > 0) {
      // q keeps its sign σ = sgn Δ: x = log(qb/qa) ∈ ℝ, (q̂a, q̂b) = σ(e^(−x/2), e^(x/2)) scaled by
      // e^(−|x|/2); λ from λ^(−1/α) F[q̂a, q̂b] = Δ.
      const double y = 0.5 * a, sy = y < 0 ? -1.0 : 1.0, sigma = delta < 0 ? -1.0 : 1.0;
      const double ea = std::exp(-y - std::abs(y)), eb = std::exp(y - std::abs(y));
      const Dual qha{sigma * ea, sigma * ea * (-0.5 - 0.5 * sy)}, qhb{sigma * eb, sigma * eb * (0.5 - 0.5 * sy)};
      const Dual G = law.divided(qha, law.F(qha), qhb);
      const Dual lambda = dual_pow(G / Dual{delta, 0}, alpha);
      qa = lambda * qha;  // not m ∓ c: q at the end next to the zero is tiny (cancellation)
      qb = lambda * qhb;
      if (!std::isfinite(lambda.d)) return false;
    } else {
      const double hv = std::hypot(delta, a);
      if (hv == 0) {  // straight
        r.I = std::polar(1.0, phi0);
        t.qa = t.qb = 0;
        return true;
      }
      const Dual h{hv, a / hv};
      const Dual s = Dual{delta, 0} / h, cbar = Dual{a, 1} / h;
      const Dual g = law.g(s, cbar);
      const Dual lambda = dual_pow(h / g, -alpha);
      qa = lambda * (s - cbar);
      qb = lambda * (s + cbar);
      if (!std::isfinite(lambda.d)) return false;
    }
    return power_from_q(qa, qb, r, t);
  }

  // The integral for given q at u = 0, 1 (their derivatives in x carried along); Δ = F[qa, qb].
  bool power_from_q(Dual qa, Dual qb, Integral& r, Trial& t) {
    const Power law(alpha);
    const Dual c = 0.5 * (qb - qa);
    t.qa = qa.v;
    t.qb = qb.v;
    if (!(std::isfinite(qa.v) && std::isfinite(qb.v))) return false;
    if (alpha > 0 && !(qa.v * qb.v > 0)) return false;
    // q(zero) = 0, from the end nearer to it.
    const Dual ustar = c.v != 0 ? (-qa) / (2.0 * c) : Dual{kNaN, 0};
    const double zero = ustar.v;
    // ∫ e^{iφ} du over the piece from r = |u − u*| = d (0 at the inflection, α < 0; the distance of
    // the zero outside [0, 1] otherwise) to the end B at r_B, where q = q_B and φ = φ_B (φ0 or φ0 + Δ,
    // fixed by the data). With w = log(r/r_B) ∈ [w0, 0], w0 = log(d/r_B) (−log1p(1/d) when r_B = 1 + d,
    // exact for far zeros): |q| = |q_B|e^w, φ = φ_B + a·expm1(pw), a = F(q_B)/(2c) (φ_B + w/(2c) at
    // α = 1), du = r_B e^w dw: an entire integrand, no pow per node, and no singularity at the
    // inflection (φ − φ* ∝ r^p there).
    // Where |a|e^(pw) ≤ kSeriesReach (near the zero for p > 0, i.e. α < 0 or α > 1; near B for p < 0)
    // e^{iφ} = e^{i(φ_B − a)} Σ (ia e^(pw))^n/n! is integrated term by term in closed form
    // (∫e^((1+np)w)dw). The rest, where the piece turns more than kSeriesReach, by Gauss–Legendre on
    // panels of width ≤ 1/|p| in w (φ' within a factor e on each), 12, 16 or 20 nodes for
    // ω = (width/2)·hypot(1, max|φ'|) up to 4, 8, 12. The split is held fixed in x, so the derivative
    // of the sum is exact; r < 1e-18 (u-width below 1e-18) is left out.
    bool too_steep = false;
    auto log_piece = [&](Dual d, Dual rB, Dual qB, double phiB) {
      if (!(rB.v > 1e-18)) return;  // a piece narrower than 1e-18 in u
      const Dual two_c = 2.0 * c;
      const double p = law.p;
      const Dual amp = (law.log_F ? Dual{1, 0} : dual_pow(qB.v < 0 ? -qB : qB, p)) / two_c;
      const Dual w0 = d.v <= 1e-18 ? dual_log(Dual{1e-18, 0} / rB)
                      : rB.v == 1 + d.v ? Dual{-std::log1p(1 / d.v), d.d / (d.v * rB.v)}
                                         : dual_log(d / rB);
      if (law.log_F) {  // α = 1, the logarithmic spiral: r_B e^{iφ_B} (1 − e^{k w0})/k, k = 1 + i/(2c)
        const Complex k(1, amp.v), dk(0, amp.d), E = std::exp(k * w0.v), G = (1.0 - E) / k;
        const Complex dG = -E * (dk * w0.v + k * w0.d) / k - G * dk / k, eB = std::polar(1.0, phiB);
        r.I += rB.v * eB * G;
        r.dI += eB * (rB.d * G + rB.v * dG);
        return;
      }
      const auto phase = [&](Dual w) -> Dual {  // φ − φ_B
        const double em = std::expm1(p * w.v);
        return amp * Dual{em / p, (em + 1) * w.d};
      };
      // The split ws: the series covers [w0, ws] (p > 0) or [ws, 0] (p < 0).
      const double ws = std::clamp(std::log(kSeriesReach / std::abs(amp.v / p)) / p, w0.v, 0.0);  // |a|e^(p·ws) = reach
      const Dual split = ws <= w0.v ? w0 : Dual{ws, 0};  // at w0 it moves with w0
      const Dual q_lo = p > 0 ? split : w0, q_hi = p > 0 ? Dual{0, 0} : split;
      const Dual span = q_hi - q_lo;
      if (span.v > 0) {
        const double want = std::ceil(span.v * std::abs(p));
        if (!(want <= 4096)) {  // |p| ~ 1/|α| huge (0 < −α ≪ 1 with an inflection): not evaluated, never a hang
          too_steep = true;
          return;
        }
        const int panels = std::max(1, static_cast<int>(want));
        PhasorBatch batch(r);
        for (int i = 0; i < panels; ++i) {
          const double ta = static_cast<double>(i) / panels, tb = static_cast<double>(i + 1) / panels;
          const double wa = q_lo.v + ta * span.v, wb = q_lo.v + tb * span.v;
          const double slope = std::abs(amp.v) * std::max(std::exp(p * wa), std::exp(p * wb));
          const double omega = 0.5 * (tb - ta) * span.v * std::hypot(1.0, slope);
          const long nodes = gauss_by_omega(omega, ta, tb, [&](double tau, double wt) {
            const Dual w = q_lo + tau * span;
            const double ew = std::exp(w.v);
            batch.add(wt * (Dual{ew, ew * w.d} * rB * span), phiB + phase(w));
          });
          if (nodes < 0) {
            too_steep = true;
            return;
          }
          evaluations += nodes;
        }
      }
      const Dual s_lo = p > 0 ? w0 : split, s_hi = p > 0 ? split : Dual{0, 0};
      const double h = s_hi.v - s_lo.v;
      if (h > 0) {
        // A = Σ c_n T_n, B = Σ c_n T_(n+1), c_n = (ia)^n/n!, T_k = ∫ e^((1+kp)w) dw over [s_lo, s_hi],
        // from x_n(w) = e^w (a e^(pw))^n/n! at both ends (c_n e^((1+np)w) = i^n x_n; no overflow of
        // e^(npw) alone), in real arithmetic: i^n sorts the terms into Re and Im with signs.
        const double a = amp.v / p, epl = std::exp(p * s_lo.v), eph = std::exp(p * s_hi.v);
        double xl = std::exp(s_lo.v), xh = std::exp(s_hi.v), bound = 1;
        const double z = std::abs(a) * std::max(epl, eph);  // ≤ kSeriesReach
        const std::array<double, kSeriesTerms + 1>& inv_k = series_reciprocals(p);
        const auto integral = [h, p, &inv_k](double lo, double hi, int n) {  // (hi − lo)/k_n, lo = hi e^(−k_n h)
          const double kh = h * (1 + n * p);
          return std::abs(kh) > 0.5 ? (hi - lo) * inv_k[n] : hi * (h * (kh == 0 ? 1.0 : -std::expm1(-kh) / kh));
        };
        double Are = 0, Aim = 0, Bre = 0, Bim = 0;
        const double al = a * epl, ah = a * eph;
        for (int n = 0; n < kSeriesTerms; ++n) {
          ++evaluations;  // one series term: counted as one kernel evaluation (comparable with a node)
          const double tA = integral(xl, xh, n), tB = integral(xl * epl, xh * eph, n + 1);
          const double sign = (n & 2) ? -1.0 : 1.0;
          if (n & 1) Aim += sign * tA, Bim += sign * tB;
          else Are += sign * tA, Bre += sign * tB;
          const double inv = kReciprocals[n + 1];
          bound *= z * inv;
          if (bound < 1e-17) break;
          xl *= al * inv;
          xh *= ah * inv;
        }
        const Complex A(Are, Aim), B(Bre, Bim);
        const Complex E0 = std::polar(1.0, phiB - amp.v / p);
        const Complex I = rB.v * E0 * A;
        r.I += I;
        // The moving ends' terms, where the integrand is not negligible (the inflection's e^w0 ~ 1e-18).
        const auto f_at = [&](Dual w) {
          return w.d == 0 || std::exp(w.v) * rB.v < 1e-17 ? Complex{} : w.d * rB.v * std::exp(w.v) * std::polar(1.0, phiB + phase(w).v);
        };
        r.dI += rB.d * E0 * A + rB.v * E0 * Complex(0, amp.d / p) * (B - A) - f_at(s_lo) + f_at(s_hi);
      }
    };
    // The zero of q outside [0, 1] by d: one piece, from the end next to it to the far end.
    auto steep = [&](bool near_start) {
      const Dual d = near_start ? qa / (2.0 * c) : -qb / (2.0 * c);
      log_piece(d, 1.0 + d, near_start ? qb : qa, near_start ? phi0 + delta : phi0);
    };
    if (alpha < 0 && std::isfinite(zero)) {
      if (zero > 0 && zero < 1) {  // the inflection: a piece from it to each end
        log_piece(Dual{0, 0}, ustar, qa, phi0);
        log_piece(Dual{0, 0}, 1.0 + (-ustar), qb, phi0 + delta);
      } else {
        steep(zero <= 0);
      }
    } else if (alpha > 0 && std::isfinite(zero)) {
      steep(zero <= 0);
    } else {  // q far from 0 on [0, 1]: nodes in u (their derivative is the integrand's), by κ_u = K(q)
      const double omega = 0.5 * std::max(std::abs(law.K(qa.v)), std::abs(law.K(qb.v)));
      const Dual Fa = law.F(qa);
      PhasorBatch batch(r);
      const long nodes = gauss_by_omega(omega, 0.0, 1.0, [&](double u, double wt) {
        const Dual q = u <= 0.5 ? qa + (2 * u) * c : qb - (2 * (1 - u)) * c;
        batch.add(Dual{wt, 0}, phi0 + u * law.divided(qa, Fa, q));
      });
      if (nodes < 0) return false;
      evaluations += nodes;
    }
    return !too_steep;
  }
};

}  // namespace

namespace {
template <class Call>
LaKernelValue run(LaSegmentKernel& s, Call&& call) {
  Kernel k;
  k.alpha = s.alpha;
  k.phi0 = s.phi0;
  k.delta = s.delta;
  k.evaluations = s.evaluations;
  k.constructions = s.constructions;
  k.budget = s.budget;
  const LaKernelValue v = call(k);
  s.evaluations = k.evaluations;
  s.constructions = k.constructions;
  return v;
}
}  // namespace

LaKernelValue LaSegmentKernel::evaluate(double x) {
  return run(*this, [x](Kernel& k) { return k.evaluate(x); });
}

LaKernelValue LaSegmentKernel::evaluate_q(double qa, double qb) {
  if (!(alpha < 0 && alpha != -1)) return {};
  return run(*this, [qa, qb](Kernel& k) { return k.evaluate_q(qa, qb); });
}

std::optional<LaSegmentIntegral> segment_integral(const LaLaw& law, const detail::LinearQ& seg, long& evaluations) {
  const double h = seg.ub - seg.ua, alpha = law.alpha;
  if (!(h > 0) || !std::isfinite(h)) return std::nullopt;
  LaSegmentKernel k;
  k.alpha = alpha;
  k.phi0 = seg.phi_a;
  k.delta = seg.turning(law);
  if (!std::isfinite(k.delta) || !std::isfinite(seg.phi_a)) return std::nullopt;
  LaKernelValue v;
  double extra = 0;
  if (alpha == 0) {
    v = k.evaluate(seg.qb - seg.qa);  // b = log(κb/κa)
  } else {
    const double ta = law.t_of_q(seg.qa), tb = law.t_of_q(seg.qb);  // the plain form's q
    // log(qb/qa): log1p of the relative change near 1 (no cancellation), the ratio itself beyond
    // (log1p(z) at z ≈ −1 keeps only the digits of 1 + z).
    const auto log_ratio = [&] {
      const double z = law.relative_t(seg.qa, seg.qb);
      return std::abs(z) <= 0.5 ? std::log1p(z) : std::log(tb / ta);
    };
    if (ta == 0 && tb == 0) return LaSegmentIntegral{std::polar(h, seg.phi_a), 0.0};  // a line (α < 0)
    if (alpha == -1) {  // q = κ per unit u: A and Δ of the unit interval
      k.delta = 0.5 * h * (ta + tb);
      v = k.evaluate(0.5 * h * (tb - ta));
    } else if (alpha > 0) {
      v = k.evaluate(log_ratio());  // log(qb/qa), scale-free
    } else if (alpha > -kLaKernelSmallAlpha && ta * tb > 0) {
      // Small |α| without inflection: the offset variables, shape a = Δ tanh(log(qb/qa)/2).
      v = k.evaluate(k.delta * std::tanh(0.5 * log_ratio()));
    } else {
      const double scale = std::exp(-alpha * std::log(h));  // q per unit u → per unit of [0, 1]
      const double qa = ta * scale, qb = tb * scale, p = 1 - 1 / alpha;
      v = k.evaluate_q(qa, qb);
      // φ's total variation: from the zero of q to each end the turning is |F(q)|/|dq/du| with
      // |F(q)| = |q|^p/|p| (la_law.hpp; F(0) = 0 for α < 0) and dq/du = qb − qa on [0, 1]; |Δ| when
      // q keeps its sign.
      const double variation = ta * tb < 0 ? (power(std::abs(qa), p) + power(std::abs(qb), p)) /
                                                 (std::abs(p) * std::abs(qb - qa))
                                            : std::abs(k.delta);
      extra = 2 * DBL_EPSILON / std::abs(alpha) * variation * h;
    }
  }
  evaluations += k.evaluations;
  if (!v.ok || !std::isfinite(v.I.real()) || !std::isfinite(v.I.imag()) || !std::isfinite(extra)) return std::nullopt;
  return LaSegmentIntegral{h * v.I, kLaKernelError * h + extra};
}

std::optional<LaSegmentDerivatives> segment_derivatives(const LaLaw& law, const detail::LinearQ& seg,
                                                        std::complex<double> I) {
  const double L = seg.ub - seg.ua, d = seg.qb - seg.qa, alpha = law.alpha;
  if (!(L > 0) || !std::isfinite(L) || !std::isfinite(I.real()) || !std::isfinite(I.imag())) return std::nullopt;
  const double scale = law.log_form() ? 1.0 : std::max(std::abs(seg.qa), std::abs(seg.qb));
  if (!(std::abs(d) >= kLaDerivativeMinChange * scale) || !std::isfinite(scale)) return std::nullopt;
  const double p = alpha == 0 ? 0.0 : 1.0 - 1.0 / alpha;
  // The plain form's closed form divides by p = 1 − 1/α: declined for 0 < |p| < 0.1, exact at α = 1.
  const bool log_spiral = !law.log_form() && alpha == 1;
  if (!law.log_form() && std::abs(p) < 0.1 && !log_spiral) return std::nullopt;
  const Complex i(0, 1);
  const double m = d / L, phib = seg.phi_b(law), ka = law.kappa_of_q(seg.qa), kb = law.kappa_of_q(seg.qb);
  const Complex ea = std::polar(1.0, seg.phi_a), eb = std::polar(1.0, phib);
  // J = ∫(φ − φa)e^{iφ}du. With t the plain q and c = dq/dt (1; −σ/α in the offset form),
  // φ − φa = c(tκ − taκa)/(p·m) and ∫tκe^{iφ} = −i([te^{iφ}] − (m/c)I); at α = 0 (t = σ, c = ∞)
  // φ − φa = (κ − κa)/m.
  Complex J;
  if (alpha == 0) {
    J = (-i * (eb - ea) - ka * I) / m;
  } else if (log_spiral) {
    // α = 1: κ = 1/q, so d/du[q(φ − φa)e^{iφ}] = m(φ − φa)e^{iφ} + e^{iφ} + i(φ − φa)e^{iφ}, and
    // J = (qb(φb − φa)e^{iφb} − I)/(m + i).
    J = (seg.qb * (phib - seg.phi_a) * eb - I) / (m + i);
  } else {
    const double ta = law.t_of_q(seg.qa), tb = law.t_of_q(seg.qb);
    const double c_over_p = law.log_form() ? law.sigma / (1.0 - alpha) : 1.0 / p;
    const double m_over_c = law.log_form() ? -law.sigma * alpha * m : m;
    J = c_over_p / m * (-i * (tb * eb - ta * ea) + i * m_over_c * I - ta * ka * I);
  }
  // ∂φ/∂qa = (κ(1 − v) − κa)/m + (φ − φa)/d, ∂φ/∂qb = κv/m − (φ − φa)/d (v = (u − ua)/L), and
  // ∫κ(1 − v)e^{iφ} = i·ea − iI/L, ∫κv·e^{iφ} = −i·eb + iI/L.
  LaSegmentDerivatives out;
  out.dI_dqa = i * ((i * ea - i * I / L - ka * I) / m + J / d);
  out.dI_dqb = i * ((-i * eb + i * I / L) / m - J / d);
  out.dphib_dqa = (phib - seg.phi_a - ka * L) / d;
  out.dphib_dqb = (kb * L - (phib - seg.phi_a)) / d;
  const bool finite = std::isfinite(std::abs(out.dI_dqa)) && std::isfinite(std::abs(out.dI_dqb)) &&
                      std::isfinite(out.dphib_dqa) && std::isfinite(out.dphib_dqb);
  if (!finite) return std::nullopt;
  return out;
}

// v = t^k with kp ≥ 4 makes the integrand k t^(k−1) e^{iΔ t^(kp)} smooth.
std::optional<std::complex<double>> power_limit_integral(double delta, double p, long& evaluations) {
  if (p < 0.25 && std::abs(delta) <= 4) {
    // Near α = 1 v = t^k needs k ~ 4/p: Σ (iΔ)^n/(n!(1 + np)) instead (|Δ| ≤ 4: ≤ 40 terms, the
    // largest 4⁴/4! ≈ 11), continuous in p; each term counts as one evaluation.
    Complex sum, c = 1;
    for (int n = 0; n < 60; ++n) {
      sum += c / (1 + n * p);
      ++evaluations;
      c *= Complex(0, delta / (n + 1));
      if (std::abs(c) < 1e-18) break;
    }
    return sum;
  }
  const double k = std::max(4.0, std::ceil(4 / p));
  const int panels = panels_for(delta);
  if (panels < 0) return std::nullopt;
  const std::vector<double>& jac = gauss_legendre_20_node_powers(k - 1, panels);
  const std::vector<double>& phase = gauss_legendre_20_node_powers(k * p, panels);
  Complex sum, unused;
  {
    PhasorBatch batch(sum, unused);
    size_t i = 0;
    evaluations += gauss_panels<kN>(0.0, 1.0, panels, [&](double, double wt) {
      batch.push(delta * phase[i], wt * k * jac[i], 0.0);
      ++i;
    });
  }
  return sum;
}

}  // namespace lac
