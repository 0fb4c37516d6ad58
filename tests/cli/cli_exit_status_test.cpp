// Exit status of every subcommand (cli/command.hpp): 0 for a usable result, 2 for invalid input
// (one line on stderr, `lac <subcommand>: …`, naming the parameter), 3 when the command ran but
// printed no usable result. Also --version, the did-you-mean suggestions and the error prefix.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lac/version.hpp"
#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

using test::run_lac;
using test::run_lac_stderr;
using test::run_lac_stdout;

struct Command {
  std::string name;       ///< as in the error prefix: "g1", "special gamma-inc"
  std::string good;       ///< a call with a usable result: exit 0
  std::string invalid;    ///< an invalid parameter: exit 2
  std::string parameter;  ///< named in the error line
  std::string unusable;   ///< runs, no usable result: exit 3
};

const std::string kSpaceEnds =  // 000 Fig. 5a with drawable endpoints (as in cli_space_test.cpp)
    "--p0 0,0,0 --v0 1,0,0 --p1 0.36235775447667362,0.93203908596722629,0 "
    "--v1=-0.4838825660252134,0.8293701183329452,0.279289937364832 ";
const std::string kG2 = "g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 ";

// The unusable calls are cheap by construction: a budget that cannot be met (rk4 with h = 1e-9
// needs 1e9 steps: max_iterations before the first step), or inputs proven to have no curve.
const std::vector<Command> kCommands = {
    {"eval", "eval --alpha 2 --lambda 1 --theta 1", "eval --alpha 2 --lambda -1 --theta 1", "lambda",
     "eval --alpha 1 --lambda 1 --theta 1 --integrator rk4 --h 1e-9"},
    {"eval", "eval --alpha -1 --lambda 1 --s 0.8 --samples 5", "eval --alpha 2 --lambda 1 --theta 1 --samples 1", "samples",
     "eval --alpha 1 --lambda 1 --theta 1 --samples 3 --integrator rk4 --h 1e-9"},
    {"quadratic", "quadratic --alpha 1 --gamma 1 --lambda 1 --samples 3", "quadratic --alpha 1 --gamma 1 --lambda 0",
     "lambda", "quadratic --alpha 1 --gamma 1 --lambda 1 --samples 3 --integrator rk4 --h 1e-9"},
    {"g1", "g1 --points '0,0 1,0 2,1' --alpha -1", "g1 --points '0,0 1,0 2,1 3,1' --alpha -1", "points",
     "g1 --points '0,0 1,0 2,1' --alpha 5 --winding 0"},  // outside the drawable region: no_solution
    {"compound", "compound --points '3,2 1.5,0.2 0.5,0.9' --alpha0 2 --alpha1 0.5 --r 0.3",
     "compound --points '3,2 1.5,0.2 0.5,0.9' --alpha0 2 --alpha1 0.5 --r 1.5", "r",
     "compound --points '0,0 1,0 2,1' --alpha0 5 --alpha1 5"},
    {"g2", kG2 + "--alpha -0.5", kG2 + "--alpha 9", "alpha",
     // κ changes sign with α ≥ 0: no_solution
     "g2 --p0 0,0 --theta0 0.3 --kappa0 1 --p1 1,0 --theta1 0.3 --kappa1 -1 --alpha 1"},
    {"scurve", "scurve --points '0,0 1,0 2,1 3,1' --alpha -1", "scurve --points '0,0 1,0 2,1 3,1' --alpha 7", "alpha",
     // S-shaped (zero turning) with α ≥ 0: κ cannot change sign; a full turn is not resolved (not_converged)
     "scurve --points '0,0 1,0.5 2,0.5 3,1' --alpha 1.5"},
    {"chain", "chain --points '0,0 1,1 2,0 3,1' --alpha -1", "chain --points '0,0 1,1 2,0 3,1' --alpha 9", "alpha",
     // the second pair needs an inflection at winding 0, α ≥ 0: no_solution
     "chain --points '0,0 1,0 2,0' --thetas '0.2 -0.2 -0.4' --alpha 1 --winding 0"},
    {"space", "space " + kSpaceEnds + "--alpha -1 --beta -1 --omega 0.1 --type 1",
     "space " + kSpaceEnds + "--alpha 0 --beta 0 --omega 0.1 --type 3", "type",
     // the end tangent turns back, alpha < 0 ends early: not_converged
     "space --p0 0,0,0 --v0 1,0,0 --p1 1,0.1,0.1 --v1 -1,0,0 --alpha -1 --beta 0 --omega 0.1 --type 1"},
    {"special erfi-inv", "special erfi-inv --y 2", "special erfi-inv --y abc", "y",
     "special erfi-inv --y 1e300 --method hybrid-003"},  // beyond 003's |x| <= 26: no_solution
    {"special erf-inv", "special erf-inv --y 0.5", "special erf-inv --y 1.5", "y",
     "special erf-inv --y 0.9999999999999 --method hybrid-003"},  // beyond 003's |x| <= 5
    {"special gamma-inc", "special gamma-inc --a 1 --z 1,0", "special gamma-inc --a 11 --z 1,0", "a",
     "special gamma-inc --a 1 --z -1000,0"},  // e^1000 overflows: numerical_failure
};

