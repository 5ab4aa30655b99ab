// Sticks on both sides: the engine's stick phases, the sticks detected in the
// exact and the candidate velocity at the candidate's times, their matching,
// and the candidate's motion inside the exact sticks (creep).
#pragma once

#include <cstddef>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::comparison {

// The stick phases among `phases`, cut at t_last.
std::vector<StickInterval> stick_phases(const std::vector<Phase>& phases, double t_last);

// Fills r.matched, r.missed and r.extra from r.exact_sticks and
// r.candidate_sticks, matched in time order: two intervals match if they
// overlap once each is widened by the stop-time tolerance. Each match names
// the engine's stick phase (r.exact_phases) that overlaps it most.
void match_sticks(ComparisonReport& r);

// The candidate's rows [first, last) inside an exact phase [begin, end], less
// the stop-time margin at ends that are events (not the record's own ends):
// where the candidate must show what the phase is, whatever its sampling
// does at the phase's edges.
struct RowRange {
  std::size_t first = 0;
  std::size_t last = 0;
};
RowRange rows_inside(const ComparisonReport& r, const std::vector<double>& t, double begin,
                     double end);

// Fills r.creep_*: the candidate's largest |v| inside the exact stick phases,
// less the stop-time margin at ends that are real stops or breakaways (not the
// record's own ends). Returns the index in r.exact_phases where it was, or
// r.exact_phases.size() if no sample falls inside.
std::size_t measure_creep(ComparisonReport& r, const std::vector<double>& t,
                          const std::vector<double>& v);

}  // namespace frictionref::comparison
