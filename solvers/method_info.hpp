#pragma once
// One row of a solver registry (the 1-D root finders of solvers/root_1d.hpp, the N-D methods of
// solvers/nonlinear.hpp): what name parsing and listings read.
#include <span>
#include <string_view>

namespace lac {

template <class Method>
struct SolverMethodInfo {
  Method method;
  std::string_view name;                      ///< canonical name (to_string)
  std::span<const std::string_view> aliases;  ///< further names the parser accepts
  std::string_view description;
  std::string_view options;                   ///< the option fields the method reads
};

}  // namespace lac