const std::vector<std::string> kNotUsable = {"max_iterations", "no_solution", "numerical_failure", "not_converged",
                                             "inaccurate"};

/// One line on stderr, the command named once at its start: `lac <name>: …`.
void expect_error_line(const std::string& err, const std::string& name, const std::string& args) {
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << args << "\n" << err;
  EXPECT_EQ(err.rfind("lac " + name + ": ", 0), 0u) << args << "\n" << err;
  EXPECT_EQ(err.find("error: lac"), std::string::npos) << args << "\n" << err;
  EXPECT_EQ(err.find(": lac"), std::string::npos) << args << "\n" << err;
}

TEST(CliExitStatus, ZeroForAUsableResult) {
  for (const Command& c : kCommands) {
    const test::CliRun r = run_lac(c.good);
    EXPECT_EQ(r.status, 0) << c.good << "\n" << r.out;
  }
}

TEST(CliExitStatus, TwoForAnInvalidParameterWithOneLineNamingIt) {
  for (const Command& c : kCommands) {
    const test::CliRun r = run_lac_stderr(c.invalid);
    EXPECT_EQ(r.status, 2) << c.invalid << "\n" << r.out;
    EXPECT_NE(r.out.find(c.parameter), std::string::npos) << c.invalid << "\n" << r.out;
    expect_error_line(r.out, c.name, c.invalid);
  }
}

TEST(CliExitStatus, ThreeWhenTheResultIsNotUsableWhichIsStillPrinted) {
  for (const Command& c : kCommands) {
    const test::CliRun r = run_lac_stdout(c.unusable + " --format json");
    EXPECT_EQ(r.status, 3) << c.unusable << "\n" << r.out;
    const bool says_why = std::any_of(kNotUsable.begin(), kNotUsable.end(), [&](const std::string& status) {
      return r.out.find("\"status\": \"" + status + "\"") != std::string::npos;
    });
    EXPECT_TRUE(says_why) << c.unusable << "\n" << r.out;
    EXPECT_EQ(run_lac_stderr(c.unusable).out, "") << c.unusable;  // not an error: the status says why
  }
}

