#pragma once
// Templates of planar_curve.hpp (positions, polylines, joints, bounding box with any quadrature).
// (planar_curve.hpp includes this file at its end; included alone, it includes planar_curve.hpp first.)
#include "lac/curves/planar/planar_curve.hpp"

#include <algorithm>
#include <complex>
#include <limits>
#include <span>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/curves/detail/polyline.hpp"

namespace lac {

template <class M>
  requires QuadratureMethod<M> || std::same_as<M, Igf>
PositionResult position_at(const PlanarCurve& curve, double s, const M& method) {
  curve.check_s(s, "s");
  const size_t k = curve.segment_at(s);
  PositionResult r = position_at(curve.segments()[k], curve.local_s(k, s), method);
  const std::complex<double> position = r.point.position;
  r.point = curve.frame_at(s);
  r.point.position = position;
  return r;
}

template <QuadratureMethod M>
std::vector<PositionResult> polyline(const PlanarCurve& curve, double s0, double s1, int n, const M& method) {
  method.validate();
  if (n < 2 || n > 1'000'000) throw_input_error("PlanarCurve polyline", "points", n, "[2, 1000000]");
  curve.check_s(s0, "s0");
  curve.check_s(s1, "s1");
  const size_t count = static_cast<size_t>(n);
  std::vector<PositionResult> out(count);
  std::vector<double> us(count);
  std::vector<size_t> index(count);
  const double lo = std::min(s0, s1), hi = std::max(s0, s1);
  for (size_t k = 0; k < count; ++k) {
    const double s = k + 1 == count ? s1 : std::clamp(s0 + (s1 - s0) * static_cast<double>(k) / (n - 1), lo, hi);
    index[k] = curve.segment_at(s);
    out[k].point = curve.frame_at(s);
    out[k].form = Form::s;
    us[k] = curve.segments()[index[k]].u_at(curve.local_s(index[k], s));
  }
  const long budget = detail::piecewise_polyline_budget(method, n);
  long spent = 0;
  for (size_t first = 0; first < count;) {
    size_t last = first;
    while (last < count && index[last] == index[first]) ++last;
    const LaSegment& seg = curve.segments()[index[first]];
    const std::complex<double> to_user = seg.scale() * seg.rotation();
    detail::AnchorState state;
    state.base = {seg.ua(), seg.start(), 0.0, Status::ok, {}};
    state.last_good = state.base;
    state.spent = spent;
    detail::anchored_samples(std::span(out).subspan(first, last - first), std::span<const double>(us).subspan(first, last - first),
                             state, budget, [&](double a, double b) {
                               IntegralResult<std::complex<double>> I = integrate_tangent(seg, a, b, method);
                               I.value *= to_user;
                               I.error_estimate *= seg.scale();
                               return I;
                             });
    spent = state.spent;
    first = last;
  }
  return out;
}

template <QuadratureMethod M>
std::vector<PositionResult> PlanarCurve::sample(int n, const M& method) const {
  check_s(0.0, "s");
  return polyline(*this, 0.0, length_, n, method);
}

template <QuadratureMethod M>
std::vector<Joint> PlanarCurve::joints(const M& method) const {
  std::vector<Joint> out;
  for (size_t k = 1; k < segments_.size(); ++k) {
    const LaSegment &prev = segments_[k - 1], &next = segments_[k];
    const PositionResult end = position_at(prev, prev.length(), method);
    Joint j;
    j.s = starts_[k];
    j.position_gap = usable(end.status) ? std::abs(next.start() - end.point.position) : std::numeric_limits<double>::infinity();
    j.angle_gap = wrap_angle(next.theta_start() - prev.theta_end());
    j.curvature_gap = next.kappa_start() - prev.kappa_end();
    j.error_estimate = end.error_estimate;
    j.status = end.status;
    j.message = end.message;
    out.push_back(j);
  }
  return out;
}

template <QuadratureMethod M>
BoundingBox PlanarCurve::bounding_box(const M& method) const {
  check_s(0.0, "s");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  BoundingBox box;
  box.lo = {kInf, kInf};
  box.hi = {-kInf, -kInf};
  const auto include = [&box](std::complex<double> z) {
    box.lo = {std::min(box.lo.real(), z.real()), std::min(box.lo.imag(), z.imag())};
    box.hi = {std::max(box.hi.real(), z.real()), std::max(box.hi.imag(), z.imag())};
  };
  for (size_t k = 0; k < segments_.size(); ++k) {
    const LaSegment& seg = segments_[k];
    const std::vector<double> us = extreme_candidates(k);
    std::complex<double> position = seg.start();
    double error = 0;
    include(position);
    // From the segment's start through the candidates in order: one pass over the segment.
    for (size_t i = 1; i < us.size(); ++i) {
      const IntegralResult<std::complex<double>> I = integrate_tangent(seg, us[i - 1], us[i], method);
      box.evaluations += I.evaluations;
      if (!usable(I.status)) {
        box.status = I.status;
        box.message = I.message;
        return box;
      }
      if (I.status != Status::ok && box.status == Status::ok) box.status = I.status, box.message = I.message;
      position += (seg.scale() * seg.rotation()) * I.value;
      error += seg.scale() * I.error_estimate;
      include(position);
      box.error_estimate = std::max(box.error_estimate, error);
    }
  }
  return box;
}

}  // namespace lac
