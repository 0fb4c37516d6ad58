#pragma once
// How a subcommand runs: one problem from its options, or with --batch FILE one problem per CSV
// row (docs/cli.md "Batch mode"). The header names options without their dashes; each row's
// cells are parsed by the subcommand's own CLI11 option objects (the same conversions and checks
// as on the command line, the app is not rebuilt per row); an empty cell, or a missing column,
// keeps the command line's value. Output: JSON Lines (one compact report per row, "row" first)
// or, with --format csv, one header and one CSV row per problem (`row` and the summary keys). An
// invalid row prints {"row": n, "status": "invalid_input", "message": …} and the batch goes on;
// the exit status is then 2, else 3 if a result is not usable (cli/command.hpp).
#include <functional>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"

namespace lac::cli {

/// The row of the batch being solved (1-based), 0 outside batch mode.
long current_batch_row();

/// Runs one problem (`solve` on the options as parsed) or the batch of `common.batch`, restoring
/// the parsed options with `restore` before each row.
void run_command(CLI::App& sub, const CommonArgs& common, const std::function<Report()>& solve,
                 const std::function<void()>& restore);

/// Sets the callback of `sub`, whose options write into `args` (with a member `common`), to
/// run_command with `solve(args)`.
template <class Args>
void set_solver(CLI::App& sub, Args& args, Report (*solve)(const Args&)) {
  sub.callback([&sub, &args, solve] {
    const Args parsed = args;
    run_command(sub, args.common, [&args, solve] { return solve(args); }, [&args, &parsed] { args = parsed; });
  });
}

}  // namespace lac::cli
