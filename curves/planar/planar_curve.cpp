#include "lac/curves/planar/planar_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_segment_angles.hpp"

namespace lac {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr size_t kMaxCandidates = 1'000'000;
}  // namespace

PlanarCurve::PlanarCurve(std::vector<LaSegment> segments) : segments_(std::move(segments)) {
  if (segments_.empty()) throw_input_error("PlanarCurve", "segments", "at least one segment is needed");
  starts_.reserve(segments_.size() + 1);
  turns_.reserve(segments_.size());
  turns_.push_back(0.0);
  for (size_t k = 0; k < segments_.size(); ++k) {
    starts_.push_back(starts_.back() + segments_[k].length());
    if (k == 0) continue;
    // θ continuous across the joint: the previous end's angle (with its turns) and this start's
    // differ by a multiple of 2π plus the G1 gap.
    const double before = segments_[k - 1].theta_end() + turns_[k - 1];
    turns_.push_back(kTwoPi * std::round((before - segments_[k].theta_start()) / kTwoPi));
  }
  length_ = starts_.back();
  if (!std::isfinite(length_)) throw_input_error("PlanarCurve", "segments", "the total length is not a finite double");
}

size_t PlanarCurve::segment_at(double s) const {
  check_s(s, "s");
  // The last start ≤ s among segments 0 … n−1.
  const auto it = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, s);
  return static_cast<size_t>(it - starts_.begin()) - 1;
}

double PlanarCurve::local_s(size_t k, double s) const {
  return std::clamp(s - starts_.at(k), 0.0, segments_.at(k).length());
}

CurvePoint PlanarCurve::frame_at(double s) const {
  const size_t k = segment_at(s);
  CurvePoint c = segments_[k].frame_at(local_s(k, s));
  c.s = s;
  c.theta += turns_[k];
  return c;
}

double PlanarCurve::theta_at(double s) const {
  const size_t k = segment_at(s);
  return segments_[k].theta_at(local_s(k, s)) + turns_[k];
}

double PlanarCurve::kappa_at(double s) const {
  const size_t k = segment_at(s);
  return segments_[k].kappa_at(local_s(k, s));
}

double PlanarCurve::dkappa_ds_at(double s) const {
  const size_t k = segment_at(s);
  return segments_[k].dkappa_ds_at(local_s(k, s));
}

PlanarCurve PlanarCurve::reversed(std::complex<double> end_point) const {
  check_s(0.0, "s");
  std::vector<LaSegment> out;
  out.reserve(segments_.size());
  for (size_t k = segments_.size(); k-- > 0;)
    out.push_back(segments_[k].reversed(k + 1 < segments_.size() ? segments_[k + 1].start() : end_point));
  return PlanarCurve(std::move(out));
}

void PlanarCurve::check_s(double s, const char* name) const {
  if (segments_.empty()) throw_input_error("PlanarCurve", name, "the curve has no segments");
  if (!(s >= 0 && s <= length_)) throw_input_error("PlanarCurve", name, s, interval_text(0, length_, true, true));
}

std::vector<double> PlanarCurve::extreme_candidates(size_t k) const {
  const LaSegment& seg = segments_.at(k);
  bool capped = false;
  std::vector<double> out = detail::angle_cuts(seg, 0.0, 0.5 * std::numbers::pi, kMaxCandidates, &capped);
  if (capped)
    throw_input_error("PlanarCurve::extreme_candidates", "segment", static_cast<double>(k),
                      "segments turning less than " + format_number(kMaxCandidates * 0.5 * std::numbers::pi) + " rad");
  return out;
}

std::vector<PositionResult> polyline(const PlanarCurve& curve, double s0, double s1, int n, const Igf& method) {
  method.validate();
  if (n < 2 || n > 1'000'000) throw_input_error("PlanarCurve polyline", "points", n, "[2, 1000000]");
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  std::vector<PositionResult> out(static_cast<size_t>(n));
  const double lo = std::min(s0, s1), hi = std::max(s0, s1);
  long evaluations = 0;
  for (int k = 0; k < n; ++k) {
    const double s = k + 1 == n ? s1 : std::clamp(s0 + (s1 - s0) * static_cast<double>(k) / (n - 1), lo, hi);
    PositionResult& r = out[static_cast<size_t>(k)];
    r = position_at(curve, s, method);
    evaluations += r.evaluations;
    r.evaluations = evaluations;
  }
  return out;
}

}  // namespace lac
