#pragma once
// Runs the `lac` executable of this build folder with arguments; stdout and stderr together.
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

inline CliRun run_lac(const std::string& args) {
  const std::string cmd = std::string(LAC_BINARY_DIR) + "/lac " + args + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe.get())) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe.release());
  return {WEXITSTATUS(status), out};
}

}  // namespace lac::test
