// Enumerations: the one spelling of every enum value (types.hpp) and slip_sign.
#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "frictionref/types.hpp"

namespace frictionref {
namespace {

// ---- PhaseKind -------------------------------------------------------------

TEST(PhaseKindNames, SpelledAsDocumented) {
  EXPECT_EQ(to_string(PhaseKind::stick), "stick");
  EXPECT_EQ(to_string(PhaseKind::slip_forward), "slip+");
  EXPECT_EQ(to_string(PhaseKind::slip_backward), "slip-");
}

TEST(PhaseKindNames, RoundTripForEveryValue) {
  for (PhaseKind kind : {PhaseKind::stick, PhaseKind::slip_forward, PhaseKind::slip_backward}) {
    const std::optional<PhaseKind> parsed = phase_kind_from_string(to_string(kind));
    ASSERT_TRUE(parsed.has_value()) << to_string(kind);
    EXPECT_EQ(*parsed, kind) << to_string(kind);
  }
}

TEST(PhaseKindNames, ParsesTheLiteralSpellings) {
  EXPECT_EQ(phase_kind_from_string("stick"), PhaseKind::stick);
  EXPECT_EQ(phase_kind_from_string("slip+"), PhaseKind::slip_forward);
  EXPECT_EQ(phase_kind_from_string("slip-"), PhaseKind::slip_backward);
}

TEST(PhaseKindNames, UnknownStringsGiveNullopt) {
  for (std::string_view text :
       {"", "Stick", "STICK", "slip", "slip +", "slip_forward", "slip_backward", " stick",
        "stick ", "slip+ ", "slip--", "+", "-", "stops", "continuous", "reached_end"}) {
    EXPECT_FALSE(phase_kind_from_string(text).has_value()) << '"' << text << '"';
  }
}

TEST(PhaseKindNames, NamesAreDistinct) {
  const std::set<std::string_view> names{to_string(PhaseKind::stick),
                                         to_string(PhaseKind::slip_forward),
                                         to_string(PhaseKind::slip_backward)};
  EXPECT_EQ(names.size(), 3u);
}

// ---- Termination -----------------------------------------------------------

TEST(TerminationNames, SpelledAsDocumented) {
  EXPECT_EQ(to_string(Termination::reached_end), "reached_end");
  EXPECT_EQ(to_string(Termination::phase_limit), "phase_limit");
  EXPECT_EQ(to_string(Termination::numerical_failure), "numerical_failure");
}

TEST(TerminationNames, RoundTripForEveryValue) {
  for (Termination t :
       {Termination::reached_end, Termination::phase_limit, Termination::numerical_failure}) {
    const std::optional<Termination> parsed = termination_from_string(to_string(t));
    ASSERT_TRUE(parsed.has_value()) << to_string(t);
    EXPECT_EQ(*parsed, t) << to_string(t);
  }
}

TEST(TerminationNames, UnknownStringsGiveNullopt) {
  for (std::string_view text : {"", "reached-end", "Reached_end", "reached_end ", "phase-limit",
                                "numerical-failure", "failure", "end", "stick", "stops"}) {
    EXPECT_FALSE(termination_from_string(text).has_value()) << '"' << text << '"';
  }
}

// ---- Regime ----------------------------------------------------------------

TEST(RegimeNames, SpelledAsDocumented) {
  EXPECT_EQ(to_string(Regime::continuous), "continuous");
  EXPECT_EQ(to_string(Regime::dead_bands), "dead-bands");
  EXPECT_EQ(to_string(Regime::stops), "stops");
}

TEST(RegimeNames, RoundTripForEveryValue) {
  for (Regime r : {Regime::continuous, Regime::dead_bands, Regime::stops}) {
    const std::optional<Regime> parsed = regime_from_string(to_string(r));
    ASSERT_TRUE(parsed.has_value()) << to_string(r);
    EXPECT_EQ(*parsed, r) << to_string(r);
  }
}

TEST(RegimeNames, UnknownStringsGiveNullopt) {
  // The enumerator is dead_bands but the spelling is "dead-bands" only.
  for (std::string_view text : {"", "dead_bands", "deadbands", "Dead-bands", "continuous ",
                                "Continuous", "stop", "stick", "slip+", "phase_limit"}) {
    EXPECT_FALSE(regime_from_string(text).has_value()) << '"' << text << '"';
  }
}

TEST(EnumNames, ParsersDoNotAcceptOtherEnumsNames) {
  EXPECT_FALSE(regime_from_string(to_string(PhaseKind::stick)).has_value());
  EXPECT_FALSE(phase_kind_from_string(to_string(Regime::stops)).has_value());
  EXPECT_FALSE(termination_from_string(to_string(Regime::continuous)).has_value());
}

TEST(EnumNames, ParsingDoesNotDependOnNulTermination) {
  // A string_view into a longer buffer: only the viewed characters count.
  const std::string buffer = "slip+XYZ";
  EXPECT_EQ(phase_kind_from_string(std::string_view(buffer).substr(0, 5)),
            PhaseKind::slip_forward);
  EXPECT_FALSE(phase_kind_from_string(std::string_view(buffer).substr(0, 4)).has_value());
  const std::string regimes = "stopsgo";
  EXPECT_EQ(regime_from_string(std::string_view(regimes).substr(0, 5)), Regime::stops);
}

// ---- slip_sign -------------------------------------------------------------

static_assert(slip_sign(PhaseKind::slip_forward) == 1, "slip+ has sign +1");
static_assert(slip_sign(PhaseKind::slip_backward) == -1, "slip- has sign -1");
static_assert(slip_sign(PhaseKind::stick) == 0, "stick has sign 0");

TEST(SlipSign, ValuesAtRunTime) {
  EXPECT_EQ(slip_sign(PhaseKind::slip_forward), 1);
  EXPECT_EQ(slip_sign(PhaseKind::slip_backward), -1);
  EXPECT_EQ(slip_sign(PhaseKind::stick), 0);
}

TEST(SlipSign, MatchesTheSpelling) {
  // "slip+" is forward (+1), "slip-" backward (-1).
  EXPECT_EQ(slip_sign(*phase_kind_from_string("slip+")), 1);
  EXPECT_EQ(slip_sign(*phase_kind_from_string("slip-")), -1);
  EXPECT_EQ(slip_sign(*phase_kind_from_string("stick")), 0);
}

}  // namespace
}  // namespace frictionref
