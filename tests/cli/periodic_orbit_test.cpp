// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed orbit (commands/periodic_orbit.h), as the command line and the Python module call
// it: Newton from the closed form's point finds the closed form's orbit (two algorithms, one
// orbit), on chains of both design branches, scaled and another mass ratio; precision auto
// raises where the closed form loses its digits, and a fixed one says so; a chain of another
// shape is refused before it is designed.
#include <gtest/gtest.h>

#include <QString>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "commands/orbit_command.h"
#include "commands/periodic_orbit.h"
#include "io/option_values.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;

std::shared_ptr<const PreparedMassChain> chainOf(const Options& options) {
  auto made = twoMassChainOf(OptionValues(options));
  EXPECT_TRUE(made.value) << made.error.toStdString();
  return *made.value;
}

const FoundOrbit<double>& foundIn(const OrbitOutcome& outcome) { return std::get<FoundOrbit<double>>(outcome.found); }

// The 1IPP orbit at a fraction of T2 by the closed form, then the same orbit by Newton on the
// return map from its own point and energy: one orbit, its multipliers alike.
void newtonFindsTheClosedForm(const Options& chainOptions, double fractionOfT2) {
  const auto chain = chainOf(chainOptions);
  ASSERT_TRUE(chain->twoMassForm<double>().value);
  const core::TwoMassForm<double>& form = chain->twoMassForm<double>().value->chain;
  const double T2 = core::twoPi<double>() / form.omegaSlow;
  OrbitRequest closed;
  closed.period = std::to_string(fractionOfT2 * T2);
  closed.precision = PrecisionChoice::Double;
  const OrbitOutcome byClosedForm = solveOrbit(*chain, closed);
  ASSERT_EQ(byClosedForm.status, OrbitStatus::Found) << byClosedForm.problem;
  const core::PeriodicOrbit<double>& orbit = foundIn(byClosedForm).orbit;

  // Newton from a guess 1e-4 off the orbit's point (u1 moved; v1 = 0 on a symmetric orbit)
  OrbitRequest newton;
  newton.impacts = 1;
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", orbit.energy);
  newton.energy = text;
  std::snprintf(text, sizeof text, "%.17g", orbit.state.u1 * (1 + 1e-4));
  newton.guess.push_back(text);
  std::snprintf(text, sizeof text, "%.17g", orbit.state.v1 + 1e-4 * std::abs(orbit.state.u1));
  newton.guess.push_back(text);
  newton.precision = PrecisionChoice::Double;
  const OrbitOutcome byNewton = solveOrbit(*chain, newton);
  ASSERT_EQ(byNewton.status, OrbitStatus::Found) << byNewton.problem;
  const core::PeriodicOrbit<double>& found = foundIn(byNewton).orbit;
  EXPECT_NEAR(found.state.u1, orbit.state.u1, 1e-9 * std::abs(orbit.state.u1));
  EXPECT_NEAR(found.period, orbit.period, 1e-10 * orbit.period);
  EXPECT_NEAR(found.trace, orbit.trace, 1e-8);
  EXPECT_EQ(found.stability, orbit.stability);
  // the document names what it is in words the command line writes
  const JsonValue document = orbitDocument(byNewton);
  EXPECT_EQ(document.find("impacts")->integer, 1);
  EXPECT_EQ(document.find("precision")->text, "double");
}

TEST(TypedOrbit, NewtonFindsTheClosedFormsOrbitOnBothBranchesScaledAndOtherMassRatios) {
  newtonFindsTheClosedForm({}, 0.9);
  newtonFindsTheClosedForm({{"branch", "lower"}}, 0.8);
  newtonFindsTheClosedForm({{"m1", "3"}, {"m2", "0.6"}, {"k1", "7"}, {"gap", "0.01"}}, 0.95);
  newtonFindsTheClosedForm({{"masses", "1,0.125"}, {"frequencies", "2:1"}}, 0.85);
}

TEST(TypedOrbit, AutoRaisesWhereTheClosedFormLosesItsDigitsAndAFixedPrecisionSaysSo) {
  // the 1IPP orbit just below T2 of the note's chain: its closed form loses its digits there in double
  const auto chain = chainOf({});
  OrbitRequest request;
  request.period = "8.8857658763";
  request.precision = PrecisionChoice::Double;
  const OrbitOutcome inDouble = solveOrbit(*chain, request);
  EXPECT_EQ(inDouble.status, OrbitStatus::Undecided);
  EXPECT_NE(inDouble.problem.find("--precision quad"), std::string::npos) << inDouble.problem;
  request.precision = PrecisionChoice::Auto;
  const OrbitOutcome raised = solveOrbit(*chain, request);
  ASSERT_EQ(raised.status, OrbitStatus::Found) << raised.problem;
  EXPECT_NE(raised.precision, core::Precision::Double);
  EXPECT_FALSE(std::holds_alternative<FoundOrbit<double>>(raised.found));
  EXPECT_EQ(orbitDocument(raised).find("precision")->text, std::string(core::toString(raised.precision)));
}

