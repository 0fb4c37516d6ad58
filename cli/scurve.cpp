// lac scurve: one LA segment from four control points, tangent P0→P1 at P0 and P2→P3 at P3
// ([Miura et al. 2013] §2.4–2.5's input): the G1 Hermite problem of constructions/g1_hermite.hpp;
// [Miura et al. 2013]'s Λ search is --solver s-curve.
#include <cmath>

#include "cli/batch.hpp"
#include "cli/g1_hermite_args.hpp"

namespace lac::cli {
namespace {

Report solve(const G1HermiteArgs& a) {
  const auto p = parse_points(need(a.points, "points"), 4, "points");
  std::vector<std::complex<double>> P;
  for (const auto& q : p) P.emplace_back(q[0], q[1]);
  return g1_hermite_report({P[0], std::arg(P[1] - P[0]), P[3], std::arg(P[3] - P[2]), need(a.alpha, "alpha")}, a, P);
}

void setup(CLI::App& app) {
  auto* a = owned<G1HermiteArgs>();
  a->alpha = -1;
  auto* sub = app.add_subcommand("scurve", "One LA segment (S-shaped or not) from four control points: start tangent "
                                           "P0->P1, end tangent P2->P3 [Miura et al. 2013] sections 2.4-2.5");
  sub->add_option("--points", a->points,
                  "Control points \"x0,y0 x1,y1 x2,y2 x3,y3\": start tangent P0->P1, end tangent P2->P3 (required)");
  add_g1_hermite_options(*sub, *a);
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
