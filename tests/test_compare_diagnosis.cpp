// The mutation check of compare()'s diagnosis: an exact record, sampled
// finely, is broken by one known defect at a time, and the report must name
// that defect in its first line (and PASS, unmutated, must name none). The
// mutations are made here, from the exact solution, so each test knows the
// truth it expects: the shift, the factor, the bias, the phase it spoiled.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref {
namespace {

// lambda = 0.7, t in [0, 30] every 0.01: sticks and slips in every period.
struct Record {
  Model model;
  Solution exact;
  TimeHistory history;
  std::vector<State> states;

  Record() {
    model.friction = 0.7;
    exact = solve(model, 30.0);
    for (int i = 0; i <= 3000; ++i) history.t.push_back(0.01 * i);
    states = sample_at(model, history.t);
    for (const State& s : states) history.v.push_back(s.v);
    history.source = "mutated exact record";
  }

  // The n-th (0-based) exact phase of `kind` that starts after t = 0.
  const Phase& phase(bool stick, int n) const {
    for (const Phase& p : exact.phases)
      if (p.t_begin > 0 && (p.kind == PhaseKind::stick) == stick && n-- == 0) return p;
    throw std::logic_error("no such phase");
  }

  ComparisonReport compare() const { return frictionref::compare(model, history); }
};

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

// The first line of both reports names `defect`.
void expect_named(const ComparisonReport& r, Defect defect) {
  EXPECT_EQ(r.diagnosis.defect, defect) << r.full_report();
  std::string words(to_string(defect));
  for (char& c : words)
    if (c == '_') c = ' ';
  if (defect == Defect::none) words = "no defect";
  const std::string expected = "diagnosis: " + words + ": ";
  EXPECT_EQ(first_line(r.brief_report()).rfind(expected, 0), 0u) << r.brief_report();
  EXPECT_EQ(first_line(r.full_report()).rfind(expected, 0), 0u) << r.full_report();
}

TEST(CompareDiagnosis, ExactRecordNamesNoDefect) {
  const ComparisonReport r = Record().compare();
  EXPECT_EQ(r.verdict, Verdict::pass);
  expect_named(r, Defect::none);
}

TEST(CompareDiagnosis, CoarseArchiveIsUnresolved) {
  Record record;
  TimeHistory coarse;
  for (double t = 0; t <= 30; t += 5) coarse.t.push_back(t);
  for (const State& s : sample_at(record.model, coarse.t)) coarse.v.push_back(s.v);
  const ComparisonReport r = compare(record.model, coarse);
  EXPECT_EQ(r.verdict, Verdict::inconclusive);
  expect_named(r, Defect::unresolved);
}

TEST(CompareDiagnosis, TimeShiftIsNamedWithItsValue) {
  Record record;
  for (const double shift : {0.03, -0.05}) {
    // v(t) = v_exact(t - shift) at t = 0.1 .. 30 (t - shift stays in the record).
    TimeHistory shifted;
    for (double t : record.history.t)
      if (t >= 0.1) shifted.t.push_back(t);
    std::vector<double> before;
    for (double t : shifted.t) before.push_back(t - shift);
    for (const State& s : sample_at(record.model, before)) shifted.v.push_back(s.v);
    const ComparisonReport r = compare(record.model, shifted);
    EXPECT_EQ(r.verdict, Verdict::fail);
    expect_named(r, Defect::time_shift);
    EXPECT_NEAR(r.diagnosis.value, shift, 1e-9) << r.diagnosis.text();
    EXPECT_NE(r.diagnosis.evidence.find(shift > 0 ? "runs late by" : "runs early by"),
              std::string::npos)
        << r.diagnosis.text();
  }
}

TEST(CompareDiagnosis, ScaleIsNamedWithItsFactor) {
  Record record;
  for (double& v : record.history.v) v *= 1.1;
  const ComparisonReport r = record.compare();
  expect_named(r, Defect::scale);
  EXPECT_NEAR(r.diagnosis.value, 1.1, 1e-12);
}

TEST(CompareDiagnosis, VelocityBiasIsDrift) {
  Record record;
  for (double& v : record.history.v) v += 0.01;
  const ComparisonReport r = record.compare();
  EXPECT_EQ(r.verdict, Verdict::fail);
  expect_named(r, Defect::drift);
  EXPECT_NEAR(r.diagnosis.value, 0.01, 1e-12);
}

// Inside every exact stick (away from its ends) the candidate moves.
template <class Motion>
Record moving_in_sticks(Motion motion) {
  Record record;
  for (std::size_t i = 0; i < record.states.size(); ++i) {
    const double t = record.history.t[i];
    for (const Phase& p : record.exact.phases)
      if (p.kind == PhaseKind::stick && t > p.t_begin + 0.1 && t < p.t_end - 0.1)
        record.history.v[i] = motion(i);
  }
  return record;
}

TEST(CompareDiagnosis, SlowMotionInsideSticksIsCreep) {
  const ComparisonReport r = moving_in_sticks([](std::size_t) { return 0.003; }).compare();
  EXPECT_EQ(r.verdict, Verdict::fail);
  expect_named(r, Defect::creep);
}

TEST(CompareDiagnosis, SignFlipsInsideSticksAreChattering) {
  const ComparisonReport r =
      moving_in_sticks([](std::size_t i) { return i % 2 ? 0.004 : -0.004; }).compare();
  EXPECT_EQ(r.verdict, Verdict::fail);
  expect_named(r, Defect::chattering);
}

TEST(CompareDiagnosis, RestThroughAnExactSlipIsAMissedBreakaway) {
  Record record;
  const Phase& slip = record.phase(false, 1);
  for (std::size_t i = 0; i < record.states.size(); ++i)
    if (record.history.t[i] >= slip.t_begin && record.history.t[i] <= slip.t_end)
      record.history.v[i] = 0;
  const ComparisonReport r = record.compare();
  EXPECT_EQ(r.verdict, Verdict::fail);
  expect_named(r, Defect::missed_breakaway);
  char at[64];
  std::snprintf(at, sizeof at, "breaks away at t = %.6g and slides until %.6g", slip.t_begin,
                slip.t_end);
  EXPECT_NE(r.diagnosis.evidence.find(at), std::string::npos) << r.diagnosis.text();
}

TEST(CompareDiagnosis, SlidingThroughAnExactStickIsAMissedStop) {
  Record record;
  const Phase& stick = record.phase(true, 1);
  // The slip before the stop goes on along its own line through v = 0.
  const double slope = sample_at(record.model, {stick.t_begin - 1e-6}).front().a;
  for (std::size_t i = 0; i < record.states.size(); ++i) {
    const double t = record.history.t[i];
    if (t > stick.t_begin && t < stick.t_end) record.history.v[i] = slope * (t - stick.t_begin);
  }
  const ComparisonReport r = record.compare();
  EXPECT_EQ(r.verdict, Verdict::fail);
  expect_named(r, Defect::missed_stop);
}

TEST(CompareDiagnosis, ConstantPositionErrorIsAnOffset) {
  Record record;
  record.history.x.emplace();
  for (const State& s : record.states) record.history.x->push_back(s.x + 0.05);
  const ComparisonReport r = record.compare();
  EXPECT_EQ(r.failed_checks(), std::vector<std::string>{"displacement_max"});
  expect_named(r, Defect::offset);
  EXPECT_NEAR(r.diagnosis.value, 0.05, 1e-9);
}

TEST(CompareDiagnosis, PositionErrorGrowingLinearlyIsDrift) {
  Record record;
  record.history.x.emplace();
  for (std::size_t i = 0; i < record.states.size(); ++i)
    record.history.x->push_back(record.states[i].x + 0.01 * record.history.t[i]);
  const ComparisonReport r = record.compare();
  EXPECT_EQ(r.failed_checks(), std::vector<std::string>{"displacement_max"});
  expect_named(r, Defect::drift);
  EXPECT_NEAR(r.diagnosis.value, 0.01, 1e-9);
}

TEST(CompareDiagnosis, DefectNamesRoundTrip) {
  for (Defect d : {Defect::none, Defect::unresolved, Defect::time_shift, Defect::scale,
                   Defect::chattering, Defect::creep, Defect::missed_breakaway, Defect::missed_stop,
                   Defect::drift, Defect::offset, Defect::unclassified})
    EXPECT_EQ(defect_from_string(to_string(d)), d);
  EXPECT_FALSE(defect_from_string("shift").has_value());
}

}  // namespace
}  // namespace frictionref
