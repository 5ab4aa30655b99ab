// Dense output: the exact state on a uniform grid or at given times,
// produced as a stream on top of the engine (memory flat for any horizon).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"

namespace frictionref {

struct GridOptions {
  double t_end = 1;             // last time (user units); finite, > model.t0
  double dt = 0.01;             // grid step (user units); finite, > 0, and t0 + dt != t0
  bool include_events = false;  // also emit a row at every phase boundary (kinks kept in plots)

  // Throws InvalidInput naming the field and the rule.
  void validate(double t0) const;
  // Grid times t0 + i dt are kept while below this (t_end - 1e-9 dt), so
  // t_end is never preceded by a near-duplicate.
  double last_grid_limit() const;
  // Rows of the plain grid: t0, t0 + dt, ... below last_grid_limit(), and
  // t_end itself (without event rows). Saturates at UINT64_MAX.
  std::uint64_t grid_rows(double t0) const;
};

// Rows at t_i = t0 + i dt (computed from i, never accumulated) while
// t_i < t_end - 1e-9 dt, then t_end itself; with include_events also at every
// phase boundary. A time on both lists appears once. At a phase boundary the
// row carries the new phase and its acceleration (right limit); the row at
// t_end carries the last phase.
class UniformSampler {
 public:
  UniformSampler(const Model& model, const GridOptions& options);
  // The next row; false at the end. (Inline where the row is already
  // evaluated: most calls copy one buffered row.)
  bool next(State& state) {
    if (buffer_next_ < buffer_size_) {
      state = buffer_[buffer_next_++];
      return true;
    }
    return next_evaluated(state);
  }
  const Summary& engine_summary() const { return engine_.summary(); }

 private:
  bool next_evaluated(State& state);  // evaluates the next rows (the buffer is empty)
  double grid_time(std::uint64_t i) const {
    return model_.t0 + static_cast<double>(i) * options_.dt;
  }
  bool advance_to(double t);  // moves phase_ until t_begin <= t <= t_end
  bool finish();              // marks the stream finished; returns false

  Model model_;
  GridOptions options_;
  ExactEngine engine_;
  Phase phase_;
  bool have_phase_ = false;
  // The closed form of phase_, built once per phase (a sample of the seed's
  // model then costs one sin_cos).
  std::optional<PhaseEvaluator> law_;
  std::uint64_t index_ = 0;
  bool finished_ = false;
  // Grid rows of the current phase evaluated together, served in order.
  static constexpr std::size_t kBufferRows = 64;
  std::array<double, kBufferRows> buffer_times_{};
  std::array<State, kBufferRows> buffer_{};
  std::size_t buffer_next_ = 0, buffer_size_ = 0;
};

// max(t, t0 + 4 time resolutions): a horizon the engine accepts however
// close t is to t0 (it resolves nothing shorter than 8 eps max(1, |w t0|) / w).
double resolvable_t_end(const Model& model, double t);

// The exact state at each of `times` (non-decreasing, within [t0, t_end]).
// Throws InvalidInput otherwise.
std::vector<State> sample_at(const Model& model, const std::vector<double>& times);

}  // namespace frictionref
