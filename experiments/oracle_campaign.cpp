// Correctness campaign with an independent oracle (docs/robustness.md, "Oracle campaign"):
// N random problems per construction, every usable result re-integrated in long double by
// fuzz/oracle_check.hpp and every no_solution checked against its proof's condition
// (fuzz/oracle_campaign.hpp). Writes results/robustness_oracle.{md,csv} (counts, worst verified
// error / accept), results/robustness_oracle_timing.{md,csv} (problems per second) and the
// oracle section of results/robustness.md. Exit status 1 when any construction has a
// wrong-but-usable result, a false no-curve answer or an unexpected exception.
//
//   exp_oracle_campaign --construction all --count 1000 --seed 1 --threads 2         (main job)
//   exp_oracle_campaign --long --revision R --construction g1 --count 1000000      (long campaign)
//
// --long writes one file per construction and slice, results/oracle_long_<construction>.{md,csv}
// (--first 0) or oracle_long_<construction>_from_<first>.{md,csv} (its row, the code revision R
// the binary was built from, its findings; times in _timing), and then
// results/robustness_oracle_long.md, one row per construction summing its slices: a campaign of
// 10^6 problems per construction takes hours for some, so it is run construction by construction
// and slice by slice (scripts/oracle_long.sh), and each row says which code it checked.
#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "fuzz/oracle_campaign.hpp"
#include "io/table.hpp"

namespace {

using namespace lac;

std::string examples(const std::vector<oracle::Example>& v) {
  std::string out;
  for (const auto& e : v) out += "\n- problem " + std::to_string(e.index) + ": `" + e.text + "`";
  return out;
}

/// Replaces the text between the oracle markers of results/robustness.md (appends the section
/// when the markers are missing; creates the file when it is missing).
void splice_section(const std::filesystem::path& file, const std::string& section) {
  const std::string begin = "<!-- oracle campaign: begin (written by exp_oracle_campaign) -->";
  const std::string end = "<!-- oracle campaign: end -->";
  std::string text;
  if (std::ifstream in(file); in) {
    std::stringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  const auto a = text.find(begin), b = text.find(end);
  const std::string block = begin + "\n" + section + end + "\n";
  if (a != std::string::npos && b != std::string::npos && b > a)
    text = text.substr(0, a) + block + text.substr(b + end.size() + (text.compare(b + end.size(), 1, "\n") == 0 ? 1 : 0));
  else
    text += (text.empty() || text.back() == '\n' ? "\n" : "\n\n") + block;
  std::ofstream(file) << text;
}

/// The file stem of a long-campaign slice: oracle_long_<name> from problem 0, else
/// oracle_long_<name>_from_<first>.
std::string long_stem(const std::string& name, long first) {
  return "oracle_long_" + name + (first == 0 ? "" : "_from_" + std::to_string(first));
}

/// The cells of the table row of `name` in a slice's .md file (its line starting "| name |").
std::vector<std::string> long_row(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| " + name + " |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line.substr(1));
    for (std::string cell; std::getline(ss, cell, '|');) {
      const auto a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
    }
    return cells;
  }
  return {};
}

/// One summary row from the rows of a construction's slices (columns as the slices' tables):
/// counts summed, other_statuses summed per status, the worst ratio the largest, the revisions
/// and seeds listed, first the smallest. `coverage` says which problems the slices cover.
std::vector<std::string> sum_slices(const std::vector<std::string>& columns, std::vector<std::vector<std::string>> rows,
                                    std::string& coverage) {
  auto col = [&](const std::string& c) { return static_cast<size_t>(std::find(columns.begin(), columns.end(), c) - columns.begin()); };
  const size_t first = col("first"), problems = col("problems"), seed = col("seed");
  std::sort(rows.begin(), rows.end(), [&](const auto& a, const auto& b) {
    return std::make_pair(a[seed], std::stol(a[first])) < std::make_pair(b[seed], std::stol(b[first]));
  });
  std::vector<std::string> sum = rows.front();
  std::map<std::string, long> statuses;
  double worst = -1;
  for (size_t c = 0; c < columns.size(); ++c) {
    const std::string& name = columns[c];
    if (name == "construction" || c == first) continue;
    if (name == "revision" || c == seed) {
      std::vector<std::string> seen;
      for (const auto& r : rows)
        if (std::find(seen.begin(), seen.end(), r[c]) == seen.end()) seen.push_back(r[c]);
      sum[c] = seen.front();
      for (size_t i = 1; i < seen.size(); ++i) sum[c] += " " + seen[i];
    } else if (name == "other_statuses") {
      for (const auto& r : rows) {
        std::stringstream ss(r[c]);
        for (std::string item; std::getline(ss, item, ',');) {
          std::stringstream is(item);
          std::string key;
          long n = 0;
          if (is >> key >> n) statuses[key] += n;
        }
      }
      sum[c].clear();
      for (const auto& [k, n] : statuses) sum[c] += (sum[c].empty() ? "" : ", ") + k + " " + std::to_string(n);
      if (sum[c].empty()) sum[c] = "0";
    } else if (name == "worst_error_over_accept") {
      for (const auto& r : rows)
        if (const double w = std::stod(r[c]); w > worst) worst = w, sum[c] = r[c];
    } else {
      long total = 0;
      for (const auto& r : rows) total += std::stol(r[c]);
      sum[c] = std::to_string(total);
    }
  }
  // Coverage: the slices in order, and whether they tile first … first + problems − 1 of one seed.
  bool tiled = true;
  coverage.clear();
  for (size_t i = 0; i < rows.size(); ++i) {
    const long f = std::stol(rows[i][first]), n = std::stol(rows[i][problems]);
    coverage += (i ? ", " : "") + std::to_string(f) + "…" + std::to_string(f + n - 1);
    if (i > 0 && (rows[i][seed] != rows[i - 1][seed] ||
                  f != std::stol(rows[i - 1][first]) + std::stol(rows[i - 1][problems])))
      tiled = false;
  }
  coverage += tiled ? " (contiguous)" : " (NOT contiguous: overlapping, gapped or of different seeds; `problems` counts every slice)";
  return sum;
}

