// Newmark's sliding-block analysis of ground-motion records: the permanent
// displacement for every record x yield acceleration x polarity, exact
// (the engine, docs/theory.md 9) or by SLAMMER's algorithm
// (slammer_rigid_block.hpp), on all cores. `frictionref newmark` prints it.
//
// Sign convention (SLAMMER's and Jibson's, 1993): the displacement is
// positive downslope, a slide starts when the ground acceleration exceeds
// KY g, and the "normal" polarity is the record as given, "inverse" the
// record negated. In the engine's model (x relative to the ground, the
// record entering as -m a_g) the normal polarity is the model with the
// record negated, so that x is SLAMMER's displacement.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frictionref/ground_motion.hpp"
#include "frictionref/model.hpp"

namespace frictionref {

enum class NewmarkMethod { exact, slammer };
enum class Polarity { normal, inverse };

// "exact", "slammer"; "normal", "inverse".
std::string_view to_string(NewmarkMethod method);
std::string_view to_string(Polarity polarity);
std::optional<NewmarkMethod> newmark_method_from_string(std::string_view text);

// The sizes of one batch that the front ends accept (they refuse more
// before reading a record).
struct NewmarkLimits {
  static constexpr std::size_t records = 10'000;
  static constexpr std::size_t yield_values = 10'000;
  static constexpr double runs = 1e7;  // records x yield values x polarities
};

// The rule a yield acceleration KY [g] breaks with `method` ("" if none):
// finite and >= 0; > 0 for SLAMMER's method. The front ends put it after
// the value as the user typed it.
std::string yield_accel_rule(double yield_accel_g, NewmarkMethod method);

struct NewmarkOptions {
  std::vector<double> yield_accels_g;  // KY values [g]; each finite, >= 0; at least one
  bool one_way = true;                 // SLAMMER's default: the downslope block
  std::vector<Polarity> polarities = {Polarity::normal};
  NewmarkMethod method = NewmarkMethod::exact;
  unsigned threads = 0;  // 0: every core
  // Called from the calling thread about every 100 ms: (done, total) runs.
  std::function<void(std::size_t, std::size_t)> progress;

  void validate() const;  // throws InvalidInput naming the field
};

struct NewmarkResult {
  std::string record;  // the record's file
  double yield_accel_g = 0;
  Polarity polarity = Polarity::normal;
  NewmarkMethod method = NewmarkMethod::exact;
  // Both in the record's length unit (that of its gravity): the displacement
  // when the record ends, and once the block has come to rest after it (the
  // ground being still); unset if it never does (KY = 0 while still moving).
  double displacement_at_record_end = 0;
  std::optional<double> permanent_displacement;
  std::size_t slip_episodes = 0;     // slides (exact: slip phases)
  double max_relative_velocity = 0;  // max |v| relative to the ground [length/s]
};

// The engine's model of one exact analysis: unit mass, R = KY g (g the
// record's gravity), the record negated for the normal polarity (so that x
// is the downslope displacement) or as read for the inverse, one-way or
// not, starting at rest at min(0, the first sample's time).
Model newmark_model(std::shared_ptr<const GroundMotion> model_record, double yield_accel_g,
                    bool one_way);
// The record as the model of `polarity` takes it: negated for the normal
// polarity (a copy), as read for the inverse.
std::shared_ptr<const GroundMotion> newmark_record(std::shared_ptr<const GroundMotion> record,
                                                   Polarity polarity);
// A horizon by which a block sliding at the record's end has come to rest
// (the ground still, it slows at KY g): the last sample's time plus
// (PGA + KY g) (t_last - t0) / (KY g), with a margin; the last sample's time
// when KY = 0, and at most 1e9 s.
double newmark_horizon(const Model& model);

// One analysis. `record` as read (normal polarity = as given).
NewmarkResult newmark_analysis(const GroundMotion& record, double yield_accel_g, bool one_way,
                               Polarity polarity, NewmarkMethod method);

// Every record x KY x polarity, in that order (records outermost), on
// options.threads threads.
std::vector<NewmarkResult> newmark_batch(
    const std::vector<std::shared_ptr<const GroundMotion>>& records, const NewmarkOptions& options);

}  // namespace frictionref
