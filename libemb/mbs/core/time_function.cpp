#include "libemb/mbs/core/time_function.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Sparse>

#include "libemb/common/error.h"
#include "libemb/mbs/core/expression_function.h"

namespace emb::mbs {

TimeFunction TimeFunction::Constant(double value) { return Polynomial({value}); }

TimeFunction TimeFunction::Polynomial(std::vector<double> coefficients) {
  EMB_THROW_IF(coefficients.empty(), "polynomial function: expected at least one coefficient");
  TimeFunction f;
  f.kind_ = Kind::kPolynomial;
  f.c_ = std::move(coefficients);
  return f;
}

TimeFunction TimeFunction::Harmonic(double amplitude, double omega, double phase, double offset) {
  TimeFunction f;
  f.kind_ = Kind::kHarmonic;
  f.c_ = {amplitude, omega, phase, offset};
  return f;
}

TimeFunction TimeFunction::Table(std::vector<double> x, std::vector<double> y, bool periodic) {
  EMB_THROW_IF(x.size() != y.size(), "table function: expected as many x as y values, got "
                                         << x.size() << " and " << y.size());
  EMB_THROW_IF(x.size() < 2, "table function: expected at least 2 points, got " << x.size());
  for (std::size_t i = 1; i < x.size(); ++i)
    EMB_THROW_IF(!(x[i] > x[i - 1]), "table function: expected strictly increasing x, got x["
                                         << i - 1 << "] = " << x[i - 1] << " and x[" << i
                                         << "] = " << x[i]);
  TimeFunction f;
  f.kind_ = Kind::kTable;
  f.x_ = std::move(x);
  f.y_ = std::move(y);
  f.periodic_ = periodic;
  return f;
}

TimeFunction TimeFunction::PeriodicSpline(std::vector<double> x, std::vector<double> y) {
  TimeFunction f = Table(std::move(x), std::move(y), true);
  const std::size_t n = f.x_.size() - 1;  // intervals = unknowns (M_n = M_0)
  EMB_THROW_IF(n < 2, "periodic spline: expected at least 3 points, got " << n + 1);
  double ymax = 0.0;
  for (double v : f.y_) ymax = std::max(ymax, std::abs(v));
  // Values typed or computed to ~10 digits close the period.
  constexpr double kClosureTolerance = 1e-9;
  EMB_THROW_IF(std::abs(f.y_.back() - f.y_.front()) > kClosureTolerance * std::max(1.0, ymax),
               "periodic spline: expected the last y to equal the first, got "
                   << f.y_.front() << " and " << f.y_.back());
  f.y_.back() = f.y_.front();
  f.kind_ = Kind::kSpline;
  // h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (s_i - s_{i-1}), indices mod n,
  // s_i the slope of interval i: a cyclic tridiagonal system (sparse LU, O(n)).
  auto h = [&](std::size_t i) { return f.x_[i + 1] - f.x_[i]; };
  auto slope = [&](std::size_t i) { return (f.y_[i + 1] - f.y_[i]) / h(i); };
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    const auto r = static_cast<int>(i);
    t.emplace_back(r, static_cast<int>(prev), h(prev));
    t.emplace_back(r, r, 2.0 * (h(prev) + h(i)));
    t.emplace_back(r, static_cast<int>(next), h(i));
    rhs[r] = 6.0 * (slope(i) - slope(prev));
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(t.begin(), t.end());  // n = 2: the two off-diagonal entries add
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
  EMB_CHECK(lu.info() == Eigen::Success);  // strictly diagonally dominant
  const Eigen::VectorXd M = lu.solve(rhs);
  f.m_.assign(M.data(), M.data() + n);
  f.m_.push_back(f.m_.front());
  return f;
}

TimeFunction TimeFunction::Expression(const std::string& text,
                                      const std::map<std::string, double>& constants,
                                      double scale) {
  TimeFunction f;
  f.kind_ = Kind::kExpression;
  f.expression_ = std::make_shared<const ExpressionFunction>(text, constants, scale);
  return f;
}

FunctionValue TimeFunction::EvalAtTime(double t, int order, const char* kind,
                                       const std::string& name) const {
  if (kind_ != Kind::kExpression) return Eval(t, order);
  try {
    return expression_->Eval(t, order);
  } catch (const NumericalError& e) {
    EMB_THROW(InputError, kind << " '" << name << "' at t = " << t << " s: " << e.what()
                                << "; a function of time must be finite over the whole run "
                                   "(a division by zero, or a root or logarithm outside its "
                                   "domain?)");
  }
}

double TimeFunction::operator()(double x) const {
  return kind_ == Kind::kExpression ? expression_->Value(x) : Eval(x, 0).f;
}

FunctionValue TimeFunction::Eval(double x, int order) const {
  FunctionValue v;
  switch (kind_) {
    case Kind::kExpression:
      return expression_->Eval(x, order);
    case Kind::kPolynomial: {
      // Horner for f, f', f''.
      for (std::size_t k = c_.size(); k-- > 0;) {
        v.d2f = v.d2f * x + 2.0 * v.df;
        v.df = v.df * x + v.f;
        v.f = v.f * x + c_[k];
      }
      return v;
    }
    case Kind::kHarmonic: {
      const double a = c_[0], w = c_[1], ph = c_[2], off = c_[3];
      v.f = off + a * std::sin(w * x + ph);
      v.df = a * w * std::cos(w * x + ph);
      v.d2f = -a * w * w * std::sin(w * x + ph);
      return v;
    }
    case Kind::kTable:
    case Kind::kSpline: {
      double xx = x;
      if (periodic_) {
        const double period = x_.back() - x_.front();
        xx = x_.front() + std::fmod(std::fmod(x - x_.front(), period) + period, period);
      }
      if (kind_ == Kind::kTable && xx <= x_.front()) return {y_.front(), 0.0, 0.0};
      if (kind_ == Kind::kTable && xx >= x_.back()) return {y_.back(), 0.0, 0.0};
      // A spline is periodic: xx is in [x_0, x_n] up to round-off; clamp the interval.
      const auto it = std::upper_bound(x_.begin(), x_.end(), xx);
      const std::size_t i = std::min<std::size_t>(
          static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - x_.begin() - 1, 0)),
          x_.size() - 2);
      const double h = x_[i + 1] - x_[i], t = xx - x_[i];
      const double slope = (y_[i + 1] - y_[i]) / h;
      if (kind_ == Kind::kTable) {
        v.f = y_[i] + slope * t;
        v.df = slope;
        return v;
      }
      const double m0 = m_[i], m1 = m_[i + 1];
      const double b = slope - h * (2.0 * m0 + m1) / 6.0;
      const double c3 = (m1 - m0) / (6.0 * h);
      v.f = y_[i] + t * (b + t * (0.5 * m0 + t * c3));
      v.df = b + t * (m0 + 3.0 * t * c3);
      v.d2f = m0 + 6.0 * t * c3;
      return v;
    }
  }
  return v;
}

std::string TimeFunction::Describe() const {
  std::ostringstream o;
  o.precision(10);
  if (kind_ == Kind::kExpression) {
    o << "expression[" << expression_->text() << "]";
    return o.str();
  }
  if (kind_ == Kind::kTable || kind_ == Kind::kSpline) {
    o << (kind_ == Kind::kSpline ? "periodic spline[" : "table[") << x_.size() << " points"
      << (periodic_ && kind_ == Kind::kTable ? ", periodic" : "") << "]";
    return o.str();
  }
  o << (kind_ == Kind::kPolynomial ? "polynomial[" : "harmonic[");
  for (std::size_t k = 0; k < c_.size(); ++k) o << (k ? ", " : "") << c_[k];
  o << "]";
  return o.str();
}

}  // namespace emb::mbs
