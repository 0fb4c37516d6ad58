// lac g1: monotonic-rhythm LA segment from control points a0, a1, a2 and α [Yoshida–Saito 2009] §2.
#include "cli/batch.hpp"
#include "cli/triangle_args.hpp"

namespace lac::cli {
namespace {

struct G1Args : TriangleArgs {
  std::optional<double> alpha;
};

Report solve(const G1Args& a) {
  const PreparedTriangle p = prepare_triangle(a);
  return triangle_report(solve_g1(p.triangle, need(a.alpha, "alpha"), p.options), a, p);
}

void setup(CLI::App& app) {
  auto* a = owned<G1Args>();
  auto* sub = app.add_subcommand("g1", "Monotonic-rhythm LA segment from control points a0, a1, a2 and alpha "
                                       "[Yoshida-Saito 2009] section 2");
  add_triangle_options(*sub, *a);
  sub->add_option("--alpha", a->alpha, "Slope alpha of the logarithmic curvature graph, finite (required)");
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