TEST(CliExitStatus, VersionAndHelp) {
  const test::CliRun v = run_lac_stdout("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_EQ(v.out, std::string("lac ") + lac::version + "\n");
  EXPECT_EQ(run_lac("--help").status, 0);
  EXPECT_EQ(run_lac("special erf-inv --help").status, 0);
}

TEST(CliExitStatus, UnknownNamesAreNamedWithTheClosestValidOne) {
  struct Case {
    std::string args, line;
  };
  const Case cases[] = {
      {"evl", "lac: unknown subcommand \"evl\"; did you mean \"eval\"?"},
      // An echoed argument's control characters are written as \xNN, its newlines as spaces: one line.
      {"\"$(printf 'ev\\001al')\"", "lac: unknown subcommand \"ev\\x01al\"; did you mean \"eval\"?"},
      {"eval \"$(printf '%s\\n%s' --alp ha)\" 1", "lac eval: unknown option --alp ha; did you mean --alpha?"},
      {"scruve --alpha -1", "lac: unknown subcommand \"scruve\"; did you mean \"scurve\"?"},
      {"xyzzy", "lac: unknown subcommand \"xyzzy\" (see lac --help)"},
      {"special gamma-in --a 1 --z 1,0", "lac special: unknown subcommand \"gamma-in\"; did you mean \"gamma-inc\"?"},
      // Named even though --alpha is then missing (CLI11 alone reports "--alpha is required").
      {"g1 --points '0,0 1,0 2,1' --alpah 1", "lac g1: unknown option --alpah; did you mean --alpha?"},
      {"g1 --points '0,0 1,0 2,1' --alpha 1 --solver=toms748 --integratr=rk4",
       "lac g1: unknown option --integratr; did you mean --integrator?"},
      {"scurve --pionts '0,0 1,0 2,1 3,1'", "lac scurve: unknown option --pionts; did you mean --points?"},
      {"eval --alpha 1 --lambda 1 --theta 1 --frobnicate", "lac eval: unknown option --frobnicate (see lac eval --help)"},
      {"eval --alpha 1 --lambda 1 --theta 1 extra", "lac eval: unexpected argument \"extra\" (see lac eval --help)"},
      {"--verison", "lac: unknown option --verison; did you mean --version?"},
  };
  for (const Case& c : cases) {
    const test::CliRun r = run_lac_stderr(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_EQ(r.out, c.line + "\n") << c.args;
  }
}

TEST(CliExitStatus, EveryErrorLineNamesTheCommandOnce) {
  const std::pair<std::string, std::string> cases[] = {
      {"", "lac: "},
      {"special", "lac special: "},
      {"eval --alpha x --lambda 1 --theta 1", "lac eval: "},  // a CLI11 conversion error
      {"eval --alpha 1 --lambda 1", "lac eval: "},              // one of --theta/--s
      {"g1 --alpha 1", "lac g1: "},                             // --points is required
      {"g2 --p0 0,0 --theta0 0 --kappa0 1 --p1 1 --theta1 0 --kappa1 1", "lac g2: "},
      {"special erf-inv --y 1 --method foo", "lac special erf-inv: "},
      // The library names the construction as the command does ("g1: alpha …"): said once.
      {"g1 --points '0,0 1,0 2,1' --alpha 7", "lac g1: alpha = 7 "},
      {"g2 --p0 0,0 --theta0 0.6 --kappa0 0.5 --p1 4,0 --theta1 -0.6 --kappa1 -0.3 --alpha 9", "lac g2: alpha = 9 "},
      {"scurve --points '0,0 1,0 2,1 3,1' --solver s-curve --alpha -7", "lac scurve: "},
  };
  for (const auto& [args, prefix] : cases) {
    const test::CliRun r = run_lac_stderr(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_EQ(r.out.rfind(prefix, 0), 0u) << args << "\n" << r.out;
    const std::string named = prefix.substr(0, prefix.find(':'));           // "lac special erf-inv"
    const std::string command = named.substr(named.rfind(' ') + 1);        // "erf-inv"
    EXPECT_EQ(r.out.find(command + ": " + command + ": "), std::string::npos) << args << "\n" << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << "\n" << r.out;
    EXPECT_EQ(r.out.find(": lac"), std::string::npos) << args << "\n" << r.out;
    EXPECT_EQ(r.out.find("error: lac"), std::string::npos) << args << "\n" << r.out;
  }
}

// A result whose achieved error exceeds the accept bound (common/accuracy.hpp) is printed with
// status inaccurate and exits 3; --accept loosens the bound knowingly. rk4 with h = 10 takes one
// step over the whole curve: positions off by a large part of the chord.
TEST(CliExitStatus, ThreeForAnInaccurateResult) {
  const std::string cases[] = {
      "compound --points '0,0 1,0 2,1' --alpha0 -1 --alpha1 -1 --integrator rk4 --h 10",
      "compound --points '0,0 1,0 2,1' --alpha0 -1 --alpha1 2 --r 0.3 --integrator rk4 --h 10",
  };
  for (const std::string& args : cases) {
    const test::CliRun r = run_lac_stdout(args);
    EXPECT_EQ(r.status, 3) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("\"status\": \"inaccurate\""), std::string::npos) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("\"length\": null"), std::string::npos) << args << "\n" << r.out;  // no curve
    EXPECT_EQ(run_lac_stderr(args).out, "") << args;
  }
  // With h = 0.3 the error bound is 1e-4 of the chord: beyond the default accept, within a loosened
  // one (usable, tolerance_not_met, exit 0).
  const std::string finer = "compound --points '0,0 1,0 2,1' --alpha0 -1 --alpha1 -1 --integrator rk4 --h 0.3";
  EXPECT_EQ(run_lac_stdout(finer).status, 3);
  const test::CliRun loose = run_lac_stdout(finer + " --accept 1e-3");
  EXPECT_EQ(loose.status, 0) << loose.out;
  EXPECT_NE(loose.out.find("\"status\": \"tolerance_not_met\""), std::string::npos) << loose.out;
}

// --max-evaluations of g2 (the whole call's integrand evaluations): spent, exit 3 with status
// max_iterations; out of [1, 1e12], exit 2 naming it.
TEST(CliExitStatus, G2EvaluationBudget) {
  const test::CliRun spent = run_lac_stdout(kG2 + "--alpha -0.5 --max-evaluations 50");
  EXPECT_EQ(spent.status, 3) << spent.out;
  EXPECT_NE(spent.out.find("\"status\": \"max_iterations\""), std::string::npos) << spent.out;
  const test::CliRun bad = run_lac_stderr(kG2 + "--alpha -0.5 --max-evaluations 0");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("max-evaluations"), std::string::npos) << bad.out;
  EXPECT_EQ(run_lac_stdout(kG2 + "--alpha -0.5 --max-evaluations 1e6").status, 0);
}

}  // namespace
}  // namespace lac
