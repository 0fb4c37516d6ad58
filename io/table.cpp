#include "io/table.hpp"

#include <cstdio>
#include <fstream>
#include <locale>
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

void write_result_table(const std::filesystem::path& dir, const std::string& stem, const ResultDoc& doc, const Table& t) {
  std::filesystem::create_directories(dir);
  std::ofstream md(dir / (stem + ".md"));
  md << "# " << doc.title << "\n\n";
  md << "Written by `" << doc.command << "` — do not edit by hand; rerun the command.\n\n";
  if (!doc.description.empty()) md << doc.description << "\n\n";
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
