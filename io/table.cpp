#include "io/table.hpp"

#include <cstdio>
#include <fstream>
#include <locale>
#include <set>
#include <sstream>
#include <stdexcept>

namespace lac::io {

void Table::add_row(std::vector<std::string> row) {
  if (row.size() != columns.size()) throw std::logic_error("Table::add_row: row width differs from the header");
  rows.push_back(std::move(row));
}

std::string Table::markdown() const {
  std::ostringstream os;
  auto line = [&](const std::vector<std::string>& cells) {
    os << '|';
    for (const auto& c : cells) os << ' ' << c << " |";
    os << '\n';
  };
  line(columns);
  os << '|';
  for (size_t i = 0; i < columns.size(); ++i) os << "---|";
  os << '\n';
  for (const auto& r : rows) line(r);
  return os.str();
}

namespace {
std::string csv_cell(const std::string& c) {
  if (c.find_first_of(",\"\n") == std::string::npos) return c;
  std::string q = "\"";
  for (char ch : c) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}
}  // namespace

std::string Table::csv() const {
  std::ostringstream os;
  auto line = [&](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) os << (i ? "," : "") << csv_cell(cells[i]);
    os << '\n';
  };
  line(columns);
  for (const auto& r : rows) line(r);
  return os.str();
}

std::string fmt(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v + 0.0);  // + 0.0: −0 becomes 0
  return buf;
}

std::string sci(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", digits - 1, v + 0.0);
  return buf;
}

namespace {
struct PlainNumbers : std::num_put<char> {
  iter_type do_put(iter_type out, std::ios_base& str, char_type fill, double v) const override {
    return std::num_put<char>::do_put(out, str, fill, v + 0.0);
  }
};
}  // namespace

void write_numbers_plainly(std::ostream& os) { os.imbue(std::locale(os.getloc(), new PlainNumbers)); }

bool is_timing_table(const std::string& stem) {
  auto ends_with = [&](const std::string& suffix) {
    return stem.size() >= suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with("_timing") || stem.find("_bench") != std::string::npos || stem.rfind("p002_appendix_a", 0) == 0;
}

#ifndef LAC_CXX_COMPILER
#define LAC_CXX_COMPILER "unknown compiler"
#endif
#ifndef LAC_BUILD_TYPE
#define LAC_BUILD_TYPE "unknown build type"
#endif
#ifndef LAC_CXX_FLAGS
#define LAC_CXX_FLAGS ""
#endif

std::string machine_description() {
  std::string cpu = "unknown CPU";
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      cpu = line.substr(line.find(':') + 1);
      cpu.erase(0, cpu.find_first_not_of(" \t"));
      break;
    }
  std::string compiler = LAC_CXX_COMPILER;
#ifdef __VERSION__
  compiler += std::string(" (") + __VERSION__ + ")";
#endif
  std::string flags = LAC_CXX_FLAGS;
  flags.erase(0, flags.find_first_not_of(' '));
  while (!flags.empty() && flags.back() == ' ') flags.pop_back();
  return "Machine: " + cpu + "; compiler " + compiler + "; build type " + std::string(LAC_BUILD_TYPE) + ", flags `" +
         (flags.empty() ? std::string("(none)") : flags) + "`. Times vary between runs and machines.";
}

void write_result_table_with_timing(const std::filesystem::path& dir, const std::string& stem, const ResultDoc& doc,
                                    const Table& t, const std::vector<std::string>& key_columns,
                                    const std::vector<std::string>& timing_columns,
                                    const std::string& timing_description) {
  auto index_of = [&](const std::string& name) {
    for (size_t i = 0; i < t.columns.size(); ++i)
      if (t.columns[i] == name) return i;
    throw std::logic_error("write_result_table_with_timing: no column '" + name + "' in " + stem);
  };
  std::vector<size_t> keys, times, kept;
  for (const auto& k : key_columns) keys.push_back(index_of(k));
  for (const auto& c : timing_columns) times.push_back(index_of(c));
  const std::set<size_t> timing_set(times.begin(), times.end());
  for (size_t i = 0; i < t.columns.size(); ++i)
    if (!timing_set.count(i)) kept.push_back(i);
  auto pick = [](const std::vector<std::string>& cells, const std::vector<size_t>& idx) {
    std::vector<std::string> out;
    for (size_t i : idx) out.push_back(cells[i]);
    return out;
  };
  Table accuracy, timing;
  accuracy.columns = pick(t.columns, kept);
  timing.columns = pick(t.columns, keys);
  for (size_t i : times) timing.columns.push_back(t.columns[i]);
  std::set<std::vector<std::string>> seen;
  for (const auto& r : t.rows) {
    accuracy.add_row(pick(r, kept));
    auto row = pick(r, keys);
    if (!seen.insert(row).second)
      throw std::logic_error("write_result_table_with_timing: key columns do not identify the rows of " + stem);
    for (size_t i : times) row.push_back(r[i]);
    timing.add_row(std::move(row));
  }
  write_result_table(dir, stem, doc, accuracy);
  ResultDoc tdoc;
  tdoc.title = doc.title + " — times";
  tdoc.command = doc.command;
  tdoc.description = "Times of the rows of " + stem + ".md (same row keys); kept apart so that " + stem +
                     ".md regenerates byte-identically. " + timing_description;
  write_result_table(dir, stem + "_timing", tdoc, timing);
}

void write_result_table(const std::filesystem::path& dir, const std::string& stem, const ResultDoc& doc, const Table& t) {
  std::filesystem::create_directories(dir);
  std::ofstream md(dir / (stem + ".md"));
  md << "# " << doc.title << "\n\n";
  md << "Written by `" << doc.command << "` — do not edit by hand; rerun the command.\n\n";
  std::string description = doc.description;
  if (is_timing_table(stem)) description += (description.empty() ? "" : "\n\n") + machine_description();
  if (!description.empty()) md << description << "\n\n";
  md << t.markdown();
  if (!doc.notes.empty()) md << "\n" << doc.notes << "\n";
  std::ofstream csv(dir / (stem + ".csv"));
  csv << "# written by: " << doc.command << "\n" << t.csv();
  if (!md || !csv) throw std::runtime_error("write_result_table: cannot write into " + dir.string());
}

std::string command_line(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (i == 0) a = std::filesystem::path(a).filename().string();
    s += (i ? " " : "") + a;
  }
  return s;
}

}  // namespace lac::io
