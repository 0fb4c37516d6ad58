#pragma once
// Shared by the polylines of every curve model: evaluation budgets (docs/robustness.md, budgets: the
// pieces of one polyline share one budget, so n pieces cannot multiply a method's per-call budget)
// and the anchored driver that integrates each point from a point known to be right.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <span>
#include <string>

#include "lac/common/accuracy.hpp"
#include "lac/common/error.hpp"
#include "lac/curves/curve.hpp"
#include "lac/integrators/quadrature.hpp"

namespace lac::detail {

/// Evaluation budget of one position call made of several quadrature calls: the method's own
/// per-call budget, so that many pieces cannot multiply it. Rk4 needs none for a standard-form
/// curve: one Rk4Sweep spans all pieces there. A method without a budget of its own
/// (GaussLegendre: fixed cost per call; GkTanhSinh: bounded depth and levels) gets Gauss–Kronrod's
/// default one.
template <class M>
long evaluation_budget(const M&) {
  return 21 * (2 * GaussKronrod{}.max_intervals + 1);
}
inline long evaluation_budget(const Rk45& m) { return 6 * m.max_steps + 1; }
inline long evaluation_budget(const GaussKronrod& m) { return 21 * (2 * m.max_intervals + 1); }

/// Evaluations a polyline of n points may spend in all: one position call's budget plus an
/// allowance of 64 Kronrod panels per point (dense polylines still work), so that its n pieces
/// cannot multiply the per-call budget. A closed form counts series terms: 10 max_pieces + 1000 n.
template <class M>
long polyline_budget(const M& m, long n) {
  if constexpr (requires { m.max_pieces; }) return 10 * m.max_pieces + 1000 * n;
  return evaluation_budget(m) + 64 * 21 * n;
}

/// polyline_budget for a polyline whose pieces are separate quadrature calls of any method: Rk4
/// gets the step budget of one sweep (2 max_steps + 1 evaluations) in all.
template <class M>
long piecewise_polyline_budget(const M& m, long n) {
  if constexpr (std::same_as<M, Rk4>) return 2 * m.max_steps + 1;
  else return detail::polyline_budget(m, n);
}

/// Adds one quadrature call's result (times `sign`) to a running total of several: value, error
/// estimate, evaluations, and the first status that is not ok.
template <class V>
void add_part(IntegralResult<V>& total, const IntegralResult<V>& part, double sign = 1.0) {
  total.value += sign * part.value;
  // The part's estimate and the rounding of this addition (ε of the partial sum).
  total.error_estimate += part.error_estimate + std::numeric_limits<double>::epsilon() * std::abs(total.value);
  total.evaluations += part.evaluations;
  if (part.status != Status::ok && total.status == Status::ok) {
    total.status = part.status;
    total.message = part.message;
  }
}

inline void merge_status(PositionResult& r, Status s, const std::string& message) {
  if (s != Status::ok && r.status == Status::ok) {
    r.status = s;
    r.message = message;
  }
}

/// Sets r's position, error estimate and evaluations from one quadrature call from the reference
/// point, and merges its status.
inline void take_integral(PositionResult& r, const IntegralResult<std::complex<double>>& piece) {
  r.point.position = piece.value;
  r.error_estimate = piece.error_estimate;
  r.evaluations = piece.evaluations;
  merge_status(r, piece.status, piece.message);
}

/// The size scale a position's error is relative to: the arc length from the point it was
/// integrated from, which for LaCurve and QuadraticLaCurve is the reference point s = 0 (a
/// polyline's points are running integrals from there, and their estimates accumulate from there).
inline double position_scale(const PositionResult& r) {
  return std::max(std::abs(r.point.s), std::numeric_limits<double>::min());
}
/// error_estimate / position_scale: the relative error a usable point's estimate bounds.
inline double relative_error(const PositionResult& r) { return r.error_estimate / position_scale(r); }

/// The accept bound (common/accuracy.hpp) on a position: a usable point whose error estimate
/// exceeds accept × `scale` (position_scale by default; or is NaN) becomes Status::inaccurate.
inline void grade_position(PositionResult& r, double accept, double scale = 0) {
  if (!(scale > 0)) scale = position_scale(r);
  if (!usable(r.status) || r.error_estimate <= accept * scale) return;
  r.status = Status::inaccurate;
  r.message = "error estimate " + format_number(r.error_estimate) + " exceeds accept " + format_number(accept) +
              " x arc length " + format_number(scale) + " integrated from the reference point" +
              (r.message.empty() ? "" : " (" + r.message + ")");
}
/// Arc length a polyline point's estimate accumulates over: the running integral goes from the
/// reference point s = 0 to the first point, then through every point before it.
inline double path_scale(std::span<const PositionResult> out, size_t k) {
  return std::max(std::abs(out[0].point.s) + std::abs(out[k].point.s - out[0].point.s),
                  std::numeric_limits<double>::min());
}
/// grade_position of every polyline point against its path_scale.
inline void grade_positions(std::span<PositionResult> out, double accept) {
  for (size_t k = 0; k < out.size(); ++k) grade_position(out[k], accept, path_scale(out, k));
}

/// ok < fell_back < tolerance_not_met < the statuses that are not usable.
inline int severity(Status s) {
  return s == Status::ok ? 0 : s == Status::fell_back ? 1 : s == Status::tolerance_not_met ? 2 : 3;
}
/// Takes s (and its message) when it is worse than r's status: the first of equally bad ones stays.
inline void take_worse(PositionResult& r, Status s, const std::string& message) {
  if (severity(s) > severity(r.status)) {
    r.status = s;
    r.message = message;
  }
}

/// A point whose position other points may be integrated from: the reference point or segment
/// start (status ok), or an earlier polyline point with status ok or fell_back.
struct Anchor {
  double t = 0;  ///< integration variable
  std::complex<double> position{};
  double error_estimate = 0;
  Status status = Status::ok;
  std::string message;
};

inline bool known_right(Status s) { return s == Status::ok || s == Status::fell_back; }

/// Where anchored_samples stands along one run of points.
struct AnchorState {
  Anchor base;        ///< always known (reference point, segment start)
  Anchor last_good;   ///< the latest known-right point (base at first)
  bool previous_good = true;
  long spent = 0;     ///< evaluations of the whole polyline so far (shared budget)
};

/// Positions of out[k] at integration variable ts[k], in order. Point k is integrated by
/// piece(a, b) -> IntegralResult<std::complex<double>> (the displacement from a to b) from the
/// previous point when that one is known right (then the numbers are those of a running sum),
/// otherwise from the nearer of the base and the latest known-right point. A point whose piece is
/// not usable, or that finds the shared budget spent, holds its anchor's position with an
/// infinite error estimate (see PositionResult). Status: the worst of the anchor's (fell_back
/// carries on), the piece's and the one the caller put in out[k] beforehand (e.g. of the frame).
/// `evaluations`: cumulative over the polyline.
template <class Piece>
void anchored_samples(std::span<PositionResult> out, std::span<const double> ts, AnchorState& st, long budget,
                      Piece&& piece) {
  for (size_t k = 0; k < out.size(); ++k) {
    PositionResult& r = out[k];
    const double t = ts[k];
    const Anchor& from =
        st.previous_good || std::abs(t - st.last_good.t) <= std::abs(t - st.base.t) ? st.last_good : st.base;
    const Status own = r.status;
    const std::string own_message = std::move(r.message);
    r.status = from.status;
    r.message = from.message;
    bool computed = false;
    if (st.spent >= budget) {
      take_worse(r, Status::max_iterations,
                 "evaluation budget " + std::to_string(budget) + " of one polyline call exhausted after " +
                     std::to_string(st.spent) + " evaluations; raise the method's budget");
    } else {
      const IntegralResult<std::complex<double>> p = piece(from.t, t);
      st.spent += p.evaluations;
      take_worse(r, p.status, p.message);
      if (usable(p.status)) {
        r.point.position = from.position + p.value;
        r.error_estimate = from.error_estimate + p.error_estimate;
        computed = std::isfinite(r.point.position.real()) && std::isfinite(r.point.position.imag()) &&
                   std::isfinite(r.error_estimate);
        if (!computed) take_worse(r, Status::numerical_failure, "non-finite position or error estimate");
      }
    }
    take_worse(r, own, own_message);
    if (!computed || !usable(r.status)) {
      r.point.position = from.position;
      r.error_estimate = std::numeric_limits<double>::infinity();
    }
    r.evaluations = st.spent;
    st.previous_good = computed && known_right(r.status);
    if (st.previous_good) st.last_good = {t, r.point.position, r.error_estimate, r.status, r.message};
  }
}

}  // namespace lac::detail
