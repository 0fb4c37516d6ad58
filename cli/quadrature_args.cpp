#include "cli/quadrature_args.hpp"

#include "lac/common/error.hpp"

namespace lac::cli {
namespace {

// "Step of rk4 (default 0.001)" / "Tolerance of rk45 (default 1e-12), gauss-kronrod (1e-14), …"
std::string option_help(std::string_view what, std::string_view option) {
  std::string text(what);
  bool first = true;
  for (const MethodInfo& m : quadrature_methods()) {
    for (const MethodOption& o : m.options) {
      if (o.name != option) continue;
      text.append(first ? " of " : ", ").append(m.name).append(first ? " (default " : " (");
      text.append(format_number(o.default_value)).append(")");
      first = false;
    }
  }
  return text;
}

}  // namespace

void add_quadrature_options(CLI::App& sub, QuadratureArgs& a, std::string_view first_choice) {
  std::string methods(first_choice);
  if (!methods.empty()) methods.append(" | ");
  methods.append(method_names_text(quadrature_methods(), " | "));
  for (const MethodInfo& m : quadrature_methods())
    if (m.applies_to != kAnyIntegrand)
      methods.append("; ").append(m.name).append(": ").append(m.applies_to);
  sub.add_option("--integrator", a.integrator, "Position method: " + methods)->capture_default_str();
  sub.add_option("--h", a.h, option_help("Step in the integration variable", "h"));
  sub.add_option("--tol", a.tol, option_help("Tolerance", "tol"));
  sub.add_option("--panels", a.panels, option_help("Equal panels", "panels"));
}

}  // namespace lac::cli
