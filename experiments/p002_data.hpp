#pragma once
// Data shared by the paper-002 reproduction (experiments/p002_*.cpp, bench/p002.cpp,
// tests/p002/): the 40-digit reference endpoints (tests/reference/p002_truncation.csv,
// written by p002_truncation.py) and the paper's own typed numbers (experiments/data/).
#include <complex>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lac/common/error.hpp"

namespace lac::p002 {

/// Default locations under the source tree (LAC_SOURCE_DIR, set by the build for experiments, tests
/// and benchmarks), so that any working directory works. __FILE__ is no substitute: a compiler
/// cache with a base directory makes it relative to the build folder.
inline std::filesystem::path source_root() { return LAC_SOURCE_DIR; }
inline std::filesystem::path default_reference_csv() { return source_root() / "tests/reference/p002_truncation.csv"; }
inline std::filesystem::path default_appendix_a_csv() { return source_root() / "experiments/data/p002_appendix_a.csv"; }
inline std::filesystem::path default_appendix_b_csv() { return source_root() / "experiments/data/p002_appendix_b.csv"; }

/// A CSV file with '#' comment lines and a header; cells by column name. No quoted cells.
struct CsvRows {
  std::vector<std::map<std::string, std::string>> rows;

  static CsvRows read(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw_input_error("p002", "data file", "cannot open " + path.string());
    CsvRows out;
    std::vector<std::string> header;
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::vector<std::string> cells;
      std::stringstream ss(line);
      for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
      if (header.empty()) {
        header = cells;
        continue;
      }
      if (cells.size() != header.size()) throw_input_error("p002", "data file", "ragged row in " + path.string() + ": " + line);
      std::map<std::string, std::string> row;
      for (size_t i = 0; i < cells.size(); ++i) row[header[i]] = cells[i];
      out.rows.push_back(std::move(row));
    }
    return out;
  }
};

/// "4/3" -> 4.0 / 3.0 (the same binary64 value as the generator's float(4) / float(3)).
inline double parse_fraction(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return std::stod(text);
  return std::stod(text.substr(0, slash)) / std::stod(text.substr(slash + 1));
}

/// One reference endpoint: C at the end of [0, theta_end] (equivalently [0, s_end]).
struct ReferenceEnd {
  std::string set;         ///< appendix_a | appendix_b | appendix_b_s
  std::string alpha_text;  ///< the paper's spelling, e.g. "4/3"
  double alpha = 0, lambda = 0, theta_end = 0, s_end = 0;
  std::complex<double> c;  ///< rounded from 25 digits
  double abs_c = 0;
  double igf_cancellation = 0;  ///< rounding amplification of the closed form's Γ difference (0: not in the file)
};

inline std::vector<ReferenceEnd> read_reference(const std::filesystem::path& path = default_reference_csv()) {
  std::vector<ReferenceEnd> out;
  for (auto& r : CsvRows::read(path).rows) {
    ReferenceEnd e;
    e.set = r.at("set");
    e.alpha_text = r.at("alpha_text");
    e.alpha = parse_fraction(e.alpha_text);
    e.lambda = std::stod(r.at("lambda_text"));
    e.theta_end = std::stod(r.at("theta_end"));
    e.s_end = std::stod(r.at("s_end"));
    e.c = {std::stod(r.at("x")), std::stod(r.at("y"))};
    e.abs_c = std::stod(r.at("abs_c"));
    if (r.count("igf_cancellation")) e.igf_cancellation = std::stod(r.at("igf_cancellation"));
    out.push_back(e);
  }
  return out;
}

/// The reference rows of one set, in file order (Appendix A: the paper's row order).
inline std::vector<ReferenceEnd> reference_set(const std::vector<ReferenceEnd>& all, const std::string& set) {
  std::vector<ReferenceEnd> out;
  for (const auto& e : all)
    if (e.set == set) out.push_back(e);
  return out;
}

inline const ReferenceEnd& find_reference(const std::vector<ReferenceEnd>& all, const std::string& set,
                                          const std::string& alpha_text, double lambda) {
  for (const auto& e : all)
    if (e.set == set && e.alpha_text == alpha_text && e.lambda == lambda) return e;
  throw_input_error("p002", "reference", "no row for set " + set + " alpha " + alpha_text + " lambda " + format_number(lambda));
}

}  // namespace lac::p002
