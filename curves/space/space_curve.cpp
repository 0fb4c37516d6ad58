#include "lac/curves/space/space_curve.hpp"

#include <algorithm>
#include <cmath>

#include "lac/common/error.hpp"

namespace lac {
namespace {

constexpr const char* kWho = "SpaceCurve";
constexpr int kMaxPoints = 1'000'000;
constexpr long kStepsPerPoint = 64;  // sampling budget: ODE max_steps + this per point

void check_piece(const SpacePiece& p, size_t k) {
  const std::string which = "pieces[" + std::to_string(k) + "]";
  const Interval r = p.law.s_range();
  if (!r.contains(p.s_begin))
    throw_input_error(kWho, which + ".s_begin", p.s_begin, interval_text(r.lo, r.hi) + " (the laws' s range)");
  if (!(p.s_end >= p.s_begin) || !(p.s_end < r.hi))
    throw_input_error(kWho, which + ".s_end", p.s_end, interval_text(p.s_begin, r.hi, true));
  if (!p.start.p.allFinite() || !p.start.t.allFinite() || !p.start.n.allFinite() || !p.start.b.allFinite())
    throw_input_error(kWho, which + ".start", "must have finite coordinates");
}

void check_placement(const SpacePlacement& pl) {
  if (!pl.origin.allFinite()) throw_input_error(kWho, "placement.origin", "must have finite coordinates");
  if (!(pl.scale > 0) || !std::isfinite(pl.scale)) throw_input_error(kWho, "placement.scale", pl.scale, "(0, inf)");
  if (pl.torsion_sign != 1 && pl.torsion_sign != -1)
    throw_input_error(kWho, "placement.torsion_sign", pl.torsion_sign, "{-1, 1}");
  const Eigen::Matrix3d q = pl.matrix / pl.scale;
  constexpr double kOrthogonal = 1e-9;
  if (!q.allFinite() || (q.transpose() * q - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > kOrthogonal ||
      !(q.determinant() * pl.torsion_sign > 0))
    throw_input_error(kWho, "placement.matrix", "must be scale · Q with Q orthogonal and det Q of the sign torsion_sign");
}

}  // namespace

SpaceCurve::SpaceCurve(std::vector<SpacePiece> pieces, const SpacePlacement& placement, const OdeOptions& ode)
    : pieces_(std::move(pieces)), placement_(placement), ode_(ode) {
  if (pieces_.empty()) throw_input_error(kWho, "pieces", "at least one piece is needed");
  ode_.validate();
  check_placement(placement_);
  double total = 0;  // standard-form length so far
  for (size_t k = 0; k < pieces_.size(); ++k) {
    check_piece(pieces_[k], k);
    total += pieces_[k].s_end - pieces_[k].s_begin;
    starts_.push_back(placement_.scale * total);
  }
  length_ = starts_.back();
  if (!std::isfinite(length_)) throw_input_error(kWho, "pieces", "the total length is not a finite double");
}

void SpaceCurve::check_s(double s, const char* name) const {
  if (pieces_.empty()) throw_input_error(kWho, name, "the curve has no pieces");
  if (!(s >= 0 && s <= length_)) throw_input_error(kWho, name, s, interval_text(0, length_, true, true));
}

size_t SpaceCurve::piece_at(double s) const {
  check_s(s, "s");
  const auto it = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, s);
  return static_cast<size_t>(it - starts_.begin()) - 1;
}

double SpaceCurve::standard_s(size_t k, double s) const {
  const SpacePiece& p = pieces_.at(k);
  // The piece's ends map exactly (the scaled difference may miss s_end by an ulp).
  if (s >= starts_.at(k + 1)) return p.s_end;
  return p.s_begin + std::clamp((s - starts_[k]) / placement_.scale, 0.0, p.s_end - p.s_begin);
}

SpacePoint SpaceCurve::closed_forms(size_t k, double s) const {
  const SpacePiece& p = pieces_[k];
  const double u = standard_s(k, s), scale = placement_.scale;
  SpacePoint pt;
  pt.s = s;
  pt.piece = k;
  pt.kappa = p.law.kappa(u) / scale;
  pt.tau = placement_.torsion_sign * p.law.tau(u) / scale;
  pt.dkappa_ds = p.law.dkappa_ds(u) / scale / scale;
  return pt;
}

SpacePoint SpaceCurve::to_user(const SpacePoint& closed, const Frame3& f) const {
  SpacePoint pt = closed;
  const Eigen::Matrix3d& m = placement_.matrix;
  pt.p = placement_.origin + m * f.p;
  pt.t = (m * f.t).normalized();
  pt.n = (m * f.n).normalized();
  pt.b = pt.t.cross(pt.n);
  return pt;
}

double SpaceCurve::kappa_at(double s) const { return closed_forms(piece_at(s), s).kappa; }
double SpaceCurve::tau_at(double s) const { return closed_forms(piece_at(s), s).tau; }
double SpaceCurve::dkappa_ds_at(double s) const { return closed_forms(piece_at(s), s).dkappa_ds; }

SpacePoint SpaceCurve::frame_at(double s) const {
  const size_t k = piece_at(s);
  const SpacePiece& p = pieces_[k];
  SpacePoint pt = closed_forms(k, s);
  const double u = standard_s(k, s);
  if (!(u > p.s_begin)) return to_user(pt, p.start);
  const FrenetResult r = integrate_frenet(p.law, p.start, p.s_begin, u, ode_);
  pt.evaluations = r.evaluations;
  pt.status = r.status;
  pt.message = r.message;
  return to_user(pt, r.status == Status::ok ? r.frame : p.start);
}

std::vector<SpacePoint> SpaceCurve::sample(int n) const {
  check_s(0.0, "s");
  return sample(0.0, length_, n);
}

std::vector<SpacePoint> SpaceCurve::sample(double s0, double s1, int n) const {
  if (n < 2 || n > kMaxPoints) throw_input_error(kWho, "points", n, "[2, 1000000]");
  check_s(s0, "s0");
  check_s(s1, "s1");
  if (!(s1 >= s0)) throw_input_error(kWho, "s1", s1, interval_text(s0, length_, true, true));
  const long budget = ode_.max_steps + kStepsPerPoint * n;
  long spent = 0, evaluations = 0;
  // The latest sample whose status is ok: later samples of its piece start there.
  struct Good {
    bool valid = false;
    size_t piece = 0;
    double u = 0;
    Frame3 frame;
  } good;
  std::vector<SpacePoint> out;
  out.reserve(static_cast<size_t>(n));
  size_t piece = 0;
  for (int i = 0; i < n; ++i) {
    const double s = i + 1 == n ? s1 : std::clamp(s0 + (s1 - s0) * i / (n - 1), s0, s1);
    if (i == 0) {
      piece = piece_at(s);
    } else {  // the piece reaching s from below: the earlier one at a joint
      const auto it = std::lower_bound(starts_.begin() + 1, starts_.end() - 1, s);
      piece = std::max(piece, static_cast<size_t>(it - starts_.begin()) - 1);
    }
    const SpacePiece& p = pieces_[piece];
    SpacePoint pt = closed_forms(piece, s);
    const bool from_good = good.valid && good.piece == piece;
    const double u0 = from_good ? good.u : p.s_begin, u = standard_s(piece, s);
    const Frame3& f0 = from_good ? good.frame : p.start;
    Frame3 frame = f0;
    if (u > u0) {
      if (spent >= budget) {
        pt.status = Status::max_iterations;
        pt.message = "SpaceCurve::sample: step budget " + std::to_string(budget) + " of one sampling spent";
      } else {
        OdeOptions o = ode_;
        o.max_steps = std::min(o.max_steps, budget - spent);
        const FrenetResult r = integrate_frenet(p.law, f0, u0, u, o);
        spent += r.status == Status::max_iterations ? o.max_steps : r.steps + 1;
        evaluations += r.evaluations;
        pt.status = r.status;
        pt.message = r.message;
        if (r.status == Status::ok) frame = r.frame;
      }
    }
    pt.evaluations = evaluations;
    out.push_back(to_user(pt, frame));
    if (pt.status == Status::ok) good = {true, piece, u, frame};
  }
  return out;
}

}  // namespace lac
