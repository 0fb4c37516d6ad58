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

/// The command line of this process, for provenance lines.
std::string command_line(int argc, char** argv);

}  // namespace lac::io
