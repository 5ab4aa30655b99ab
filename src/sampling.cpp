#include "frictionref/sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "frictionref/error.hpp"

namespace frictionref {
namespace {

std::string text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

void GridOptions::validate(double t0) const {
  if (!std::isfinite(t_end)) throw InvalidInput("t_end", text(t_end), "must be a finite number");
  if (!std::isfinite(dt)) throw InvalidInput("dt", text(dt), "must be a finite number");
  if (!(t_end > t0)) throw InvalidInput("t_end", text(t_end), "must be > t0 = " + text(t0));
  if (!(dt > 0)) throw InvalidInput("dt", text(dt), "must be > 0");
  // Grid times are t0 + i dt; a step below the spacing of doubles near the
  // grid would repeat times.
  const double largest = std::fmax(std::fabs(t0), std::fabs(t_end));
  if (!(largest + dt > largest))
    throw InvalidInput("dt", text(dt),
                       "must exceed the spacing of doubles at |t| = " + text(largest));
}

double GridOptions::last_grid_limit() const { return t_end - 1e-9 * dt; }

std::uint64_t GridOptions::grid_rows(double t0) const {
  // Count i with t0 + i dt < last_grid_limit() by the sampler's own
  // arithmetic (estimate, then correct the rounding), plus the row at t_end.
  const double limit = last_grid_limit();
  const double estimate = std::ceil((limit - t0) / dt);
  if (!(estimate < 1.8e19)) return std::numeric_limits<std::uint64_t>::max();
  std::uint64_t below = estimate > 0 ? static_cast<std::uint64_t>(estimate) : 0;
  const auto grid = [&](std::uint64_t i) { return t0 + static_cast<double>(i) * dt; };
  while (below > 0 && grid(below - 1) >= limit) --below;
  while (grid(below) < limit) ++below;
  return below + 1;
}

UniformSampler::UniformSampler(const Model& model, const GridOptions& options)
    : model_(model), options_(options), engine_(model, options.t_end) {
  options.validate(model.t0);
  have_phase_ = engine_.next(phase_);
  if (have_phase_) law_.emplace(model_, phase_);
}

bool UniformSampler::finish() {
  finished_ = true;
  return false;
}

bool UniformSampler::advance_to(double t) {
  while (t >= phase_.t_end && phase_.t_end < options_.t_end) {
    if (!engine_.next(phase_)) return false;
    law_ = law_->for_phase(phase_);
  }
  return true;
}

bool UniformSampler::buffer_one(const State& state) {
  times_[0] = state.t;
  x_[0] = state.x;
  v_[0] = state.v;
  a_[0] = state.a;
  buffer_phase_ = state.phase;
  buffer_next_ = 0;
  buffer_size_ = 1;
  return true;
}

void UniformSampler::fill_grid_times() {
  // i as index_ + k in double, exact below 2^53 (a loop without conversions
  // of 64-bit integers, which the compiler turns into vector code).
  const double t0 = model_.t0, dt = options_.dt;
  if (index_ + kBufferRows <= (std::uint64_t{1} << 53)) {
    const double base = static_cast<double>(index_);
    for (std::size_t k = 0; k < kBufferRows; ++k)
      times_[k] = t0 + (base + static_cast<double>(static_cast<int>(k))) * dt;
  } else {
    for (std::size_t k = 0; k < kBufferRows; ++k) times_[k] = grid_time(index_ + k);
  }
}

bool UniformSampler::evaluate_next_rows() {
  if (finished_ || !have_phase_) return false;
  // The next grid time below t_end (a grid time within 1e-9 dt of t_end is
  // dropped, so t_end is not preceded by a near-duplicate), else t_end.
  double t = grid_time(index_);
  const double limit = options_.last_grid_limit();
  const bool on_grid = t < limit;
  if (!on_grid) t = options_.t_end;
  // With events, a phase boundary before the next grid time comes first; it
  // is reported in the phase that starts there.
  if (options_.include_events && phase_.t_end < t) {
    const double boundary = phase_.t_end;
    if (!advance_to(boundary)) return finish();
    return buffer_one((*law_)(boundary));
  }
  if (!advance_to(t)) return finish();
  if (!on_grid) {
    finished_ = true;
    return buffer_one((*law_)(t));
  }
  // This grid time and the next ones inside the same phase, evaluated
  // together (four or eight at a time on the fast paths). Grid times do not
  // decrease with i, so those below the phase's end and the grid's limit
  // are the first `count`, found by bisection (this one, t, is among them:
  // advance_to).
  fill_grid_times();
  const double below = std::fmin(limit, phase_.t_end);
  const std::size_t count =
      static_cast<std::size_t>(std::partition_point(times_.begin() + 1, times_.end(),
                                                    [below](double g) { return g < below; }) -
                               times_.begin());
  (*law_)(times_.data(), count, x_.data(), v_.data(), a_.data());
  buffer_phase_ = phase_.kind;
  index_ += count;
  buffer_next_ = 0;
  buffer_size_ = count;
  return true;
}

double resolvable_t_end(const Model& model, double t) {
  return std::fmax(t, model.t0 + 4 * time_resolution(model, model.t0));
}

std::vector<State> sample_at(const Model& model, const std::vector<double>& times) {
  std::vector<State> states;
  if (times.empty()) return states;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]))
      throw InvalidInput("times[" + std::to_string(i) + "]", text(times[i]),
                         "must be a finite number");
    if (times[i] < model.t0)
      throw InvalidInput("times[" + std::to_string(i) + "]", text(times[i]),
                         "must be >= t0 = " + text(model.t0));
    if (i > 0 && times[i] < times[i - 1])
      throw InvalidInput("times[" + std::to_string(i) + "]", text(times[i]),
                         "must be >= the previous time " + text(times[i - 1]));
  }
  // Times at or just after t0 fall in the first phase of a resolvable horizon.
  const double last = resolvable_t_end(model, times.back());
  ExactEngine engine(model, last);
  Phase phase;
  engine.next(phase);
  std::optional<PhaseEvaluator> law(std::in_place, model, phase);
  states.resize(times.size());
  for (std::size_t i = 0; i < times.size();) {
    // An engine that stops early (a status, never expected) must not loop here.
    bool moved = false;
    while (times[i] >= phase.t_end && phase.t_end < last) {
      if (!engine.next(phase))
        throw std::runtime_error("exact engine: " + engine.summary().message);
      moved = true;
    }
    if (moved) law = law->for_phase(phase);
    // This time and the following ones in the same phase, evaluated together.
    std::size_t end = i + 1;
    while (end < times.size() && (times[end] < phase.t_end || phase.t_end >= last)) ++end;
    (*law)(&times[i], end - i, &states[i]);
    i = end;
  }
  return states;
}

}  // namespace frictionref
