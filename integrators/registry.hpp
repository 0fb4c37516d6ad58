#pragma once
// Run-time selection of a quadrature method by name, for the CLI and experiments.
// The hot path uses the method types directly (templates); this variant is the edge.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "lac/integrators/quadrature.hpp"

namespace lac {

/// Options given by name on a command line. `h` applies to rk4 only; `tol` to the
/// adaptive methods. Unset options keep each method's documented default.
struct IntegratorOptions {
  std::optional<double> h;
  std::optional<double> tol;
};

using AnyQuadrature = std::variant<Rk4, Rk45, GaussKronrod>;

/// "rk4" | "rk45" | "gauss-kronrod" (alias "gk"). InputError for other names or misplaced options.
AnyQuadrature make_quadrature(std::string_view name, const IntegratorOptions& options = {});
std::span<const std::string_view> quadrature_names();

/// Applies options to one method; shared by every registry that contains these methods.
void apply_options(Rk4& m, const IntegratorOptions& o);
void apply_options(Rk45& m, const IntegratorOptions& o);
void apply_options(GaussKronrod& m, const IntegratorOptions& o);

/// One-line description of a configured method, e.g. "rk4 h=0.001".
std::string describe(const Rk4& m);
std::string describe(const Rk45& m);
std::string describe(const GaussKronrod& m);

}  // namespace lac
