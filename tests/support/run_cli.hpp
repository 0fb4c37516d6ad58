#pragma once
// Runs the `lac` executable of this build folder with arguments: its exit status and output
// (stdout and stderr together, or one of them), or its JSON output checked.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace lac::test {

struct CliRun {
  int status;       ///< exit status
  std::string out;  ///< stdout and stderr
};

/// `redirect`: how the shell routes the streams into `out` (default: both).
inline CliRun run_lac(const std::string& args, const std::string& redirect = " 2>&1") {
  const std::string cmd = std::string(LAC_BINARY_DIR) + "/lac " + args + redirect;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe.get())) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe.release());
  return {WEXITSTATUS(status), out};
}

/// As run_lac, `out` holding stderr only (stdout discarded): the error line of a failed call.
inline CliRun run_lac_stderr(const std::string& args) { return run_lac(args, " 2>&1 >/dev/null"); }

/// As run_lac, `out` holding stdout only (stderr discarded).
inline CliRun run_lac_stdout(const std::string& args) { return run_lac(args, " 2>/dev/null"); }

/// Runs `lac args`, expects `exit_status` and returns the output parsed as JSON (a test failure
/// and an empty value when it is not JSON).
inline nlohmann::ordered_json run_lac_json(const std::string& args, int exit_status = 0) {
  const CliRun run = run_lac(args);
  EXPECT_EQ(run.status, exit_status) << args << "\n" << run.out;
  try {
    return nlohmann::ordered_json::parse(run.out);
  } catch (const nlohmann::json::exception& e) {
    ADD_FAILURE() << args << ": not JSON (" << e.what() << ")\n" << run.out;
    return {};
  }
}

}  // namespace lac::test
