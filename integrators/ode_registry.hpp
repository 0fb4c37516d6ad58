#pragma once
// The ODE registry: the methods of the Frenet integration of LA space curves (curves/space/
// frenet.hpp) by name, with their options. rk4 and rk45 are the steppers of integrators/ode.hpp on
// the 12-vector (P, T, N, B); magnus6 is the Lie-group stepper of integrators/magnus.hpp on SE(3).
#include <span>
#include <string_view>

#include "lac/integrators/method_info.hpp"

namespace lac {

/// rk4: classical fixed step; rk45: adaptive Dormand–Prince 5(4); magnus6: adaptive order-6 Magnus on SE(3).
enum class OdeMethod { rk4, rk45, magnus6 };

/// "rk4" | "rk45" | "magnus6"; InputError naming "integrator" (listing the valid names) otherwise.
OdeMethod parse_ode_method(std::string_view name);
std::string_view to_string(OdeMethod m);

/// rk4, rk45, magnus6 in the order of OdeMethod: names, options with their defaults, where each applies.
std::span<const MethodInfo> ode_methods();

struct OdeOptions {
  OdeMethod method = OdeMethod::rk45;
  double rtol = 1e-12;      ///< adaptive methods: relative tolerance per step
  double atol = 1e-13;      ///< adaptive methods: absolute tolerance per step (standard-form units, ρ(0) = 1)
  double h = 1e-3;          ///< rk4 fixed step
  long max_steps = 20'000;  ///< cap on attempted steps (status max_iterations when hit)
  void validate() const;
};

}  // namespace lac
