#include "lac/integrators/registry.hpp"

#include <array>
#include <utility>

namespace lac {
namespace {

constexpr std::array<MethodOption, 1> kRk4Options = {{{"h", Rk4{}.h, "step in the integration variable"}}};
constexpr std::array<MethodOption, 1> kRk45Options = {{{"tol", Rk45{}.tol, "relative tolerance per step"}}};
constexpr std::array<MethodOption, 1> kGkOptions = {{{"tol", GaussKronrod{}.tol, "relative tolerance"}}};
constexpr std::array<MethodOption, 2> kGlOptions = {
    {{"panels", GaussLegendre{}.panels, "equal panels over the interval"},
     {"tol", GaussLegendre{}.tol, "relative tolerance the estimate is checked against (status only)"}}};
constexpr std::array<MethodOption, 1> kGkTsOptions = {{{"tol", GkTanhSinh{}.tol, "relative tolerance of both rules"}}};
constexpr std::array<MethodOption, 1> kIgfOptions = {{{"tol", Igf{}.tol, "relative accuracy of each position difference"}}};
constexpr std::array<std::string_view, 1> kGkAliases = {"gk"};

constexpr std::array<MethodInfo, std::variant_size_v<AnyQuadrature>> kMethods = {{
    {Rk4::name, {}, "classical RK4 with fixed step on y' = f(t) (composite Simpson)", kRk4Options, kAnyIntegrand},
    {Rk45::name, {}, "adaptive Dormand-Prince 5(4) on y' = f(t)", kRk45Options, kAnyIntegrand},
    {GaussKronrod::name, kGkAliases, "globally adaptive Gauss-Kronrod G10K21", kGkOptions, kAnyIntegrand},
    {GaussLegendre::name, {}, "composite 20-point Gauss-Legendre on equal panels; estimate from the 10-point rule and from halved panels", kGlOptions,
     kAnyIntegrand},
    {GkTanhSinh::name, {}, "Gauss-Kronrod G10K21 (depth 4), tanh-sinh where it misses its tolerance", kGkTsOptions,
     kAnyIntegrand},
    {Igf::name, {}, "closed form through the complex incomplete gamma function", kIgfOptions,
     "planar LA curves and segments (each piece in standard form); not quadratic curves"},
}};

// kMethods[i] describes alternative i of AnyQuadrature.
template <std::size_t... I>
constexpr bool names_match(std::index_sequence<I...>) {
  return ((kMethods[I].name == std::variant_alternative_t<I, AnyQuadrature>::name) && ...);
}
static_assert(names_match(std::make_index_sequence<kMethods.size()>{}));

template <class M>
AnyQuadrature configured(const QuadratureOptions& o) {
  M m;
  if constexpr (requires { m.h; }) {
    if (o.h) m.h = *o.h;
  }
  if constexpr (requires { m.tol; }) {
    if (o.tol) m.tol = *o.tol;
  }
  if constexpr (requires { m.panels; }) {
    if (o.panels) m.panels = *o.panels;
  }
  m.validate();
  return m;
}

template <std::size_t... I>
constexpr auto factories(std::index_sequence<I...>) {
  return std::array<AnyQuadrature (*)(const QuadratureOptions&), sizeof...(I)>{
      &configured<std::variant_alternative_t<I, AnyQuadrature>>...};
}

std::string describe_one(const Rk4& m) { return "rk4 h=" + format_number(m.h); }
std::string describe_one(const Rk45& m) { return "rk45 tol=" + format_number(m.tol); }
std::string describe_one(const GaussKronrod& m) {
  return "gauss-kronrod G10K21 tol=" + format_number(m.tol) + " max_intervals=" + std::to_string(m.max_intervals) +
         " max_depth=" + std::to_string(m.max_depth);
}
std::string describe_one(const GaussLegendre& m) {
  return "gauss-legendre G20 panels=" + std::to_string(m.panels) + " tol=" + format_number(m.tol);
}
std::string describe_one(const GkTanhSinh& m) {
  return "gk-tanh-sinh tol=" + format_number(m.tol) + " gk_max_depth=" + std::to_string(m.gk_max_depth) +
         " ts_max_levels=" + std::to_string(m.ts_max_levels);
}
std::string describe_one(const Igf& m) {
  return "igf (incomplete-gamma closed form) tol=" + format_number(m.tol) + " max_pieces=" + std::to_string(m.max_pieces);
}

}  // namespace

std::span<const MethodInfo> quadrature_methods() { return kMethods; }

AnyQuadrature make_quadrature(std::string_view name, const QuadratureOptions& options) {
  const MethodInfo* info = find_method(kMethods, name);
  if (!info)
    throw_input_error("make_quadrature", "integrator",
                      "unknown name '" + std::string(name) + "'; valid: " + method_names_text(kMethods));
  if (options.h) require_option(*info, "h");
  if (options.tol) require_option(*info, "tol");
  if (options.panels) require_option(*info, "panels");
  static constexpr auto kMake = factories(std::make_index_sequence<kMethods.size()>{});
  return kMake[static_cast<std::size_t>(info - kMethods.data())](options);
}

std::string_view name_of(const AnyQuadrature& method) {
  return std::visit([](const auto& m) -> std::string_view { return std::decay_t<decltype(m)>::name; }, method);
}

std::string describe(const AnyQuadrature& method) {
  return std::visit([](const auto& m) { return describe_one(m); }, method);
}

}  // namespace lac
