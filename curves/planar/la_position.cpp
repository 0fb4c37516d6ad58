#include "lac/curves/planar/la_position.hpp"

#include <variant>

namespace lac {

Form parse_form(std::string_view text) {
  if (text == "theta") return Form::theta;
  if (text == "s") return Form::s;
  if (text == "auto") return Form::automatic;
  throw_input_error("parse_form", "form", "unknown form '" + std::string(text) + "'; valid: theta, s, auto");
}

PositionResult position_at(const LaCurve& c, Parameter p, double t, const AnyQuadrature& method, Form form,
                           double accept) {
  return std::visit([&](const auto& m) { return position_at(c, p, t, m, form, accept); }, method);
}

std::vector<PositionResult> polyline(const LaCurve& c, Parameter p, double t0, double t1, int n,
                                     const AnyQuadrature& method, Form form, double accept) {
  return std::visit([&](const auto& m) { return polyline(c, p, t0, t1, n, m, form, accept); }, method);
}

}  // namespace lac
