// `frictionref curve`: the exact state on a uniform time grid.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "figure.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref::cli {

// "grid: t0=0 t_end=30 dt=0.01 include_events=true grid_rows=3001"
std::string grid_metadata(const Model& model, const GridOptions& grid);

// Streams every row of `sampler` as the curve CSV (metadata, header, rows);
// memory stays flat for any horizon. `observe`, if set, sees every row too.
// Returns the engine's summary.
Summary write_curve_csv(std::FILE* out, const Model& model, UniformSampler& sampler,
                        const std::string& command, const std::vector<std::string>& extra_metadata,
                        const std::function<void(const State&)>& observe = {});

// The rows a figure needs from a stream of known length: about `target`
// evenly spaced rows, plus every row where the phase changes (the kinks).
class FigureSamples {
 public:
  FigureSamples(std::uint64_t rows, std::uint64_t target = 20000)
      : stride_(rows > target ? rows / target : 1) {}
  void add(const State& state);
  const std::vector<State>& states() const { return states_; }

 private:
  std::uint64_t stride_;
  std::uint64_t seen_ = 0;
  std::vector<State> states_;
};

// Exact velocity and position against time, two panels, units in the labels.
Figure exact_curve_figure(const Model& model, const std::vector<State>& states);

}  // namespace frictionref::cli
