#pragma once
/// @file
/// Scalar functions f(x) with first and second derivatives, used for prescribed motions
/// (x = time, e.g. a crank angle 2 pi N t) and applied loads (x = time or a joint
/// coordinate, e.g. cylinder pressure force vs crank angle).

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace emb::mbs {

class ExpressionFunction;

/// f, f' and f'' at one point.
struct FunctionValue {
  double f{0.0};
  double df{0.0};
  double d2f{0.0};
};

/// An immutable scalar function. Kinds:
///  - polynomial: f = sum_k c_k x^k (constant, ramp a + b x, 2 pi N t, ...);
///  - harmonic:   f = offset + amplitude sin(omega x + phase);
///  - table:      piecewise-linear through (x_i, y_i), x strictly increasing, held constant
///                outside; optionally periodic with period x_last - x_first
///                (f'' = 0 inside intervals; use it for loads, not for motions);
///  - periodic spline: the periodic cubic spline (C2) through (x_i, y_i), period
///                x_last - x_first, y_last = y_first (e.g. a cylinder pressure curve);
///  - expression: a formula of t (expression_function.h, muParser), derivatives by
///                Richardson-extrapolated central differences.
class TimeFunction {
 public:
  /// f = 0.
  TimeFunction() = default;
  static TimeFunction Constant(double value);
  /// @throws InputError if coefficients is empty.
  static TimeFunction Polynomial(std::vector<double> coefficients);
  static TimeFunction Harmonic(double amplitude, double omega, double phase, double offset);
  /// @throws InputError if sizes differ, fewer than 2 points, or x not strictly increasing.
  static TimeFunction Table(std::vector<double> x, std::vector<double> y, bool periodic);
  /// @throws InputError as Table, for fewer than 3 points, or if y_last != y_first
  /// (relative 1e-9 of max |y|).
  static TimeFunction PeriodicSpline(std::vector<double> x, std::vector<double> y);
  /// A formula of t (or x) with named constants; `scale` the first difference step of its
  /// derivatives (ExpressionFunction). @throws InputError for a formula muParser refuses.
  static TimeFunction Expression(const std::string& text,
                                 const std::map<std::string, double>& constants = {},
                                 double scale = 1e-3);

  /// f and its derivatives up to `order` (0, 1 or 2) at x; the others may be left 0. Only
  /// an expression computes less for a lower order (and only it can fail: @throws
  /// ExpressionFunction::Eval's errors).
  FunctionValue Eval(double x, int order = 2) const;
  /// Eval at the time t of a run, for a function of time only (a motion, a load of time):
  /// there no iterate of the solver moves the argument, so an expression that is not finite
  /// at t (a division by zero, a root or logarithm outside its domain) is the input's fault.
  /// @throws InputError naming the owner ("<kind> '<name>'", e.g. motion 'drive'), the
  /// expression, t and the value, for a non-finite value; ExpressionFunction::Eval's
  /// InputError for an unresolvable derivative. Allocates nothing unless it throws.
  FunctionValue EvalAtTime(double t, int order, const char* kind, const std::string& name) const;
  /// f(x) alone (an expression needs no derivative, so a kink is no error here).
  double operator()(double x) const;
  /// "polynomial[0, 6.28]" etc. for reports.
  std::string Describe() const;

 private:
  enum class Kind { kPolynomial, kHarmonic, kTable, kSpline, kExpression };
  Kind kind_{Kind::kPolynomial};
  std::vector<double> c_{0.0};  // polynomial coefficients, or (amplitude, omega, phase, offset)
  std::vector<double> x_, y_;
  std::vector<double> m_;  // spline second derivatives at x_ (m_.back() = m_.front())
  bool periodic_{false};
  std::shared_ptr<const ExpressionFunction> expression_;  // immutable, shared by copies
};

}  // namespace emb::mbs
