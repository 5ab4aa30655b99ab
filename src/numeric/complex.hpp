// Complex arithmetic for the engine's work types. std::complex is specified
// for float, double and long double only; the multiprecision engine needs the
// same few operations on Boost.Multiprecision numbers.
#pragma once

#include <cmath>

namespace frictionref::detail {

template <class Work>
struct Complex {
  Work re = 0, im = 0;
  Complex operator+(const Complex& b) const { return {re + b.re, im + b.im}; }
  Complex operator-(const Complex& b) const { return {re - b.re, im - b.im}; }
  Complex operator*(const Complex& b) const {
    return {re * b.re - im * b.im, re * b.im + im * b.re};
  }
  Complex operator*(const Work& b) const { return {re * b, im * b}; }
  Complex operator/(const Complex& b) const {
    // Smith's algorithm: no overflow or underflow in |b|^2.
    using std::fabs;
    if (fabs(b.re) >= fabs(b.im)) {
      const Work r = b.im / b.re, d = b.re + b.im * r;
      return {(re + im * r) / d, (im - re * r) / d};
    }
    const Work r = b.re / b.im, d = b.re * r + b.im;
    return {(re * r + im) / d, (im * r - re) / d};
  }
  Work abs() const {
    using std::hypot;
    return hypot(re, im);
  }
};

}  // namespace frictionref::detail