/// Rewrites <out>/robustness_oracle_long.md: per construction, the sum of the rows of its
/// slices <out>/oracle_long_<name>.md and <out>/oracle_long_<name>_from_<first>.md.
void write_long_summary(const std::filesystem::path& out, const std::vector<std::string>& columns,
                        const std::string& header, const std::string& description) {
  std::vector<std::string> lines, notes;
  for (const std::string& name : oracle::constructions()) {
    std::vector<std::vector<std::string>> rows;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
      const std::string file = entry.path().filename().string(), stem = "oracle_long_" + name;
      const bool whole = file == stem + ".md";
      const bool slice = file.rfind(stem + "_from_", 0) == 0 && file.size() > 3 && file.ends_with(".md") &&
                         file.find_first_not_of("0123456789", stem.size() + 6) == file.size() - 3;
      if (!whole && !slice) continue;
      if (auto row = long_row(entry.path(), name); row.size() == columns.size()) rows.push_back(std::move(row));
    }
    if (rows.empty()) continue;
    std::string coverage;
    const auto sum = sum_slices(columns, rows, coverage);
    std::string line = "|";
    for (const auto& cell : sum) line += " " + cell + " |";
    lines.push_back(line);
    if (rows.size() > 1) notes.push_back("- " + name + ": " + std::to_string(rows.size()) + " slices, problems " + coverage);
  }
  std::ofstream md(out / "robustness_oracle_long.md");
  md << "# Robustness: long oracle campaign\n\n"
     << "Written by `exp_oracle_campaign --long` (one row per construction, the sum of its slices; each slice by the "
        "command in its own file, oracle_long_<construction>.md from problem 0 or "
        "oracle_long_<construction>_from_<first>.md, with its findings) — do not edit by hand; rerun the "
        "commands.\n\n"
     << description << "\n\n" << header;
  for (const auto& l : lines) md << l << "\n";
  if (!notes.empty()) {
    md << "\nSlices:\n\n";
    for (const auto& n : notes) md << n << "\n";
  }
}

