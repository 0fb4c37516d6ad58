// The `lac` command line as a function: parse, run one subcommand, map errors to exit status.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/command.hpp"
#include "lac/common/error.hpp"
#include "lac/version.hpp"

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

std::string* add_format_option(CLI::App& sub) {
  auto* target = owned<std::string>("json");
  sub.add_option("--format", *target, "Output format: json | csv")->check(CLI::IsMember({"json", "csv"}))->capture_default_str();
  return target;
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
      throw_input_error("lac", parameter, "'" + echo_value(text) + "' is not a comma-separated list of " + std::to_string(expected) + " numbers");
    v.push_back(x);
  }
  if (v.size() != expected)
    throw_input_error("lac", parameter, "'" + echo_value(text) + "' has " + std::to_string(v.size()) + " numbers; expected " + std::to_string(expected));
  for (double x : v) require_finite("lac", parameter, x);
  return v;
}

std::vector<std::vector<double>> parse_points(const std::string& text, size_t expected_points, const std::string& parameter) {
  std::vector<std::vector<double>> pts;
  std::stringstream ss(text);
  std::string item;
  while (ss >> item) pts.push_back(parse_tuple(item, 2, parameter));
  if (pts.size() != expected_points)
    throw_input_error("lac", parameter, "'" + echo_value(text) + "' has " + std::to_string(pts.size()) + " points; expected " + std::to_string(expected_points) + " as \"x0,y0 x1,y1 ...\"");
  return pts;
}

std::vector<std::complex<double>> parse_point_list(const std::string& text, const std::string& parameter) {
  std::vector<std::complex<double>> pts;
  std::stringstream ss(text);
  std::string item;
  while (ss >> item) {
    const std::vector<double> xy = parse_tuple(item, 2, parameter);
    pts.emplace_back(xy[0], xy[1]);
  }
  return pts;
}

std::vector<double> parse_number_list(const std::string& text, const std::string& parameter) {
  std::string spaced = text;
  for (char& c : spaced) c = c == ',' ? ' ' : c;
  std::vector<double> out;
  std::stringstream ss(spaced);
  std::string item;
  while (ss >> item) out.push_back(parse_tuple(item, 1, parameter)[0]);
  return out;
}

namespace {

/// Whether the running subcommand printed a result that is not usable (reset by run()).
bool& unusable_recorded() {
  static bool any = false;
  return any;
}

/// Edit distance with adjacent transpositions counted as one edit ("alpah" -> "alpha": 1).
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

std::string strip_dashes(const std::string& s) { return s.substr(std::min(s.find_first_not_of('-'), s.size())); }

/// The candidate closest to `typed`, if it is close enough to be a likely typo: no guess for
/// names of 1 or 2 characters, at most 1 edit up to 5 characters, else 2. Options are compared
/// with options of the same kind (--long with --long, -s with -s), without their dashes.
std::optional<std::string> closest_in(const std::string& typed, const std::vector<std::string>& candidates) {
  const std::string t = strip_dashes(typed);
  const size_t dashes = typed.size() - t.size();
  const size_t limit = t.size() <= 2 ? 0 : t.size() <= 5 ? 1 : 2;
  std::optional<std::string> best;
  size_t best_distance = limit + 1;
  for (const std::string& c : candidates) {
    const std::string name = strip_dashes(c);
    if (c.size() - name.size() != dashes) continue;
    const size_t dist = edit_distance(t, name);
    if (dist < best_distance) best = c, best_distance = dist;
  }
  return best;
}

/// `lac`, `lac g1`, `lac special gamma-inc`: the command `app` (a parsed (sub)command) names.
std::string command_name(const CLI::App* app) {
  std::string name;
  for (; app != nullptr; app = app->get_parent())
    name = app->get_parent() == nullptr ? "lac" + name : " " + app->get_name() + name;
  return name;
}

/// The deepest subcommand the command line selected (the app itself if none).
CLI::App* selected_command(CLI::App& app) {
  CLI::App* cmd = &app;
  while (!cmd->get_subcommands().empty()) cmd = cmd->get_subcommands().front();
  return cmd;
}

bool is_number(const std::string& s) {
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return !s.empty() && end != s.c_str() && *end == '\0';
}

/// "unknown option --alpah; did you mean --alpha?" for the first argument CLI11 could not place,
/// with the (sub)command that was given it; nullopt if every argument was placed.
std::optional<std::string> unplaced_argument(CLI::App& app) {
  std::vector<CLI::App*> chain{&app};
  while (!chain.back()->get_subcommands().empty()) chain.push_back(chain.back()->get_subcommands().front());
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {  // the deepest command first
    CLI::App* cmd = *it;
    const std::vector<std::string> left = cmd->remaining();
    if (left.empty()) continue;
    const std::string prefix = command_name(cmd) + ": ";
    std::vector<std::string> children;
    for (const CLI::App* sub : cmd->get_subcommands([](const CLI::App*) { return true; })) children.push_back(sub->get_name());
    // A command with subcommands ("special") expects one first: "special gamma-in --a 1".
    const std::string& first = left.front();
    if (!children.empty() && !first.empty() && first[0] != '-') {
      const auto guess = closest_in(first, children);
      return prefix + "unknown subcommand \"" + first + "\"" +
             (guess ? "; did you mean \"" + *guess + "\"?" : " (see " + command_name(cmd) + " --help)");
    }
    // Otherwise an option-like argument first: a value after it ("--alpah 1") is only stranded by it.
    for (const std::string& arg : left) {
      if (arg.size() < 2 || arg[0] != '-' || is_number(arg)) continue;
      const std::string name = arg.substr(0, arg.find('='));
      std::vector<std::string> names;
      for (const CLI::Option* o : cmd->get_options()) {
        for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
        for (const std::string& s : o->get_snames()) names.push_back("-" + s);
      }
      const auto guess = closest_in(name, names);
      return prefix + "unknown option " + name + (guess ? "; did you mean " + *guess + "?" : " (see " + command_name(cmd) + " --help)");
    }
    return prefix + "unexpected argument \"" + first + "\" (see " + command_name(cmd) + " --help)";
  }
  return std::nullopt;
}

/// One printable line: newlines of a multi-line message become spaces, other control characters
/// (which an echoed argument may hold) are written as \xNN.
std::string one_line(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += ' ';
    } else if (u < 0x20 || u == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += c;
    }
  }
  return out;
}

