#pragma once
// Options and output shared by `lac g1` (cli/g1.cpp, which defines the functions) and
// `lac compound` (cli/compound.cpp).
#include <string>

#include "cli/command.hpp"
#include "cli/quadrature_args.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lac::cli {

/// Options common to `g1` and `compound`.
struct SegmentArgs {
  std::string points;
  std::string solver = "toms748";
  QuadratureArgs quadrature{.integrator = "auto"};
  int points_out = 0;
  std::string* format = nullptr;
};
struct PreparedSegment {
  ControlTriangle triangle;
  TriangleOptions options;          ///< integrator: the construction's default unless --integrator names one
  bool explicit_integrator = false;
};
void add_segment_options(CLI::App& sub, SegmentArgs& a);
PreparedSegment prepare_segment(const SegmentArgs& a);
void print_segment(const TriangleResult& g, const SegmentArgs& a, const PreparedSegment& s);

}  // namespace lac::cli