/// What the campaign's tables mean (the description of every table it writes).
std::string campaign_description() {
  return
      "Random problems per construction (generators in fuzz/oracle_campaign.hpp; problem i has its own seed), each "
      "result checked end to end by an independent computation in long double (fuzz/oracle_check.hpp: the linear-q "
      "law written afresh, Boost Gauss–Kronrod on pieces of at most 1.5 rad, in log|q| near steep ends; Boost.Odeint "
      "RKF78 for the quadratic curve). A usable result is *wrong* when a condition misses by more than its accept bound "
      "(summary.accept relative to the chord for constructions; 1e-6 of the arc length for eval and quadratic "
      "positions): end points, end tangents, end curvatures (G2), joints (position, tangent; curvature for G2; dκ/ds "
      "for compound), each segment's α, the total turning with its winding (g1, compound) and the turning share r "
      "(compound). `silent_wrong`: the wrong results whose own reported error (summary.error, or a position's "
      "error estimate) was within accept too, or unset: nothing in the result tells that it is wrong. A no_solution is *false* when the proof's condition (recomputed) does not hold for every winding of "
      "the scope its message states, or when the solver itself verifies a curve inside that scope "
      "(docs/robustness.md). `unverified`: usable results the oracle could not evaluate (no verdict); "
      "`no_curve_by_scan`: G1 no_solution resting at some winding on the solver's certified scan of the "
      "alpha >= 0 shapes (docs/g1_hermite.md), which the oracle does not re-derive; each was tried by the auto, "
      "toms748 and bisection solvers at that winding and none verified a curve (its claim is tested against "
      "tanh-sinh end points by G1Hermite.SearchUpToMaxTurningStatesItsScope); "
      "`curve_at_other_winding`: no_solution whose data have a verified curve at a winding in −2…2 outside the "
      "message's scope (information, not a failure). Both `wrong_but_usable` and `false_no_curve` must be 0.";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Correctness campaign: random problems per construction checked by an independent long-double oracle"};
  std::string construction = "all", out = "results";
  long count = 1000, first = 0;
  unsigned long seed = 1;
  int threads = 2;
  bool write = true;
  app.add_option("--construction", construction, "g1, g2, scurve, chain, compound, quadratic, eval, space, or all");
  app.add_option("--count", count, "problems per construction")->check(CLI::Range(1L, 1000000000L));
  app.add_option("--first", first, "index of the first problem (a slice of a campaign)")->check(CLI::NonNegativeNumber);
  app.add_option("--seed", seed, "campaign seed");
  app.add_option("--threads", threads, "TBB threads")->check(CLI::Range(1, 256));
  app.add_option("--out", out, "folder of the result tables");
  app.add_flag("!--no-write", write, "print the table only");
  bool fail_on_finding = false;
  app.add_flag("--fail-on-finding", fail_on_finding,
               "exit 1 when a wrong-but-usable result, false no-curve answer or exception is found (the tables "
               "record the findings either way)");
  std::string findings_file;
  std::vector<std::string> counts;
  app.add_option("--counts", counts, "per-construction counts NAME=N (override --count for those named)");
  app.add_option("--findings-file", findings_file, "write every finding (construction, index, kind, input) to this file");
  bool long_campaign = false;
  std::string revision;
  app.add_flag("--long", long_campaign,
               "write results/oracle_long_<construction>.md per construction and the summary "
               "results/robustness_oracle_long.md (instead of the main job's robustness_oracle.md)");
  app.add_option("--revision", revision, "code revision the binary was built from, recorded in each --long row");
  bool summary_only = false;
  app.add_flag("--long-summary", summary_only,
               "only rewrite <out>/robustness_oracle_long.md from the slices in --out (no problem is run)");
  oracle::Settings settings;
  app.add_option("--max-evaluations", settings.max_evaluations,
                 "integrand-evaluation budget of each g2, scurve and compound solve and (where lower than "
                 "the method's own) each quadratic position (default: the library's)")
      ->check(CLI::Range(1L, 1'000'000'000'000L));
  CLI11_PARSE(app, argc, argv);
  if (long_campaign && revision.empty()) {
    std::cerr << "exp_oracle_campaign: --revision: needed with --long (the commit the binary was built from)\n";
    return 2;
  }

  std::vector<std::string> names;
  if (construction == "all") names = oracle::constructions();
  else names = {construction};
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));

  io::Table t, full;
  t.columns = {"construction", "problems", "usable", "verified", "wrong_but_usable", "silent_wrong", "unverified", "no_solution",
               "false_no_curve", "no_curve_by_scan", "curve_at_other_winding", "input_error", "other_statuses", "exceptions",
               "worst_error_over_accept"};
  full.columns = t.columns;
  for (const char* c : {"seconds", "problems_per_second", "us_per_problem_per_thread"}) full.columns.emplace_back(c);
  if (summary_only) {
    io::Table header;
    header.columns = t.columns;
    header.columns.insert(header.columns.begin() + 1, {"revision", "seed", "first"});
    write_long_summary(out, header.columns, header.markdown(), campaign_description());
    return 0;
  }
  std::string findings;
  std::vector<std::pair<std::string, std::string>> findings_of;  // construction, its findings
  bool bad = false;
  for (const auto& name : names) {
    const auto t0 = std::chrono::steady_clock::now();
    long n = count;
    for (const std::string& c : counts)
      if (c.rfind(name + "=", 0) == 0) n = std::stol(c.substr(name.size() + 1));
    const oracle::Tally tally = oracle::run_campaign(name, first, n, seed, settings);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::string others;
    for (const auto& [k, n] : tally.statuses) others += (others.empty() ? "" : ", ") + k + " " + std::to_string(n);
    std::vector<std::string> row{name, std::to_string(tally.problems), std::to_string(tally.usable), std::to_string(tally.verified),
               std::to_string(tally.wrong), std::to_string(tally.silent), std::to_string(tally.unverified), std::to_string(tally.no_solution),
               std::to_string(tally.false_no_curve), std::to_string(tally.by_scan), std::to_string(tally.other_winding), std::to_string(tally.input_error),
               others.empty() ? "0" : others, std::to_string(tally.exceptions), io::sci(tally.worst, 2)};
    t.add_row(row);
    for (const std::string& v : {io::fmt(sec, 3), io::fmt(static_cast<double>(n) / sec, 3),
                                 io::fmt(1e6 * sec * threads / static_cast<double>(n), 3)})
      row.push_back(v);
    full.add_row(row);
    if (!findings_file.empty()) {
      std::ofstream ff(findings_file, std::ios::app);
      for (const auto& e : tally.all) ff << name << "\t" << seed << "\t" << e.index << "\t" << e.text << "\n";
    }
    bad = bad || tally.wrong > 0 || tally.false_no_curve > 0 || tally.exceptions > 0;
    std::cerr << name << ": " << tally.problems << " problems, " << tally.usable << " usable, " << tally.wrong
              << " wrong, " << tally.unverified << " unverified, " << tally.no_solution << " no_solution, "
              << tally.false_no_curve << " false no-curve, " << tally.exceptions << " exceptions, worst "
              << tally.worst << " x accept, " << sec << " s\n";
    std::string f;
    if (!tally.wrong_examples.empty()) f += "\nWrong but usable (first by index):" + examples(tally.wrong_examples) + "\n";
    if (!tally.false_examples.empty()) f += "\nFalse no-curve (first by index):" + examples(tally.false_examples) + "\n";
    if (!tally.exception_examples.empty()) f += "\nExceptions (first by index):" + examples(tally.exception_examples) + "\n";
    if (!tally.unverified_examples.empty())
      f += "\nUnverified by the oracle (not a verdict; first by index):" + examples(tally.unverified_examples) + "\n";
    if (!tally.other_winding_examples.empty())
      f += "\nno_solution with a verified curve at another winding in −2…2, outside the message's scope (first by index):" +
           examples(tally.other_winding_examples) + "\n";
    if (!f.empty()) findings += "\n#### " + name + "\n" + f;
    findings_of.emplace_back(name, f);
  }
  std::cout << t.markdown();
  if (!write) return bad && fail_on_finding ? 1 : 0;

  io::ResultDoc doc;
  doc.title = "Robustness: oracle campaign";
  doc.command = io::command_line(argc, argv);
  doc.description = campaign_description();
  doc.notes = findings.empty() ? "No finding." : "### Findings\n" + findings;
  const std::vector<std::string> timing_columns{"seconds", "problems_per_second", "us_per_problem_per_thread"};
  const std::string timing_description =
      "Wall time of the whole campaign per construction (solver and oracle), with the threads given; µs per "
      "problem per thread = seconds × threads / problems.";
  if (long_campaign) {
    io::Table header_table;
    for (size_t i = 0; i < names.size(); ++i) {
      io::Table one;
      one.columns = full.columns;
      one.columns.insert(one.columns.begin() + 1, {"revision", "seed", "first"});
      auto row = full.rows[i];
      row.insert(row.begin() + 1, {revision, std::to_string(seed), std::to_string(first)});
      one.add_row(row);
      io::ResultDoc d = doc;
      d.title = "Robustness: long oracle campaign, " + names[i];
      d.description += " `revision`: the commit the binary was built from; problems first … first + problems − 1 of the seed.";
      if (settings.max_evaluations > 0)
        d.description += " Each g2, scurve and compound solve, and each quadratic position, may spend at most " +
                         std::to_string(settings.max_evaluations) +
                         " integrand evaluations (--max-evaluations; the library's default otherwise): one that spends "
                         "them ends max_iterations, counted in other_statuses.";
      d.notes = findings_of[i].second.empty() ? "No finding." : "### Findings\n" + findings_of[i].second;
      io::write_result_table_with_timing(out, long_stem(names[i], first), d, one, {"construction"}, timing_columns,
                                         timing_description);
      if (header_table.columns.empty())
        for (const auto& c : one.columns)
          if (std::find(timing_columns.begin(), timing_columns.end(), c) == timing_columns.end())
            header_table.columns.push_back(c);
    }
    const std::string table = header_table.markdown();  // header and separator lines only
    write_long_summary(out, header_table.columns, table, doc.description);
    return bad && fail_on_finding ? 1 : 0;
  }
  io::write_result_table_with_timing(out, "robustness_oracle", doc, full, {"construction"}, timing_columns,
                                     timing_description);
  std::string section = "## Oracle campaign\n\nWritten by `" + doc.command +
                        "` (the full table with its description: results/robustness_oracle.md; findings there).\n\n" +
                        t.markdown() + "\n";
  splice_section(std::filesystem::path(out) / "robustness.md", section);
  return bad && fail_on_finding ? 1 : 0;
}
