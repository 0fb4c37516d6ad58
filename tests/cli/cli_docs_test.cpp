// docs/cli.md cannot rot: every command line of its ```console blocks ("$ …") runs, in order, in
// one temporary folder (with the lac of this build first on PATH and the source's scripts/ linked
// there), and must exit with the documented status: the "# exit N" at the end of the line, else 0.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

struct Example {
  int line;
  std::string command;
  int exit_status;
};

std::vector<Example> console_commands(const std::string& path) {
  std::ifstream in(path);
  std::vector<Example> out;
  bool console = false;
  const std::regex exit_comment(R"(\s+#\s*exit\s+(\d+)\s*$)");
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.rfind("```", 0) == 0) {
      console = !console && line == "```console";
      continue;
    }
    if (!console || line.rfind("$ ", 0) != 0) continue;
    std::string command = line.substr(2);
    int status = 0;
    std::smatch m;
    if (std::regex_search(command, m, exit_comment)) {
      status = std::stoi(m[1]);
      command = command.substr(0, m.position(0));
    }
    out.push_back({n, command, status});
  }
  return out;
}

/// Single quotes for the shell.
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

TEST(CliDocs, EveryCommandExitsAsDocumented) {
  const std::string doc = std::string(LAC_SOURCE_DIR) + "/docs/cli.md";
  const std::vector<Example> examples = console_commands(doc);
  ASSERT_GE(examples.size(), 10u) << doc;
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("lac_cli_docs_test_" + std::to_string(::getpid()));  // own dir per run
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::create_directory_symlink(fs::path(LAC_SOURCE_DIR) / "scripts", dir / "scripts");
  int lac_commands = 0;
  for (const Example& e : examples) {
    const std::string shell = "cd " + quoted(dir.string()) + " && PATH=" + quoted(LAC_BINARY_DIR) +
                              ":\"$PATH\" bash -o pipefail -c " + quoted(e.command) + " >/dev/null 2>&1";
    const int raw = std::system(shell.c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << "docs/cli.md:" << e.line << ": " << e.command;
    EXPECT_EQ(WEXITSTATUS(raw), e.exit_status) << "docs/cli.md:" << e.line << ": " << e.command;
    lac_commands += e.command.find("lac ") != std::string::npos;
  }
  EXPECT_GE(lac_commands, 10);
  fs::remove_all(dir);
}

}  // namespace
