// lac special erfi-inv / erf-inv: inverse error functions (special/erf_family.hpp).
#include "cli/command.hpp"
#include "cli/report.hpp"
#include "lac/common/error.hpp"
#include "lac/special/erf_family.hpp"

namespace lac::cli {
namespace {

struct InverseArgs {
  std::string y_text;
  std::string method;
  std::string* format = nullptr;
};

// Reads y as text so that "nan" and "inf" reach the library's own validation (InputError).
double parse_y(const std::string& text) {
  char* end = nullptr;
  const double y = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') throw_input_error("lac special", "y", "'" + text + "' is not a number");
  return y;
}

void print(const InverseArgs& a, const char* function, double y, const special::InverseResult& r) {
  record_status(r.status);
  print_record(Json{{"status", std::string(to_string(r.status))},
                    {"function", function},
                    {"y", number(y)},
                    {"value", number(r.value)},
                    {"iterations", r.iterations},
                    {"method", a.method}},
               *a.format);
}

void setup(CLI::App& app) {
  CLI::App& special = parent_command(app, "special", "Special functions");

  auto* erfi_args = owned<InverseArgs>(InverseArgs{"", "ours"});
  auto* erfi_cmd = special.add_subcommand("erfi-inv", "Inverse imaginary error function erfi^-1(y), any real y");
  erfi_cmd->add_option("--y", erfi_args->y_text, "Argument y (any double; +-inf gives +-inf)")->required();
  erfi_cmd->add_option("--method", erfi_args->method, "ours | hybrid-003 (003's bisection-Newton, |x| <= 26)")
      ->check(CLI::IsMember({"ours", "hybrid-003"}))
      ->capture_default_str();
  erfi_args->format = add_format_option(*erfi_cmd);
  erfi_cmd->callback([erfi_args] {
    const double y = parse_y(erfi_args->y_text);
    print(*erfi_args, "erfi_inv", y, special::erfi_inv_detailed(y, special::parse_erf_inverse_method(erfi_args->method)));
  });

  auto* erf_args = owned<InverseArgs>(InverseArgs{"", "boost"});
  auto* erf_cmd = special.add_subcommand("erf-inv", "Inverse error function erf^-1(y), -1 < y < 1");
  erf_cmd->add_option("--y", erf_args->y_text, "Argument y in (-1, 1)")->required();
  erf_cmd->add_option("--method", erf_args->method, "boost (Boost.Math erf_inv) | hybrid-003 (003's, |x| <= 5)")
      ->check(CLI::IsMember({"boost", "hybrid-003"}))
      ->capture_default_str();
  erf_args->format = add_format_option(*erf_cmd);
  erf_cmd->callback([erf_args] {
    const double y = parse_y(erf_args->y_text);
    if (!(std::abs(y) < 1.0)) throw_input_error("lac special erf-inv", "y", y, "(-1, 1)");
    const special::InverseResult r =
        erf_args->method == "boost" ? special::InverseResult{special::erf_inv(y), 0, Status::ok} : special::erf_inv_hybrid_003(y);
    print(*erf_args, "erf_inv", y, r);
  });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
