#pragma once
// What a registry tells about one of its methods (quadrature: integrators/registry.hpp; ODE:
// integrators/ode_registry.hpp), for help texts, error messages and listings.
#include <span>
#include <string>
#include <string_view>

namespace lac {

/// An option a method takes by name (on the command line `--<name>`), with its default.
struct MethodOption {
  std::string_view name;
  double default_value;
  std::string_view meaning;
};

struct MethodInfo {
  std::string_view name;
  std::span<const std::string_view> aliases;
  std::string_view description;  ///< one line
  std::span<const MethodOption> options;
  std::string_view applies_to;   ///< where the method can be used
};

/// "rk4, rk45, gauss-kronrod (alias gk), …": the names and aliases, joined by `separator`.
std::string method_names_text(std::span<const MethodInfo> methods, std::string_view separator = ", ");

/// The method of that name or alias; nullptr for none.
const MethodInfo* find_method(std::span<const MethodInfo> methods, std::string_view name);

/// Whether `method` takes the option `option`.
bool takes_option(const MethodInfo& method, std::string_view option);

/// InputError naming `option` ("not applicable to rk45; rk45 takes --tol") when `method` does not take it.
void require_option(const MethodInfo& method, std::string_view option);

}  // namespace lac
