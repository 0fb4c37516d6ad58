// The `lac` command line as a function: parse, run one subcommand, map errors to exit status.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/command.hpp"
#include "lac/common/error.hpp"

namespace lac::cli {

std::vector<CommandSetup>& command_registry() {
  static std::vector<CommandSetup> r;
  return r;
}

CLI::App& parent_command(CLI::App& app, const std::string& name, const std::string& description) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return *sub;
  CLI::App* sub = app.add_subcommand(name, description);
  sub->require_subcommand(1);
  return *sub;
}

std::vector<std::shared_ptr<void>>& option_storage() {
  static std::vector<std::shared_ptr<void>> storage;
  return storage;
}

std::string* add_format_option(CLI::App& sub, std::vector<std::string> allowed) {
  auto* target = owned<std::string>(allowed.front());
  sub.add_option("--format", *target, "Output format")->check(CLI::IsMember(allowed))->capture_default_str();
  return target;
}

Format parse_format(const std::string& name) {
  if (name == "json") return Format::json;
  if (name == "csv") return Format::csv;
  if (name == "svg") return Format::svg;
  return Format::table;
}

std::vector<double> parse_tuple(const std::string& text, size_t expected, const std::string& parameter) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos)
      throw_input_error("lac", parameter, "'" + text + "' is not a comma-separated list of " + std::to_string(expected) + " numbers");
    v.push_back(x);
  }
  if (v.size() != expected)
    throw_input_error("lac", parameter, "'" + text + "' has " + std::to_string(v.size()) + " numbers; expected " + std::to_string(expected));
  for (double x : v) require_finite("lac", parameter, x);
  return v;
}

std::vector<std::vector<double>> parse_points(const std::string& text, size_t expected_points, const std::string& parameter) {
  std::vector<std::vector<double>> pts;
  std::stringstream ss(text);
  std::string item;
  while (ss >> item) pts.push_back(parse_tuple(item, 2, parameter));
  if (pts.size() != expected_points)
    throw_input_error("lac", parameter, "'" + text + "' has " + std::to_string(pts.size()) + " points; expected " + std::to_string(expected_points) + " as \"x0,y0 x1,y1 ...\"");
  return pts;
}

}  // namespace lac::cli

int lac::cli::run(int argc, char** argv) {
  struct FreeOptionStorage {  // declared before the app: runs after the app is destroyed
    ~FreeOptionStorage() { lac::cli::option_storage().clear(); }
  } free_storage;
  CLI::App app{"lac — log-aesthetic curves: evaluate curves, build segments, reproduce published tables.\n"
               "Run `lac <command> --help` for each command's options."};
  app.require_subcommand(1);
  app.fallthrough(false);
  for (auto setup : lac::cli::command_registry()) setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    for (char& c : what) if (c == '\n') c = ' ';
    std::cerr << "lac: error: " << what << " (see --help)\n";
    return 2;
  } catch (const lac::InputError& e) {
    std::cerr << "lac: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "lac: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
