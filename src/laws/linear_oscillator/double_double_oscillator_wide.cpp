// The general model's dense rows on eight lanes: compiled with -mavx512f and
// FRICTIONREF_LANES=8 (src/CMakeLists.txt), entered only where
// double_double_wide_lanes_available(). Includes nothing that defines inline
// functions of the library or the standard library (see
// double_double_slip.cpp).
#include "laws/linear_oscillator/double_double_oscillator_rows.hpp"

namespace frictionref::detail {

template void DoubleDoubleOscillator::evaluate_lanes<8>(const double*, std::size_t, double*,
                                                        double*, double*, unsigned char*) const;

}  // namespace frictionref::detail
