#include "lac/geometry/detail/space_spans.hpp"

#include <algorithm>
#include <cmath>

namespace lac::detail {

namespace {
constexpr double kMaxTurn = 0.5;  // initial spans turn at most this much (rad)
constexpr int kMinSpans = 16;
}  // namespace

double SpaceSpan::turn() const { return std::min(kappa_max * half(), 2.0); }

SpacePoint SpaceTracer::at(size_t piece, double s) {
  ++evaluations;
  const double lo = c_.piece_start(piece), hi = c_.piece_start(piece + 1);
  SpacePoint p = c_.frame_at(std::clamp(s, lo, piece + 1 < c_.pieces().size() ? std::nextafter(hi, lo) : hi));
  if (!usable(p.status) && usable(status)) status = p.status, message = p.message;
  return p;
}

SpaceSpan SpaceTracer::make(size_t piece, double s0, double s1) {
  SpaceSpan sp{piece, s0, s1};
  const SpacePoint c = at(piece, sp.sc());
  sp.pc = c.p;
  sp.tc = c.t;
  // κ decreases along a piece: its largest value on [s0, s1] is at s0 (closed form).
  const double lo = c_.piece_start(piece), hi = c_.piece_start(piece + 1);
  sp.kappa_max = std::max(c_.kappa_at(std::clamp(s0, lo, hi)), c_.kappa_at(std::clamp(s1, lo, std::nextafter(hi, lo))));
  ++spans;
  return sp;
}

std::vector<SpaceSpan> cover(SpaceTracer& tr, const GeometryOptions& options) {
  const SpaceCurve& curve = tr.curve();
  const double L = curve.length();
  double total = 0;
  std::vector<long> counts;
  for (size_t k = 0; k < curve.pieces().size(); ++k) {
    const double a = curve.piece_start(k), b = curve.piece_start(k + 1);
    const double n = std::max({std::ceil(curve.kappa_at(a) * (b - a) / kMaxTurn), std::ceil((b - a) / L * kMinSpans), 1.0});
    total += n;
    if (!(total <= static_cast<double>(options.max_spans))) {
      tr.status = Status::max_iterations;
      tr.message = "covering the curve needs more than max_spans = " + std::to_string(options.max_spans) + " spans";
      return {};
    }
    counts.push_back(static_cast<long>(n));
  }
  std::vector<SpaceSpan> store;
  for (size_t k = 0; k < curve.pieces().size(); ++k) {
    const double a = curve.piece_start(k), b = curve.piece_start(k + 1);
    for (long i = 0; i < counts[k]; ++i) {
      const double n = static_cast<double>(counts[k]);
      store.push_back(tr.make(k, i == 0 ? a : a + (b - a) * i / n, i + 1 == counts[k] ? b : a + (b - a) * (i + 1) / n));
      if (tr.failed()) return {};
    }
  }
  return store;
}

}  // namespace lac::detail
