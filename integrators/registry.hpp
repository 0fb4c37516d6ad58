#pragma once
// The quadrature registry: every quadrature method by name, for the CLI and experiments. The hot
// path uses the method types directly (templates); this variant is the edge, dispatched once per
// call (std::visit) by the curves and constructions that take it.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "lac/integrators/gauss_legendre.hpp"
#include "lac/integrators/gk_tanh_sinh.hpp"
#include "lac/integrators/igf.hpp"
#include "lac/integrators/method_info.hpp"
#include "lac/integrators/quadrature.hpp"

namespace lac {

/// Options given by name on a command line (`--h`, `--tol`, `--panels`). Each method takes the
/// ones quadrature_methods() lists for it; unset options keep the method's default.
struct QuadratureOptions {
  std::optional<double> h{};
  std::optional<double> tol{};
  std::optional<int> panels{};
};

/// MethodInfo::applies_to of the methods that integrate any integrand (all but igf).
inline constexpr std::string_view kAnyIntegrand = "any integrand (planar LA and quadratic LA curves)";

/// Alternatives in the order of quadrature_methods().
using AnyQuadrature = std::variant<Rk4, Rk45, GaussKronrod, GaussLegendre, GkTanhSinh, Igf>;

/// rk4, rk45, gauss-kronrod (alias gk), gauss-legendre, gk-tanh-sinh, igf: names, aliases, options
/// with their defaults and where each applies (igf: planar LA curves and segments, through their standard form).
std::span<const MethodInfo> quadrature_methods();

/// The method `name` (or alias) with `options` applied and validated. InputError naming
/// "integrator" for an unknown name (listing the valid ones), naming the option for an option the
/// method does not take (e.g. h for rk45), or from the method's validate().
AnyQuadrature make_quadrature(std::string_view name, const QuadratureOptions& options = {});

std::string_view name_of(const AnyQuadrature& method);
/// One line with the method's settings, e.g. "rk4 h=0.001".
std::string describe(const AnyQuadrature& method);

}  // namespace lac
