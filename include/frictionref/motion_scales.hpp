// The scales that make a tolerance mean the same in every consistent set of
// units: a velocity, a displacement and a time, read off the excitation
// (compare, convergence and the report judge errors relative to them).
//
// Harmonic forcing B cos(w t):  B/(m w), B/(m w^2) and the period 2 pi / w.
// A ground-motion record:       its peak ground velocity PGV, PGV^2 / PGA and
//                               T* = 2 pi PGV / PGA.
// A harmonic ground acceleration (B/m) cos(w t) has PGA = B/m and
// PGV = B/(m w), so the two rows give the same scales for it.
#pragma once

#include <string>
#include <string_view>

#include "frictionref/model.hpp"

namespace frictionref {

struct MotionScales {
  double velocity = 0;      // [length/time]
  double displacement = 0;  // velocity * period / (2 pi) [length]
  double period = 0;        // [time]
  // How reports name them: "B/(m w)" or "PGV"; "B/(m w^2)" or "PGV^2/PGA";
  // the time unit after a number, "periods" or "T*"; and its definition,
  // "period 2 pi / w" or "T* = 2 pi PGV/PGA".
  std::string velocity_name;
  std::string displacement_name;
  std::string period_unit;
  std::string period_name;
};

// The scales of `model`'s excitation: its record's when it has one, else its
// harmonic forcing's. Throws InvalidInput naming "amplitude" (B = 0 without a
// record) or "ground_motion" (a record that is zero throughout), with the
// rule and `purpose` ("to compare"), or either if a scale is not a finite
// positive number (over- or underflow).
MotionScales motion_scales(const Model& model, std::string_view purpose);

}  // namespace frictionref
