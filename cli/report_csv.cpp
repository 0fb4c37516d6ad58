// CSV form of a report (cli/report.hpp): the same names as the JSON keys.
#include <charconv>
#include <iostream>

#include "cli/report.hpp"

namespace lac::cli {

namespace {

void flatten(const Json& j, const std::string& prefix, std::vector<std::string>& keys, std::vector<const Json*>& values) {
  for (const auto& [key, value] : j.items()) {
    if (value.is_array()) continue;  // segments, points: the table below the summary
    if (value.is_object()) {
      flatten(value, prefix + key + ".", keys, values);
    } else {
      keys.push_back(prefix + key);
      values.push_back(&value);
    }
  }
}

void write_row(std::ostream& out, const std::vector<const Json*>& values) {
  for (size_t k = 0; k < values.size(); ++k) out << (k ? "," : "") << csv_cell(*values[k]);
  out << "\n";
}

void write_table(std::ostream& out, const Json& rows) {
  if (rows.empty()) return;
  std::vector<std::string> keys;
  std::vector<const Json*> values;
  flatten(rows.front(), "", keys, values);
  for (size_t k = 0; k < keys.size(); ++k) out << (k ? "," : "") << keys[k];
  out << "\n";
  for (const Json& row : rows) {
    keys.clear();
    values.clear();
    flatten(row, "", keys, values);
    write_row(out, values);
  }
}

}  // namespace

std::string csv_cell(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) {
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v.get<double>());
    return std::string(buf, res.ptr);
  }
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  }
  return v.dump();  // integers, booleans
}

void flatten_summary(const Json& report, std::vector<std::string>& keys, std::vector<const Json*>& values) {
  flatten(report, "", keys, values);
}

void write_csv_report(std::ostream& out, const Json& report) {
  std::vector<std::string> keys;
  std::vector<const Json*> values;
  flatten(report, "", keys, values);
  out << "# ";
  for (size_t k = 0; k < keys.size(); ++k) out << (k ? "," : "") << keys[k];
  out << "\n# ";
  write_row(out, values);
  const auto points = report.find("points");
  write_table(out, points != report.end() ? *points : report["segments"]);
}

void print_record(const Json& record, const std::string& format) {
  if (format != "csv") {
    std::cout << record.dump(2) << "\n";
    return;
  }
  std::vector<std::string> keys;
  std::vector<const Json*> values;
  flatten(record, "", keys, values);
  for (size_t k = 0; k < keys.size(); ++k) std::cout << (k ? "," : "") << keys[k];
  std::cout << "\n";
  write_row(std::cout, values);
}

}  // namespace lac::cli
