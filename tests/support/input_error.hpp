#pragma once
// The parameter an InputError names, for tests that check which parameter bad input is blamed on.
#include <string>

#include "lac/common/error.hpp"

namespace lac::test {

/// Runs f and returns the parameter named by the InputError it throws, "<no error>" if none.
template <class F>
std::string thrown_parameter(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.parameter();
  }
  return "<no error>";
}

}  // namespace lac::test
