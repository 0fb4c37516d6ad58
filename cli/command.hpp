#pragma once
// Subcommand registration: each cli/<name>.cpp defines a setup function and registers it
// with `LAC_REGISTER_COMMAND(setup)`; main() adds them all. Invalid input anywhere is an
// InputError (or a CLI11 parse error): one line on stderr, exit status 2.
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lac::cli {

using CommandSetup = void (*)(CLI::App& app);

/// Runs the command line: 0 on success, 2 on invalid input (one line on stderr naming the
/// parameter), 1 on an internal error. Used by main() and by the fuzz targets.
int run(int argc, char** argv);

std::vector<CommandSetup>& command_registry();

struct CommandRegistrar {
  explicit CommandRegistrar(CommandSetup setup) { command_registry().push_back(setup); }
};

#define LAC_CONCAT_INNER(a, b) a##b
#define LAC_CONCAT(a, b) LAC_CONCAT_INNER(a, b)
#define LAC_REGISTER_COMMAND(setup) \
  static const ::lac::cli::CommandRegistrar LAC_CONCAT(lac_command_registrar_, __LINE__){setup}

/// Storage for option targets: lives until lac::cli::run returns (then freed, so repeated
/// calls neither leak nor grow). Use instead of `new` in a subcommand's setup function.
std::vector<std::shared_ptr<void>>& option_storage();
template <class T, class... Args>
T* owned(Args&&... args) {
  auto p = std::make_shared<T>(std::forward<Args>(args)...);
  option_storage().push_back(p);
  return p.get();
}

/// Gets or creates a parent subcommand (e.g. "special") so that several files can add
/// children to it (e.g. "special gamma-inc", "special erfi-inv").
CLI::App& parent_command(CLI::App& app, const std::string& name, const std::string& description);

/// Output formats shared by subcommands.
enum class Format { json, csv, table, svg };
/// Adds `--format` with the given allowed names (first is the default) and returns its target.
std::string* add_format_option(CLI::App& sub, std::vector<std::string> allowed);
Format parse_format(const std::string& name);

/// Parses "x,y" or "x,y,z" into doubles; InputError naming `parameter` on bad text.
std::vector<double> parse_tuple(const std::string& text, size_t expected, const std::string& parameter);
/// Parses a point list "x0,y0 x1,y1 ..." of 2-D points.
std::vector<std::vector<double>> parse_points(const std::string& text, size_t expected_points, const std::string& parameter);

}  // namespace lac::cli
