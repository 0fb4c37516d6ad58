#pragma once
// The quadrature options of a subcommand (`--integrator`, `--h`, `--tol`, `--panels`), with help
// texts generated from the quadrature registry (integrators/registry.hpp). Used by every planar
// curve command (eval, quadratic, g1, compound, scurve, g2).
#include <optional>
#include <string>
#include <string_view>

#include "cli/command.hpp"
#include "lac/integrators/registry.hpp"

namespace lac::cli {

struct QuadratureArgs {
  std::string integrator;
  std::optional<double> h{}, tol{};
  std::optional<int> panels{};

  QuadratureOptions options() const { return {h, tol, panels}; }
  bool any_option() const { return h || tol || panels; }
};

/// Adds the options; `--integrator` lists every registered method after `first_choice` (e.g.
/// "auto (…)"; empty for none), and each of `--h`, `--tol`, `--panels` lists the methods taking
/// it with their defaults.
void add_quadrature_options(CLI::App& sub, QuadratureArgs& a, std::string_view first_choice = "");

}  // namespace lac::cli
