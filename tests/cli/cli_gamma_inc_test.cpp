// `lac special gamma-inc` and `lac eval --integrator igf` end to end: JSON keys and values,
// and exit status 2 with one line naming the parameter. Needs the `lac` executable built.
#include <gtest/gtest.h>

#include "tests/support/run_cli.hpp"

#include <array>
#include <complex>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/reference_csv.hpp"

namespace {

using lac::test::run_lac;

TEST(CliGammaInc, JsonMatchesTheReference) {
  // Γ(0, −i) = E₁(−i) and Γ(−2.5, 2i) from tests/reference/gamma_inc.csv.
  const auto t = lac::test::read_reference_csv("gamma_inc.csv");
  int checked = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const std::string a = t.rows[i][t.column("a")];
    const double zr = t.number(i, "z_re"), zi = t.number(i, "z_im");
    if (!((a == "0" && zr == 0 && zi == -1) || (a == "-2.5" && zr == 0 && zi == 2))) continue;
    char z[64];
    std::snprintf(z, sizeof z, "%.17g,%.17g", zr, zi);
    const lac::test::CliRun r = run_lac("special gamma-inc --a " + a + " --z " + z + " --format json");
    ASSERT_EQ(r.status, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    const std::complex<double> value(j["re"].get<double>(), j["im"].get<double>());
    const std::complex<double> ref(t.number(i, "re"), t.number(i, "im"));
    EXPECT_LE(std::abs(value - ref), 1e-13 * std::abs(ref)) << r.out;
    EXPECT_EQ(j["status"], "ok");
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(CliGammaInc, InvalidInputExitsWithTwo) {
  for (const char* args : {"special gamma-inc --a 0 --z 0,0", "special gamma-inc --a 11 --z 1,0",
                           "special gamma-inc --a nan --z 1,0", "special gamma-inc --a 1 --z 1"}) {
    const lac::test::CliRun r = run_lac(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(r.out.rfind("lac special gamma-inc: ", 0), 0u) << r.out;  // the command, once
  }
}

TEST(CliEvalIgf, WorksAndRejectsStep) {
  const lac::test::CliRun ok = run_lac("eval --alpha 0.999 --lambda 1 --theta 3 --integrator igf --format json");
  ASSERT_EQ(ok.status, 0) << ok.out;
  const auto j = nlohmann::json::parse(ok.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_TRUE(std::isfinite(j["point"]["x"].get<double>()));
  const lac::test::CliRun bad = run_lac("eval --alpha 2 --lambda 1 --theta 1 --integrator igf --h 0.1");
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("h"), std::string::npos) << bad.out;
}

}  // namespace
