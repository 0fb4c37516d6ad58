#include "lac/curves/planar/la_integrator.hpp"

#include <array>

namespace lac {

Form parse_form(std::string_view text) {
  if (text == "theta") return Form::theta;
  if (text == "s") return Form::s;
  if (text == "auto") return Form::automatic;
  throw_input_error("parse_form", "form", "unknown form '" + std::string(text) + "'; valid: theta, s, auto");
}

std::span<const std::string_view> la_integrator_names() {
  static constexpr std::array<std::string_view, 4> kNames = {Rk4::name, Rk45::name, GaussKronrod::name, Igf::name};
  return kNames;
}

LaIntegrator make_la_integrator(std::string_view name, const IntegratorOptions& options) {
  if (name == Igf::name) {
    if (options.h) throw_input_error("igf", "h", "not applicable to igf (a closed form has no step); use --tol");
    Igf m;
    if (options.tol) m.tol = *options.tol;
    m.validate();
    return m;
  }
  if (name != Rk4::name && name != Rk45::name && name != GaussKronrod::name && name != "gk")
    throw_input_error("make_la_integrator", "integrator",
                      "unknown name '" + std::string(name) + "'; valid: rk4, rk45, gauss-kronrod, igf");
  return std::visit([](auto m) -> LaIntegrator { return m; }, make_quadrature(name, options));
}

std::string_view name_of(const LaIntegrator& m) {
  return std::visit([](const auto& x) -> std::string_view { return std::decay_t<decltype(x)>::name; }, m);
}

std::string describe(const Igf& m) {
  return "igf (incomplete-gamma closed form) tol=" + format_number(m.tol) + " max_pieces=" + std::to_string(m.max_pieces);
}

std::string describe(const LaIntegrator& m) {
  return std::visit([](const auto& x) { return lac::describe(x); }, m);
}

PositionResult position_at(const LaCurve& c, Parameter p, double t, const LaIntegrator& m, Form form) {
  return std::visit([&](const auto& x) { return position_at(c, p, t, x, form); }, m);
}

std::vector<PositionResult> polyline(const LaCurve& c, Parameter p, double t0, double t1, int n, const LaIntegrator& m,
                                     Form form) {
  return std::visit([&](const auto& x) { return polyline(c, p, t0, t1, n, x, form); }, m);
}

}  // namespace lac
