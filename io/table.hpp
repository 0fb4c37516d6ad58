#pragma once
// Result tables written by programs: Markdown and CSV side by side, each stating the
// command that wrote it. Experiments call write_result_table; nothing in results/ is typed.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace lac::io {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;

  void add_row(std::vector<std::string> row);
  std::string markdown() const;
  std::string csv() const;
};

/// Formats a number for tables: %.*g with `digits` significant digits (−0 is written 0, as in
/// fmt, sci and streams set up by write_numbers_plainly: a sign of zero is rounding, not data).
std::string fmt(double v, int digits = 3);
/// Scientific notation with `digits` significant digits, e.g. 1.23e-14.
std::string sci(double v, int digits = 3);
/// Makes `os` write −0.0 as 0 (a num_put facet), for data files written with <<.
void write_numbers_plainly(std::ostream& os);

struct ResultDoc {
  std::string title;        ///< first heading of the Markdown file
  std::string command;      ///< the command line that regenerates it
  std::string description;  ///< Markdown paragraph(s) before the table: what, settings, how to read
  std::string notes;        ///< Markdown after the table (explanations of differences)
};

/// Writes <dir>/<stem>.md (title, provenance, description, table, notes) and <dir>/<stem>.csv
/// (a `# written by:` comment line, then the header and rows). Creates dir.
void write_result_table(const std::filesystem::path& dir, const std::string& stem, const ResultDoc& doc, const Table& t);

/// Whether a result file stem names a timing table, whose numbers are wall/CPU times and change on
/// every run: the stem ends in `_timing`, contains `_bench`, or starts with `p002_appendix_a` (the
/// p002 timing experiment). Every other table must regenerate byte-identically
/// (scripts/check_reproducible.sh); scripts/index_results.py states the same rule.
bool is_timing_table(const std::string& stem);

/// One sentence naming the machine a timing was taken on: CPU model (/proc/cpuinfo "model name"),
/// compiler and version, build type and flags of this build. write_result_table appends it to the
/// description of every timing table.
std::string machine_description();

/// Writes `t` as two tables: <stem> with every column except `timing_columns`, and <stem>_timing
/// with `key_columns` (which must identify each row) followed by `timing_columns`. The accuracy
/// table takes `doc`; the timing table takes the same title and command with `timing_description`.
void write_result_table_with_timing(const std::filesystem::path& dir, const std::string& stem, const ResultDoc& doc,
                                    const Table& t, const std::vector<std::string>& key_columns,
                                    const std::vector<std::string>& timing_columns,
                                    const std::string& timing_description);

/// The command line of this process, for provenance lines.
std::string command_line(int argc, char** argv);

}  // namespace lac::io
