// lac compound: compound-rhythm LA curve from control points, α0, α1 and r (001 §4).
#include <optional>

#include "cli/command.hpp"
#include "io/timing.hpp"
#include "segments/planar/g1_segment.hpp"

namespace lac::cli {

// Shared with `lac g1`; defined in cli/g1.cpp.
struct SegmentArgs {
  std::string points;
  std::string solver = "toms748";
  std::string integrator = "auto";
  std::optional<double> h, tol;
  int points_out = 0;
  std::string* format = nullptr;
};
struct PreparedSegment {
  ControlTriangle triangle;
  SegmentOptions options;
  std::optional<LaIntegrator> integrator;  ///< empty: the solvers' default (gk+tanh-sinh)
};
void add_segment_options(CLI::App& sub, SegmentArgs& a);
PreparedSegment prepare_segment(const SegmentArgs& a);
void print_segment(const G1Segment& g, const SegmentArgs& a, const PreparedSegment& s, double seconds);

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
    io::Stopwatch clock;
    const G1Segment g = s.integrator ? solve_compound(s.triangle, c->alpha0, c->alpha1, c->r, s.options, *s.integrator)
                                      : solve_compound(s.triangle, c->alpha0, c->alpha1, c->r, s.options);
    print_segment(g, *a, s, clock.seconds());
  });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
