// Expressions of t (muParser) as motion and load functions: values, and the derivatives that
// the velocity- and acceleration-level constraints use (Richardson-extrapolated differences),
// against closed forms; a second route (TimeFunction::Polynomial's Horner derivatives); the
// guard against a function faster than its scale; and every malformed text refused.

#include "libemb/mbs/core/expression_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "libemb/common/error.h"
#include "libemb/mbs/core/time_function.h"

namespace emb::mbs {
namespace {

constexpr double kPi = std::numbers::pi;

// The smooth spin-up of issue 14 to Omega over T seconds, then constant speed (C3 at T):
//   theta = Omega (t^2/2 + (T/2pi)^2 (cos(2 pi t/T) - 1)) / T           (t < T)
//         = Omega (t - T/2)                                             (t >= T)
//   theta'  = Omega (t - (T/2pi) sin(2 pi t/T)) / T,  theta'' = Omega (1 - cos(2 pi t/T)) / T.
constexpr double kOmega = 100 * kPi;  // [rad/s] 3000 rpm
constexpr double kRampTime = 0.1;     // [s]
const char* kSpinUp =
    "t < T ? Omega*(t^2/2 + (T/(2*pi))^2*(cos(2*pi*t/T) - 1))/T : Omega*(t - T/2)";

FunctionValue SpinUp(double t) {
  const double T = kRampTime, W = kOmega;
  if (t >= T) return {W * (t - T / 2), W, 0.0};
  const double a = 2 * kPi * t / T, c = T / (2 * kPi);
  return {W * (t * t / 2 + c * c * (std::cos(a) - 1)) / T, W * (t - c * std::sin(a)) / T,
          W * (1 - std::cos(a)) / T};
}

TEST(ExpressionFunction, SpinUpDerivativesMatchTheClosedForm) {
  const TimeFunction f =
      TimeFunction::Expression(kSpinUp, {{"Omega", kOmega}, {"T", kRampTime}});
  // Relative to the scales of the motion: Omega (speed) and Omega / T (acceleration).
  // Measured: f' within 2.5e-9, f'' within 7e-7 — at the end of the ramp, where the fourth
  // derivative jumps and no extrapolation of differences that straddle it converges
  // further; elsewhere f'' within 1e-8. The bounds leave a factor 2..4.
  constexpr double kSpeedRelative = 1e-8, kAccelerationRelative = 2e-6;
  constexpr double kSmoothAccelerationRelative = 4e-8;  // more than 5 ms from the joint
  double worst1 = 0.0, worst2 = 0.0, worst2_smooth = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double t = 2 * kRampTime * k / 400.0;  // through the ramp, its end and the hold
    const FunctionValue got = f.Eval(t), want = SpinUp(t);
    // Values: the same formula evaluated twice, to round-off of an angle of ~50 rad.
    EXPECT_NEAR(got.f, want.f, 1e-12 * kOmega * kRampTime) << "t = " << t;
    worst1 = std::max(worst1, std::abs(got.df - want.df) / kOmega);
    const double e2 = std::abs(got.d2f - want.d2f) / (kOmega / kRampTime);
    worst2 = std::max(worst2, e2);
    if (std::abs(t - kRampTime) > 5e-3) worst2_smooth = std::max(worst2_smooth, e2);
  }
  EXPECT_LT(worst1, kSpeedRelative);
  EXPECT_LT(worst2, kAccelerationRelative);
  EXPECT_LT(worst2_smooth, kSmoothAccelerationRelative);
  std::printf("spin-up: worst relative error of f' %.2e, of f'' %.2e (%.2e away from t = T)\n",
              worst1, worst2, worst2_smooth);
}

TEST(ExpressionFunction, PolynomialAgreesWithHorner) {
  // The same cubic by the two routes. Round-off of f(x +- h) over h^2 bounds f'':
  // eps |f| / h^2 relative to |f''| is ~1e-9 at t = 5 with the default scale; at t = 50
  // (f = 3.75e5) a larger scale (0.1) gives the digits back.
  const TimeFunction horner = TimeFunction::Polynomial({1.0, -2.0, 0.5, 3.0});
  const TimeFunction parsed = TimeFunction::Expression("1 - 2*t + 0.5*t^2 + 3*t^3");
  const TimeFunction coarse = TimeFunction::Expression("1 - 2*t + 0.5*t^2 + 3*t^3", {}, 0.1);
  for (auto [t, f] : {std::pair{-1.3, &parsed}, std::pair{0.0, &parsed}, std::pair{0.7, &parsed},
                      std::pair{5.0, &parsed}, std::pair{50.0, &coarse}}) {
    const FunctionValue a = horner.Eval(t), b = f->Eval(t);
    EXPECT_NEAR(b.f, a.f, 1e-14 * std::max(1.0, std::abs(a.f)));
    EXPECT_NEAR(b.df, a.df, 1e-9 * std::max(1.0, std::abs(a.df))) << "t = " << t;
    EXPECT_NEAR(b.d2f, a.d2f, 1e-8 * std::max(1.0, std::abs(a.d2f))) << "t = " << t;
  }
}

TEST(ExpressionFunction, FastFunctionNeedsItsScale) {
  // 1 kHz: with the scale set to 0.1 ms the derivatives are right; with the default 1 ms the
  // first difference step is one whole period (f(t +- h) = f(t)), which the error estimate
  // catches instead of returning f' = 0.
  const double w = 2 * kPi * 1000;
  const TimeFunction fine = TimeFunction::Expression("sin(w*t)", {{"w", w}}, 1e-4);
  for (double t : {0.0, 1.234e-4, 0.01}) {
    const FunctionValue v = fine.Eval(t);
    EXPECT_NEAR(v.df, w * std::cos(w * t), 1e-9 * w);
    EXPECT_NEAR(v.d2f, -w * w * std::sin(w * t), 1e-9 * w * w);
  }
  const TimeFunction coarse = TimeFunction::Expression("sin(w*t)", {{"w", w}});
  EXPECT_THROW(coarse.Eval(1.234e-4), InputError);
}

TEST(ExpressionFunction, KinkIsNotDifferentiable) {
  // |t - 1| has no derivative at 1: an error about the function, not a made-up slope; its
  // value is fine (a load of time needs no derivative).
  const TimeFunction f = TimeFunction::Expression("abs(t - 1)");
  EXPECT_NEAR(f.Eval(2.0).df, 1.0, 1e-12);
  EXPECT_THROW(f.Eval(1.0), InputError);
  // f' alone: near the kink the differences that straddle it disagree with those that do
  // not (exactly at it, central differences give the mean slope 0 at every step).
  EXPECT_THROW(f.Eval(1.0002, 1), InputError);
  EXPECT_NEAR(f.Eval(1.0, 1).df, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(f.Eval(1.0, 0).f, 0.0);
  EXPECT_DOUBLE_EQ(f(1.0), 0.0);
}

TEST(ExpressionFunction, NonFiniteValueIsANumericalError) {
  // Outside the domain: recoverable where an integrator tried a point too far.
  const TimeFunction f = TimeFunction::Expression("sqrt(t)");
  EXPECT_THROW(f.Eval(-1.0), NumericalError);
}

TEST(ExpressionFunction, CopiesShareOneParser) {
  const TimeFunction f = TimeFunction::Expression("2*t");
  const TimeFunction g = f;  // TimeFunction is a value; the parsed formula is shared
  EXPECT_DOUBLE_EQ(g(3.0), 6.0);
  EXPECT_DOUBLE_EQ(f(4.0), 8.0);
  EXPECT_EQ(g.Describe(), "expression[2*t]");
}

void ExpectRefused(const std::string& text, const std::string& word,
                   std::map<std::string, double> constants = {}, double scale = 1e-3) {
  try {
    TimeFunction::Expression(text, constants, scale);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(ExpressionFunction, MalformedTextIsRefused) {
  ExpectRefused("sin(t", "expression 'sin(t'");
  ExpectRefused("2*t +", "expression");
  ExpectRefused("omega*t", "omega");  // unknown name
  ExpectRefused("t = 3", "assigns");
  ExpectRefused("t, 2*t", "one formula");
  ExpectRefused("", "empty");
  ExpectRefused("  \n", "empty");
  ExpectRefused(std::string(5000, '1'), "at most");
  ExpectRefused("a*t", "finite", {{"a", std::nan("")}});
  ExpectRefused("t", "taken", {{"pi", 3.0}});
  ExpectRefused("sin*t", "function sin()", {{"sin", 3.0}});  // shadows a built-in function
  ExpectRefused("t", "function max()", {{"max", 3.0}});
  ExpectRefused("t", "name", {{"2a", 3.0}});
  ExpectRefused("t", "scale", {}, 0.0);
  ExpectRefused("t", "scale", {}, std::nan(""));
  // Comparisons are no assignments.
  EXPECT_DOUBLE_EQ(TimeFunction::Expression("t <= 1 ? 1 : (t == 2 ? 5 : 0)")(2.0), 5.0);
}

}  // namespace
}  // namespace emb::mbs
