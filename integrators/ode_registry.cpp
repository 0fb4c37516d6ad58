#include "lac/integrators/ode_registry.hpp"

#include <array>
#include <cmath>
#include <string>

#include "lac/common/error.hpp"

namespace lac {
namespace {

constexpr OdeOptions kDefaults{};
constexpr std::array<MethodOption, 2> kFixedOptions = {{{"h", kDefaults.h, "fixed step"},
                                                        {"max_steps", static_cast<double>(kDefaults.max_steps), "step cap"}}};
constexpr std::array<MethodOption, 3> kAdaptiveOptions = {
    {{"rtol", kDefaults.rtol, "relative tolerance per step"},
     {"atol", kDefaults.atol, "absolute tolerance per step"},
     {"max_steps", static_cast<double>(kDefaults.max_steps), "cap on attempted steps"}}};

constexpr std::array<MethodInfo, 3> kMethods = {{
    {"rk4", {}, "classical RK4 with fixed step, frame re-orthonormalized after each step", kFixedOptions,
     "any ODE y' = f(s, y) (Frenet 12-vector)"},
    {"rk45", {}, "adaptive Dormand-Prince 5(4), frame re-orthonormalized after each step", kAdaptiveOptions,
     "any ODE y' = f(s, y) (Frenet 12-vector)"},
    {"magnus6", {}, "adaptive order-6 Magnus (3 Gauss nodes, order-4 estimate), exact for constant generators",
     kAdaptiveOptions, "g' = g xi(s) on SE(3) (Frenet frame and position)"},
}};
static_assert(kMethods[static_cast<std::size_t>(OdeMethod::rk4)].name == "rk4" &&
              kMethods[static_cast<std::size_t>(OdeMethod::rk45)].name == "rk45" &&
              kMethods[static_cast<std::size_t>(OdeMethod::magnus6)].name == "magnus6");

}  // namespace

std::span<const MethodInfo> ode_methods() { return kMethods; }

OdeMethod parse_ode_method(std::string_view name) {
  for (std::size_t i = 0; i < kMethods.size(); ++i)
    if (kMethods[i].name == name) return static_cast<OdeMethod>(i);
  throw_input_error("parse_ode_method", "integrator",
                    "unknown name '" + std::string(name) + "'; valid: " + method_names_text(kMethods));
}

std::string_view to_string(OdeMethod m) {
  const auto i = static_cast<std::size_t>(m);
  return i < kMethods.size() ? kMethods[i].name : "unknown";
}

void OdeOptions::validate() const {
  constexpr const char* who = "OdeOptions";
  if (!(rtol >= 1e-15) || !std::isfinite(rtol)) throw_input_error(who, "rtol", rtol, "[1e-15, inf)");
  if (!(atol > 0) || !std::isfinite(atol)) throw_input_error(who, "atol", atol, "(0, inf)");
  if (!(h > 0) || !std::isfinite(h)) throw_input_error(who, "h", h, "(0, inf)");
  if (max_steps < 1) throw_input_error(who, "max_steps", static_cast<double>(max_steps), "[1, inf)");
}

}  // namespace lac
