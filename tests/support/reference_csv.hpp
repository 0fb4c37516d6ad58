#pragma once
// Reads the reference tables in tests/reference/ (comment lines start with '#').
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lac::test {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  size_t column(const std::string& name) const {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    throw std::runtime_error("reference table has no column " + name);
  }
  double number(size_t row, const std::string& name) const { return std::stod(rows[row][column(name)]); }
};

inline CsvTable read_reference_csv(const std::string& file_name) {
  const std::string path = std::string(LAC_REFERENCE_DIR) + "/" + file_name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path + " (run its generator beside it)");
  CsvTable t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();  // getline drops a trailing empty cell
    if (t.header.empty())
      t.header = std::move(cells);
    else
      t.rows.push_back(std::move(cells));
  }
  return t;
}

}  // namespace lac::test
