// Time functions: values and both derivatives against closed forms and differences.

#include "libemb/mbs/core/time_function.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace emb::mbs
