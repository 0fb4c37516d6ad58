#include "cli/batch.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>

#include "cli/csv_reader.hpp"
#include "lac/common/error.hpp"

namespace lac::cli {

namespace {

long g_batch_row = 0;

/// Output collected in memory and written in large blocks (per-row writes to std::cout would
/// cost more than a G1 solve).
class Sink {
 public:
  ~Sink() { flush(); }
  std::string& text() { return text_; }
  void maybe_flush() {
    if (text_.size() > (1 << 16)) flush();
  }
  void flush() {
    std::cout << text_;
    std::cout.flush();
    text_.clear();
  }

 private:
  std::string text_;
};

/// The option of `sub` a batch column names; InputError for columns that are not per-row options.
CLI::Option* column_option(CLI::App& sub, const std::string& name) {
  if (name == "format" || name == "batch")
    throw_input_error("lac", "batch", "column '" + name + "' is not a per-row option (give --" + name + " on the command line)");
  CLI::Option* opt = name.empty() ? nullptr : sub.get_option_no_throw("--" + name);
  if (opt == nullptr) {
    std::string names;
    std::vector<std::string> candidates;
    for (const CLI::Option* o : sub.get_options())
      for (const std::string& l : o->get_lnames())
        if (l != "help" && l != "format" && l != "batch") {
          names.append(names.empty() ? "" : ", ").append(l);
          candidates.push_back(l);
        }
    const auto guess = closest_name(name, candidates);
    throw_input_error("lac", "batch", "column '" + echo_value(name) + "' names no option of this command" +
                                          (guess ? "; did you mean '" + *guess + "'?" : "") + " (" + names + ")");
  }
  return opt;
}

class BatchWriter {
 public:
  BatchWriter(Sink& sink, bool csv) : sink_(sink), csv_(csv) {}

  void result(long row, const Report& report) {
    if (!csv_) {
      const std::string body = report.json.dump();
      sink_.text().append("{\"row\":").append(std::to_string(row)).append(",").append(body, 1).append("\n");
      return;
    }
    keys_.clear();
    values_.clear();
    flatten_summary(report.json, keys_, values_);
    if (header_.empty()) {
      header_ = keys_;
      std::string& t = sink_.text();
      t.append("row");
      for (const std::string& k : header_) t.append(",").append(k);
      t.append("\n");
      for (const auto& [r, message] : pending_) invalid(r, message);
      pending_.clear();
    }
    std::string& t = sink_.text();
    t.append(std::to_string(row));
    for (const Json* v : values_) t.append(",").append(csv_cell(*v));
    t.append("\n");
  }

  void invalid(long row, const std::string& message) {
    std::string& t = sink_.text();
    if (!csv_) {
      t.append(Json{{"row", row}, {"status", "invalid_input"}, {"message", message}}.dump()).append("\n");
      return;
    }
    if (header_.empty()) {
      pending_.emplace_back(row, message);
      return;
    }
    t.append(std::to_string(row));
    for (const std::string& k : header_)
      t.append(",").append(k == "status" ? "invalid_input" : k == "message" ? csv_cell(Json(message)) : "");
    t.append("\n");
  }

  void finish() {  // no valid row: the columns of an error
    if (!csv_ || !header_.empty()) return;
    header_ = {"status", "message"};
    sink_.text().append("row,status,message\n");
    for (const auto& [r, message] : pending_) invalid(r, message);
  }

 private:
  Sink& sink_;
  bool csv_;
  std::vector<std::string> header_, keys_;
  std::vector<const Json*> values_;
  std::vector<std::pair<long, std::string>> pending_;
};

void run_batch(CLI::App& sub, const CommonArgs& common, const std::function<Report()>& solve,
               const std::function<void()>& restore) {
  std::ifstream file;
  if (common.batch != "-") {
    file.open(common.batch);
    if (!file) throw_input_error("lac", "batch", "cannot open '" + common.batch + "'");
  }
  std::istream& in = common.batch == "-" ? std::cin : file;
  std::vector<std::string> header, cells;
  if (!read_csv_record(in, header, true)) throw_input_error("lac", "batch", "'" + common.batch + "' has no header line");
  std::vector<CLI::Option*> options;
  for (size_t k = 0; k < header.size(); ++k) {
    options.push_back(column_option(sub, header[k]));
    for (size_t j = 0; j < k; ++j)
      if (options[j] == options[k])  // the same option twice (also under two of its names)
        throw_input_error("lac", "batch", "column '" + echo_value(header[k]) + "' (column " + std::to_string(k + 1) +
                                              ") repeats the option of column " + std::to_string(j + 1) + " ('" +
                                              echo_value(header[j]) + "'): each option may have one column");
  }
  Sink sink;
  BatchWriter writer(sink, common.format == "csv");
  struct RowReset {
    ~RowReset() { g_batch_row = 0; }
  } reset;
  for (long row = 1; read_csv_record(in, cells); ++row) {
    restore();
    g_batch_row = row;
    try {
      if (cells.size() != header.size())
        throw_input_error("lac", "batch", "row has " + std::to_string(cells.size()) + " fields; the header has " +
                                              std::to_string(header.size()));
      for (size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].empty()) continue;
        if (const size_t nul = cells[k].find('\0'); nul != std::string::npos)
          throw_input_error("lac", header[k], "'" + echo_value(cells[k]) + "': a NUL byte (at character " +
                                                  std::to_string(nul + 1) + ") is not text");
        try {
          options[k]->clear();
          options[k]->add_result(cells[k]);
          options[k]->run_callback();
        } catch (const CLI::ParseError& e) {
          // CLI11's message repeats the value: each copy shortened as the echo.
          std::string why = e.what();
          const std::string shown = echo_value(cells[k]);
          for (size_t at = why.find(cells[k]); at != std::string::npos; at = why.find(cells[k], at + shown.size()))
            why.replace(at, cells[k].size(), shown);
          throw_input_error("lac", header[k], "'" + shown + "': " + echo_value(why, 400));
        }
      }
      writer.result(row, solve());
    } catch (const InputError& e) {
      record_invalid_row();
      writer.invalid(row, echo_value(without_lac_prefix(e.what()), 1000));  // a thrower may echo a whole cell
    }
    sink.maybe_flush();
  }
  writer.finish();
}

}  // namespace

long current_batch_row() { return g_batch_row; }

void run_command(CLI::App& sub, const CommonArgs& common, const std::function<Report()>& solve,
                 const std::function<void()>& restore) {
  if (common.batch.empty()) {
    print_report(solve(), common.format, common.comb);
    return;
  }
  if (common.format == "svg") throw_input_error("lac", "format", "svg draws one curve; --batch prints json or csv");
  run_batch(sub, common, solve, restore);
}

}  // namespace lac::cli
