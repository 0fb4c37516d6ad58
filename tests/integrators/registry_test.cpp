// The quadrature and ODE registries: every listed name parses and integrates known integrals to
// its tolerance; unknown names and misplaced options are InputErrors naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <set>
#include <string>
#include <utility>
#include <variant>

#include "lac/common/error.hpp"
#include "lac/curves/planar/la_curve.hpp"
#include "lac/curves/planar/la_position.hpp"
#include "lac/integrators/ode_registry.hpp"
#include "lac/integrators/registry.hpp"

namespace lac {
namespace {

using cplx = std::complex<double>;

// The InputError `call` throws: its parameter and message ("(no InputError)" for none).
std::pair<std::string, std::string> input_error_of(auto&& call) {
  try {
    call();
  } catch (const InputError& e) {
    return {e.parameter(), e.what()};
  }
  return {"(no InputError)", "(no InputError)"};
}
std::string parameter_of(auto&& call) { return input_error_of(call).first; }
std::string message_of(auto&& call) { return input_error_of(call).second; }

// Accuracy each method reaches at its defaults on the smooth integrands below, relative to the
// integral: its tolerance where it has one (rk45's is per unit length, whence the margin), and
// the h⁴ error of rk4 at h = 0.001.
double accuracy(std::string_view name) {
  if (name == "rk4") return 1e-11;
  if (name == "rk45") return 1e-10;
  if (name == "gauss-kronrod") return 1e-13;
  if (name == "gauss-legendre") return 1e-8;
  if (name == "gk-tanh-sinh") return 1e-12;
  if (name == "igf") return 1e-12;
  ADD_FAILURE() << "no accuracy for " << name;
  return 0;
}

TEST(QuadratureRegistry, ListsEveryMethodOnceInVariantOrder) {
  const auto methods = quadrature_methods();
  ASSERT_EQ(methods.size(), std::variant_size_v<AnyQuadrature>);
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const MethodInfo& m = methods[i];
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_FALSE(m.description.empty()) << m.name;
    EXPECT_FALSE(m.options.empty()) << m.name;
    EXPECT_FALSE(m.applies_to.empty()) << m.name;
    const AnyQuadrature q = make_quadrature(m.name);
    EXPECT_EQ(q.index(), i) << m.name;
    EXPECT_EQ(name_of(q), m.name);
    EXPECT_EQ(describe(q).rfind(m.name, 0), 0u) << describe(q);
    for (std::string_view alias : m.aliases) EXPECT_EQ(make_quadrature(alias).index(), i) << alias;
  }
  for (std::string_view name : {"rk4", "rk45", "gauss-kronrod", "gauss-legendre", "gk-tanh-sinh", "igf"})
    EXPECT_TRUE(names.count(name)) << name;
  EXPECT_EQ(name_of(make_quadrature("gk")), "gauss-kronrod");
  EXPECT_EQ(find_method(methods, "igf")->applies_to, "planar LA curves and segments (each piece in standard form); not quadratic curves");
  EXPECT_EQ(method_names_text(methods), "rk4, rk45, gauss-kronrod (alias gk), gauss-legendre, gk-tanh-sinh, igf");
}

TEST(QuadratureRegistry, ListedDefaultsAreTheMethodsDefaults) {
  EXPECT_EQ(find_method(quadrature_methods(), "rk4")->options[0].default_value, Rk4{}.h);
  EXPECT_EQ(find_method(quadrature_methods(), "rk45")->options[0].default_value, Rk45{}.tol);
  EXPECT_EQ(find_method(quadrature_methods(), "gk")->options[0].default_value, GaussKronrod{}.tol);
  EXPECT_EQ(find_method(quadrature_methods(), "gauss-legendre")->options[0].default_value, GaussLegendre{}.panels);
  EXPECT_EQ(find_method(quadrature_methods(), "gauss-legendre")->options[1].default_value, GaussLegendre{}.tol);
  EXPECT_EQ(find_method(quadrature_methods(), "gk-tanh-sinh")->options[0].default_value, GkTanhSinh{}.tol);
  EXPECT_EQ(find_method(quadrature_methods(), "igf")->options[0].default_value, IgfOptions{}.tol);
}

// Every listed option is applied; every other one is an InputError naming it.
TEST(QuadratureRegistry, OptionsApplyWhereListedAndAreRejectedElsewhere) {
  for (const MethodInfo& m : quadrature_methods()) {
    for (std::string_view option : {"h", "tol", "panels"}) {
      QuadratureOptions o;
      if (option == "h") o.h = 0.01;
      if (option == "tol") o.tol = 1e-9;
      if (option == "panels") o.panels = 3;
      if (takes_option(m, option)) {
        const std::string d = describe(make_quadrature(m.name, o));
        const std::string expected = option == "h" ? "h=0.01" : option == "tol" ? "tol=1e-09" : "panels=3";
        EXPECT_NE(d.find(expected), std::string::npos) << m.name << ": " << d;
      } else {
        EXPECT_EQ(parameter_of([&] { make_quadrature(m.name, o); }), option) << m.name;
        EXPECT_NE(message_of([&] { make_quadrature(m.name, o); }).find("not applicable to " + std::string(m.name)),
                  std::string::npos);
      }
    }
  }
  EXPECT_EQ(parameter_of([] { make_quadrature("rk45", {.h = 0.1}); }), "h");
  EXPECT_EQ(parameter_of([] { make_quadrature("rk4", {.tol = 1e-8}); }), "tol");
  EXPECT_EQ(parameter_of([] { make_quadrature("igf", {.h = 0.1}); }), "h");
  EXPECT_EQ(parameter_of([] { make_quadrature("gauss-kronrod", {.panels = 2}); }), "panels");
  EXPECT_EQ(parameter_of([] { make_quadrature("gauss-legendre", {.panels = 0}); }), "panels");  // out of range
  EXPECT_EQ(parameter_of([] { make_quadrature("gk-tanh-sinh", {.tol = -1.0}); }), "tol");
}

TEST(QuadratureRegistry, UnknownNameListsTheValidOnes) {
  for (std::string_view name : {"simpson", "", "GK", "gk+tanh-sinh", "magnus6"}) {
    EXPECT_EQ(parameter_of([&] { make_quadrature(name); }), "integrator") << name;
    const std::string what = message_of([&] { make_quadrature(name); });
    for (const MethodInfo& m : quadrature_methods()) EXPECT_NE(what.find(m.name), std::string::npos) << what;
  }
}

// Every registered method on the planar LA curve α = 2 (ρ = 1 + Λθ), whose position has the
// closed form C(θ) = −i(e^{iθ} − 1) + Λ((1 − iθ)e^{iθ} − 1) (002 Eq. (7) integrated by parts).
TEST(QuadratureRegistry, EveryMethodIntegratesAKnownLaPosition) {
  const double lambda = 0.7;
  const LaCurve curve(2.0, lambda);
  for (double theta : {0.25, 1.5, -1.0}) {
    const cplx e = std::polar(1.0, theta), i(0, 1);
    const cplx exact = -i * (e - 1.0) + lambda * ((1.0 - i * theta) * e - 1.0);
    for (const MethodInfo& m : quadrature_methods()) {
      const PositionResult r = position_at(curve, Parameter::theta, theta, make_quadrature(m.name), Form::theta);
      EXPECT_EQ(r.status, Status::ok) << m.name << " " << r.message;
      const double err = std::abs(r.point.position - exact);
      EXPECT_LE(err, accuracy(m.name) * std::abs(exact)) << m.name << " theta " << theta;
      EXPECT_LE(err, std::max(r.error_estimate, 4e-16 * std::abs(exact))) << m.name << " theta " << theta;
    }
  }
}

// The quadratures (all but igf) on plain integrands, real and complex.
TEST(QuadratureRegistry, EveryQuadratureIntegratesKnownIntegrals) {
  for (const MethodInfo& m : quadrature_methods()) {
    std::visit(
        [&](const auto& q) {
          if constexpr (QuadratureMethod<std::decay_t<decltype(q)>>) {
            const auto real = q.integrate([](double x) { return std::exp(x); }, 0.0, 1.0);
            EXPECT_EQ(real.status, Status::ok) << m.name;
            EXPECT_LE(std::abs(real.value - (std::exp(1.0) - 1.0)), accuracy(m.name) * (std::exp(1.0) - 1.0)) << m.name;
            const auto turn = q.integrate([](double x) { return std::polar(1.0, x); }, 0.0, 1.0);
            const cplx exact(std::sin(1.0), 1.0 - std::cos(1.0));
            EXPECT_LE(std::abs(turn.value - exact), accuracy(m.name) * std::abs(exact)) << m.name;
          } else {
            EXPECT_EQ(m.name, "igf");
          }
        },
        make_quadrature(m.name));
  }
}

TEST(OdeRegistry, ListsEveryMethodAndParsesItsNames) {
  const auto methods = ode_methods();
  ASSERT_EQ(methods.size(), 3u);
  for (OdeMethod m : {OdeMethod::rk4, OdeMethod::rk45, OdeMethod::magnus6}) {
    EXPECT_EQ(parse_ode_method(to_string(m)), m);
    EXPECT_EQ(methods[static_cast<std::size_t>(m)].name, to_string(m));
    EXPECT_FALSE(methods[static_cast<std::size_t>(m)].options.empty());
  }
  EXPECT_EQ(method_names_text(methods, " | "), "rk4 | rk45 | magnus6");
  EXPECT_TRUE(takes_option(*find_method(methods, "rk4"), "h"));
  EXPECT_FALSE(takes_option(*find_method(methods, "rk4"), "rtol"));
  EXPECT_TRUE(takes_option(*find_method(methods, "magnus6"), "rtol"));
  EXPECT_EQ(find_method(methods, "rk45")->options[0].default_value, OdeOptions{}.rtol);
  EXPECT_EQ(find_method(methods, "rk45")->options[1].default_value, OdeOptions{}.atol);
  EXPECT_EQ(find_method(methods, "rk4")->options[0].default_value, OdeOptions{}.h);
}

TEST(OdeRegistry, InvalidNamesAndOptionsNameTheParameter) {
  EXPECT_EQ(parameter_of([] { parse_ode_method("euler"); }), "integrator");
  EXPECT_NE(message_of([] { parse_ode_method("gk"); }).find("rk4, rk45, magnus6"), std::string::npos);
  EXPECT_EQ(parameter_of([] { OdeOptions{.rtol = 0}.validate(); }), "rtol");
  EXPECT_EQ(parameter_of([] { OdeOptions{.atol = -1}.validate(); }), "atol");
  EXPECT_EQ(parameter_of([] { OdeOptions{.h = 0}.validate(); }), "h");
  EXPECT_EQ(parameter_of([] { OdeOptions{.max_steps = 0}.validate(); }), "max_steps");
  EXPECT_NO_THROW(OdeOptions{}.validate());
}

}  // namespace
}  // namespace lac
