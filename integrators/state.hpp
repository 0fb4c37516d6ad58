#pragma once
// What an ODE state must offer: a vector space over double with a max-norm.
// double, std::complex<double> and Eigen fixed-size vectors qualify.
#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <concepts>

namespace lac {

inline double max_abs(double v) { return std::abs(v); }
inline double max_abs(const std::complex<double>& v) { return std::max(std::abs(v.real()), std::abs(v.imag())); }
template <class Derived>
double max_abs(const Eigen::MatrixBase<Derived>& v) {
  return v.cwiseAbs().maxCoeff();
}

/// Element-wise weighted error norm used by step control: max_i |e_i| / (atol + rtol * max(|a_i|, |b_i|)).
inline double scaled_error(double e, double a, double b, double atol, double rtol) {
  return std::abs(e) / (atol + rtol * std::max(std::abs(a), std::abs(b)));
}
inline double scaled_error(const std::complex<double>& e, const std::complex<double>& a,
                           const std::complex<double>& b, double atol, double rtol) {
  return std::max(scaled_error(e.real(), a.real(), b.real(), atol, rtol),
                  scaled_error(e.imag(), a.imag(), b.imag(), atol, rtol));
}
template <class D1, class D2, class D3>
double scaled_error(const Eigen::MatrixBase<D1>& e, const Eigen::MatrixBase<D2>& a, const Eigen::MatrixBase<D3>& b,
                    double atol, double rtol) {
  auto scale = (a.cwiseAbs().cwiseMax(b.cwiseAbs()).array() * rtol + atol);
  return (e.cwiseAbs().array() / scale).maxCoeff();
}

template <class S>
concept OdeState = std::copyable<S> && requires(S a, S b, double c) {
  { a + b } -> std::convertible_to<S>;
  { c * a } -> std::convertible_to<S>;
  { max_abs(a) } -> std::convertible_to<double>;
  { scaled_error(a, a, b, c, c) } -> std::convertible_to<double>;
};

}  // namespace lac
