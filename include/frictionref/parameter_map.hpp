// Two-parameter maps of the steady state, in the style of Hong & Liu (2000):
// for every point of a grid over two model parameters, the steady motion
// found by simulation (classification.hpp) - stops per period (sticks of
// non-zero duration, not direct reversals), reversals per period, the
// period multiplicity and the stuck fraction. All cores; results in grid
// order whatever the number of threads (docs/cli.md, "map").
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frictionref/classification.hpp"
#include "frictionref/model.hpp"
#include "frictionref/shard.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

// A parameter a map axis can vary. Setting one (with_parameter) changes the
// base model as follows:
//   lambda           R = value * B; a static friction set in the base model keeps its ratio Rs/R
//   static-ratio     Rs = value * R (>= 1)
//   frequency-ratio  w = value * sqrt(k/m) (needs k > 0)
//   damping-ratio    c = value * 2 sqrt(k m) (needs k > 0)
//   mass, amplitude, omega, friction, static-friction, stiffness, damping,
//   force-offset, x0, v0: that field itself (friction keeps a set Rs/R as lambda does).
enum class MapParameter {
  lambda,
  static_ratio,
  frequency_ratio,
  damping_ratio,
  mass,
  amplitude,
  omega,
  friction,
  static_friction,
  stiffness,
  damping,
  force_offset,
  x0,
  v0,
};
// "lambda", "static-ratio", "frequency-ratio", ...: the names on the command line.
std::string_view to_string(MapParameter parameter);
std::optional<MapParameter> map_parameter_from_string(std::string_view text);
// The CSV column: the name with '_' for '-' ("frequency_ratio").
std::string column_name(MapParameter parameter);
// Every name, comma-separated, for messages and help.
std::string map_parameter_names();

// The base model with one parameter set (rules above); the caller validates.
// Throws InvalidInput naming the parameter where it needs k > 0 or B > 0.
Model with_parameter(const Model& base, MapParameter parameter, double value);

struct MapAxis {
  MapParameter parameter = MapParameter::lambda;
  double from = 0;           // first value; finite
  double to = 0;             // last value; finite, >= from
  std::uint64_t points = 1;  // evenly spaced values from..to; >= 1 (1 needs from = to)

  // Throws InvalidInput naming `option` ("x", "y") and the rule.
  void validate(const std::string& option) const;
  std::vector<double> values() const;  // computed from the index, never accumulated
  // "lambda:0:1.2:241" (name:from:to:points); throws InvalidInput naming `option`.
  static MapAxis parse(std::string_view spec, const std::string& option);
};

struct MapOptions {
  ClassifyOptions classify;  // max_periods: periods simulated per point at most
  unsigned threads = 0;      // 0: all cores
  // Only this shard's contiguous block of the grid's points (in the order
  // below); the default is the whole grid.
  Shard shard;
};

struct MapPoint {
  double x = 0, y = 0;  // the axes' values
  Regime regime = Regime::stops;
  double stops_per_period = 0;
  double reversals_per_period = 0;
  unsigned multiplicity = 0;  // 0: no repetition found
  double stuck_fraction = 0;
  std::uint64_t transient_periods = 0;
};

using MapProgress = std::function<void(std::size_t done, std::size_t total)>;

// Every point of x.values() x y.values(), x outer (rows of constant x), each
// classified by simulation (closed forms are not used: a map shows what the
// motion does); with options.shard, only that shard's block of these points
// (options.shard.range(x.points * y.points)), the same numbers as in the
// whole map. Validates the axes, options (the shard: "shard") and the base
// model at every corner of the whole grid first (InvalidInput).
std::vector<MapPoint> parameter_map(const Model& base, const MapAxis& x, const MapAxis& y,
                                    const MapOptions& options, const MapProgress& progress = {});

}  // namespace frictionref
