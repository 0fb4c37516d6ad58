// lac g1: one LA segment of slope α between two points with given tangents (G1 Hermite,
// constructions/g1_hermite.hpp), entered as Hermite data (--p0 --theta0 --p1 --theta1) or as a
// control triangle (--points "a0 a1 a2": start, tangent intersection, end, as in
// [Yoshida–Saito 2009] §2, whose similar-triangle search is --solver triangle).
#include <cmath>

#include "cli/batch.hpp"
#include "cli/g1_hermite_args.hpp"

namespace lac::cli {
namespace {

Report solve(const G1HermiteArgs& a) {
  const double alpha = need(a.alpha, "alpha");
  const bool hermite = a.p0 || a.p1 || a.theta0 || a.theta1;
  if (a.points && hermite)
    throw_input_error("lac", "points", "give either --points or --p0/--theta0/--p1/--theta1, not both");
  if (a.points) {
    const auto p = parse_points(*a.points, 3, "points");
    const std::complex<double> a0{p[0][0], p[0][1]}, a1{p[1][0], p[1][1]}, a2{p[2][0], p[2][1]};
    if (a1 == a0 || a1 == a2)
      throw_input_error("lac", "points", "the tangent intersection a1 coincides with a0 or a2: no tangent direction there");
    return g1_hermite_report({a0, std::arg(a1 - a0), a2, std::arg(a2 - a1), alpha}, a, {a0, a1, a2});
  }
  if (!hermite) throw_input_error("lac", "points", "give --points \"a0 a1 a2\" or --p0/--theta0/--p1/--theta1");
  const auto p0 = parse_tuple(need(a.p0, "p0"), 2, "p0"), p1 = parse_tuple(need(a.p1, "p1"), 2, "p1");
  const G1HermiteProblem problem{{p0[0], p0[1]}, radians(need(a.theta0, "theta0"), a.common), {p1[0], p1[1]},
                                 radians(need(a.theta1, "theta1"), a.common), alpha};
  return g1_hermite_report(problem, a, {problem.p0, problem.p1});
}

void setup(CLI::App& app) {
  auto* a = owned<G1HermiteArgs>();
  auto* sub = app.add_subcommand("g1", "One LA segment of slope alpha from P0 with tangent theta0 to P1 with tangent theta1 "
                                       "(G1 Hermite), or from a control triangle");
  sub->add_option("--points", a->points, "Control points \"x0,y0 x1,y1 x2,y2\": start, tangent intersection, end");
  add_hermite_data_options(*sub, *a);
  add_g1_hermite_options(*sub, *a);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
