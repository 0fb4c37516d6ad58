#pragma once
// Input validation at the API boundary. Every rejection names the function, the
// parameter, the offending value and the valid range, so a CLI can print it as one line.
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lac {

/// Thrown for invalid input only (never for non-convergence, which is a Status).
class InputError : public std::domain_error {
 public:
  InputError(std::string parameter, const std::string& message)
      : std::domain_error(message), parameter_(std::move(parameter)) {}
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

/// Shortest text that reads back as the same double (e.g. 1e-12, not 9.9999999999999998e-13).
inline std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

[[noreturn]] inline void throw_input_error(std::string_view function, std::string_view parameter,
                                           double value, std::string_view valid_range) {
  std::string msg;
  msg.append(function).append(": ").append(parameter).append(" = ").append(format_number(value));
  msg.append(" is outside its valid range ").append(valid_range);
  throw InputError(std::string(parameter), msg);
}

[[noreturn]] inline void throw_input_error(std::string_view function, std::string_view parameter,
                                           std::string_view what) {
  std::string msg;
  msg.append(function).append(": ").append(parameter).append(": ").append(what);
  throw InputError(std::string(parameter), msg);
}

inline void require_finite(std::string_view function, std::string_view parameter, double value) {
  if (!std::isfinite(value)) throw_input_error(function, parameter, value, "(finite real numbers)");
}

/// Half-open or open interval text for messages, e.g. "(-inf, 2.5)".
inline std::string interval_text(double lo, double hi, bool lo_closed = false, bool hi_closed = false) {
  std::string text(lo_closed ? "[" : "(");
  text.append(format_number(lo)).append(", ").append(format_number(hi)).append(hi_closed ? "]" : ")");
  return text;
}

}  // namespace lac
