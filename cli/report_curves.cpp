// The curve parts of a report: segments and points of planar and space curves (cli/report.hpp).
#include <cmath>
#include <variant>

#include "cli/command.hpp"
#include "cli/report.hpp"

namespace lac::cli {

Json planar_segment(const LaSegment& seg) {
  const double alpha = seg.law().alpha, length = seg.length();
  const double k0 = seg.kappa_start(), k1 = seg.kappa_end();
  // q in user units is linear in s; its slope is αΛ (−Λ for α = 0) up to the direction of ρ.
  const double q0 = seg.law().q_of_kappa(k0), q1 = seg.law().q_of_kappa(k1);
  const double lambda = std::abs(q1 - q0) / (length * (alpha == 0 ? 1.0 : std::abs(alpha)));
  Json j;
  j["kind"] = "la";
  j["alpha"] = alpha;
  j["q0"] = number(q0);
  j["q1"] = number(q1);
  j["lambda"] = number(lambda);
  j["length"] = number(length);
  j["start"] = xy(seg.start());
  j["theta"] = number(seg.theta_start());
  j["kappa"] = number(k0);
  j["theta_end"] = number(seg.theta_end());
  j["kappa_end"] = number(k1);
  return j;
}

void set_extent(Json& r, double length, double kappa0, double kappa1) {
  r["length"] = number(length);
  r["kappa0"] = number(kappa0);
  r["kappa1"] = number(kappa1);
}

void add_planar_curve(Json& r, const PlanarCurve& curve) {
  if (curve.segments().empty()) return;
  set_extent(r, curve.length(), curve.kappa_at(0), curve.kappa_at(curve.length()));
  Json segs = Json::array();
  for (const LaSegment& seg : curve.segments()) segs.push_back(planar_segment(seg));
  r["segments"] = std::move(segs);
}

Json planar_point(const PositionResult& p) {
  record_status(p.status);
  const bool ok = usable(p.status);
  const CurvePoint& q = p.point;
  return Json{{"s", number(q.s)},
              {"x", ok ? number(q.position.real()) : Json(nullptr)},
              {"y", ok ? number(q.position.imag()) : Json(nullptr)},
              {"theta", number(q.theta)},
              {"kappa", number(q.kappa)}};
}

void add_planar_points(Json& r, const PlanarCurve& curve, int n, const AnyQuadrature& integrator) {
  if (n == 0 || curve.segments().empty()) return;
  // Every registered method samples by itself (igf: its closed form per segment, planar_curve.hpp).
  const std::vector<PositionResult> pts =
      std::visit([&](const auto& m) { return polyline(curve, 0.0, curve.length(), n, m); }, integrator);
  Json arr = Json::array();
  for (const PositionResult& p : pts) arr.push_back(planar_point(p));
  r["points"] = std::move(arr);
}

void add_space_curve(Json& r, const SpaceCurve& curve) {
  if (curve.pieces().empty()) return;
  set_extent(r, curve.length(), curve.kappa_at(0), curve.kappa_at(curve.length()));
  Json segs = Json::array();
  for (size_t k = 0; k < curve.pieces().size(); ++k) {
    const LaSpaceCurve& law = curve.pieces()[k].law;
    const double s0 = curve.piece_start(k), s1 = curve.piece_start(k + 1);
    const SpacePoint start = curve.frame_at(s0);  // the piece's own start: no integration
    Json j;
    j["kind"] = "la-space";
    j["alpha"] = law.alpha();
    j["beta"] = law.beta();
    j["lambda"] = number(law.lambda());
    j["omega"] = number(law.omega());
    j["nu"] = number(law.nu());
    j["type"] = static_cast<int>(law.type());
    j["length"] = number(s1 - s0);
    j["start"] = xyz(start.p);
    j["kappa"] = number(start.kappa);
    j["tau"] = number(start.tau);
    segs.push_back(std::move(j));
  }
  r["segments"] = std::move(segs);
}

void add_space_points(Json& r, const SpaceCurve& curve, int n) {
  if (n == 0 || curve.pieces().empty()) return;
  Json arr = Json::array();
  for (const SpacePoint& p : curve.sample(n)) {
    record_status(p.status);
    const bool ok = p.status == Status::ok;
    arr.push_back(Json{{"s", number(p.s)},
                       {"x", ok ? number(p.p.x()) : Json(nullptr)},
                       {"y", ok ? number(p.p.y()) : Json(nullptr)},
                       {"z", ok ? number(p.p.z()) : Json(nullptr)},
                       {"kappa", number(p.kappa)},
                       {"tau", number(p.tau)}});
  }
  r["points"] = std::move(arr);
}

}  // namespace lac::cli
