// Uses the installed package the way README.md's "Library use" shows: a standard-form LA curve, a
// placed segment and a PlanarCurve, the four planar constructions and a space segment, each with an
// integrator and a solver chosen by name. Exit status 0 when every result is usable and meets the
// data it was built from.
#include <cmath>
#include <complex>
#include <cstdio>
#include <lac/constructions/chain.hpp>
#include <lac/constructions/g1_hermite.hpp>
#include <lac/constructions/g2_hermite.hpp>
#include <lac/constructions/s_curve.hpp>
#include <lac/constructions/space_segment.hpp>
#include <lac/constructions/triangle_g1.hpp>
#include <lac/curves/planar/la_position.hpp>
#include <lac/curves/planar/planar_curve.hpp>
#include <lac/version.hpp>
#include <string>

namespace {
int failures = 0;
void check(bool ok, const char* what, const std::string& detail = "") {
  std::printf("%s %s %s\n", ok ? "ok  " : "FAIL", what, detail.c_str());
  if (!ok) ++failures;
}
template <class R>
std::string summary_of(const R& r) {
  return std::string(lac::to_string(r.summary.status)) + ", " + std::to_string(r.summary.iterations) +
         " iterations, length " + std::to_string(r.curve.length());
}
}  // namespace

int main() {
  std::printf("lac %s\n", lac::version);

  // A standard-form LA curve (α = −1: a clothoid, κ = 1 − s), its position by any quadrature.
  const lac::LaCurve clothoid(/*alpha=*/-1.0, /*lambda=*/1.0);
  const auto p = lac::position_at(clothoid, lac::Parameter::s, 0.5, lac::make_quadrature("gauss-kronrod"));
  check(std::abs(clothoid.kappa_at_s(0.5) - 0.5) < 1e-15 && p.status == lac::Status::ok &&
            std::abs(p.point.position) > 0.4,
        "LaCurve position_at");

  // Triangle G1 (monotonic rhythm) with rk45 and the secant root finder.
  const lac::ControlTriangle t{{0, 0}, {1, 0}, {2, 1}};
  const auto g1 = lac::solve_g1(t, /*alpha=*/2.0,
                                {.integrator = lac::make_quadrature("rk45"), .solver = lac::parse_root_method("secant")});
  check(g1.usable() && std::abs(lac::position_at(g1.curve, g1.curve.length()).point.position - t.a2) < 1e-9,
        "solve_g1", summary_of(g1));

  // Compound rhythm: α0 = −0.5 then α1 = 1.5, 40 % of the turning in segment 0.
  const auto compound = lac::solve_compound(t, -0.5, 1.5, 0.4);
  check(compound.usable() && compound.curve.segments().size() == 2, "solve_compound", summary_of(compound));

  // G1 Hermite: points and tangent angles, one LA segment of slope α.
  const auto h1 = lac::solve_g1_hermite({{0, 0}, 0.3, {1, 0}, -0.4, -2.0});
  check(h1.usable() && h1.curve.segments().size() == 1, "solve_g1_hermite", summary_of(h1));

  // A closed G1 chain through six points, tangents estimated.
  const auto chain = lac::solve_chain(
      {.points = {{0, 0}, {2, -0.5}, {4, 0.3}, {5, 2}, {4, 4}, {0, 3}}, .alpha = -1.0, .closed = true});
  check(chain.usable() && chain.curve.segments().size() == 6 && chain.info.thetas.size() == 6, "solve_chain",
        summary_of(chain));

  // S-curve through an inflection (α < 0) from four control points.
  const auto s = lac::solve_s_curve({{{0, 0}, {1, 0}, {2, 1}, {3, 1}}}, -1.0,
                                    {.solver = lac::RootMethod::bisection, .integrator = lac::make_quadrature("gk-tanh-sinh")});
  check(s.usable() && s.info.inflection_s.has_value(), "solve_s_curve", summary_of(s));

  // G2 Hermite: two points, tangent angles and curvatures; Ceres and rk45.
  lac::G2Options o;
  o.solver = lac::parse_g2_solver("ceres");
  o.integrator = lac::make_quadrature("rk45");
  const auto g2 = lac::solve_g2({{{0, 0}, 0.6, 0.5}, {{4, 0}, -0.6, -0.3}, -0.5}, o);
  check(g2.usable() && std::abs(g2.curve.kappa_at(0) - 0.5) < 1e-9 &&
            std::abs(g2.curve.kappa_at(g2.curve.length()) + 0.3) < 1e-9,
        "solve_g2", summary_of(g2));

  // Every planar construction returns a PlanarCurve: sample it, bound it.
  const auto pts = g2.curve.sample(50);
  const auto box = g2.curve.bounding_box();
  check(pts.size() == 50 && lac::usable(pts.back().status) && box.hi.real() >= 4 - 1e-9, "PlanarCurve sample");

  // Space G1 segment (monotonic rhythm) with rk45 and the simplex.
  lac::SpaceSegmentOptions so;
  so.integrator.method = lac::parse_ode_method("rk45");
  so.solver = lac::parse_nonlinear_method("simplex");
  const auto sp = lac::solve_g1_space_segment({.p0 = {0, 0, 0}, .v0 = {1, 0, 0}, .p1 = {1, 1, 0.3}, .v1 = {0, 1, 0.2}},
                                              {.alpha = 0.0, .beta = 0.0, .omega = 0.1}, so);
  check(sp.usable() && (sp.curve.frame_at(sp.curve.length()).p - lac::Vec3(1, 1, 0.3)).norm() < 1e-8,
        "solve_g1_space_segment", summary_of(sp));

  return failures == 0 ? 0 : 1;
}