TEST(TypedOrbit, NearT1AnOrbitNoPrecisionDecidesIsUndecidedNotRefusedAsOpen) {
  // 1.3e-10 below T1 = T2 / 2 of the note's chain, where the family's lower part ends on GLOM1:
  // the impact speed is 4e-10 and the return map amplifies the rounding 2e10 times; no precision
  // decides the orbit, and none says that its path does not close
  const auto chain = chainOf({});
  OrbitRequest request;
  request.period = "4.44288293802508";
  for (PrecisionChoice precision :
       {PrecisionChoice::Double, PrecisionChoice::Long, PrecisionChoice::Quad, PrecisionChoice::Auto}) {
    request.precision = precision;
    const OrbitOutcome outcome = solveOrbit(*chain, request);
    EXPECT_EQ(outcome.status, OrbitStatus::Undecided) << outcome.problem;
    EXPECT_EQ(outcome.problem.find("does not close"), std::string::npos) << outcome.problem;
    EXPECT_TRUE(std::holds_alternative<std::monostate>(outcome.found));
  }
  // 1e-7 below T1 auto no longer stops at long double's "does not close": found or undecided
  request.period = "4.442882838158366247";
  request.precision = PrecisionChoice::Auto;
  const OrbitOutcome below = solveOrbit(*chain, request);
  EXPECT_NE(below.status, OrbitStatus::Refused) << below.problem;
  // 1e-7 above T1 the data leave into the stop (V > 0): refused, decided
  request.period = "4.442883038158366247";
  const OrbitOutcome above = solveOrbit(*chain, request);
  EXPECT_EQ(above.status, OrbitStatus::Refused);
  EXPECT_NE(above.problem.find(">= 0"), std::string::npos) << above.problem;
}

TEST(TypedOrbit, AClassTheTracesErrorCannotDecideIsSaidUndecidedAndAutoRaisesPastIt) {
  // m2 = 0.3, 1e-8 below T1 = 3.815845380119236: long double's orbit has trace -2.2417 with an
  // error of 0.41 (flip-hyperbolic or elliptic); binary128's -2.242050 +- 7e-16
  const auto chain = chainOf({{"m2", "0.3"}});
  OrbitRequest request;
  request.period = "3.815845370119236";
  request.precision = PrecisionChoice::Long;
  const OrbitOutcome inLong = solveOrbit(*chain, request);
  ASSERT_EQ(inLong.status, OrbitStatus::Found) << inLong.problem;
  const auto& longOrbit = std::get<FoundOrbit<long double>>(inLong.found).orbit;
  EXPECT_EQ(core::decidedStability(longOrbit), core::Stability::Undecided);
  EXPECT_EQ(orbitDocument(inLong).find("stability")->text, "undecided");
  request.precision = PrecisionChoice::Auto;
  const OrbitOutcome raised = solveOrbit(*chain, request);
  ASSERT_EQ(raised.status, OrbitStatus::Found) << raised.problem;
  ASSERT_TRUE(std::holds_alternative<FoundOrbit<core::Quad>>(raised.found));
  const auto& orbit = std::get<FoundOrbit<core::Quad>>(raised.found).orbit;
  EXPECT_EQ(core::decidedStability(orbit), core::Stability::FlipHyperbolic);
  EXPECT_LT(core::toDouble(orbit.traceError), 1e-12);
}

TEST(TypedOrbit, RefusalsAreLinesAndAnotherShapeIsNotDesigned) {
  // three masses: refused on their shape (a design of them would take a while first)
  const auto three = twoMassChainOf(OptionValues(Options{{"masses", "1,0.2,0.05"}, {"frequencies", "3:2:1"}}));
  EXPECT_FALSE(three.value);
  EXPECT_TRUE(three.error.contains("two-mass chain stopped on mass 2")) << three.error.toStdString();
  const auto chain = chainOf({});
  OrbitRequest beyond;
  beyond.period = "100";
  const OrbitOutcome none = solveOrbit(*chain, beyond);
  EXPECT_EQ(none.status, OrbitStatus::Refused);
  EXPECT_NE(none.problem.find("T/T2 in about"), std::string::npos) << none.problem;
  EXPECT_TRUE(std::holds_alternative<std::monostate>(none.found));
  OrbitRequest badEnergy;
  badEnergy.impacts = 2;
  badEnergy.energy = "-1";
  badEnergy.guess = {"0.1", "0"};
  EXPECT_NE(solveOrbit(*chain, badEnergy).problem.find("not a positive energy"), std::string::npos);
  badEnergy.impacts = 65;
  EXPECT_NE(solveOrbit(*chain, badEnergy).problem.find("from 1 to 64"), std::string::npos);
}

}  // namespace
}  // namespace grazelab::cli
