#include "lac/integrators/registry.hpp"

#include <array>

namespace lac {
namespace {

void reject_h(std::string_view method, const IntegratorOptions& o) {
  if (o.h) throw_input_error(std::string(method), "h", "not applicable to " + std::string(method) + " (--h is rk4's step); use --tol");
}

}  // namespace

void apply_options(Rk4& m, const IntegratorOptions& o) {
  if (o.tol) throw_input_error("rk4", "tol", "not applicable to rk4 (fixed step); use --h");
  if (o.h) m.h = *o.h;
  m.validate();
}

void apply_options(Rk45& m, const IntegratorOptions& o) {
  reject_h("rk45", o);
  if (o.tol) m.tol = *o.tol;
  m.validate();
}

void apply_options(GaussKronrod& m, const IntegratorOptions& o) {
  reject_h("gauss-kronrod", o);
  if (o.tol) m.tol = *o.tol;
  m.validate();
}

std::string describe(const Rk4& m) { return "rk4 h=" + format_number(m.h); }
std::string describe(const Rk45& m) { return "rk45 tol=" + format_number(m.tol); }
std::string describe(const GaussKronrod& m) {
  return "gauss-kronrod G10K21 tol=" + format_number(m.tol) + " max_intervals=" + std::to_string(m.max_intervals) +
         " max_depth=" + std::to_string(m.max_depth);
}

std::span<const std::string_view> quadrature_names() {
  static constexpr std::array<std::string_view, 3> kNames = {Rk4::name, Rk45::name, GaussKronrod::name};
  return kNames;
}

AnyQuadrature make_quadrature(std::string_view name, const IntegratorOptions& options) {
  if (name == Rk4::name) {
    Rk4 m;
    apply_options(m, options);
    return m;
  }
  if (name == Rk45::name) {
    Rk45 m;
    apply_options(m, options);
    return m;
  }
  if (name == GaussKronrod::name || name == "gk") {
    GaussKronrod m;
    apply_options(m, options);
    return m;
  }
  throw_input_error("make_quadrature", "integrator", "unknown name '" + std::string(name) + "'; valid: rk4, rk45, gauss-kronrod");
}

}  // namespace lac
