// Time functions: values and both derivatives against closed forms and differences.

#include "libemb/mbs/core/time_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

constexpr double kRoundOff = 1e-12;

TEST(TimeFunction, PolynomialDerivatives) {
  const TimeFunction f = TimeFunction::Polynomial({1.0, -2.0, 0.5, 3.0});  // 1 - 2t + t^2/2 + 3t^3
  const double t = 0.7;
  const FunctionValue v = f.Eval(t);
  EXPECT_NEAR(v.f, 1 - 2 * t + 0.5 * t * t + 3 * t * t * t, kRoundOff);
  EXPECT_NEAR(v.df, -2 + t + 9 * t * t, kRoundOff);
  EXPECT_NEAR(v.d2f, 1 + 18 * t, kRoundOff);
}

TEST(TimeFunction, HarmonicDerivatives) {
  const TimeFunction f = TimeFunction::Harmonic(2.0, 5.0, 0.3, 1.0);
  const double t = 0.4, h = 1e-5;
  const FunctionValue v = f.Eval(t);
  EXPECT_NEAR(v.f, 1.0 + 2.0 * std::sin(5.0 * t + 0.3), kRoundOff);
  // Central differences with h = 1e-5: truncation ~ h^2 |f'''| ~ 2.5e-8.
  EXPECT_NEAR(v.df, (f(t + h) - f(t - h)) / (2 * h), 1e-7);
  EXPECT_NEAR(v.d2f, (f.Eval(t + h).df - f.Eval(t - h).df) / (2 * h), 1e-6);
}

TEST(TimeFunction, TableInterpolatesHoldsAndRepeats) {
  const TimeFunction f = TimeFunction::Table({0.0, 1.0, 3.0}, {0.0, 10.0, 0.0}, false);
  EXPECT_NEAR(f(0.5), 5.0, kRoundOff);
  EXPECT_NEAR(f(2.0), 5.0, kRoundOff);
  EXPECT_NEAR(f.Eval(2.0).df, -5.0, kRoundOff);
  EXPECT_NEAR(f(-1.0), 0.0, kRoundOff);
  EXPECT_NEAR(f(4.0), 0.0, kRoundOff);
  const TimeFunction p = TimeFunction::Table({0.0, 1.0, 3.0}, {0.0, 10.0, 0.0}, true);
  EXPECT_NEAR(p(3.5), 5.0, kRoundOff);  // period 3
  EXPECT_NEAR(p(-2.5), 5.0, kRoundOff);
}

TEST(TimeFunction, BadTablesThrow) {
  EXPECT_THROW(TimeFunction::Table({0.0, 1.0}, {1.0}, false), InputError);
  EXPECT_THROW(TimeFunction::Table({0.0}, {1.0}, false), InputError);
  EXPECT_THROW(TimeFunction::Table({0.0, 0.0}, {1.0, 2.0}, false), InputError);
  EXPECT_THROW(TimeFunction::Polynomial({}), InputError);
}

// Issue 36: an expression of time that is not finite reaches no solver; it is refused naming
// the owner, the expression, the time and the value.
std::string InputMessage(const TimeFunction& f, double t) {
  try {
    f.EvalAtTime(t, 2, "motion", "drive");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TimeFunction, ExpressionOfTimeNotFiniteIsAnInputError) {
  const TimeFunction pole = TimeFunction::Expression("1/t");
  const std::string at_pole = InputMessage(pole, 0.0);
  EXPECT_NE(at_pole.find("motion 'drive' at t = 0 s"), std::string::npos) << at_pole;
  EXPECT_NE(at_pole.find("'1/t' is +inf"), std::string::npos) << at_pole;
  // Evaluated outside a run's time (a joint-angle argument) it stays recoverable.
  EXPECT_THROW(pole.Eval(0.0), NumericalError);
  // Finite at t but not at a point of the derivative's differences (t + h past the domain).
  const TimeFunction edge = TimeFunction::Expression("t + 0*ln(0.05 - t)");
  const std::string near_edge = InputMessage(edge, 0.0495);
  EXPECT_NE(near_edge.find("is NaN at 0.0505"), std::string::npos) << near_edge;
  EXPECT_NE(near_edge.find("derivatives at 0.0495"), std::string::npos) << near_edge;
  EXPECT_NEAR(edge.EvalAtTime(0.02, 2, "motion", "drive").df, 1.0, 1e-8);  // finite: no error
  // Other kinds cannot fail.
  EXPECT_NEAR(TimeFunction::Constant(2.0).EvalAtTime(0.0, 2, "motion", "x").f, 2.0, kRoundOff);
}

}  // namespace
}  // namespace emb::mbs
