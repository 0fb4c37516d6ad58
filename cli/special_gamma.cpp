// lac special gamma-inc: the upper incomplete gamma function Γ(a, z), real a, complex z.
#include "cli/command.hpp"
#include "cli/report.hpp"
#include "lac/common/error.hpp"
#include "lac/special/incomplete_gamma.hpp"

namespace lac::cli {
namespace {

struct GammaIncArgs {
  double a = 0;
  std::string z = "";
  bool scaled = false;
  std::string* format = nullptr;
};

void run(const GammaIncArgs& args) {
  const std::vector<double> zz = parse_tuple(args.z, 2, "z");
  const std::complex<double> z(zz[0], zz[1]);
  const special::GammaIncResult r = args.scaled ? special::gamma_inc_scaled(args.a, z) : special::gamma_inc(args.a, z);
  record_status(r.status);
  print_record(Json{{"status", std::string(to_string(r.status))},
                    {"re", number(r.value.real())},
                    {"im", number(r.value.imag())},
                    {"a", args.a},
                    {"z_re", z.real()},
                    {"z_im", z.imag()},
                    {"scaled", args.scaled},
                    {"region", std::string(special::to_string(r.region))},
                    {"iterations", r.iterations}},
               *args.format);
}

void setup(CLI::App& app) {
  auto* args = owned<GammaIncArgs>();
  CLI::App& special = parent_command(app, "special", "Special functions");
  auto* sub = special.add_subcommand("gamma-inc", "Upper incomplete gamma function Gamma(a, z) = int_z^inf t^(a-1) e^-t dt "
                                                  "(principal branch), real a in [-10, 10], complex z");
  sub->add_option("--a", args->a, "Order a in [-10, 10] (a <= 0 allowed; a = 0 is E1)")->required();
  sub->add_option("--z", args->z, "Argument as RE,IM (z != 0 when a <= 0)")->required();
  sub->add_flag("--scaled", args->scaled, "Print exp(z) z^-a Gamma(a, z) instead (no overflow for large |z|)");
  args->format = add_format_option(*sub);
  sub->callback([args] { run(*args); });
}

LAC_REGISTER_COMMAND(setup);

}  // namespace
}  // namespace lac::cli
