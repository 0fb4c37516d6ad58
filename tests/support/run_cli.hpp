#pragma once
// Runs the `lac` executable of this build folder with arguments: its exit status and output
// (stdout and stderr together, or one of them).
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <memory>
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

}  // namespace lac::test
