#include "lac/curves/planar/standard_form.hpp"

#include <cmath>

#include "lac/common/error.hpp"

namespace lac {
namespace {

constexpr const char* kToSegment = "to_segment";
constexpr const char* kToPieces = "to_standard_pieces";

struct EndValues {
  double s = 0, theta = 0, log_rho = 0;
};

// The inflection of the standard form: α < 0, Λ > 0 and t the upper end of the domain (ρ = ∞).
bool at_inflection(const LaCurve& c, Parameter p, double t) {
  return c.alpha() < 0 && c.lambda() > 0 && t == c.domain(p).hi;
}

EndValues end_values(const LaCurve& c, Parameter p, double t, const char* name) {
  if (at_inflection(c, p, t)) return {c.s_domain().hi, c.theta_domain().hi, INFINITY};
  c.check(p, t, name);
  if (p == Parameter::theta) return {c.s_at_theta(t), t, c.log_rho_at_theta(t)};
  return {t, c.theta_at_s(t), c.log_rho_at_s(t)};
}

}  // namespace

Similarity Similarity::after(const Similarity& inner) const {
  const auto m = [this](std::complex<double> z) { return mirror ? std::conj(z) : z; };
  return {factor * m(inner.factor), factor * m(inner.offset) + offset, mirror != inner.mirror};
}

// w = F m(z) + O  ⇔  z = m((w − O)/F) = m(1/F) m(w) − m(O/F) (m is an involution).
Similarity Similarity::inverse() const {
  const std::complex<double> inv = 1.0 / factor;
  const auto m = [this](std::complex<double> z) { return mirror ? std::conj(z) : z; };
  return {m(inv), -m(offset * inv), mirror};
}

std::pair<double, double> theta_range(const StandardPiece& piece) {
  return {end_values(piece.curve, piece.parameter, piece.from, "from").theta,
          end_values(piece.curve, piece.parameter, piece.to, "to").theta};
}

std::pair<double, double> s_range(const StandardPiece& piece) {
  return {end_values(piece.curve, piece.parameter, piece.from, "from").s,
          end_values(piece.curve, piece.parameter, piece.to, "to").s};
}

// Along u = ±s the tangent of the user's curve is ±factor·m(e^{iθ}) = ±(factor/|factor|) e^{±iθ}:
// φ = ±θ (− when mirrored), R = ±factor/|factor| (− against the direction); the curvature per unit
// of u is dφ/du = ±κ, so q = ±ρ^α (α = 0: q = −log ρ with that sign in σ).
LaSegment to_segment(const StandardPiece& piece, std::complex<double> standard_position_at_from) {
  const LaCurve& c = piece.curve;
  const EndValues a = end_values(c, piece.parameter, piece.from, "from");
  const EndValues b = end_values(c, piece.parameter, piece.to, "to");
  if (!(a.s != b.s)) throw_input_error(kToSegment, "to", piece.to, "values other than from (an empty piece)");
  const double ell = std::abs(piece.to_user.factor);
  if (!(ell > 0) || !std::isfinite(ell))
    throw_input_error(kToSegment, "to_user.factor", ell, "nonzero finite complex numbers");
  const double dir = b.s > a.s ? 1.0 : -1.0;
  const double mirror = piece.to_user.mirror ? -1.0 : 1.0;
  const double sign = dir * mirror;  // of the curvature per unit of u
  const double alpha = c.alpha();
  const auto q_of = [&](const EndValues& e) { return alpha == 0 ? -e.log_rho : sign * std::exp(alpha * e.log_rho); };
  const double qa = q_of(a), qb = q_of(b);
  if (!std::isfinite(qa) || !std::isfinite(qb))
    throw_input_error(kToSegment, std::isfinite(qa) ? "to" : "from", std::isfinite(qa) ? piece.to : piece.from,
                      "values where q = rho^alpha is a finite double");
  const Placement placement{piece.to_user(standard_position_at_from), ell, dir * (piece.to_user.factor / ell)};
  return LaSegment(LaLaw{alpha, alpha == 0 ? sign : 1.0}, dir * a.s, dir * b.s, qa, qb, mirror * a.theta, placement);
}

std::vector<StandardPiece> to_standard_pieces(const LaSegment& seg, std::optional<std::complex<double>> end_point) {
  const double alpha = seg.law().alpha;
  const auto zero = [alpha](double q) { return alpha < 0 && q == 0; };  // an inflection: ρ = ∞
  if (zero(seg.qa()) && zero(seg.qb()))
    throw_input_error(kToPieces, "seg", "is straight (kappa = 0 throughout): no standard form");
  struct Range {
    double lo, hi;
  };
  std::vector<Range> ranges{{seg.ua(), seg.ub()}};
  const auto inflection = seg.inflection_u();
  if (inflection && *inflection > seg.ua() && *inflection < seg.ub())
    ranges = {{seg.ua(), *inflection}, {*inflection, seg.ub()}};
  const double c0 = seg.normalized().slope();
  std::vector<StandardPiece> out;
  for (size_t i = 0; i < ranges.size(); ++i) {
    const Range r = ranges[i];
    const bool at_start = i == 0 && !zero(seg.qa());
    if (!at_start && !end_point)
      throw_input_error(kToPieces, "end_point",
                        "needed: the piece at the segment's end (after an inflection, or from an inflection at its "
                        "start) is placed from the end point");
    const double u_star = at_start ? seg.ua() : seg.ub();
    const double q_star = at_start ? seg.qa() : seg.qb();
    const double phi_star = at_start ? seg.phi_a() : seg.phi_b();
    const std::complex<double> p_star = at_start ? seg.start() : *end_point;
    // ρ̃ = |q|^(1/α) (α = 0: e^(−q)) per unit of u: k = ρ̃(u*), dρ̃/du = k c0/(α q*) (−k c0).
    const double k = alpha != 0 ? std::pow(std::abs(q_star), 1.0 / alpha) : std::exp(-q_star);
    const double drho = alpha != 0 ? k * c0 / (alpha * q_star) : -k * c0;
    const double lambda = std::abs(drho);
    if (!(k > 0) || !std::isfinite(k) || !std::isfinite(lambda))
      throw_input_error(kToPieces, "seg", "has no standard form in double precision (rho or its rate of change "
                                          "at the anchor is not a finite positive double)");
    const double dir = drho < 0 ? -1.0 : 1.0;  // u − u* = dir·k·s
    const double sign_q = alpha != 0 ? (q_star > 0 ? 1.0 : -1.0) : seg.law().sigma;
    const LaCurve curve(alpha, lambda);
    const auto s_of = [&](double u) {
      const bool infl = (inflection && u == *inflection) || (u == seg.ua() && zero(seg.qa())) ||
                        (u == seg.ub() && zero(seg.qb()));
      return infl ? curve.s_domain().hi : dir * (u - u_star) / k;
    };
    const Similarity to_user{seg.rotation() * std::polar(dir * seg.scale() * k, phi_star), p_star, sign_q * dir < 0};
    out.push_back(StandardPiece{curve, Parameter::s, s_of(r.lo), s_of(r.hi), to_user});
  }
  return out;
}

}  // namespace lac
