// libFuzzer target: `lac` argument parsing and execution for every registered subcommand.
// Input layout: byte 0 picks a command path among the registered ones in sorted order (e.g.
// "eval", "special erfi-inv"; 0xff: none, the arguments name it); the rest is split on NUL and newline into arguments (spaces stay inside
// an argument, as in --points "x0,y0 x1,y1 x2,y2"). lac::cli::run must return 0, 2 (invalid
// input) or 3 (no usable result); 1 (internal error), any other value or an escaping exception
// is a finding.
#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "fuzz/fuzz_support.hpp"

namespace {

/// Every runnable command path: top-level subcommands and the children of parent commands.
std::vector<std::vector<std::string>> command_paths() {
  CLI::App app;
  for (auto setup : lac::cli::command_registry()) setup(app);
  std::vector<std::vector<std::string>> paths;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    auto children = sub->get_subcommands([](CLI::App*) { return true; });
    if (children.empty()) paths.push_back({sub->get_name()});
    for (CLI::App* child : children) paths.push_back({sub->get_name(), child->get_name()});
  }
  std::sort(paths.begin(), paths.end());  // independent of registration (link) order
  return paths;
}

class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Silence the commands' output; sanitizer reports and findings go to file descriptor 2.
  static NullBuffer null_buffer;
  std::cout.rdbuf(&null_buffer);
  if (!std::freopen("/dev/null", "w", stdout)) return 0;
  // `--batch -` reads stdin: an empty one, so that a call never waits for input.
  if (!std::freopen("/dev/null", "r", stdin)) return 0;
  return 0;
}

int lac::fuzz::fuzz_one(lac::fuzz::FuzzInput& in) {
  const uint8_t* data = in.cursor();
  const size_t size = in.remaining();
  static const std::vector<std::vector<std::string>> paths = command_paths();
  if (size == 0 || paths.empty()) return 0;
  std::vector<std::string> args{"lac"};
  if (data[0] != 0xff) {  // 0xff: the input spells the command itself (seed corpus)
    const auto& path = paths[data[0] % paths.size()];
    args.insert(args.end(), path.begin(), path.end());
  }
  std::string current;
  for (size_t i = 1; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\0' || c == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(c);
    }
  }
  if (!current.empty()) args.push_back(current);
  if (args.size() > 64) return 0;  // argv length is not what we test

  std::vector<char*> argv;
  std::string command_line;
  for (auto& a : args) {
    argv.push_back(a.data());
    command_line += "'" + a + "' ";
  }
  argv.push_back(nullptr);

  std::ostringstream errors;
  auto* old_cerr = std::cerr.rdbuf(errors.rdbuf());
  int rc = 0;
  {
    lac::fuzz::CallTimer timer("lac " + command_line);
    try {
      rc = lac::cli::run(static_cast<int>(args.size()), argv.data());
    } catch (const std::exception& e) {
      lac::fuzz::finding("EXCEPTION", command_line + "-> escaped lac::cli::run: " + e.what());
    } catch (...) {
      lac::fuzz::finding("EXCEPTION", command_line + "-> non-std exception escaped lac::cli::run");
    }
  }
  std::cerr.rdbuf(old_cerr);
  if (rc == 1) lac::fuzz::finding("INTERNAL_ERROR", command_line + "-> exit 1: " + errors.str());
  if (rc != 0 && rc != 2 && rc != 3) lac::fuzz::finding("EXIT_STATUS", command_line + "-> exit " + std::to_string(rc));
  if (rc == 2) {
    // Invalid input: exactly one line on stderr.
    const std::string e = errors.str();
    if (e.empty() || e.find('\n') != e.size() - 1)
      lac::fuzz::finding("ERROR_LINE", command_line + "-> exit 2 with stderr '" + e + "' (want one line)");
    // Named once: `lac: …` or `lac <subcommand>: …`, never "lac: error: lac: …". Only the prefix is
    // checked: the rest may echo the arguments, which can hold any text.
    const size_t colon = e.find(": ");
    const std::string rest = colon == std::string::npos ? "" : e.substr(colon + 2);
    if (e.rfind("lac", 0) != 0 || colon == std::string::npos || e.substr(0, colon).find(':') != std::string::npos ||
        rest.rfind("lac", 0) == 0 || rest.rfind("error", 0) == 0)
      lac::fuzz::finding("ERROR_LINE", command_line + "-> exit 2 with stderr '" + e + "' (want one `lac …:` prefix)");
  }
  return 0;
}
