// SLAMMER's rigorous rigid-block analysis, operation for operation
// (slammer_rigid_block.hpp). Variable names follow the original so that a
// reader can hold the two side by side: a ground acceleration, t yield
// level, n friction direction (or a / t at rest), y relative acceleration,
// v / r relative velocity now / before, u / q displacement now / before,
// s relative acceleration before, d the step.
#include "frictionref/slammer_rigid_block.hpp"

#include <algorithm>
#include <cmath>

#include "frictionref/error.hpp"
#include "io/text_fields.hpp"

namespace frictionref {
namespace {

// SLAMMER's sign(): +1 for 0.
double sign(double value) { return value >= 0 ? 1.0 : -1.0; }

// SLAMMER's rest threshold on |v| (and on |r| in the two-way test).
constexpr double kRest = 1e-15;

}  // namespace

void SlammerOptions::validate() const {
  if (!std::isfinite(yield_accel_g) || yield_accel_g < 0)
    throw InvalidInput("yield_accel", io::text(yield_accel_g),
                       "must be a finite number >= 0 (the yield acceleration in g)");
}

SlammerResult slammer_rigid_block(const GroundMotion& record, const SlammerOptions& options) {
  options.validate();
  record.validate();
  if (!record.dt)
    throw InvalidInput("record", record.file,
                       "has no uniform step (a table of times); SLAMMER's algorithm integrates "
                       "at the record's step: give an .AT2 file or one column with --record-dt");
  const double d = *record.dt;
  const double t = options.yield_accel_g * record.gravity;
  const bool dual = options.two_way;
  // SLAMMER skips zero samples when its multiplier is positive (the normal
  // polarity), whatever the scale.
  const bool skip_zeros = !options.inverse;

  SlammerResult result;
  if (options.keep_history) result.displacement_history.reserve(record.a.size());
  double n = 0, q = 0, r = 0, s = 0, u = 0, v = 0, y = 0;
  for (const double a : record.a) {
    if (a == 0.0 && skip_zeros) {
      ++result.skipped_zero_samples;
      if (options.keep_history) result.displacement_history.push_back(u);
      continue;
    }
    if (std::fabs(v) < kRest)
      n = std::fabs(a) > t ? sign(a) : a / t;
    else
      n = sign(v);
    y = a - n * t;
    v = r + d / 2.0 * (y + s);
    if ((!dual && v <= 0.0) || (dual && !(std::fabs(r) < kRest || (v / r) > 0.0))) {
      v = 0;
      y = 0;
    }
    u = q + d / 2.0 * (v + r);
    if (std::fabs(r) < kRest && !(std::fabs(v) < kRest)) ++result.slip_episodes;
    result.max_relative_velocity = std::max(result.max_relative_velocity, std::fabs(v));
    q = u;
    r = v;
    s = y;
    if (options.keep_history) result.displacement_history.push_back(u);
  }
  result.displacement = u;
  result.final_velocity = v;
  result.at_rest_at_end = std::fabs(v) < kRest;
  return result;
}

}  // namespace frictionref
