// What compare() can see: PASS needs the candidate's samples to resolve the
// exact motion (every exact phase longer than the stop-time tolerance holds a
// sample, the samples around every exact event are at most that tolerance
// apart); a run that passes every check without that is INCONCLUSIVE.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "comparison/resolution.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref {
namespace {

Phase phase(PhaseKind kind, double begin, double end) {
  Phase p;
  p.kind = kind;
  p.t_begin = begin;
  p.t_end = end;
  return p;
}

TEST(CompareResolution, EventsAndPhasesBetweenSamplesAreNamed) {
  const std::vector<Phase> phases = {
      phase(PhaseKind::stick, 0, 1),
      phase(PhaseKind::slip_forward, 1, 3),
      phase(PhaseKind::stick, 3, 3.05),  // shorter than the tolerance: not required
      phase(PhaseKind::slip_backward, 3.05, 4),
      phase(PhaseKind::stick, 4, 4.5),
      phase(PhaseKind::slip_forward, 4.5, 6)};
  const std::vector<double> t = {0, 0.5, 0.96, 1.04, 2, 2.9, 3.2, 3.95, 4.55, 6};
  const comparison::Resolution r = comparison::resolution(phases, t, 0.1);
  // Event at 1: samples 0.96 and 1.04, 0.08 apart: resolved (at most the
  // tolerance). Events at 3 and 3.05: samples 2.9 and 3.2. Events at 4 and
  // 4.5: samples 3.95 and 4.55, and the stick [4, 4.5] holds no sample.
  EXPECT_EQ(r.events, 4u);
  EXPECT_EQ(r.phases, 1u);
  ASSERT_EQ(r.parts.size(), 5u);
  EXPECT_EQ(r.parts[0].kind, UnresolvedPart::Kind::event);
  EXPECT_EQ(r.parts[0].start, 3);
  EXPECT_NEAR(r.parts[0].spacing, 0.3, 1e-15);
  EXPECT_EQ(r.parts[1].start, 3.05);
  EXPECT_EQ(r.parts[1].phase, PhaseKind::slip_backward);
  EXPECT_EQ(r.parts[2].kind, UnresolvedPart::Kind::event);
  EXPECT_EQ(r.parts[2].start, 4);
  EXPECT_EQ(r.parts[3].kind, UnresolvedPart::Kind::phase);
  EXPECT_EQ(r.parts[3].phase, PhaseKind::stick);
  EXPECT_EQ(r.parts[3].start, 4);
  EXPECT_EQ(r.parts[3].end, 4.5);
  EXPECT_NEAR(r.parts[3].spacing, 0.6, 1e-15);
  EXPECT_EQ(r.parts[4].start, 4.5);
  // Half the smaller of the tolerance and the shortest required phase (0.5).
  EXPECT_DOUBLE_EQ(r.resolving_step, 0.05);

  // A sample on an event resolves it; samples on both ends of a phase do not
  // see it.
  const comparison::Resolution on = comparison::resolution(
      {phase(PhaseKind::stick, 0, 1), phase(PhaseKind::slip_forward, 1, 2)}, {0, 1, 2}, 0.1);
  EXPECT_EQ(on.events, 0u);
  EXPECT_EQ(on.phases, 0u);  // [0, 1] reaches back to the record's start: t = 0 is in it
  const comparison::Resolution ends =
      comparison::resolution({phase(PhaseKind::slip_forward, 0, 1), phase(PhaseKind::stick, 1, 2),
                              phase(PhaseKind::slip_forward, 2, 3)},
                             {0, 1, 2, 3}, 0.1);
  EXPECT_EQ(ends.events, 0u);
  EXPECT_EQ(ends.phases, 1u);  // the stick [1, 2]; the slips reach the record's ends
  EXPECT_EQ(comparison::resolution(phases, t, 0.1, 2).parts.size(), 2u);  // keeps the first 2
}

// The case: a run archived every 5 time units plus its own event rows
// misses two breakaways at lambda = 0.7. Its samples are exact wherever it
// has them, so every check passes, and compare used to say PASS. The exact
// phases between the samples are named now, and the verdict is INCONCLUSIVE.
TEST(CompareResolution, CoarseArchiveThatHidesMissedBreakawaysIsInconclusive) {
  Model model;
  model.friction = 0.7;
  const Solution exact = solve(model, 30.0);
  std::vector<double> t;
  for (double s = 0; s <= 30; s += 5) t.push_back(s);
  std::vector<double> breakaways;
  for (const Phase& p : exact.phases)
    if (p.kind != PhaseKind::stick && p.t_begin > 0) breakaways.push_back(p.t_begin);
  ASSERT_GE(breakaways.size(), 4u);
  for (const Phase& p : exact.phases) {
    const bool hidden = p.t_begin == breakaways[1] || p.t_begin == breakaways[2];
    if (p.t_begin > 0 && !hidden) t.push_back(p.t_begin);
  }
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  TimeHistory history;
  history.t = t;
  for (const State& s : sample_at(model, t)) history.v.push_back(s.v);
  history.source = "coarse archive";

  const ComparisonReport r = compare(model, history);
  EXPECT_TRUE(r.failed_checks().empty()) << r.full_report();
  EXPECT_EQ(r.verdict, Verdict::inconclusive) << r.full_report();
  EXPECT_GT(r.unresolved_phases, 0u);
  bool names_hidden = false;
  for (const UnresolvedPart& part : r.unresolved)
    names_hidden = names_hidden || part.start == breakaways[1] || part.start == breakaways[2];
  EXPECT_TRUE(names_hidden) << r.full_report();
  const std::string brief = r.brief_report();
  EXPECT_NE(brief.find("\nresolution: "), std::string::npos) << brief;
  EXPECT_NE(brief.find("verdict: INCONCLUSIVE (the samples do not resolve the exact motion: "
                       "archive at most every 0.0314159 to resolve them)"),
            std::string::npos)
      << brief;

  // The same run with a defect it can see is still FAIL.
  history.v.back() += 0.5;
  EXPECT_EQ(compare(model, history).verdict, Verdict::fail);
}

TEST(CompareResolution, VerdictNames) {
  EXPECT_EQ(to_string(Verdict::inconclusive), "INCONCLUSIVE");
  EXPECT_EQ(verdict_from_string("INCONCLUSIVE"), Verdict::inconclusive);
}

}  // namespace
}  // namespace frictionref
