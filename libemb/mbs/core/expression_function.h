#pragma once
/// @file
/// A scalar function given as a text expression of its argument (issue 14), parsed and
/// evaluated by muParser (a maintained expression library, Debian's libmuparser-dev), e.g.
/// the smooth spin-up of a crank to Omega over T seconds:
///   Omega * (t^2/2 + (T/(2*pi))^2 * (cos(2*pi*t/T) - 1)) / T
/// The argument is `t` (also spelled `x`: for a load of a joint angle); `pi` and named
/// constants are defined; muParser's functions (sin, cos, tan, asin, ..., sinh, ..., exp, ln,
/// log10, sqrt, abs, sign, rint, min, max, sum, avg) and operators (+ - * / ^, comparisons,
/// && ||, the ternary ?:) are available.
///
/// Derivatives: muParser only evaluates values, so f' and f'' (needed by velocity- and
/// acceleration-level constraints: Phi_t, Phi_tt) come from central differences at steps
/// h_k = h_0 / c^k (c = 1.4), D1(h) = (f(x+h) - f(x-h)) / 2h and D2(h) = (f(x+h) - 2 f(x) +
/// f(x-h)) / h^2, whose errors are even series in h, extrapolated to h -> 0 in a Neville
/// tableau (Ridders' method): entry j of row k removes the h^2j term,
///   A[k][j] = (c^2j A[k][j-1] - A[k-1][j-1]) / (c^2j - 1),
/// and the result is the entry whose differences to its neighbours (the error estimate) are
/// smallest; rows stop once the diagonal grows again (round-off takes over). h_0 is the
/// function's `scale`: the shortest interval of the argument over which it changes
/// appreciably (default 1e-3 s); a function much faster than its scale aliases, which the
/// error estimate catches (Eval throws InputError naming the expression).
/// Measured (tests/mbs/core/expression_function_test.cpp): on the spin-up above (Omega =
/// 100 pi rad/s, T = 0.1 s, then held) f' within 3e-9 of Omega, f'' within 4e-11 of
/// Omega/T except at the end of the ramp, where the fourth derivative jumps and f'' is
/// within 7e-7. Round-off bounds f'' by eps |f| / scale^2: a large |f| wants a larger scale.

#include <map>
#include <memory>
#include <string>

namespace emb::mbs {

struct FunctionValue;

class ExpressionFunction {
 public:
  /// Parses `text` with the constants `constants` (names as in the expression).
  /// @throws InputError with muParser's message and the position for a syntax error, an
  /// unknown name, an assignment, more than one result, a bad constant name or value, a
  /// scale that is not positive and finite, or a text longer than kMaxLength.
  ExpressionFunction(const std::string& text, const std::map<std::string, double>& constants,
                     double scale = kDefaultScale);
  ~ExpressionFunction();
  ExpressionFunction(const ExpressionFunction&) = delete;
  ExpressionFunction& operator=(const ExpressionFunction&) = delete;

  /// f(x). Thread-safe (one evaluation at a time). Cost: one muParser evaluation.
  double Value(double x) const;
  /// f and its derivatives up to `order` (0: f; 1: f, f'; 2: f, f', f'') at x (Ridders
  /// extrapolation, see above; the derivatives not asked for are 0). Cost: at most
  /// 2 kMaxRows + 1 evaluations. @throws NumericalError if f is not finite at x or at a
  /// point x +- h of the differences (an iterate outside the function's domain: recoverable
  /// in a residual; TimeFunction::EvalAtTime makes it an InputError for time), InputError if a
  /// derivative asked for cannot be resolved at this scale (error estimate above
  /// kDerivativeTolerance: a kink, a jump or a function too fast for its scale; no smaller
  /// step helps).
  FunctionValue Eval(double x, int order = 2) const;

  const std::string& text() const { return text_; }
  double scale() const { return scale_; }

  static constexpr double kDefaultScale = 1e-3;  ///< [argument unit], e.g. s
  static constexpr std::size_t kMaxLength = 4096;
  static constexpr int kMaxRows = 12;
  /// Error estimate of a derivative relative to its size (or, where it vanishes, to the
  /// change of f over the scale): well above the ~1e-10 Ridders delivers on smooth
  /// functions, well below what would upset the constraint levels of the DAE.
  static constexpr double kDerivativeTolerance = 1e-6;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string text_;
  double scale_;
};

}  // namespace emb::mbs
