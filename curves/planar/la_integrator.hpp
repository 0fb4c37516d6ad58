#pragma once
// Run-time choice of how to compute positions on a planar LA curve: any quadrature method
// or a closed form. Used by the CLI and experiments; library code can call the templates of
// la_position.hpp with a concrete method instead.
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "lac/curves/planar/la_igf.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/integrators/registry.hpp"

namespace lac {

using LaIntegrator = std::variant<Rk4, Rk45, GaussKronrod, Igf>;

/// Names accepted by make_la_integrator, in a stable order.
std::span<const std::string_view> la_integrator_names();
/// InputError for an unknown name or an option the method does not take ("igf" takes --tol,
/// its relative accuracy target, and rejects --h).
LaIntegrator make_la_integrator(std::string_view name, const IntegratorOptions& options = {});
std::string_view name_of(const LaIntegrator& m);
std::string describe(const LaIntegrator& m);
std::string describe(const Igf& m);

PositionResult position_at(const LaCurve& c, Parameter p, double t, const LaIntegrator& m, Form form = Form::automatic);
std::vector<PositionResult> polyline(const LaCurve& c, Parameter p, double t0, double t1, int n, const LaIntegrator& m,
                                     Form form = Form::automatic);

}  // namespace lac
