// LA chains through N points (constructions/chain.hpp).
#include "lac/constructions/chain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "lac/common/error.hpp"

namespace lac {

namespace {

constexpr const char* kFunction = "solve_chain";

/// Lower is worse: the status a chain reports is its worst pair's.
int rank(Status s) {
  switch (s) {
    case Status::ok: return 3;
    case Status::fell_back: return 2;
    case Status::tolerance_not_met: return 1;
    default: return 0;
  }
}

/// acc = max(acc, v) where v exists.
void take_max(std::optional<double>& acc, const std::optional<double>& v) {
  if (v) acc = std::max(acc.value_or(*v), *v);
}

/// Frame at b from the circle through a, b, c (traversed a → b → c).
PointFrame middle_frame(std::complex<double> a, std::complex<double> b, std::complex<double> c) {
  const std::complex<double> ab = b - a, bc = c - b, ac = c - a;
  const double theta = std::arg(ab) + std::arg(bc / ac);
  const double kappa = 2 * (ab.real() * bc.imag() - ab.imag() * bc.real()) / (std::abs(ab) * std::abs(bc) * std::abs(ac));
  return {theta, kappa};
}

/// Frame at a, the first of three points on one circle (traversed a → b → c).
PointFrame end_frame(std::complex<double> a, std::complex<double> b, std::complex<double> c) {
  const std::complex<double> ab = b - a, bc = c - b, ac = c - a;
  const double theta = std::arg(ab) - std::arg(bc / ac);
  const double kappa = 2 * (ab.real() * bc.imag() - ab.imag() * bc.real()) / (std::abs(ab) * std::abs(bc) * std::abs(ac));
  return {theta, kappa};
}

void validate(const ChainProblem& p) {
  const size_t n = p.points.size();
  const size_t need = p.closed ? 3 : 2;
  if (n < need)
    throw_input_error(kFunction, "points", std::to_string(n) + " points given, a" + std::string(p.closed ? " closed" : "n open") +
                                               " chain needs at least " + std::to_string(need));
  for (size_t k = 0; k < n; ++k) {
    require_finite(kFunction, "points", p.points[k].real());
    require_finite(kFunction, "points", p.points[k].imag());
  }
  const size_t pairs = p.closed ? n : n - 1;
  for (size_t k = 0; k < pairs; ++k) {
    const auto d = std::abs(p.points[(k + 1) % n] - p.points[k]);
    if (!(d > 0) || !std::isfinite(d))
      throw_input_error(kFunction, "points", "points " + std::to_string(k) + " and " + std::to_string((k + 1) % n) +
                                                 " coincide or are too far apart for double precision");
  }
  for (const auto* list : {&p.thetas, &p.kappas}) {
    const char* name = list == &p.thetas ? "thetas" : "kappas";
    if (!list->empty() && list->size() != n)
      throw_input_error(kFunction, name, std::to_string(list->size()) + " values for " + std::to_string(n) + " points (one per point, or none to estimate them)");
    for (double v : *list) require_finite(kFunction, name, v);
  }
  if (p.continuity == ChainContinuity::g1 && !p.kappas.empty())
    throw_input_error(kFunction, "kappas", "a g1 chain takes no curvatures (continuity g2 does)");
  require_finite(kFunction, "alpha", p.alpha);
}

}  // namespace

std::string_view to_string(ChainContinuity c) { return c == ChainContinuity::g1 ? "g1" : "g2"; }

ChainContinuity parse_chain_continuity(std::string_view name) {
  if (name == "g1") return ChainContinuity::g1;
  if (name == "g2") return ChainContinuity::g2;
  std::string m(1, '\'');  // built step by step: GCC 12 warns (-Wrestrict) on "'" + std::string
  m.append(name).append("' is not one of g1 | g2");
  throw_input_error(kFunction, "continuity", m);
}

std::vector<PointFrame> estimate_frames(std::span<const std::complex<double>> pts, bool closed) {
  const size_t n = pts.size();
  std::vector<PointFrame> out(n);
  if (n < 2) return out;
  if (n == 2 && !closed) {
    const double chord = std::arg(pts[1] - pts[0]);
    return {{chord, 0.0}, {chord, 0.0}};
  }
  for (size_t k = 0; k < n; ++k) {
    if (closed || (k > 0 && k + 1 < n)) {
      out[k] = middle_frame(pts[(k + n - 1) % n], pts[k], pts[(k + 1) % n]);
    } else if (k == 0) {
      out[k] = end_frame(pts[0], pts[1], pts[2]);
    } else {  // the last point: the first of the reversed triple, angle turned back
      const PointFrame r = end_frame(pts[n - 1], pts[n - 2], pts[n - 3]);
      out[k] = {r.theta + std::numbers::pi, -r.kappa};
    }
  }
  return out;
}

ChainResult solve_chain(const ChainProblem& p, const ChainOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  validate(p);
  ChainResult r;
  const size_t n = p.points.size();
  const size_t pairs = p.closed ? n : n - 1;
  const std::vector<PointFrame> est = estimate_frames(p.points, p.closed);
  r.info.estimated_thetas = p.thetas.empty();
  r.info.estimated_kappas = p.kappas.empty();
  for (size_t k = 0; k < n; ++k) {
    r.info.thetas.push_back(p.thetas.empty() ? est[k].theta : p.thetas[k]);
    r.info.kappas.push_back(p.kappas.empty() ? est[k].kappa : p.kappas[k]);
  }
  std::vector<LaSegment> segments;
  Summary& sum = r.summary;
  sum.accept = p.continuity == ChainContinuity::g1 ? o.g1.accept : o.g2.accept;
  Status worst = Status::ok;
  std::string worst_message;
  for (size_t k = 0; k < pairs; ++k) {
    const size_t j = (k + 1) % n;
    Summary pair;
    std::vector<LaSegment> part;
    if (p.continuity == ChainContinuity::g1) {
      const G1HermiteResult g = solve_g1_hermite({p.points[k], r.info.thetas[k], p.points[j], r.info.thetas[j], p.alpha}, o.g1);
      pair = g.summary;
      r.info.windings.push_back(g.info.winding);
      r.info.turnings.push_back(g.info.turning);
      if (g.usable()) part = g.curve.segments();
    } else {
      const G2Result g = solve_g2({{p.points[k], r.info.thetas[k], r.info.kappas[k]}, {p.points[j], r.info.thetas[j], r.info.kappas[j]}, p.alpha}, o.g2);
      pair = g.summary;
      r.info.windings.push_back(g.info.winding);
      r.info.turnings.push_back(g.info.turning);
      if (g.usable()) part = g.curve.segments();
    }
    sum.iterations += pair.iterations;
    sum.evaluations += pair.evaluations;
    sum.constructions += pair.constructions;
    sum.solver = pair.solver;
    sum.integrator = pair.integrator;
    take_max(sum.residuals.position, pair.residuals.position);
    take_max(sum.residuals.angle, pair.residuals.angle);
    take_max(sum.residuals.curvature, pair.residuals.curvature);
    take_max(sum.error_estimate, pair.error_estimate);
    take_max(sum.error, pair.error);  // each relative to its pair's chord
    if (rank(pair.status) < rank(worst)) {
      worst = pair.status;
      worst_message = "pair " + std::to_string(k) + " (points " + std::to_string(k) + " → " + std::to_string(j) + "): " +
                      std::string(to_string(pair.status)) + (pair.message.empty() ? "" : ": " + pair.message);
    }
    r.info.pairs.push_back(std::move(pair));
    if (!usable(r.info.pairs.back().status)) {
      r.info.failed_pair = static_cast<int>(k);
      break;  // the chain has no curve; later pairs would not change that
    }
    segments.insert(segments.end(), part.begin(), part.end());
  }
  if (usable(worst)) r.curve = PlanarCurve(std::move(segments));
  r.conclude(worst, worst_message);
  sum.seconds = seconds_since(start);
  return r;
}

}  // namespace lac
