#pragma once
// The checks every solver registry passes (solvers/root_1d.hpp, solvers/nonlinear.hpp): one row per
// method in enum order, every name and alias parses back, unknown names throw InputError naming
// "solver" and listing every method.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <string_view>

#include "lac/common/error.hpp"
#include "lac/solvers/method_info.hpp"

namespace lac::test {

template <class Method, class Parse>
void expect_complete_registry(std::span<const SolverMethodInfo<Method>> list, std::span<const Method> all, Parse parse,
                              std::string_view unknown) {
  ASSERT_EQ(list.size(), all.size());
  for (size_t i = 0; i < list.size(); ++i) {
    const SolverMethodInfo<Method>& m = list[i];
    EXPECT_EQ(m.method, all[i]);  // enum order
    EXPECT_EQ(to_string(m.method), m.name);
    EXPECT_EQ(parse(m.name), m.method);
    for (std::string_view alias : m.aliases) EXPECT_EQ(parse(alias), m.method) << alias;
    EXPECT_FALSE(m.description.empty());
    EXPECT_FALSE(m.options.empty());
  }
  try {
    parse(unknown);
    ADD_FAILURE() << "no exception for '" << unknown << "'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "solver");
    const std::string what = e.what();
    for (const SolverMethodInfo<Method>& m : list) EXPECT_NE(what.find(m.name), std::string::npos) << what;
  }
}

}  // namespace lac::test
