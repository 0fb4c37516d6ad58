#include "cli/csv_reader.hpp"

#include "lac/common/error.hpp"

namespace lac::cli {

namespace {

std::string trimmed(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

bool read_csv_record(std::istream& in, std::vector<std::string>& fields, bool first) {
  std::string line;
  do {
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (first && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte order mark
    first = false;
  } while (trimmed(line).empty() || line[0] == '#');
  fields.clear();
  std::string field;
  bool quoted = false, was_quoted = false;
  for (size_t i = 0;; ++i) {
    if (i == line.size()) {
      if (!quoted) break;
      std::string next;  // a newline inside quotes: the record goes on
      if (!std::getline(in, next)) throw_input_error("lac", "batch", "a quoted field is not closed");
      if (!next.empty() && next.back() == '\r') next.pop_back();
      field += '\n';
      line = next;
      i = static_cast<size_t>(-1);
      continue;
    }
    const char c = line[i];
    if (quoted) {
      if (c != '"') field += c;
      else if (i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
      else quoted = false;
    } else if (c == '"' && trimmed(field).empty()) {
      quoted = was_quoted = true;
      field.clear();
    } else if (c == ',') {
      fields.push_back(was_quoted ? field : trimmed(field));
      field.clear();
      was_quoted = false;
    } else if (!was_quoted) {
      field += c;
    }  // (after a closing quote only blanks are expected before the comma)
  }
  fields.push_back(was_quoted ? field : trimmed(field));
  return true;
}

}  // namespace lac::cli
