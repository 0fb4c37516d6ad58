// Uses the installed package: a standard-form LA curve's closed-form conversions and a position by
// Gauss–Kronrod. Exit status 0 when the results are what the formulas give.
#include <cmath>
#include <cstdio>
#include <lac/curves/planar/la_position.hpp>
#include <lac/version.hpp>

int main() {
  const lac::LaCurve curve(/*alpha=*/-1.0, /*lambda=*/1.0);  // a clothoid: kappa = 1 - s
  const auto r = lac::position_at(curve, lac::Parameter::s, 0.5, lac::GaussKronrod{});
  const double kappa = curve.kappa_at_s(0.5);
  std::printf("lac %s: kappa(0.5) = %.17g, position (%.17g, %.17g), status %s\n", lac::version, kappa,
              r.point.position.real(), r.point.position.imag(), std::string(lac::to_string(r.status)).c_str());
  const bool ok = std::abs(kappa - 0.5) < 1e-15 && r.status == lac::Status::ok && std::abs(r.point.position) > 0.4;
  return ok ? 0 : 1;
}
