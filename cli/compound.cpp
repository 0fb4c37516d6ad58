// lac compound: compound-rhythm LA curve from control points, α0, α1 and r [Yoshida–Saito 2009] §4.
#include "cli/batch.hpp"
#include "cli/triangle_args.hpp"

namespace lac::cli {
namespace {

struct CompoundArgs : TriangleArgs {
  std::optional<double> alpha0, alpha1;
  double r = 0.5;
};

Report solve(const CompoundArgs& a) {
  const PreparedTriangle p = prepare_triangle(a);
  return triangle_report(solve_compound(p.triangle, need(a.alpha0, "alpha0"), need(a.alpha1, "alpha1"), a.r, p.options),
                         a, p);
}

void setup(CLI::App& app) {
  auto* a = owned<CompoundArgs>();
  auto* sub = app.add_subcommand("compound", "Compound-rhythm LA curve (two LCG slopes, G3 joint) from control points "
                                             "[Yoshida-Saito 2009] section 4");
  add_triangle_options(*sub, *a);
  sub->add_option("--alpha0", a->alpha0, "LCG slope of segment 0, at the end with the shorter control leg (required)");
  sub->add_option("--alpha1", a->alpha1, "LCG slope of segment 1 (required)");
  sub->add_option("--r", a->r, "Share of the total turning in segment 0, in (0, 1)")->capture_default_str();
  set_solver(*sub, *a, solve);
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
