// Regression tests for the fuzzing findings of docs/robustness.md that still wait for their fix.
// Move into tests/robustness/ (and delete from here) once the fix is in; each test checks the
// correct behaviour, so it fails until then. Inputs are the ones the fuzzers saved
// (fuzz/findings/fuzz_<target>/), reduced to the call that goes wrong.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <sys/wait.h>

#include "common/error.hpp"
#include "curves/planar/la_integrator.hpp"
#include "segments/planar/g1_segment.hpp"
#include "special/incomplete_gamma.hpp"

namespace {

/// Either a finite value or an InputError naming `parameter`; never NaN.
template <class Call>
void expect_finite_or_input_error(Call call, const std::string& parameter, const std::string& what) {
  try {
    const double v = call();
    EXPECT_TRUE(std::isfinite(v)) << what << " returned " << v << " instead of an InputError naming " << parameter;
  } catch (const lac::InputError& e) {
    EXPECT_EQ(e.parameter(), parameter) << what << ": " << e.what();
  }
}

// Finding R8 (fuzz_planar_segments): an overflowing triangle gives a usable segment of infinite length.
TEST(FuzzRegression, OverflowingTriangleIsRejectedOrFinite) {
  const lac::ControlTriangle t{{-DBL_MAX, 7.812255859375}, {3.392578125, 1e300}, {-3.437744140625, 7.999755859375}};
  lac::SegmentOptions o;
  o.solver = lac::RootMethod::ceres;
  try {
    const lac::G1Segment g = lac::solve_g1(t, 0.0, o);
    if (lac::usable(g.status)) EXPECT_TRUE(std::isfinite(g.length));
  } catch (const lac::InputError& e) {
    EXPECT_FALSE(e.parameter().empty());
  }
}

int run_lac(const std::string& args, std::string* out) {
  const std::string cmd = std::string(LAC_BINARY_DIR) + "/lac " + args + " 2>&1 >/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe.get())) out->append(buf, n);
  const int status = pclose(pipe.release());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}


}  // namespace
