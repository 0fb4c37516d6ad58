#pragma once
// Subcommand registration: each cli/<name>.cpp defines a setup function and registers it
// with `LAC_REGISTER_COMMAND(setup)`; main() adds them all.
//
// Exit status of `lac` (lac::cli::run), the same for every subcommand:
//   0  a usable result was printed (also --help, --version);
//   2  invalid input: an InputError or a CLI11 parse error (unknown subcommand or option, with
//      the closest valid name suggested; missing or malformed value): one line on stderr,
//      `lac <subcommand>: …`, naming the parameter;
//      With --batch: a row with invalid input prints its error object and the batch goes on;
//      the exit status is 2 at the end (record_invalid_row()).
//   3  the command ran and printed its result, but the result is not usable
//      (lac::usable(status) is false: no_solution, not_converged, max_iterations,
//      numerical_failure). The rule: a subcommand calls record_status() with the status of
//      every result it prints — a report's status (cli/report.hpp records it), each sampled
//      point, a special function's value — and the exit status is 3 if any of them is not
//      usable (and no batch row was invalid).
//   1  an internal error (an unexpected exception): a bug.
#include <CLI/CLI.hpp>
#include <complex>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lac/common/status.hpp"

namespace lac::cli {

using CommandSetup = void (*)(CLI::App& app);

/// Runs the command line and returns the exit status above (0, 1, 2 or 3). Used by main() and
/// by the fuzz targets.
int run(int argc, char** argv);

/// Exit statuses of lac::cli::run.
inline constexpr int kExitOk = 0, kExitInternalError = 1, kExitInvalidInput = 2, kExitNotUsable = 3;

/// Records the status of a result the running subcommand prints; run() exits with 3 if any
/// recorded status is not usable. Call it once per printed result (see the rule above).
void record_status(Status status);
/// Records a batch row with invalid input: run() then exits with 2.
void record_invalid_row();

/// An InputError's message without the "lac …: " its CLI thrower put in front (run() adds the
/// command's own); a library function's name ("LaCurve: …") stays.
std::string without_lac_prefix(const std::string& message);

/// An InputError's message as `lac <command>: …` prints it: without the "lac …: " of a CLI
/// thrower and without a leading "<command>: " of the library (e.g. "g1: alpha …" under
/// `lac g1`), so the command is named once.
std::string without_command_prefix(const std::string& message, const std::string& command);

/// A user's value for an error message: control characters (NUL included, which would end the
/// message) as \xNN, and at most `max_chars` characters of it followed by "…".
std::string echo_value(const std::string& value, size_t max_chars = 60);

/// The candidate closest to `typed`, if close enough to be a likely typo (no guess for names of
/// 1 or 2 characters, at most 1 edit up to 5 characters, else 2); names are compared without
/// leading dashes, and only with candidates having as many dashes as `typed`.
std::optional<std::string> closest_name(const std::string& typed, const std::vector<std::string>& candidates);

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

/// Adds `--format json|csv` (json the default) to a command without a report (`special …`) and
/// returns its target.
std::string* add_format_option(CLI::App& sub);

/// Parses "x,y" or "x,y,z" into doubles; InputError naming `parameter` on bad text.
std::vector<double> parse_tuple(const std::string& text, size_t expected, const std::string& parameter);
/// Parses a point list "x0,y0 x1,y1 ..." of 2-D points.
std::vector<std::vector<double>> parse_points(const std::string& text, size_t expected_points, const std::string& parameter);
/// Parses a point list "x0,y0 x1,y1 ..." of any length.
std::vector<std::complex<double>> parse_point_list(const std::string& text, const std::string& parameter);
/// Parses a list of numbers "v0 v1 ..." (spaces or commas between them).
std::vector<double> parse_number_list(const std::string& text, const std::string& parameter);

}  // namespace lac::cli
