// A double-double constant of a fast path with its error bound, computed once
// per phase (double_double_slip.hpp, double_double_oscillator.hpp). A plain
// struct, so that the classes' headers stay free of AVX2 code.
#pragma once

namespace frictionref::detail {

struct DoubleDoubleConstant {
  double hi = 0, lo = 0, error = 0;  // |hi + lo - exact| <= error
};

}  // namespace frictionref::detail
