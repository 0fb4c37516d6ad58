#pragma once
// Name lookup shared by the solver registries (solvers/root_1d.cpp, solvers/nonlinear.cpp).
#include <span>
#include <string>
#include <string_view>

#include "lac/common/error.hpp"
#include "lac/solvers/method_info.hpp"

namespace lac::detail {

/// The method named `name` (canonical name or alias); InputError naming "solver" and listing
/// the valid names otherwise. `what` names the family in the message ("root finder").
template <class Method>
Method parse_solver_method(std::span<const SolverMethodInfo<Method>> table, std::string_view name,
                           std::string_view who, std::string_view what) {
  std::string valid;
  for (const auto& row : table) {
    if (row.name == name) return row.method;
    for (std::string_view alias : row.aliases)
      if (alias == name) return row.method;
    if (!valid.empty()) valid += ", ";
    valid += row.name;
    for (size_t i = 0; i < row.aliases.size(); ++i)
      valid.append(i == 0 ? " (alias " : ", ").append(row.aliases[i]).append(i + 1 == row.aliases.size() ? ")" : "");
  }
  throw_input_error(who, "solver", "unknown " + std::string(what) + " '" + std::string(name) + "'; valid: " + valid);
}

template <class Method>
std::string_view solver_method_name(std::span<const SolverMethodInfo<Method>> table, Method m) {
  for (const auto& row : table)
    if (row.method == m) return row.name;
  return "unknown";
}

}  // namespace lac::detail
