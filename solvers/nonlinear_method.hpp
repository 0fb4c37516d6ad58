#pragma once
// The N-D method family of solvers/nonlinear.hpp and its registry, without Eigen: what a
// construction's options name (constructions/g2_hermite.hpp, space_segment.hpp).
#include <span>
#include <string_view>

#include "lac/solvers/method_info.hpp"

namespace lac {

enum class NonlinearMethod { newton, ceres, simplex };

using NonlinearMethodInfo = SolverMethodInfo<NonlinearMethod>;
/// The registry, one row per method in enum order.
std::span<const NonlinearMethodInfo> nonlinear_methods();
/// A name or alias of nonlinear_methods(); InputError naming "solver" (listing the valid names) otherwise.
NonlinearMethod parse_nonlinear_method(std::string_view name);
std::string_view to_string(NonlinearMethod m);

}  // namespace lac
