#pragma once
// Minimal reader for the reference tables in tests/reference/ ('#' lines are comments,
// the first other line is the header). Shared by tests/special_erf and tests/quadratic.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lac::test_erf {

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  size_t column(const std::string& name) const {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    throw std::runtime_error("reference table has no column " + name);
  }
};

inline Csv read_csv(const std::string& file_name) {
  const std::string path = std::string(LAC_REFERENCE_DIR) + "/" + file_name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path + " (run its generator beside it)");
  Csv t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (t.header.empty()) t.header = std::move(cells);
    else t.rows.push_back(std::move(cells));
  }
  return t;
}

}  // namespace lac::test_erf
