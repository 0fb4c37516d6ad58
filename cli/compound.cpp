// lac compound: compound-rhythm LA curve from control points, α0, α1 and r (001 §4).
#include "cli/command.hpp"
#include "cli/segment_args.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lac::cli {

namespace {

struct CompoundArgs {
  double alpha0 = 0, alpha1 = 0, r = 0.5;
};

void setup(CLI::App& app) {
  auto* a = owned<SegmentArgs>();
  auto* c = owned<CompoundArgs>();
  auto* sub = app.add_subcommand("compound",
                                 "Compound-rhythm LA curve (two LCG slopes, G3 joint) from control points (001 section 4)");
  add_segment_options(*sub, *a);
  sub->add_option("--alpha0", c->alpha0, "LCG slope of segment 0 (at the end with the shorter control leg)")->required();
  sub->add_option("--alpha1", c->alpha1, "LCG slope of segment 1")->required();
  sub->add_option("--r", c->r, "Share of the total turning in segment 0, in (0, 1)")->capture_default_str();
  sub->callback([a, c] {
    const PreparedSegment s = prepare_segment(*a);
    print_segment(solve_compound(s.triangle, c->alpha0, c->alpha1, c->r, s.options), *a, s);
  });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
