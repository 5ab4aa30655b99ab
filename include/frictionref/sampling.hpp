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
// Consecutive rows of one phase as columns (UniformSampler::next(StateRows&)):
// row i is the state {t[i], x[i], v[i], a[i], phase}. The arrays are the
// sampler's own, valid until its next call.
struct StateRows {
  const double* t = nullptr;
  const double* x = nullptr;
  const double* v = nullptr;
  const double* a = nullptr;
  PhaseKind phase = PhaseKind::stick;
  std::size_t size = 0;

  State operator[](std::size_t i) const { return {t[i], x[i], v[i], a[i], phase}; }
};

class UniformSampler {
 public:
  UniformSampler(const Model& model, const GridOptions& options);
  // The next row; false at the end. (Inline: most calls copy one row the
  // sampler has already evaluated.)
  bool next(State& state) {
    if (buffer_next_ == buffer_size_ && !evaluate_next_rows()) return false;
    const std::size_t i = buffer_next_++;
    state = {times_[i], x_[i], v_[i], a_[i], buffer_phase_};
    return true;
  }
  // The next rows, all of one phase (up to 64: those evaluated together, or
  // what next(State&) has left of them); false at the end. The same rows as
  // next(State&), in the same order, without building a state per row: the
  // cheapest way through a grid.
  bool next(StateRows& rows) {
    if (buffer_next_ == buffer_size_ && !evaluate_next_rows()) return false;
    const std::size_t i = buffer_next_;
    rows = {&times_[i], &x_[i], &v_[i], &a_[i], buffer_phase_, buffer_size_ - i};
    buffer_next_ = buffer_size_;
    return true;
  }
  const Summary& engine_summary() const { return engine_.summary(); }

 private:
  // Evaluates the next rows into the buffer (it is empty); false at the end.
  bool evaluate_next_rows();
  bool buffer_one(const State& state);  // the buffer holds this row alone; true
  // grid times from index_ on into times_, as many as the buffer holds
  void fill_grid_times();
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
  // Rows of one phase evaluated together (grid rows, or a single boundary
  // or end row), as columns, served in order.
  static constexpr std::size_t kBufferRows = 64;
  std::array<double, kBufferRows> times_{}, x_{}, v_{}, a_{};
  PhaseKind buffer_phase_ = PhaseKind::stick;
  std::size_t buffer_next_ = 0, buffer_size_ = 0;
};

// max(t, t0 + 4 time resolutions): a horizon the engine accepts however
// close t is to t0 (it resolves nothing shorter than 8 eps max(1, |w t0|) / w).
double resolvable_t_end(const Model& model, double t);

// The exact state at each of `times` (non-decreasing, within [t0, t_end]).
// Throws InvalidInput otherwise.
std::vector<State> sample_at(const Model& model, const std::vector<double>& times);

}  // namespace frictionref
