// The commands a report prints so that a reader can redo it: the compare run
// behind the verdict, and the exact reference curves. They spell the model
// and every tolerance out as options whose numbers round-trip, so they give
// the same doubles whatever the report's own command line said.
#pragma once

#include <string>
#include <vector>

#include "../compare_run.hpp"
#include "frictionref/comparison.hpp"

namespace frictionref::cli {

// --mass M --amplitude B --omega W --friction R [--static-friction RS]
// [--stiffness K] [--damping C] [--force-offset F0] [--harmonic B,W,PHI]...
// --x0 X --v0 V --t0 T.
std::vector<std::string> model_arguments(const Model& model);

struct ReproduceCommands {
  std::string checksum;  // sha256sum FILE
  std::string compare;   // the text verdict and full report
  std::string curve;     // the exact curve t,x,v,a,phase over the record, with every event
  std::string events;    // the exact phase table over the record
};

// Shell-quoted, one line each.
ReproduceCommands reproduce_commands(const ComparisonReport& report, const CompareInputs& typed);

// The step of the reference curve: the largest 1, 2 or 5 times a power of
// ten that is at most `spacing` (> 0, finite).
double reference_step(double spacing);

}  // namespace frictionref::cli
