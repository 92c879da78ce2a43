#include "libemb/mbs/core/expression_function.h"

#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <regex>

#include "libemb/common/error.h"
#include "libemb/mbs/core/time_function.h"

namespace emb::mbs {
namespace {

// A non-finite value as a reader expects it ("-nan" from the stream is noise).
const char* NonFinite(double v) { return std::isnan(v) ? "NaN" : v > 0.0 ? "+inf" : "-inf"; }

}  // namespace

struct ExpressionFunction::Impl {
  mu::Parser parser;
  double x{0.0};
  std::mutex mutex;
};

ExpressionFunction::ExpressionFunction(const std::string& text,
                                       const std::map<std::string, double>& constants,
                                       double scale)
    : impl_(std::make_unique<Impl>()), text_(text), scale_(scale) {
  EMB_THROW_IF(text.size() > kMaxLength, "expression: expected at most "
                                             << kMaxLength << " characters, got " << text.size());
  EMB_THROW_IF(text.find_first_not_of(" \t\r\n") == std::string::npos,
               "expression: expected a formula of t, got an empty text");
  EMB_THROW_IF(!(std::isfinite(scale) && scale > 0.0),
               "expression scale: expected a positive, finite interval of the argument, got "
                   << scale);
  // A lone '=' is muParser's assignment: it would change t itself.
  static const std::regex kAssignment("(^|[^<>=!])=($|[^=])");
  EMB_THROW_IF(std::regex_search(text, kAssignment),
               "expression '" << text << "': '=' assigns in muParser; expected a formula "
                                 "(comparisons are ==, !=, <=, >=)");
  static const std::regex kName("[A-Za-z_][A-Za-z0-9_]*");
  mu::Parser& p = impl_->parser;
  try {
    p.DefineVar("t", &impl_->x);
    p.DefineVar("x", &impl_->x);
    p.DefineConst("pi", std::numbers::pi);
    for (const auto& [name, value] : constants) {
      EMB_THROW_IF(!std::regex_match(name, kName),
                   "expression constant '" << name << "': expected a name of letters, digits "
                                              "and _, starting with a letter");
      EMB_THROW_IF(name == "t" || name == "x" || name == "pi",
                   "expression constant '" << name << "': the name is taken (t and x are the "
                                              "argument, pi is defined)");
      // muParser takes a constant named like one of its functions, and "sin" then no longer
      // reads as the reader meant.
      EMB_THROW_IF(p.GetFunDef().count(name) != 0,
                   "expression constant '" << name << "': the name is taken by muParser's "
                                              "function " << name << "(); expected another name");
      EMB_THROW_IF(!std::isfinite(value),
                   "expression constant '" << name << "': expected a finite value, got "
                                           << value);
      p.DefineConst(name, value);
    }
    p.SetExpr(text);
    p.Eval();  // parses now: syntax errors and unknown names surface here
    EMB_THROW_IF(p.GetNumResults() != 1, "expression '" << text << "': expected one formula, got "
                                                         << p.GetNumResults()
                                                         << " separated by commas");
  } catch (const mu::Parser::exception_type& e) {
    EMB_THROW(InputError, "expression '" << text << "': " << e.GetMsg() << " (at character "
                                         << e.GetPos() + 1 << ")");
  }
}

ExpressionFunction::~ExpressionFunction() = default;

double ExpressionFunction::Value(double x) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->x = x;
  try {
    return impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    EMB_THROW(NumericalError, "expression '" << text_ << "' at " << x << ": " << e.GetMsg());
  }
}

FunctionValue ExpressionFunction::Eval(double x, int order) const {
  constexpr double kShrink = 1.4, kShrink2 = kShrink * kShrink;
  constexpr double kSafe = 2.0;  // stop once a row's diagonal moves this much past the best
  FunctionValue v;
  v.f = Value(x);
  if (!std::isfinite(v.f))
    EMB_THROW(NumericalError, "expression '" << text_ << "' is " << NonFinite(v.f) << " at " << x);
  if (order <= 0) return v;
  double a1[kMaxRows][kMaxRows], a2[kMaxRows][kMaxRows];
  double err1 = HUGE_VAL, err2 = HUGE_VAL, change = 0.0;
  bool done1 = false, done2 = order < 2;
  double h = scale_;
  for (int k = 0; k < kMaxRows && !(done1 && done2); ++k, h /= kShrink) {
    const double fp = Value(x + h), fm = Value(x - h);
    if (!std::isfinite(fp) || !std::isfinite(fm))
      EMB_THROW(NumericalError, "expression '" << text_ << "' is " << NonFinite(std::isfinite(fp) ? fm : fp)
                                               << " at " << (std::isfinite(fp) ? x - h : x + h)
                                               << ", where the central differences for its "
                                                  "derivatives at "
                                               << x << " look (steps up to its scale, "
                                               << scale_ << ")");
    // The step actually taken: x + h rounds for large |x|.
    const double h_eff = 0.5 * ((x + h) - (x - h));
    if (k == 0) change = std::max(std::abs(fp - v.f), std::abs(fm - v.f));
    a1[k][0] = (fp - fm) / (2.0 * h_eff);
    a2[k][0] = (fp - 2.0 * v.f + fm) / (h_eff * h_eff);
    double fac = kShrink2;
    for (int j = 1; j <= k; ++j, fac *= kShrink2) {
      a1[k][j] = (a1[k][j - 1] * fac - a1[k - 1][j - 1]) / (fac - 1.0);
      a2[k][j] = (a2[k][j - 1] * fac - a2[k - 1][j - 1]) / (fac - 1.0);
      const double e1 = std::max(std::abs(a1[k][j] - a1[k][j - 1]),
                                 std::abs(a1[k][j] - a1[k - 1][j - 1]));
      const double e2 = std::max(std::abs(a2[k][j] - a2[k][j - 1]),
                                 std::abs(a2[k][j] - a2[k - 1][j - 1]));
      if (!done1 && e1 <= err1) err1 = e1, v.df = a1[k][j];
      if (!done2 && e2 <= err2) err2 = e2, v.d2f = a2[k][j];
    }
    if (k > 0) {
      done1 = done1 || std::abs(a1[k][k] - a1[k - 1][k - 1]) >= kSafe * err1;
      done2 = done2 || std::abs(a2[k][k] - a2[k - 1][k - 1]) >= kSafe * err2;
    }
  }
  // Where a derivative vanishes its error counts against the change of f over the scale.
  const double ref1 = std::max(std::abs(v.df), change / scale_);
  const double ref2 = std::max(std::abs(v.d2f), change / (scale_ * scale_));
  if (order < 2) v.d2f = 0.0, err2 = 0.0;
  // The function, not the step, is at fault: an InputError (a smaller integrator step
  // cannot help), where a non-finite value above may be an iterate outside its domain.
  if (!(err1 <= kDerivativeTolerance * ref1) || !(err2 <= kDerivativeTolerance * ref2))
    EMB_THROW(InputError,
                  "expression '" << text_ << "': its derivatives at " << x
                                 << " cannot be resolved from the scale " << scale_
                                 << " (error estimates " << err1 << " of f' = " << v.df << ", "
                                 << err2 << " of f'' = " << v.d2f
                                 << "): a kink or jump has no derivative (motions need "
                                    "smooth functions), and a function faster than its scale "
                                    "needs a smaller scale (the shortest interval over which it "
                                    "changes appreciably)");
  return v;
}

}  // namespace emb::mbs
