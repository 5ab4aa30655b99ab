// Axis ticks (axis_ticks.hpp).
#include "axis_ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionref::cli {

Axis make_axis(double lo, double hi, int target, double padding) {
  Axis axis;
  const double magnitude = std::max(std::fabs(lo), std::fabs(hi));
  // A span a double can still divide into ticks: at least a millionth of the
  // magnitude (or 1 around zero).
  const double min_span = magnitude > 0 ? magnitude * 1e-6 : 1.0;
  if (!(hi - lo >= min_span)) {
    const double middle = lo / 2 + hi / 2;
    lo = middle - min_span / 2;
    hi = middle + min_span / 2;
  }
  const double span = hi - lo;
  axis.min = lo - padding * span;
  axis.max = hi + padding * span;

  // The step: 1, 2 or 5 times a power of ten, nearest above span / target.
  const double raw = (axis.max - axis.min) / std::max(target, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * power;
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * power >= raw) {
      step = factor * power;
      break;
    }
  }
  // Digits enough to tell ticks `step` apart at this magnitude.
  const double largest = std::max(std::fabs(axis.min), std::fabs(axis.max));
  const int digits = std::clamp(
      static_cast<int>(std::floor(std::log10(largest)) - std::floor(std::log10(step))) + 1, 1, 17);
  for (double k = std::ceil(axis.min / step); k * step <= axis.max && axis.ticks.size() < 50; ++k) {
    double value = k * step;
    if (std::fabs(value) < step * 1e-9) value = 0;  // no "-0" or "1e-17" at the origin
    axis.ticks.push_back(value);
    axis.labels.push_back(fmt::format("{:.{}g}", value, digits));
  }
  return axis;
}

}  // namespace frictionref::cli