bool& invalid_rows() {
  static bool any = false;
  return any;
}

}  // namespace

std::string without_lac_prefix(const std::string& message) {
  if (message.rfind("lac", 0) == 0 && message.size() > 3 && (message[3] == ':' || message[3] == ' ')) {
    const size_t colon = message.find(": ");
    if (colon != std::string::npos) return message.substr(colon + 2);
  }
  return message;
}

std::string without_command_prefix(const std::string& message, const std::string& command) {
  std::string text = without_lac_prefix(message);
  if (!command.empty() && text.size() > command.size() + 2 && text.compare(0, command.size(), command) == 0 &&
      text.compare(command.size(), 2, ": ") == 0)
    text.erase(0, command.size() + 2);
  return text;
}

std::string echo_value(const std::string& value, size_t max_chars) {
  std::string out;
  size_t chars = 0;
  for (size_t i = 0; i < value.size(); ++i) {
    const auto u = static_cast<unsigned char>(value[i]);
    if ((u & 0xC0) != 0x80 && chars++ == max_chars) return out + "…";  // counted by UTF-8 lead bytes
    if (u < 0x20 || u == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += value[i];
    }
  }
  return out;
}

std::optional<std::string> closest_name(const std::string& typed, const std::vector<std::string>& candidates) {
  return closest_in(typed, candidates);
}

void record_status(Status status) { unusable_recorded() = unusable_recorded() || !lac::usable(status); }
void record_invalid_row() { invalid_rows() = true; }

}  // namespace lac::cli

int lac::cli::run(int argc, char** argv) {
  struct FreeOptionStorage {  // declared before the app: runs after the app is destroyed
    ~FreeOptionStorage() { lac::cli::option_storage().clear(); }
  } free_storage;
  unusable_recorded() = false;
  invalid_rows() = false;
  CLI::App app{"lac — log-aesthetic curves: evaluate curves, build segments, reproduce published tables.\n"
               "Run `lac <command> --help` for each command's options.\n"
               "Exit status: 0 usable result, 2 invalid input, 3 no usable result (see the printed status)."};
  app.set_version_flag("--version", std::string("lac ") + lac::version);
  app.require_subcommand(1);
  app.fallthrough(false);
  for (auto setup : lac::cli::command_registry()) setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    if (const auto unplaced = unplaced_argument(app)) {
      std::cerr << one_line(*unplaced) << "\n";
      return kExitInvalidInput;
    }
    const std::string name = command_name(selected_command(app));
    std::cerr << name << ": " << one_line(e.what()) << " (see " << name << " --help)\n";
    return kExitInvalidInput;
  } catch (const lac::InputError& e) {
    const CLI::App* cmd = selected_command(app);
    std::cerr << command_name(cmd) << ": " << one_line(without_command_prefix(e.what(), cmd->get_name())) << "\n";
    return kExitInvalidInput;
  } catch (const std::exception& e) {
    std::cerr << command_name(selected_command(app)) << ": internal error: " << one_line(e.what()) << "\n";
    return kExitInternalError;
  }
  if (invalid_rows()) return kExitInvalidInput;
  return unusable_recorded() ? kExitNotUsable : kExitOk;
}
