// The model, its validation and its derived quantities (model.hpp, error.hpp),
// and SolveOptions::validate (exact_engine.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"

namespace frictionref {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using testing::expect_invalid;

// Every field of Model, by name, for table-driven tests.
struct Field {
  const char* name;
  double Model::*member;
};
const std::vector<Field>& fields() {
  static const std::vector<Field> list{
      {"mass", &Model::mass}, {"amplitude", &Model::amplitude}, {"omega", &Model::omega},
      {"friction", &Model::friction}, {"x0", &Model::x0},       {"v0", &Model::v0},
      {"t0", &Model::t0},
  };
  return list;
}

// ---- defaults --------------------------------------------------------------

TEST(ModelValidate, DefaultsAreValidAndDocumented) {
  const Model model{};
  EXPECT_NO_THROW(model.validate());
  EXPECT_EQ(model.mass, 1.0);
  EXPECT_EQ(model.amplitude, 1.0);
  EXPECT_EQ(model.omega, 1.0);
  EXPECT_EQ(model.friction, 0.0);  // frictionless by default, and that is valid
  EXPECT_EQ(model.x0, 0.0);
  EXPECT_EQ(model.v0, 0.0);
  EXPECT_EQ(model.t0, 0.0);
}

TEST(ModelValidate, DefaultsAreValidInLongDoubleAndHighPrecision) {
  EXPECT_NO_THROW(BasicModel<long double>{}.validate());
  EXPECT_NO_THROW(BasicModel<HighPrecision>{}.validate());
}

// ---- non-finite values -----------------------------------------------------

TEST(ModelValidate, NonFiniteRejectedForEveryFieldNamingIt) {
  for (const Field& field : fields()) {
    for (double bad : {kNaN, kInf, -kInf}) {
      Model model;
      model.*field.member = bad;
      const InvalidInput error = expect_invalid([&] { model.validate(); });
      EXPECT_EQ(error.parameter(), field.name) << field.name << " = " << bad;
      EXPECT_EQ(error.rule(), "must be a finite number") << field.name << " = " << bad;
      // what() is "<name> = <value>; violated: <rule>".
      EXPECT_EQ(std::string(error.what()),
                std::string(field.name) + " = " + error.value() + "; violated: " + error.rule());
      EXPECT_FALSE(error.value().empty());
    }
  }
}

TEST(ModelValidate, NonFiniteValueTextSaysWhichNonFinite) {
  Model model;
  model.v0 = kInf;
  EXPECT_NE(expect_invalid([&] { model.validate(); }).value().find("inf"), std::string::npos);
  model.v0 = -kInf;
  EXPECT_NE(expect_invalid([&] { model.validate(); }).value().find("-inf"), std::string::npos);
  model.v0 = kNaN;
  EXPECT_NE(expect_invalid([&] { model.validate(); }).value().find("nan"), std::string::npos);
}

TEST(ModelValidate, NonFiniteRejectedInLongDouble) {
  BasicModel<long double> model;
  model.t0 = std::numeric_limits<long double>::infinity();
  const InvalidInput error = expect_invalid([&] { model.validate(); });
  EXPECT_EQ(error.parameter(), "t0");
  EXPECT_EQ(error.rule(), "must be a finite number");
}

// ---- sign rules ------------------------------------------------------------

TEST(ModelValidate, MassMustBePositive) {
  for (double bad : {0.0, -0.0, -1.0, -1e-300, -std::numeric_limits<double>::denorm_min()}) {
    Model model;
    model.mass = bad;
    const InvalidInput error = expect_invalid([&] { model.validate(); });
    EXPECT_EQ(error.parameter(), "mass") << bad;
    EXPECT_EQ(error.rule(), "must be > 0") << bad;
  }
  Model tiny;
  tiny.mass = std::numeric_limits<double>::denorm_min();
  EXPECT_NO_THROW(tiny.validate());
}

TEST(ModelValidate, OmegaMustBePositive) {
  for (double bad : {0.0, -0.0, -2.0, -1e-300}) {
    Model model;
    model.omega = bad;
    const InvalidInput error = expect_invalid([&] { model.validate(); });
    EXPECT_EQ(error.parameter(), "omega") << bad;
    EXPECT_EQ(error.rule(), "must be > 0") << bad;
  }
}

TEST(ModelValidate, AmplitudeMustBeNonNegative) {
  for (double bad : {-1.0, -1e-300, -std::numeric_limits<double>::denorm_min()}) {
    Model model;
    model.amplitude = bad;
    const InvalidInput error = expect_invalid([&] { model.validate(); });
    EXPECT_EQ(error.parameter(), "amplitude") << bad;
    EXPECT_EQ(error.rule(), "must be >= 0") << bad;
  }
}

TEST(ModelValidate, FrictionMustBeNonNegative) {
  for (double bad : {-0.3, -1e-300, -std::numeric_limits<double>::denorm_min()}) {
    Model model;
    model.friction = bad;
    const InvalidInput error = expect_invalid([&] { model.validate(); });
    EXPECT_EQ(error.parameter(), "friction") << bad;
    EXPECT_EQ(error.rule(), "must be >= 0") << bad;
  }
}

TEST(ModelValidate, ZeroAmplitudeAndZeroFrictionAccepted) {
  Model model;
  model.amplitude = 0;
  model.friction = 0;
  EXPECT_NO_THROW(model.validate());
  model.friction = 0.5;  // unforced, with friction
  EXPECT_NO_THROW(model.validate());
  model.amplitude = 2;
  model.friction = 0;  // forced, frictionless
  EXPECT_NO_THROW(model.validate());
}

TEST(ModelValidate, InitialStateAndTimeMayHaveAnySign) {
  Model model;
  model.x0 = -1e300;
  model.v0 = -1e300;
  model.t0 = -1e300;
  EXPECT_NO_THROW(model.validate());
  model.x0 = 1e300;
  model.v0 = 1e300;
  model.t0 = 1e300;
  EXPECT_NO_THROW(model.validate());
  model.x0 = model.v0 = model.t0 = -0.0;
  EXPECT_NO_THROW(model.validate());
}

TEST(ModelValidate, LargeButFinitePhysicalParametersAccepted) {
  Model model;
  model.mass = std::numeric_limits<double>::max();
  model.amplitude = std::numeric_limits<double>::max();
  model.omega = std::numeric_limits<double>::max();
  model.friction = std::numeric_limits<double>::max();
  EXPECT_NO_THROW(model.validate());
}

// ---- message format --------------------------------------------------------

TEST(ModelValidate, WhatFormatForNegativeMass) {
  Model model;
  model.mass = -1;
  const InvalidInput error = expect_invalid([&] { model.validate(); });
  EXPECT_STREQ(error.what(), "mass = -1; violated: must be > 0");
  EXPECT_EQ(error.parameter(), "mass");
  EXPECT_EQ(error.value(), "-1");
  EXPECT_EQ(error.rule(), "must be > 0");
}

TEST(ModelValidate, WhatFormatForNegativeFriction) {
  Model model;
  model.friction = -0.5;  // exactly representable: printed without noise digits
  const InvalidInput error = expect_invalid([&] { model.validate(); });
  EXPECT_STREQ(error.what(), "friction = -0.5; violated: must be >= 0");
}

TEST(ModelValidate, ValueIsPrintedToRoundTrip) {
  // The value text must identify the double exactly (max_digits10).
  Model model;
  model.amplitude = -0.1;
  const InvalidInput error = expect_invalid([&] { model.validate(); });
  EXPECT_EQ(error.parameter(), "amplitude");
  EXPECT_EQ(std::stod(error.value()), -0.1);
  model.amplitude = -(0.1 + 0.2);  // -0.30000000000000004, not -0.3
  const InvalidInput error2 = expect_invalid([&] { model.validate(); });
  EXPECT_EQ(std::stod(error2.value()), -(0.1 + 0.2));
  EXPECT_NE(std::stod(error2.value()), -0.3);
}

TEST(InvalidInput, IsAnInvalidArgumentWithTheDocumentedWhat) {
  const InvalidInput error("dt", "0", "must be > 0");
  const std::invalid_argument& base = error;
  EXPECT_STREQ(base.what(), "dt = 0; violated: must be > 0");
  EXPECT_EQ(error.parameter(), "dt");
  EXPECT_EQ(error.value(), "0");
  EXPECT_EQ(error.rule(), "must be > 0");
}

// ---- lambda and force ------------------------------------------------------

TEST(ModelLambda, RatioOfFrictionToAmplitude) {
  Model model;
  model.friction = 3;
  model.amplitude = 4;
  EXPECT_EQ(model.lambda(), 0.75);  // exact in binary
  model.friction = 0;
  EXPECT_EQ(model.lambda(), 0.0);
  model.friction = 7;
  model.amplitude = 7;
  EXPECT_EQ(model.lambda(), 1.0);
  EXPECT_EQ(Model{}.lambda(), 0.0);
}

TEST(ModelLambda, ZeroAmplitude) {
  Model model;
  model.amplitude = 0;
  model.friction = 0.25;
  EXPECT_TRUE(std::isinf(model.lambda()));
  EXPECT_GT(model.lambda(), 0);
  model.friction = 0;
  EXPECT_TRUE(std::isnan(model.lambda()));
}

TEST(ModelLambda, LongDouble) {
  BasicModel<long double> model;
  model.friction = 1;
  model.amplitude = 3;
  // 1/3 in long double is not the double 1/3.
  EXPECT_EQ(model.lambda(), 1.0L / 3.0L);
  EXPECT_NE(model.lambda(), static_cast<long double>(1.0 / 3.0));
}

TEST(ModelForce, IsBSinOmegaT) {
  Model model;
  model.amplitude = 2;
  model.omega = 3;
  // mpmath: 2*sin(mpf(3)*mpf(0.5)) = 1.994989973208108861883
  EXPECT_NEAR(model.force(0.5), 1.994989973208108861883, 4e-16);
  EXPECT_EQ(model.force(0.0), 0.0);
  // The phase is w t, not w (t - t0).
  model.t0 = 0.5;
  EXPECT_NEAR(model.force(0.5), 1.994989973208108861883, 4e-16);
  model.amplitude = 0;
  EXPECT_EQ(model.force(0.5), 0.0);
}

// ---- model_cast ------------------------------------------------------------

Model distinctive_model() {
  Model m;
  m.mass = 0.1;  // none of these is exact in decimal: a re-rounding would show
  m.amplitude = 2.0 / 3.0;
  m.omega = 1e-7 + 0.3;
  m.friction = 0.7;
  m.x0 = -1.0 / 7.0;
  m.v0 = std::nextafter(1.0, 2.0);
  m.t0 = -123.456;
  return m;
}

TEST(ModelCast, ToLongDoubleIsExact) {
  const Model m = distinctive_model();
  const BasicModel<long double> l = model_cast<long double>(m);
  EXPECT_EQ(l.mass, static_cast<long double>(m.mass));
  EXPECT_EQ(l.amplitude, static_cast<long double>(m.amplitude));
  EXPECT_EQ(l.omega, static_cast<long double>(m.omega));
  EXPECT_EQ(l.friction, static_cast<long double>(m.friction));
  EXPECT_EQ(l.x0, static_cast<long double>(m.x0));
  EXPECT_EQ(l.v0, static_cast<long double>(m.v0));
  EXPECT_EQ(l.t0, static_cast<long double>(m.t0));
  // Not re-rounded from decimal: the double 0.1 is not the long double 0.1L.
  EXPECT_NE(l.mass, 0.1L);
  EXPECT_EQ(static_cast<double>(l.mass), 0.1);
  EXPECT_NO_THROW(l.validate());
}

TEST(ModelCast, ToHighPrecisionAndBackIsExact) {
  const Model m = distinctive_model();
  const BasicModel<HighPrecision> h = model_cast<HighPrecision>(m);
  const Model back = model_cast<double>(h);
  for (const Field& field : fields()) {
    EXPECT_EQ(back.*field.member, m.*field.member) << field.name;
  }
  // 0.1 as a double is 0.1000000000000000055511151231257827...: the 50-digit
  // value keeps that, it is not 0.1 to 50 digits.
  EXPECT_NE(h.mass, HighPrecision("0.1"));
  EXPECT_EQ(h.mass, HighPrecision("0.1000000000000000055511151231257827021181583404541015625"));
}

// ---- SolveOptions ----------------------------------------------------------

TEST(SolveOptionsValidate, DefaultsAreValid) {
  const SolveOptions options{};
  EXPECT_NO_THROW(options.validate());
  EXPECT_EQ(options.max_phases, std::numeric_limits<std::uint64_t>::max());
}

TEST(SolveOptionsValidate, ZeroMaxPhasesRejected) {
  SolveOptions options;
  options.max_phases = 0;
  const InvalidInput error = expect_invalid([&] { options.validate(); });
  EXPECT_EQ(error.parameter(), "max_phases");
  EXPECT_EQ(error.value(), "0");
  EXPECT_EQ(error.rule(), "must be >= 1");
  EXPECT_STREQ(error.what(), "max_phases = 0; violated: must be >= 1");
}

TEST(SolveOptionsValidate, OneMaxPhaseAccepted) {
  SolveOptions options;
  options.max_phases = 1;
  EXPECT_NO_THROW(options.validate());
}

TEST(SolveValidation, SolveRejectsInvalidModelAndOptions) {
  Model model;
  model.omega = 0;
  EXPECT_EQ(expect_invalid([&] { solve(model, 1.0); }).parameter(), "omega");
  SolveOptions options;
  options.max_phases = 0;
  EXPECT_EQ(expect_invalid([&] { solve(Model{}, 1.0, options); }).parameter(), "max_phases");
}

}  // namespace
}  // namespace frictionref
